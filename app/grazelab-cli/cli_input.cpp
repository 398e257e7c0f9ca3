// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "cli_input.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QStringList>

#include <cmath>

#include "core/modes.h"
#include "core/orbits.h"

namespace grazelab::cli {
namespace {

const QStringList kSimulateOnly = {"glo", "onepp", "state", "perturb", "contacts", "t-end",
                                   "format"};

// a finite-or-not real number; non-finite values are caught later by validation with a reason
std::optional<double> toNumber(const QString& text) {
  bool ok = false;
  const double value = text.trimmed().toDouble(&ok);
  if (ok) return value;
  const QString lower = text.trimmed().toLower();
  if (lower == "nan") return std::nan("");
  if (lower == "inf" || lower == "+inf") return INFINITY;
  if (lower == "-inf") return -INFINITY;
  return std::nullopt;
}

QString numberError(const QString& option, const QString& text) {
  return QStringLiteral("--%1: '%2' is not a number").arg(option, text);
}

// "a,b,c,d" into a state
std::optional<core::State> toState(const QString& text) {
  const QStringList parts = text.split(',');
  if (parts.size() != 4) return std::nullopt;
  double values[4];
  for (int i = 0; i < 4; ++i) {
    const auto value = toNumber(parts[i]);
    if (!value) return std::nullopt;
    values[i] = *value;
  }
  return core::State{values[0], values[1], values[2], values[3]};
}

QString fromStd(const std::string& text) { return QString::fromStdString(text); }

}  // namespace

void addOptions(QCommandLineParser& parser) {
  parser.addOptions({
      {"m1", "Mass 1 (default 1).", "value", "1"},
      {"m2", "Mass 2, the one that hits the stop (default 0.5).", "value", "0.5"},
      {"k1", "Stiffness wall-m1 (default 1).", "value", "1"},
      {"gap", "Gap d between mass 2 at rest and the stop (default 1).", "value", "1"},
      {"k2", "Stiffness m1-m2 as given: no resonance imposed (excludes --branch).", "value"},
      {"branch", "k2 from the 1:2 design: upper (default) or lower.", "upper|lower"},
      {"glo", "Start on GLO_lambda data, any real lambda (default 0.5).", "lambda"},
      {"onepp", "Start on the one-impact-per-period orbit of period T.", "T"},
      {"state", "Start from the state u1,u2,v1,v2.", "u1,u2,v1,v2"},
      {"perturb", "Add du1,du2,dv1,dv2 to the initial state.", "du1,du2,dv1,dv2"},
      {"contacts", "Stop after N contacts (default 100 when no --t-end).", "N"},
      {"t-end", "Stop at time T.", "T"},
      {"format", "Output: json (default), csv or summary.", "json|csv|summary", "json"},
  });
}

QStringList simulateOnlyOptionsSet(const QCommandLineParser& parser) {
  QStringList set;
  for (const QString& name : kSimulateOnly) {
    if (parser.isSet(name)) set << "--" + name;
  }
  return set;
}

Parsed<ModelInput> parseModel(const QCommandLineParser& parser) {
  ModelInput input;
  double* targets[] = {&input.model.m1, &input.model.m2, &input.model.k1, &input.model.gap};
  const char* names[] = {"m1", "m2", "k1", "gap"};
  for (int i = 0; i < 4; ++i) {
    const QString text = parser.value(names[i]);
    const auto value = toNumber(text);
    if (!value) return {std::nullopt, numberError(names[i], text)};
    *targets[i] = *value;
  }
  if (parser.isSet("k2") && parser.isSet("branch")) {
    return {std::nullopt, "--k2 and --branch exclude each other: give k2, or let the 1:2 design "
                          "choose it"};
  }
  if (parser.isSet("k2")) {
    const auto value = toNumber(parser.value("k2"));
    if (!value) return {std::nullopt, numberError("k2", parser.value("k2"))};
    input.model.k2 = *value;
  } else {
    const QString branchText = parser.isSet("branch") ? parser.value("branch") : "upper";
    const auto branch = core::parseBranch(branchText.toStdString());
    if (!branch) {
      return {std::nullopt,
              QStringLiteral("--branch: '%1' is neither 'upper' nor 'lower'").arg(branchText)};
    }
    input.branch = branch;
    input.model.k2 = 1.0;  // placeholder so that validation below reports the other fields only
  }
  auto problems = core::validate(input.model);
  if (!problems.empty()) return {std::nullopt, fromStd(core::describe(problems))};
  if (input.branch) {
    const auto k2 = core::resonantK2(input.model.m1, input.model.m2, input.model.k1, *input.branch);
    if (!k2) {
      return {std::nullopt,
              QStringLiteral("m2/m1 = %1 > 9/16: no 1:2 resonant chain exists for these masses "
                             "(give --k2 for a detuned chain)")
                  .arg(input.model.m2 / input.model.m1, 0, 'g', 17)};
    }
    input.model.k2 = *k2;
  }
  return {input, {}};
}

Parsed<RunInput> parseRun(const QCommandLineParser& parser) {
  const Parsed<ModelInput> model = parseModel(parser);
  if (!model.value) return {std::nullopt, model.error};
  RunInput run;
  run.model = *model.value;
  const core::Model& chain = run.model.model;
  const core::Modes modes = core::computeModes(chain);

  const int starts = int(parser.isSet("glo")) + int(parser.isSet("onepp")) +
                     int(parser.isSet("state"));
  if (starts > 1) return {std::nullopt, "give one of --glo, --onepp, --state, not several"};

  core::State initial;
  if (parser.isSet("onepp")) {
    const auto period = toNumber(parser.value("onepp"));
    if (!period) return {std::nullopt, numberError("onepp", parser.value("onepp"))};
    const core::OnePeriodicOrbit orbit = core::onePeriodicOrbit(chain, modes, *period);
    if (!orbit.admissible) return {std::nullopt, "--onepp: " + fromStd(orbit.reason)};
    initial = orbit.postImpact;
    run.initialDescription = QStringLiteral("1IPP orbit of period T = %1").arg(*period, 0, 'g', 17);
  } else if (parser.isSet("state")) {
    const auto state = toState(parser.value("state"));
    if (!state) {
      return {std::nullopt,
              QStringLiteral("--state: '%1' is not four numbers u1,u2,v1,v2").arg(parser.value("state"))};
    }
    initial = *state;
    run.initialDescription = "explicit state";
  } else {
    const QString text = parser.isSet("glo") ? parser.value("glo") : "0.5";
    const auto lambda = toNumber(text);
    if (!lambda) return {std::nullopt, numberError("glo", text)};
    if (!std::isfinite(*lambda)) {
      return {std::nullopt, QStringLiteral("--glo must be a finite number (got %1)").arg(text)};
    }
    initial = core::gloData(chain, modes, *lambda);
    run.initialDescription = QStringLiteral("GLO_lambda data, lambda = %1 (as such: %2)")
                                 .arg(*lambda, 0, 'g', 17)
                                 .arg(fromStd(core::describe(core::classifyGlo(*lambda))));
  }
  if (parser.isSet("perturb")) {
    const auto delta = toState(parser.value("perturb"));
    if (!delta) {
      return {std::nullopt, QStringLiteral("--perturb: '%1' is not four numbers du1,du2,dv1,dv2")
                                .arg(parser.value("perturb"))};
    }
    const auto problems = core::validateState(chain, *delta, "perturb");
    for (const auto& problem : problems) {
      if (problem.field != "perturb.u2") return {std::nullopt, fromStd(core::describe({problem}))};
    }
    initial = initial + *delta;
    run.initialDescription += QStringLiteral(", perturbed by (%1)").arg(parser.value("perturb"));
  }
  const auto stateProblems = core::validateState(chain, initial, "initial");
  if (!stateProblems.empty()) return {std::nullopt, fromStd(core::describe(stateProblems))};
  run.request.initial = initial;

  if (parser.isSet("contacts")) {
    bool ok = false;
    const qlonglong contacts = parser.value("contacts").toLongLong(&ok);
    if (!ok || contacts < 0) {
      return {std::nullopt, QStringLiteral("--contacts: '%1' is not a count (a whole number >= 0)")
                                .arg(parser.value("contacts"))};
    }
    run.request.maxContacts = contacts;
  } else {
    run.request.maxContacts = parser.isSet("t-end") ? std::numeric_limits<std::int64_t>::max() : 100;
  }
  if (parser.isSet("t-end")) {
    const auto tEnd = toNumber(parser.value("t-end"));
    if (!tEnd || std::isnan(*tEnd) || *tEnd < 0) {
      return {std::nullopt,
              QStringLiteral("--t-end: '%1' is not a time >= 0").arg(parser.value("t-end"))};
    }
    run.request.tEnd = *tEnd;
  }
  run.format = parser.value("format");
  if (run.format != "json" && run.format != "csv" && run.format != "summary") {
    return {std::nullopt,
            QStringLiteral("--format: '%1' is not json, csv or summary").arg(run.format)};
  }
  run.request.needs.events = run.format != "summary";
  return {run, {}};
}

}  // namespace grazelab::cli
