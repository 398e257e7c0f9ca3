// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <stop_token>

#include "io/cli_io.h"
#include "io/option_values.h"

namespace grazelab::cli {

class PreparedMassChain;

/// `grazelab-cli simulate`: an exact run of a chain (core/solver/chain_run.h), given by --masses
/// ... or by the note's options (--m1 --m2 --k1 --k2 --branch --gap: the two-mass chain they
/// write), from its start, up to --contacts (default 100) or --t-end, streamed as json, jsonl, csv
/// or a summary with its error estimate (docs/cli.md). Exit 0; 2 on invalid input (`error`,
/// nothing on stdout); 130 when `stop` ended it (`error`: what was written).
int runSimulate(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);
/// The same for a chain read once (`options` then says how to run it; its chain options are
/// not read again).
int runSimulate(const PreparedMassChain& chain, const OptionValues& options, const Io& io, std::stop_token stop,
                QString& error);

}  // namespace grazelab::cli
