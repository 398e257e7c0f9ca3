// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <optional>
#include <stop_token>

#include "commands/onepp_family.h"
#include "io/cli_io.h"
#include "io/option_values.h"

namespace grazelab::cli {

/// `grazelab-cli family --onepp [chain] --out PREFIX [--count N] [--precision P]`: the 1IPP family
/// of the note's chain or of a chain of N masses (commands/onepp_family.h) as a table
/// (PREFIX.csv, PREFIX.npy: the same columns, PREFIX.json) and a frequency-energy picture
/// (PREFIX.png, PREFIX.svg) when pictures are available. Exit 0; 2 with `error` on invalid input;
/// 130 (nothing written) when `stop` is requested; 1 when a file could not be written.
int runFamily(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

/// The options of `family` (--count, --precision) as a request; nothing, with `error` the line
/// that says why.
std::optional<FamilyRequest> readFamilyRequest(const OptionValues& options, QString& error);

/// The family of the options' chain, its files written where --out names them (`filesRequired`:
/// the command line, which writes nothing else, refuses a run without --out; the Python module
/// writes files only when asked). `code` is the command's exit code; `outcome` the family when
/// computed.
struct FamilyRun {
  int code = 0;
  FamilyOutcome outcome;
};
FamilyRun familyWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                          bool filesRequired);

}  // namespace grazelab::cli
