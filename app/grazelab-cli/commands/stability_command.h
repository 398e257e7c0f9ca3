// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>
#include <QString>

#include <optional>
#include <stop_token>

#include "commands/stability_matrix.h"
#include "io/cli_io.h"
#include "io/option_values.h"

namespace grazelab::cli {

/// The options of `stability` as a request (commands/stability_matrix.h): --methods, --quick, and
/// the cases, the built-in ones or those of a chain given by --masses (its springs, wall, stop,
/// gap) from its start (--state, --glo-weights or --onepp, and --perturb); nothing, with `error`
/// the line that says why, or with `stopped` when `stop` ended the chain's design.
std::optional<StabilityRequest> readStabilityRequest(const OptionValues& options, std::stop_token stop,
                                                     QString& error, bool& stopped);

/// The matrix as matrix.csv: a row per cell (case, method, seconds, errors, verdict, reason).
QByteArray stabilityCsv(const StabilityOutcome& outcome);
/// The matrix as matrix.md: the verdicts by case and method, the cases, why a cell is not ok,
/// the long exact run.
QString stabilityMarkdown(const StabilityRequest& request, const StabilityOutcome& outcome);

/// The matrix with its files in the directory --out names (`filesRequired`: the command line,
/// which writes nothing else, refuses a run without --out; the Python module writes them only
/// when asked). `code` is the command's exit code (0; 2 with `error` on invalid input; 130 when
/// interrupted, nothing written; 1 when a file could not be written).
struct StabilityRun {
  int code = 0;
  StabilityRequest request;
  StabilityOutcome outcome;
};
StabilityRun stabilityWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                                bool filesRequired);

/// `grazelab-cli stability --out DIR`: every method on stiff and extreme cases (issue 8), each
/// cell ending with a verdict and a reason: DIR/matrix.csv and DIR/matrix.md.
int runStability(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

}  // namespace grazelab::cli
