// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QStringList>

#include <stop_token>

#include "core/version.h"
#include "io/cli_io.h"

namespace grazelab::cli {

/// The version the command line and the Python module report: the project's one version.
inline constexpr const char* kVersion = grazelab::kVersion;

/// Runs one command line (`commandLine[0]` is the program's name, as in argv) in this process:
/// parses it with the command line's own parser and rules and runs the command, writing to `io`.
/// Returns the exit code: 0, 2 on invalid input (one line on io.messages, nothing on io.out),
/// 130 when `stop` ended it, 1 when a file could not be written. Needs no QCoreApplication
/// instance; the caller sets QCoreApplication's application version to kVersion first (the
/// files' "generator" field), once, before any command runs. Several may run at once on
/// different threads.
int runCommandLine(const QStringList& commandLine, const Io& io, std::stop_token stop);

}  // namespace grazelab::cli
