// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>
#include <QString>

#include <stop_token>

#include "commands/work_precision_report.h"
#include "io/cli_io.h"
#include "exit_codes.h"
#include "io/option_values.h"

class QCommandLineParser;

namespace grazelab::cli {

/// Registers the options of `report` and `stability` (--out, --methods, --quick).
void addReportOptions(QCommandLineParser& parser);

/// The report of the options' chain and start (commands/work_precision_report.h), its files in
/// the directory --out names (`filesRequired`: the command line, which writes nothing else,
/// refuses a run without --out; the Python module writes them only when asked, without
/// pictures). `code` is the command's exit code (0; 2 with `error` on invalid input or when no
/// reference can be made; 130 when interrupted, nothing written; 1 when a file could not be
/// written); `csv` and `markdown` are results.csv and report.md.
struct ReportRun {
  int code = 0;
  ReportOutcome outcome;
  QByteArray csv;
  QByteArray markdown;
};
ReportRun reportWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                          bool filesRequired);

/// `grazelab-cli report`: the work-precision report (issue 8), reportWithFiles with --out required. Writes DIR/results.csv,
/// work_precision.svg/.png, convergence.svg/.png and report.md, each atomically; progress on
/// stderr. On an invalid input: one line on stderr (`error`), exit 2, nothing written.
int runReport(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

}  // namespace grazelab::cli
