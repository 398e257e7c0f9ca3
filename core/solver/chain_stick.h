// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <Eigen/Core>

#include "core/model/mass_chain.h"
#include "core/solver/chain_flight.h"
#include "core/solver/sinusoid_zero.h"

namespace grazelab::core {

/// The stuck phase of a chain of N masses (docs/model.md section 11): mass s held on the stop
/// (u_s = d, v_s = 0) splits the chain at the clamp into two exact chains: the masses left of s
/// between the wall and the clamp, and those right of it between the clamp and the right wall
/// (or a free end). Each moves in its own modes about its rest with the clamp at d, which the
/// series springs give in closed form. The phase ends when the springs' force on mass s,
/// F_s = k_s (u_(s-1) - d) + k_(s+1) (u_(s+1) - d), falls to zero: its mean -d (1/C_left +
/// 1/C_right) is negative (C the sides' series compliances), so it always does.
template <typename S>
struct BasicChainStuckPhase {
  /// One side of the clamp: masses first .. first+count-1 (0-based) of the whole chain.
  struct Side {
    Eigen::Index first = 0;
    Eigen::Index count = 0;
    BasicChainDynamics<S> dynamics;  ///< the side as a chain of its own (the clamp one of its walls)
    ChainVector<S> rest;             ///< its displacements at rest, the clamp at d
    BasicChainFlight<S> flight;      ///< about the rest: u - rest in the side's modes
    S clampSpring = 0;               ///< the spring joining it to mass s (0: no such side)
    Eigen::Index clampMass = 0;      ///< the side's mass on that spring (side-local)
  };
  int stop = 0;  ///< s, 0-based
  S gap = 1;
  Side left, right;
  /// F_s at the sides' rest: -d (1/C_left + 1/C_right) < 0, a wall's spring next to mass s
  /// included (C_right infinite for a free right end)
  S restForce = 0;
};
using ChainStuckPhase = BasicChainStuckPhase<double>;

/// The stuck phase from `start` (u_s = d, v_s = 0, F_s > 0) of a usable chain.
template <typename S>
BasicChainStuckPhase<S> stuckPhase(const BasicMassChain<S>& chain, const BasicChainState<S>& start);

/// The state `t` after the phase's start (u_s = d, v_s = 0).
template <typename S>
BasicChainState<S> stuckStateAt(const BasicChainStuckPhase<S>& phase, std::type_identity_t<S> t);

/// The springs' force on the stopped mass, F_s = -(K u)_s, and a bound of its rounding.
template <typename S>
struct BasicStopForce {
  S value = 0;
  S error = 0;
};
template <typename S>
BasicStopForce<S> stopForce(const BasicMassChain<S>& chain, const BasicChainState<S>& state);

/// When the phase ends: -F_s(t) searched for its first zero by firstZero (certified, over up to
/// `horizon`): a Crossing is the release; a Touch means the force comes back to zero within
/// the precision's rounding without being seen to change sign (undecided); Budget, none found.
template <typename S>
BasicFirstZero<S> releaseOf(const BasicChainStuckPhase<S>& phase, std::type_identity_t<S> horizon,
                            long maxWindows = 1'000'000);

}  // namespace grazelab::core
