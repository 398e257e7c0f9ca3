// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli orbit`: its options read into a request (commands/periodic_orbit.h), its outcome
// written as a JSON document.
#include "commands/orbit_command.h"

#include <QCommandLineParser>

#include <string>

#include "commands/simulate_command.h"
#include "exit_codes.h"
#include "io/cli_input.h"
#include "io/cli_output.h"
#include "io/prepared_chain.h"

namespace grazelab::cli {

void addOrbitOptions(QCommandLineParser& parser) {
  parser.addOptions({
      {"period", "orbit --onepp: the period T of the 1IPP orbit; orbit --impacts: the period of the orbit sought.",
       "T"},
      {"impacts", "orbit, family: impacts per period K of the orbit sought (family: followed from).", "K"},
      {"energy", "orbit, family --impacts: the energy E of the orbit sought.", "E"},
      {"guess",
       "orbit --impacts, family --impacts: a guess of the orbit's point just after an impact on H: u then v of every mass but the "
       "stopped one (two masses: u1,v1), and at a fixed --period the stopped mass's v_s < 0 last.",
       "U,V"},
  });
}

std::optional<OrbitRequest> readOrbitRequest(const OptionValues& options, QString& error) {
  if (options.isSet("format") && options.value("format") != "json") {
    error = "orbit: --format json is the only format";
    return std::nullopt;
  }
  const bool onePeriodic = options.isSet("onepp");
  if (onePeriodic == options.isSet("impacts")) {
    error = "orbit: give --onepp --period T, or --impacts K --energy E (or --period T) --guess U,V";
    return std::nullopt;
  }
  if (onePeriodic && (!options.isSet("period") || options.isSet("energy") || options.isSet("guess"))) {
    error = "orbit --onepp: give --period T (and no --energy or --guess)";
    return std::nullopt;
  }
  if (!onePeriodic && (options.isSet("energy") == options.isSet("period") || !options.isSet("guess"))) {
    error = "orbit --impacts K: give --guess U,V and one of --energy E (a fixed energy) or --period T (a fixed period)";
    return std::nullopt;
  }
  OrbitRequest request;
  const std::optional<PrecisionChoice> precision = readPrecisionChoice(options, error);
  if (!precision) return std::nullopt;
  request.precision = *precision;
  if (onePeriodic) {
    request.period = options.value("period").toStdString();
    return request;
  }
  bool ok = false;
  request.impacts = options.value("impacts").toInt(&ok);
  if (!ok || request.impacts < 1 || request.impacts > 64) {
    error = QStringLiteral("--impacts: '%1' is not a number of impacts from 1 to 64").arg(options.value("impacts"));
    return std::nullopt;
  }
  request.energy = options.value("energy").toStdString();
  request.period = options.value("period").toStdString();
  request.fixed = options.isSet("period") ? core::ChainOrbitConstraint::Period : core::ChainOrbitConstraint::Energy;
  for (const QString& number : options.value("guess").split(',')) request.guess.push_back(number.trimmed().toStdString());
  return request;
}

Parsed<std::shared_ptr<const PreparedMassChain>> twoMassChainOf(const OptionValues& options, std::stop_token stop) {
  // the shape first: a chain of more masses is not designed only to be refused
  if (options.isSet("masses") && !hasTheNotesShape(options)) return {std::nullopt, parseModel<double>(options).error};
  return recentChain(options, std::move(stop));
}

Parsed<std::shared_ptr<const PreparedMassChain>> orbitChainOf(const OptionValues& options, std::stop_token stop) {
  return recentChain(options, std::move(stop));
}

int runOrbit(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  const std::optional<OrbitRequest> request = readOrbitRequest(options, error);
  if (!request) return kExitInvalidInput;
  const auto chain = orbitChainOf(options, stop);
  if (!chain.value) {
    error = chain.error;
    return chain.error.isEmpty() ? kExitInterrupted : kExitInvalidInput;  // (empty: the design was interrupted)
  }
  const OrbitOutcome outcome = solveOrbit(**chain.value, *request, stop);
  if (stop.stop_requested()) return kExitInterrupted;
  if (outcome.status != OrbitStatus::Found) {
    error = QString::fromStdString(outcome.problem);
    return kExitInvalidInput;
  }
  emitDocument(io, orbitDocument(outcome));
  return kExitOk;
}

}  // namespace grazelab::cli
