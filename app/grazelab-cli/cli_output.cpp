// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "cli_output.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QString>

#include "core/orbits.h"

namespace grazelab::cli {
namespace {

// 17 significant digits: every double round-trips
QByteArray exact(double value) { return QByteArray::number(value, 'g', 17); }

QJsonObject stateJson(double t, const core::State& state) {
  return {{"t", t}, {"u1", state.u1}, {"u2", state.u2}, {"v1", state.v1}, {"v2", state.v2}};
}

double contactsPerSecond(const core::Result& result) {
  return result.cost.wallSeconds > 0 ? double(result.cost.contacts) / result.cost.wallSeconds : 0;
}

}  // namespace

QJsonObject modelJson(const ModelInput& input, const core::Modes& modes) {
  const core::Model& model = input.model;
  QJsonObject json{
      {"m1", model.m1},
      {"m2", model.m2},
      {"k1", model.k1},
      {"k2", model.k2},
      {"gap", model.gap},
      {"k2_source", input.branch ? QString("1:2 design, %1 branch")
                                       .arg(QString::fromUtf8(core::toString(*input.branch).data()))
                                 : QString("given")},
      {"mass_ratio", model.m2 / model.m1},
      {"omega1", modes.omegaFast},
      {"omega2", modes.omegaSlow},
      {"T1", modes.T1},
      {"T2", modes.T2},
      {"resonant", modes.resonant},
      {"detuning", modes.detuning},
      {"mode_labelling", "mode 1 is the fast mode, mode 2 the slow one (omega1 = 2 omega2)"},
      {"P", QJsonArray{QJsonArray{modes.P(0, 0), modes.P(0, 1)},
                       QJsonArray{modes.P(1, 0), modes.P(1, 1)}}},
  };
  if (modes.resonant) {
    json["lambda_star"] = core::lambdaStar(modes);
  } else {
    json["lambda_star"] = QJsonValue::Null;
  }
  return json;
}

QByteArray simulationJson(const RunInput& run, const core::Result& result) {
  QJsonArray events;
  for (const core::Event& event : result.events) {
    events.append(QJsonObject{
        {"t", event.t},
        {"type", QString::fromUtf8(core::toString(event.type).data())},
        {"u1", event.before.u1},
        {"u2", event.before.u2},
        {"v1", event.before.v1},
        {"v2_pre", event.before.v2},
        {"v2_post", event.after.v2},
    });
  }
  const core::Cost& cost = result.cost;
  const QJsonObject json{
      {"model", modelJson(run.model, result.modes)},
      {"initial", QJsonObject{{"description", run.initialDescription},
                              {"state", stateJson(0.0, run.request.initial)}}},
      {"events", events},
      {"final", stateJson(result.tFinal, result.final)},
      {"stop_reason", QString::fromUtf8(core::toString(result.stop).data())},
      {"contacts", QJsonObject{{"total", double(cost.contacts)},
                               {"impacts", double(cost.impacts)},
                               {"grazings", double(cost.grazings)},
                               {"sticks", double(cost.sticks)}}},
      {"energy", QJsonObject{{"initial", result.initialEnergy},
                             {"max_rel_drift", cost.maxRelEnergyDrift},
                             {"max_flight_error", cost.maxFlightEnergyError}}},
      {"accuracy", QJsonObject{{"max_contact_residual", cost.maxContactResidual}}},
      {"timing", QJsonObject{{"seconds", cost.wallSeconds},
                             {"contacts_per_second", contactsPerSecond(result)}}},
  };
  return QJsonDocument(json).toJson(QJsonDocument::Indented);
}

QByteArray simulationCsv(const core::Result& result) {
  QByteArray csv = "t,type,u1,u2,v1,v2_pre,v2_post\n";
  for (const core::Event& event : result.events) {
    csv += exact(event.t) + ',' + QByteArray(core::toString(event.type).data()) + ',' +
           exact(event.before.u1) + ',' + exact(event.before.u2) + ',' + exact(event.before.v1) +
           ',' + exact(event.before.v2) + ',' + exact(event.after.v2) + '\n';
  }
  return csv;
}

QByteArray simulationSummary(const RunInput& run, const core::Result& result) {
  const core::Cost& cost = result.cost;
  const core::Modes& modes = result.modes;
  QString text;
  text += QString("start          %1\n").arg(run.initialDescription);
  text += QString("chain          m1=%1 m2=%2 k1=%3 k2=%4 gap=%5 (%6; T2=%7)\n")
              .arg(run.model.model.m1, 0, 'g', 10)
              .arg(run.model.model.m2, 0, 'g', 10)
              .arg(run.model.model.k1, 0, 'g', 10)
              .arg(run.model.model.k2, 0, 'g', 10)
              .arg(run.model.model.gap, 0, 'g', 10)
              .arg(modes.resonant ? "1:2 resonant" : "detuned")
              .arg(modes.T2, 0, 'g', 10);
  text += QString("contacts       %1 (impacts %2, grazings %3, sticks %4)\n")
              .arg(cost.contacts)
              .arg(cost.impacts)
              .arg(cost.grazings)
              .arg(cost.sticks);
  text += QString("stopped        %1 at t = %2%3\n")
              .arg(QString::fromUtf8(core::toString(result.stop).data()))
              .arg(result.tFinal, 0, 'g', 17)
              .arg(result.message.empty() ? QString() : " (" + QString::fromStdString(result.message) + ")");
  text += QString("wall time      %1 s (%2 contacts/s)\n")
              .arg(cost.wallSeconds, 0, 'g', 4)
              .arg(contactsPerSecond(result), 0, 'g', 4);
  text += QString("energy drift   %1 (max relative, at contacts; one flight: %2)\n")
              .arg(cost.maxRelEnergyDrift, 0, 'g', 3)
              .arg(cost.maxFlightEnergyError, 0, 'g', 3);
  text += QString("|u2 - gap|     %1 (max at contacts)\n").arg(cost.maxContactResidual, 0, 'g', 3);
  text += QString("final          t=%1 u1=%2 u2=%3 v1=%4 v2=%5\n")
              .arg(result.tFinal, 0, 'g', 17)
              .arg(result.final.u1, 0, 'g', 17)
              .arg(result.final.u2, 0, 'g', 17)
              .arg(result.final.v1, 0, 'g', 17)
              .arg(result.final.v2, 0, 'g', 17);
  return text.toUtf8();
}

}  // namespace grazelab::cli
