// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <optional>
#include <stop_token>

#include "commands/modes_atlas_command.h"
#include "io/cli_io.h"
#include "io/option_values.h"

class QCommandLineParser;

namespace grazelab::cli {

/// The options of `modes`: --max-impacts, --energy-range.
void addModesOptions(QCommandLineParser& parser);

/// `grazelab-cli modes [model] [--max-impacts K] [--energy-range A:B] [--precision P] --out
/// PREFIX`: the atlas of the chain's periodic impacting families up to K impacts per period
/// (PREFIX.json, one CSV and .npy per family, the frequency-energy picture PREFIX.png/.svg).
/// Exit 2 with `error` on invalid input, 130 (nothing written) when `stop` is requested.
int runModes(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

/// The options of `modes` (--max-impacts, --energy-range, --precision) as a request; nothing,
/// with `error` the line that says why.
std::optional<ModesRequest> readModesRequest(const OptionValues& options, QString& error);

/// The atlas of the options' chain, its files written where --out names them (`filesRequired`:
/// the command line refuses a run without --out; the Python module writes files only when
/// asked). `code` is the command's exit code; `outcome` the atlas when computed.
struct ModesRun {
  int code = 0;
  ModesOutcome outcome;
};
ModesRun modesWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                        bool filesRequired);

/// `grazelab-cli family --impacts K (--energy E | --period T) --guess U,V [--energy-range A:B]
/// [--count N] --out PREFIX`: the family of the kIPP orbit found from the guess, followed both
/// ways (commands/modes_atlas_command.h, impactsFamily), written as an atlas of one family (as
/// `modes` writes: PREFIX.json, PREFIX-family-0.csv and .npy, the picture).
ModesRun impactsFamilyWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                                bool filesRequired);

}  // namespace grazelab::cli
