// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <optional>
#include <stop_token>

#include "commands/grazing_set.h"
#include "io/cli_input.h"
#include "io/cli_io.h"
#include "io/option_values.h"

namespace grazelab::cli {

/// The chain glo-set reads: --masses ..., or the two-mass chain of --m1 ... (the note's by
/// default); neither value nor error when `stop` ended its design.
Parsed<core::MassChain> gloSetChainOf(const OptionValues& options, std::stop_token stop);
/// --directions (3 to 100000) and --precision (double or auto only), or nothing with `error`.
std::optional<GloSetRequest> readGloSetRequest(const OptionValues& options, QString& error);

/// `grazelab-cli glo-set`: which affine combinations of a resonant chain's GLOMs are grazing
/// linear orbits (commands/grazing_set.h), for the two-mass chain (--m1 ...) or a chain of N
/// masses (--masses ...): the lambda-interval of two modes, the boundary of the region of the
/// lambda-plane of three (--directions rays), one JSON document; with --out its picture. Exit 0;
/// 2 on invalid input or a chain it cannot answer for (not commensurate; more than three modes
/// move the stopped mass): `error`, nothing on stdout; 130 when `stop` ended it.
int runGloSet(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

}  // namespace grazelab::cli
