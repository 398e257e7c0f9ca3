// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <stop_token>

#include "io/cli_io.h"
#include "io/option_values.h"

namespace grazelab::cli {

class PreparedMassChain;

/// `grazelab-cli simulate --masses ...`: an exact run of a chain of N masses
/// (core/solver/chain_run.h) from --state u1,...,uN,v1,...,vN, up to --contacts (default 100)
/// or --t-end, written as one JSON document (double). Exit 0; 2 on invalid input (`error`,
/// nothing on stdout); 130 when `stop` ended it (nothing on stdout).
int runChainSimulate(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);
/// The same for a chain read once (`options` then says how to run it; its chain options are
/// not read again).
int runChainSimulate(const PreparedMassChain& chain, const OptionValues& options, const Io& io, std::stop_token stop,
                     QString& error);

}  // namespace grazelab::cli
