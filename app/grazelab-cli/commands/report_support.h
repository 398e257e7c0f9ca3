// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>
#include <QString>

#include <optional>
#include <vector>

#include "io/cli_io.h"
#include "core/methods/method.h"
#include "io/option_values.h"


// What `report` and `stability` share: their options, number formats and file writing.
namespace grazelab::cli {

/// "1.23e-04", or "" for a number that is not finite (an error that could not be formed).
QString scientific(double value, int digits = 3);
/// A run time for people: "0.12 ms", "35 ms", "2.4 s".
QString humanSeconds(double seconds);

/// --methods a,b,c (all when absent), checked against the method names.
std::optional<std::vector<core::methods::MethodKind>> parseMethodsOption(
    const OptionValues& options, QString& error);

/// --out DIR: created when missing; error when it cannot be.
std::optional<QString> prepareOutputDirectory(const OptionValues& options, QString& error);

/// Writes bytes atomically; on failure, `error` says which file and why.
bool writeAtomically(const QString& path, const QByteArray& bytes, QString& error);

/// One progress line on the messages, "grazelab-cli <command>: <text>", and to the caller's
/// progress with the fraction done (negative when not known).
void progress(const Io& io, const char* command, const QString& text, double fraction = -1);

/// The version written into every file.
QString versionString();

}  // namespace grazelab::cli
