// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli stability`: every method on stiff and extreme cases, each cell ending with a
// verdict and a reason (issue 8).

#include "commands/stability_command.h"

#include <map>

#include "core/methods/stress_matrix.h"
#include "exit_codes.h"
#include "io/chain_start.h"
#include "io/cli_input.h"
#include "io/option_values.h"
#include "commands/report_support.h"

namespace grazelab::cli {
namespace {

using core::methods::CaseHorizon;
using core::methods::CellVerdict;
using core::methods::LongRunMark;
using core::methods::StressCase;
using core::methods::MethodKind;
using core::methods::StressCell;

QString name(MethodKind kind) {
  const std::string_view text = core::methods::methodName(kind);
  return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

QString verdictText(CellVerdict verdict) {
  const std::string_view text = core::methods::toString(verdict);
  return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

QString csvField(QString text) {
  text.replace('"', "'");
  return '"' + text + '"';
}

QString settingText(const core::methods::MethodSetting& setting) {
  if (setting.kind == MethodKind::Exact) return "double";
  const std::string_view p = core::methods::parameterName(setting.kind);
  return QString::fromUtf8(p.data(), qsizetype(p.size())) + "=" + QString::number(setting.value, 'g', 3);
}

// The matrix of the chain given by --masses (its springs, wall, stop and gap) from its start
// (--state, --glo-weights or --onepp, and --perturb): the chain and its stiff and extreme
// variants. Nothing, with `error`, when the chain or its start is refused.
std::optional<std::vector<core::methods::StressCase>> chainCases(const OptionValues& options, bool quick,
                                                                  std::stop_token stop, QString& error) {
  if (!noTwoMassStart(options, error)) return std::nullopt;
  const Parsed<MassChainInput> parsed = parseMassChain(options, stop);
  if (!parsed.value) {
    error = parsed.error;
    return std::nullopt;
  }
  const core::MassChain& chain = parsed.value->chain;
  const auto start = chainStart<double>(options, chain, error);
  if (!start) return std::nullopt;
  std::vector<double> weights;  // chainStart has read and checked them
  if (options.isSet("glo-weights")) {
    for (const QString& part : options.value("glo-weights").split(',')) weights.push_back(part.toDouble());
  }
  return core::methods::chainStressCases(chain, *start, weights, quick);
}

}  // namespace

std::optional<StabilityRequest> readStabilityRequest(const OptionValues& options, std::stop_token stop,
                                                     QString& error, bool& stopped) {
  stopped = false;
  StabilityRequest request;
  auto methods = parseMethodsOption(options, error);
  if (!methods) return std::nullopt;
  request.methods = std::move(*methods);
  request.quick = options.isSet("quick");
  if (options.isSet("masses")) {
    auto ofTheChain = chainCases(options, request.quick, stop, error);
    if (!ofTheChain) {
      stopped = stop.stop_requested();
      return std::nullopt;
    }
    request.cases = std::move(*ofTheChain);
    return request;
  }
  for (const char* option : {"springs", "right-spring", "stop-mass", "frequencies", "design-branch", "gap", "state", "onepp",
                             "perturb", "glo-weights"}) {
    if (options.isSet(option)) {
      error = QStringLiteral("--%1 describes a chain given by --masses (without it, stability runs its own cases)").arg(option);
      return std::nullopt;
    }
  }
  request.cases = core::methods::stressCases(request.quick);
  return request;
}

QByteArray stabilityCsv(const StabilityOutcome& outcome) {
  QByteArray csv = "case,method,seconds,state_error,contact_time_error,missed_contacts,"
                   "energy_drift,verdict,reason\n";
  for (const StressCell& c : outcome.cells) {
    csv += QStringLiteral("%1,%2,%3,%4,%5,%6,%7,%8,%9\n")
               .arg(QString::fromStdString(c.caseName), name(c.method), scientific(c.seconds, 4),
                    scientific(c.errors.state), scientific(c.errors.contactTime))
               .arg(c.errors.missed)
               .arg(scientific(c.errors.energyDrift), verdictText(c.verdict),
                    csvField(QString::fromStdString(c.reason)))
               .toUtf8();
  }
  return csv;
}

QString stabilityMarkdown(const StabilityRequest& request, const StabilityOutcome& outcome) {
  using namespace core::methods;
  const std::vector<MethodKind>& methods = request.methods;
  QString md = "# GrazeLab stability matrix\n\n";
  md += QStringLiteral("Written by %1%2 in %3. Each case runs %4 slowest periods T2, or up to the "
                       "predictability horizon of its start when that comes first (the long run "
                       "excepted), with every method at its standard setting: h = T2 / 1000 (T2: "
                       "the slowest mode's period of the case's chain), "
                       "rtol = 1e-8, penalty k_c = 1e8 k1 (CVODE rtol 1e-10), the exact solver "
                       "in double; errors against the exact solver in binary128. A cell is ok "
                       "when the state error at the end and the contact-time error (/ T2) are at "
                       "most 1e-3 (for the exact solver: 1e-9, or 10 times its own error estimate when that is "
                       "larger) and no contact is missed or "
                       "invented; budget: %5 s per cell.\n\n")
            .arg(versionString(), request.quick ? " with --quick (a subset)" : "", humanSeconds(outcome.seconds))
            .arg(kCasePeriods)
            .arg(request.budgetSeconds());
  md += "| case |";
  for (MethodKind kind : methods) md += " " + name(kind) + " |";
  md += "\n|---|";
  for (std::size_t i = 0; i < methods.size(); ++i) md += "---|";
  md += "\n";
  std::map<std::pair<std::string, MethodKind>, const StressCell*> byCell;
  for (const StressCell& c : outcome.cells) byCell[{c.caseName, c.method}] = &c;
  for (const StressCase& row : request.cases) {
    md += "| " + QString::fromStdString(row.name) + " |";
    for (MethodKind kind : methods) {
      const auto found = byCell.find({row.name, kind});
      const QString v = found == byCell.end() ? "—" : verdictText(found->second->verdict);
      md += " " + (v == "ok" ? v : "**" + v + "**") + " |";
    }
    md += "\n";
  }
  md += "\n## Cases\n\n";
  for (const StressCase& row : request.cases) {
    md += "- `" + QString::fromStdString(row.name) + "`: " +
          QString::fromStdString(row.description);
    const auto horizon = outcome.horizons.find(row.name);
    if (horizon != outcome.horizons.end() && horizon->second.shortened) {
      const CaseHorizon& h = horizon->second;
      md += QStringLiteral(" — compared up to t = %1 (%2 T2), before the predictability horizon "
                           "t = %3 of its start, where the exact double run's error reaches 1e-6 "
                           "(a long-double shadow of the whole run, as `simulate --trust full`; "
                           "the default `--trust auto` stops shadowing when it gets costly and "
                           "extrapolates, so its horizon can differ)")
                .arg(h.tEnd, 0, 'g', 4)
                .arg(h.tEnd / h.period, 0, 'g', 3)
                .arg(h.horizon, 0, 'g', 4);
    }
    md += "\n";
  }
  md += "\n## Why a cell is not ok\n\n";
  for (const StressCell& c : outcome.cells) {
    if (c.verdict == CellVerdict::Ok) continue;
    md += QStringLiteral("- %1 / %2 (%3): %4 — %5\n")
              .arg(QString::fromStdString(c.caseName), name(c.method), settingText(c.setting),
                   verdictText(c.verdict), QString::fromStdString(c.reason));
  }
  if (!outcome.marks.empty()) {
    md += "\n## The long exact run\n\n| contacts | t | energy drift (max so far) | ns per contact (this stretch) |\n|---|---|---|---|\n";
    for (const LongRunMark& mark : outcome.marks) {
      md += QStringLiteral("| %1 | %2 | %3 | %4 |\n")
                .arg(mark.contacts)
                .arg(mark.t, 0, 'g', 6)
                .arg(scientific(mark.energyDrift, 2))
                .arg(mark.nanosecondsPerContact, 0, 'f', 0);
    }
  }
  return md;
}

StabilityRun stabilityWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                                bool filesRequired) {
  StabilityRun run;
  bool stopped = false;
  std::optional<StabilityRequest> request = readStabilityRequest(options, stop, error, stopped);
  if (!request) {
    run.code = stopped ? kExitInterrupted : kExitInvalidInput;
    return run;
  }
  run.request = std::move(*request);
  std::optional<QString> directory;
  if (filesRequired || options.isSet("out")) {
    directory = prepareOutputDirectory(options, error);
    if (!directory) {
      run.code = kExitInvalidInput;
      return run;
    }
  }
  run.outcome = stabilityMatrix(run.request, stop, [&io](std::size_t index, std::size_t count, const std::string& name) {
    progress(io, "stability", QStringLiteral("[%1/%2] %3").arg(index + 1).arg(count).arg(QString::fromStdString(name)),
             double(index) / double(count));
  });
  if (run.outcome.status == StabilityStatus::Interrupted) {
    run.code = kExitInterrupted;
    return run;
  }
  if (!directory) return run;
  const QString& dir = *directory;
  if (!writeAtomically(dir + "/matrix.csv", stabilityCsv(run.outcome), error) ||
      !writeAtomically(dir + "/matrix.md", stabilityMarkdown(run.request, run.outcome).toUtf8(), error)) {
    run.code = 1;
    return run;
  }
  progress(io, "stability", QStringLiteral("wrote %1/{matrix.csv, matrix.md} in %2")
                            .arg(dir, humanSeconds(run.outcome.seconds)));
  return run;
}

int runStability(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  return stabilityWithFiles(options, io, std::move(stop), error, true).code;
}

}  // namespace grazelab::cli
