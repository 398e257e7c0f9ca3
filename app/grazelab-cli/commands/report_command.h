// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <stop_token>

#include "io/cli_io.h"
#include "exit_codes.h"
#include "io/option_values.h"

class QCommandLineParser;

namespace grazelab::cli {

/// Registers the options of `report` and `stability` (--out, --methods, --quick).
void addReportOptions(QCommandLineParser& parser);

/// `grazelab-cli report`: the work-precision report (issue 8). Writes DIR/results.csv,
/// work_precision.svg/.png, convergence.svg/.png and report.md, each atomically; progress on
/// stderr. On an invalid input: one line on stderr (`error`), exit 2, nothing written.
int runReport(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

}  // namespace grazelab::cli
