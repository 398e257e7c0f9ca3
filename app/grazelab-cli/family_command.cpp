// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli family --onepp`: the one-impact-per-period family of the chain (issue 10).
#include "family_command.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "cli_input.h"
#include "core/family.h"
#include "core/orbits.h"
#include "npy.h"
#include "output_files.h"
#include "report_command.h"

#if GRAZELAB_CLI_PICTURES
#include <QPainter>

#include "ui/plots/family_picture.h"
#endif

namespace grazelab::cli {
namespace {

QByteArray number(double value) { return QByteArray::number(value, 'g', 17); }

QJsonObject pointJson(const core::FamilyPoint& p) {
  return {{"T", p.T}, {"omega", p.omega}, {"V", p.V}, {"u1", p.u1}, {"energy", p.energy}};
}


}  // namespace

int runFamily(const QCommandLineParser& parser, std::stop_token stop, QString& error) {
  if (!parser.isSet("onepp")) {
    error = "family: name the family: --onepp (one impact per period)";
    return kExitInvalidInput;
  }
  for (const char* name : {"glo", "state", "perturb", "contacts", "t-end", "format", "trust", "x",
                           "y", "threads", "shard", "picture", "methods", "quick", "search-steps"}) {
    if (parser.isSet(name)) {
      error = QStringLiteral("--%1 does not apply to 'family'").arg(name);
      return kExitInvalidInput;
    }
  }
  if (parser.value("precision") != "auto" && parser.value("precision") != "double") {
    error = "--precision: the family is computed in double";
    return kExitInvalidInput;
  }
  std::int64_t count = 2000;
  if (parser.isSet("count")) {
    bool ok = false;
    count = parser.value("count").toLongLong(&ok);
    if (!ok || count < 1 || count > 10'000'000) {
      error = QStringLiteral("--count: '%1' is not a count from 1 to 10000000").arg(parser.value("count"));
      return kExitInvalidInput;
    }
  }
  const Parsed<ModelInput<double>> model = parseModel<double>(parser);
  if (!model.value) {
    error = model.error;
    return kExitInvalidInput;
  }
  if (!model.value->chain.resonant) {
    error = "family: the 1IPP family of Theorem 2.1 needs the 1:2 resonant chain (give no --k2)";
    return kExitInvalidInput;
  }
  const auto output = parseOutputPrefix(parser, "PREFIX.csv, PREFIX.npy, PREFIX.json, ...", "family", error);
  if (!output) return kExitInvalidInput;
  const QString& prefix = *output;

  const core::Chain<double>& chain = model.value->chain;
  const std::vector<core::FamilyPoint> family = core::onePeriodicFamily(chain, count, stop);
  if (stop.stop_requested()) return kExitInterrupted;
  const core::FamilyPoint end = core::grazingEnd(chain);

  QByteArray csv = "T,omega,V,u1,energy,admissible\n";
  NpyArray array;
  array.rows = std::int64_t(family.size());
  array.columns = 6;
  for (const core::FamilyPoint& p : family) {
    csv += number(p.T) + "," + number(p.omega) + "," + number(p.V) + "," + number(p.u1) + "," +
           number(p.energy) + "," + (p.admissible ? "1" : "0") + "\n";
    for (double v : {p.T, p.omega, p.V, p.u1, p.energy, p.admissible ? 1.0 : 0.0}) array.reals.push_back(v);
  }
  const core::Model& m = chain.model;
  const QJsonObject json{
      {"format", "grazelab-family"},
      {"family", "onepp"},
      {"model", QJsonObject{{"m1", m.m1}, {"m2", m.m2}, {"k1", m.k1}, {"k2", m.k2}, {"gap", m.gap},
                            {"T2", core::twoPi<double>() / chain.omegaSlow}}},
      {"lambda_star", core::lambdaStar(chain)},
      {"grazing_end", pointJson(end)},
      {"columns", QJsonArray{"T", "omega", "V", "u1", "energy", "admissible"}},
      {"rows", qint64(family.size())},
      {"periods", QStringLiteral("T2 k / (count + 1) for k = 1 ... %1, and T2 (1 - 2^-k) for k = 8 ... 40, "
                                 "sorted; multiples of T1 left out").arg(count)},
      {"energy", "E = 1/2 v^T M v + 1/2 u^T K u of the post-impact state (constant on the orbit)"},
      {"post_impact_state", "u1 = u1, u2 = gap, v1 = 0, v2 = V"},
      {"conditioning", "each row is computed in binary128 from its double period and rounded "
                       "once; near T2, V is conditioned like T2 / (T2 - T) in T and in the "
                       "masses: a mass that is not a binary number (m2 = 0.3) read exactly moves "
                       "V there by up to that factor times 1e-17"},
      {"files", QJsonObject{{"csv", QFileInfo(prefix).fileName() + ".csv"},
                            {"npy", QFileInfo(prefix).fileName() + ".npy (float64, rows x 6 "
                                    "columns in the CSV's order, admissible as 1.0 / 0.0)"}}},
      {"admissible", "1 when V < 0 and the free flight from the data first returns to the stop "
                     "at T (exact contact search), else 0"},
      {"generator", "grazelab-cli " + QCoreApplication::applicationVersion()}};
  const QByteArray jsonBytes = QJsonDocument(json).toJson();
  if (!saveAtomically(prefix + ".csv", csv, error) ||
      !saveAtomically(prefix + ".npy", encodeNpy(array), error) ||
      !saveAtomically(prefix + ".json", jsonBytes, error)) {
    return 1;
  }
#if GRAZELAB_CLI_PICTURES
  const QString title = QStringLiteral("1IPP family: frequency against energy (m2/m1 = %1, λ* = %2)")
                            .arg(m.m2 / m.m1, 0, 'g', 4)
                            .arg(core::lambdaStar(chain), 0, 'g', 4);
  const QSize size(1100, 760);
  const bool drawn = savePngAndSvg(
      prefix, size, title, "GrazeLabFamily", QJsonDocument(json).toJson(QJsonDocument::Compact),
      [&](QPainter& painter) {
        ui::paintFrequencyEnergy(painter, QRectF(QPointF(0, 0), size), family, end, title);
      },
      error);
  if (!drawn) return 1;
#endif
  std::int64_t admissible = 0;
  for (const auto& p : family) admissible += p.admissible ? 1 : 0;
  std::fprintf(stderr, "grazelab-cli: family: %lld orbits (%lld admissible): %s.csv\n",
               (long long)family.size(), (long long)admissible, qPrintable(prefix));
  return kExitOk;
}

}  // namespace grazelab::cli
