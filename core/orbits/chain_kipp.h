// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <stop_token>
#include <string_view>

#include "core/orbits/chain_monodromy.h"

/// Periodic impacting orbits of k impacts (kIPP) of any chain, by Newton on the exact return map
/// to the stopped mass's impacts (docs/model.md section 12): the section H+ is u_s = d just after
/// an impact; a point of it is the other masses' (u_j, v_j) and the energy, which gives v_s <= 0.
/// The return map's Jacobian is the path's monodromy projected on the section along the flow, so
/// Newton converges quadratically from a guess near an orbit, in any precision.
namespace grazelab::core {

/// What the orbit sought keeps fixed: its energy (the section's 2N - 2 coordinates are the
/// unknowns), or its period (the energy is one more).
enum class ChainOrbitConstraint { Energy, Period };

/// Why a search gave no orbit.
enum class ChainOrbitProblem {
  None,                ///< found
  NoImpacts,           ///< k < 1
  NoStateAtGuess,      ///< the guess holds more energy than asked (no v_s), or v_s > 0 at a fixed period
  GuessOffSequence,    ///< the guess's own path makes another sequence of contacts (`refusal` says which)
  LeftEnergyLevel,     ///< a Newton step left the states of the energy asked for
  LeftImpactSequence,  ///< an iterate's path made another sequence of contacts (`refusal` says which)
  Singular,            ///< the Jacobian is singular: a multiplier at 1 (a fold or branch point), or at a
                       ///< fixed period a family whose period does not change with its energy
  NotConverging,       ///< the residual stopped falling
  Stalled,             ///< closed to the rounding, yet with a step far larger still to go
  NotAdmissible,       ///< the orbit found is not admissible (`refusal` says why)
  Stopped,             ///< a stop was requested
};
/// The problem in words, for one line of a refusal.
std::string_view toString(ChainOrbitProblem problem);

/// The result of a search: the orbit, with its monodromy and multipliers, or why none.
template <typename S>
struct ChainOrbitSearch {
  std::optional<BasicChainPeriodicOrbit<S>> orbit;
  ChainOrbitProblem problem = ChainOrbitProblem::None;
  /// the path's refusal where it says more (Undecided: a higher precision may decide)
  OrbitRefusal refusal = OrbitRefusal::None;
  int iterations = 0;
  /// the last Newton step, in the scaled units of the state (energy: relative): how far the exact
  /// orbit may still be from the one given
  S correction = 0;
};

/// The kIPP orbit near `guess` (a state on H+: u_s = d, v_s <= 0) whose energy (or period) is
/// `value`, after `impacts` impacts. With ChainOrbitConstraint::Energy the guess's v_s is set by
/// the energy; with Period the guess's energy is the first one tried. Admissible as
/// evaluateChainOrbit says, closed to the rounding the return map amplifies.
template <typename S>
ChainOrbitSearch<S> findChainOrbit(const BasicReadyChain<S>& chain, const BasicChainState<S>& guess, int impacts,
                                   ChainOrbitConstraint fixed, const std::type_identity_t<S>& value,
                                   std::stop_token stop = {});

}  // namespace grazelab::core
