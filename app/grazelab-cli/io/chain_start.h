// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <optional>
#include <string>

#include "core/orbits/special_orbits.h"
#include "core/solver/chain_flight.h"
#include "io/option_values.h"

// The start of a chain of N masses as the commands read it (simulate --masses, report --masses).
namespace grazelab::cli {

/// Exactly one start of a chain of n masses given (--state, --glo-weights, --onepp), or false
/// with `error` set.
bool oneStartOf(const OptionValues& options, Eigen::Index n, QString& error);
/// Why a period has no admissible 1IPP orbit (the data's refusal), in words.
const char* onePeriodicRefusalWords(core::OnePeriodicRefusal refusal);
/// --glo is the two-mass chain's: a chain of N masses has --glo-weights; false with `error` set.
bool noTwoMassStart(const OptionValues& options, QString& error);

/// The run's start in S, from the chain in S: --state, --glo-weights (GLO_lambda at its touch) or
/// --onepp T (the 1IPP orbit's data right after its impact), plus --perturb. --state, the weights,
/// T and --perturb are read in S (0.1 is 0.1 to binary128's digits). `description`, when given,
/// receives how the start was given, in words. A GLO start not pushed names its modes of weight 0
/// as still. Nothing, with `error`, for a start refused. `ready`, when given, is `chain` made
/// ready: its modes serve the GLO start (not computed again: they cost more than a short run).
template <typename S>
std::optional<core::BasicChainStart<S>> chainStart(const OptionValues& options, const core::BasicMassChain<S>& chain,
                                                   QString& error, std::string* description = nullptr,
                                                   const core::BasicChainDynamics<S>* ready = nullptr);

}  // namespace grazelab::cli
