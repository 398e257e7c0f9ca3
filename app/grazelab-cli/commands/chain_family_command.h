// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <stop_token>

#include "io/option_values.h"


namespace grazelab::cli {

struct Io;

/// `grazelab-cli family --onepp --masses ...`: the 1IPP family of a chain of N masses
/// (core/orbits/chain_onepp.h) over (0, T_max), T_max the common period (or the slowest mode's),
/// written as PREFIX.csv, PREFIX.npy and PREFIX.json (with the grazing limit of Theorem 2.1: its
/// weights and GLO data), and PREFIX.png/.svg (frequency against energy) when pictures are
/// available. Exit 0; 2 on invalid input (`error`); 130 when `stop` ended it; 1 when a file
/// could not be written.
int runChainFamily(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

}  // namespace grazelab::cli
