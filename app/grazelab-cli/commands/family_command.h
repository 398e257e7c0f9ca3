// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <stop_token>

#include "io/cli_io.h"
#include "io/option_values.h"


namespace grazelab::cli {

/// `grazelab-cli family --onepp [model] --out PREFIX [--count N]`: the 1IPP family as a table
/// (PREFIX.csv: T,omega,V,u1,energy,admissible; PREFIX.npy: the same columns; PREFIX.json) and
/// a frequency-energy picture (PREFIX.png, PREFIX.svg). Exit 2 with `error` on invalid input.
/// Exit 130 (nothing written) when `stop` is requested.
int runFamily(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

}  // namespace grazelab::cli
