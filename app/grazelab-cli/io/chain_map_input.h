// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <optional>
#include <stop_token>

#include "core/experiments/chain_map.h"
#include "io/option_values.h"

namespace grazelab::cli {

/// A map of a chain of N masses from the command line: the chain (--masses ... as simulate),
/// the start --state u1..uN,v1..vN (default the grazing-start plane: u_s = d, all else 0), --x and --y u<i>|v<i>:from:to:count,
/// or w<j> (GLO weights: --glo-weights, --perturb), --contacts, --trust; or nothing with `error` set (`stopped`: a design interrupted).
std::optional<core::ChainMapSpec> parseChainMapSpec(const OptionValues& options, std::stop_token stop,
                                                    QString& error, bool& stopped);

}  // namespace grazelab::cli
