// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli stability`: every method on stiff and extreme cases, each cell ending with a
// verdict and a reason (issue 8).

#include <chrono>
#include <map>

#include "core/methods/stress_matrix.h"
#include "exit_codes.h"
#include "io/chain_start.h"
#include "io/cli_input.h"
#include "io/option_values.h"
#include "commands/report_command.h"
#include "commands/report_support.h"

namespace grazelab::cli {
namespace {

using core::methods::CellVerdict;
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

int runStability(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  using namespace core::methods;
  const auto methods = parseMethodsOption(options, error);
  if (!methods) return kExitInvalidInput;
  const auto directory = prepareOutputDirectory(options, error);
  if (!directory) return kExitInvalidInput;
  const bool quick = options.isSet("quick");
  WorkBudget budget;
  budget.maxSeconds = quick ? 0.5 : 20;
  const auto started = std::chrono::steady_clock::now();

  std::vector<StressCase> cases;
  if (options.isSet("masses")) {
    auto ofTheChain = chainCases(options, quick, stop, error);
    if (!ofTheChain) return stop.stop_requested() ? kExitInterrupted : kExitInvalidInput;
    cases = std::move(*ofTheChain);
  } else {
    for (const char* option : {"springs", "right-spring", "stop-mass", "frequencies", "design-branch", "gap", "state", "onepp",
                               "perturb", "glo-weights"}) {
      if (options.isSet(option)) {
        error = QStringLiteral("--%1 describes a chain given by --masses (without it, stability runs its own cases)").arg(option);
        return kExitInvalidInput;
      }
    }
    cases = stressCases(quick);
  }
  std::vector<StressCell> cells;
  std::vector<LongRunMark> marks;
  std::map<std::string, CaseHorizon> horizons;
  int index = 0;
  for (const StressCase& row : cases) {
    ++index;
    progress(io, "stability", QStringLiteral("[%1/%2] %3").arg(index).arg(cases.size())
                              .arg(QString::fromStdString(row.name)),
             double(index - 1) / double(cases.size()));
    horizons[row.name] = runStressCase(
        row, *methods, budget, [&cells](const StressCell& cell) { cells.push_back(cell); },
        &marks, stop);
    if (stop.stop_requested()) return kExitInterrupted;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  QByteArray csv = "case,method,seconds,state_error,contact_time_error,missed_contacts,"
                   "energy_drift,verdict,reason\n";
  for (const StressCell& c : cells) {
    csv += QStringLiteral("%1,%2,%3,%4,%5,%6,%7,%8,%9\n")
               .arg(QString::fromStdString(c.caseName), name(c.method), scientific(c.seconds, 4),
                    scientific(c.errors.state), scientific(c.errors.contactTime))
               .arg(c.errors.missed)
               .arg(scientific(c.errors.energyDrift), verdictText(c.verdict),
                    csvField(QString::fromStdString(c.reason)))
               .toUtf8();
  }

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
            .arg(versionString(), quick ? " with --quick (a subset)" : "", humanSeconds(seconds))
            .arg(kCasePeriods)
            .arg(budget.maxSeconds);
  md += "| case |";
  for (MethodKind kind : *methods) md += " " + name(kind) + " |";
  md += "\n|---|";
  for (std::size_t i = 0; i < methods->size(); ++i) md += "---|";
  md += "\n";
  std::map<std::pair<std::string, MethodKind>, const StressCell*> byCell;
  for (const StressCell& c : cells) byCell[{c.caseName, c.method}] = &c;
  for (const StressCase& row : cases) {
    md += "| " + QString::fromStdString(row.name) + " |";
    for (MethodKind kind : *methods) {
      const auto found = byCell.find({row.name, kind});
      const QString v = found == byCell.end() ? "—" : verdictText(found->second->verdict);
      md += " " + (v == "ok" ? v : "**" + v + "**") + " |";
    }
    md += "\n";
  }
  md += "\n## Cases\n\n";
  for (const StressCase& row : cases) {
    md += "- `" + QString::fromStdString(row.name) + "`: " +
          QString::fromStdString(row.description);
    const CaseHorizon& h = horizons[row.name];
    if (h.shortened) {
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
  for (const StressCell& c : cells) {
    if (c.verdict == CellVerdict::Ok) continue;
    md += QStringLiteral("- %1 / %2 (%3): %4 — %5\n")
              .arg(QString::fromStdString(c.caseName), name(c.method), settingText(c.setting),
                   verdictText(c.verdict), QString::fromStdString(c.reason));
  }
  if (!marks.empty()) {
    md += "\n## The long exact run\n\n| contacts | t | energy drift (max so far) | ns per contact (this stretch) |\n|---|---|---|---|\n";
    for (const LongRunMark& mark : marks) {
      md += QStringLiteral("| %1 | %2 | %3 | %4 |\n")
                .arg(mark.contacts)
                .arg(mark.t, 0, 'g', 6)
                .arg(scientific(mark.energyDrift, 2))
                .arg(mark.nanosecondsPerContact, 0, 'f', 0);
    }
  }
  const QString dir = *directory;
  if (!writeAtomically(dir + "/matrix.csv", csv, error) ||
      !writeAtomically(dir + "/matrix.md", md.toUtf8(), error)) {
    return 1;
  }
  progress(io, "stability", QStringLiteral("wrote %1/{matrix.csv, matrix.md} in %2")
                            .arg(dir, humanSeconds(seconds)));
  return kExitOk;
}

}  // namespace grazelab::cli
