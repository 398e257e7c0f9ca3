// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/bar_command.h"

#include <QStringList>

#include <chrono>
#include <cmath>
#include <functional>

#include "exit_codes.h"
#include "io/cli_output.h"

namespace grazelab::cli {

using V = JsonValue;

void addBarOptions(QCommandLineParser& parser) {
  parser.addOptions({
      {"bar", "bar: the elastic bar E,rho,S,L in Pa, kg/m3, m2, m (default 210e9,7800,3.14e-4,1: steel).",
       "E,rho,S,L"},
      {"speed", "bar: its speed onto the wall in m/s (default 0.1).", "V"},
      {"masses-count", "bar: the numbers N of masses it is lumped into, ascending, 1 to 2000 (default 10,100,1000).",
       "N1,N2,..."},
      {"stop-end", "bar: the wall ahead of mass N (last, default) or behind mass 1 (first: the mirror image).",
       "last|first"},
      {"each-impact", "bar: also list every impact's time and impulse."},
  });
}

std::optional<BarRequest> readBarRequest(const OptionValues& options, QString& error) {
  BarRequest request;
  if (options.isSet("bar")) {
    const QStringList parts = options.value("bar").split(',');
    double values[4] = {};
    bool ok = parts.size() == 4;
    for (int i = 0; ok && i < 4; ++i) values[i] = parts[i].trimmed().toDouble(&ok);
    if (!ok) {
      error = QStringLiteral("--bar: '%1' is not four numbers E,rho,S,L (Pa, kg/m3, m2, m)").arg(options.value("bar"));
      return std::nullopt;
    }
    request.bar.youngModulus = values[0];
    request.bar.density = values[1];
    request.bar.area = values[2];
    request.bar.length = values[3];
  }
  if (options.isSet("speed")) {
    bool ok = false;
    request.bar.speed = options.value("speed").toDouble(&ok);
    if (!ok) {
      error = QStringLiteral("--speed: '%1' is not a number").arg(options.value("speed"));
      return std::nullopt;
    }
  }
  for (const core::Problem& problem : core::validate(request.bar)) {
    error = QStringLiteral("--bar/--speed: %1 %2").arg(QString::fromStdString(problem.field),
                                                      QString::fromStdString(problem.reason));
    return std::nullopt;
  }
  if (options.isSet("masses-count")) {
    request.masses.clear();
    for (const QString& part : options.value("masses-count").split(',')) {
      bool ok = false;
      const int n = part.trimmed().toInt(&ok);
      if (!ok || n < 1 || n > BarRequest::kMaxMasses || (!request.masses.empty() && n <= request.masses.back())) {
        error = QStringLiteral("--masses-count: whole numbers from 1 to %1, ascending (got '%2')")
                    .arg(BarRequest::kMaxMasses)
                    .arg(options.value("masses-count"));
        return std::nullopt;
      }
      request.masses.push_back(n);
    }
  }
  if (options.isSet("stop-end")) {
    const QString end = options.value("stop-end");
    if (end != "last" && end != "first") {
      error = QStringLiteral("--stop-end: last (the wall ahead of mass N, default) or first (behind mass 1), not '%1'")
                  .arg(end);
      return std::nullopt;
    }
    request.end = end == "first" ? core::BarEnd::First : core::BarEnd::Last;
  }
  request.eachImpact = options.isSet("each-impact");
  return request;
}

BarOutcome throwBars(const BarRequest& request, std::stop_token stop) {
  BarOutcome outcome;
  outcome.request = request;
  outcome.continuum = core::barContinuum(request.bar);
  for (const int n : request.masses) {
    const auto started = std::chrono::steady_clock::now();
    core::BarImpact impact = core::throwBar(request.bar, n, request.end, stop);
    if (impact.status == core::BarStatus::Cancelled) {
      outcome.status = BarOutcomeStatus::Interrupted;
      return outcome;
    }
    outcome.seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    outcome.rows.push_back(std::move(impact));
  }
  return outcome;
}

namespace {

const char* statusName(core::BarStatus status) {
  switch (status) {
    case core::BarStatus::Computed: return "computed";
    case core::BarStatus::Undecided: return "undecided";
    case core::BarStatus::Unfinished: return "unfinished";
    case core::BarStatus::Cancelled: return "cancelled";
  }
  return "computed";
}

const char* precisionName(core::Precision precision) {
  switch (precision) {
    case core::Precision::Double: return "double";
    case core::Precision::Long: return "long";
    case core::Precision::Quad: return "quad";
  }
  return "double";
}

V numbers(const std::vector<double>& values) {
  std::vector<V> items;
  items.reserve(values.size());
  for (double value : values) items.push_back(V::number(value));
  return V::array(std::move(items));
}

// x / limit - 1, the quantity's relative error against the continuum
double relative(double value, double limit) { return value / limit - 1; }

}  // namespace

JsonValue barDocument(const BarOutcome& outcome) {
  const core::Bar& bar = outcome.request.bar;
  const core::BarContinuum& limit = outcome.continuum;
  std::vector<V> rows;
  // the rows computed: what convergence is measured over
  std::vector<int> masses;
  std::vector<double> durations, forces, rebounds, vibrations;
  for (std::size_t i = 0; i < outcome.rows.size(); ++i) {
    const core::BarImpact& row = outcome.rows[i];
    std::vector<V::Field> fields;
    fields.emplace_back("masses", V::of(std::int64_t(row.masses)));
    fields.emplace_back("status", V::of(statusName(row.status)));
    fields.emplace_back("precision", V::of(precisionName(row.precision)));
    if (row.status == core::BarStatus::Computed) {
      fields.emplace_back("impacts", V::of(std::int64_t(row.impacts)));
      fields.emplace_back("duration", V::number(row.duration));
      fields.emplace_back("impulse", V::number(row.impulse));
      fields.emplace_back("rebound", V::number(row.rebound));
      fields.emplace_back("vibration", V::number(row.vibration));
      fields.emplace_back("mean_force", V::number(row.meanForce));
      fields.emplace_back("energy_drift", V::number(row.energyDrift));
      fields.emplace_back("relative", V::object({{"duration", V::number(relative(row.duration, limit.duration))},
                                                  {"impulse", V::number(relative(row.impulse, limit.impulse))},
                                                  {"rebound", V::number(relative(row.rebound, limit.rebound))},
                                                  {"mean_force", V::number(relative(row.meanForce, limit.force))}}));
      if (outcome.request.eachImpact) {
        fields.emplace_back("impact_times", numbers(row.times));
        fields.emplace_back("impact_impulses", numbers(row.impulses));
      }
      masses.push_back(row.masses);
      durations.push_back(row.duration);
      forces.push_back(row.meanForce);
      rebounds.push_back(row.rebound);
      vibrations.push_back(row.vibration);
    }
    fields.emplace_back("seconds", V::number(outcome.seconds[i]));
    rows.push_back(V::object(std::move(fields)));
  }
  const auto converging = [&](const std::vector<double>& values, double to) {
    const core::Convergence found = core::convergence(masses, values, to);
    std::vector<V::Field> fields;
    fields.emplace_back("limit", V::number(to));
    fields.emplace_back("orders", numbers(found.orders));
    fields.emplace_back("extrapolated", found.extrapolated ? V::number(*found.extrapolated) : V::null());
    fields.emplace_back("extrapolated_order", found.extrapolatedOrder ? V::number(*found.extrapolatedOrder) : V::null());
    // against the limit: absolute for a limit of 0 (the vibration), else relative
    const double error = found.extrapolated ? (to != 0 ? *found.extrapolated / to - 1 : *found.extrapolated) : NAN;
    fields.emplace_back("extrapolated_error", found.extrapolated ? V::number(error) : V::null());
    return V::object(std::move(fields));
  };
  return V::object(
      {{"bar", V::object({{"E", V::number(bar.youngModulus)},
                          {"rho", V::number(bar.density)},
                          {"S", V::number(bar.area)},
                          {"L", V::number(bar.length)},
                          {"speed", V::number(bar.speed)},
                          {"wave_speed", V::number(limit.waveSpeed)},
                          {"stop_end", V::of(outcome.request.end == core::BarEnd::Last ? "last" : "first")},
                          {"lumped", V::of("N equal masses rho S L / N joined by N - 1 springs E S N / L, no wall "
                                           "holding it; every mass at the wall's gap moving onto it at speed")}})},
       {"continuum", V::object({{"duration", V::number(limit.duration)},
                                {"force", V::number(limit.force)},
                                {"impulse", V::number(limit.impulse)},
                                {"rebound", V::number(limit.rebound)},
                                {"vibration", V::number(0.0)}})},
       {"rows", V::array(std::move(rows))},
       {"convergence", V::object({{"duration", converging(durations, limit.duration)},
                                  {"mean_force", converging(forces, limit.force)},
                                  {"rebound", converging(rebounds, limit.rebound)},
                                  {"vibration", converging(vibrations, 0.0)}})}});
}

int runBar(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  const std::optional<BarRequest> request = readBarRequest(options, error);
  if (!request) return kExitInvalidInput;
  const BarOutcome outcome = throwBars(*request, std::move(stop));
  if (outcome.status == BarOutcomeStatus::Interrupted) {
    std::fprintf(io.messages, "grazelab-cli: interrupted: nothing written\n");
    return kExitInterrupted;
  }
  emitDocument(io, barDocument(outcome));
  return kExitOk;
}

}  // namespace grazelab::cli
