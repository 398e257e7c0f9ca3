// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/model/two_mass_form.h"
#include "core/model/model.h"
#include "core/orbits/special_orbits.h"
#include "core/model/resonance.h"
#include "core/solver/chain_flight.h"

namespace grazelab::core {

/// The one place that builds starts (GLO/GLOM/1IPP data, perturbation) for the command line, the
/// explorer, the tests and the benchmarks; a designed chain is core/model/model.h's
/// designedModel.

/// How a run starts.
template <typename S>
struct StartSpec {
  enum class Kind { Glo, Glom, OnePeriodic, Explicit };
  Kind kind = Kind::Glo;
  S lambda = 0.5;                 ///< Glo: GLO_lambda
  Mode mode = Mode::Fast;         ///< Glom
  S period = 0;                   ///< OnePeriodic: T [time]
  BasicState<S> state;            ///< Explicit
  std::optional<BasicState<S>> perturbation;  ///< added afterwards

  friend bool operator==(const StartSpec&, const StartSpec&) = default;
};

/// A start state with the words that describe it.
template <typename S>
struct Start {
  BasicState<S> state;
  std::string description;         ///< e.g. "GLO_lambda data, lambda = 0.5 (as such: ...)"
  std::vector<std::string> notes;  ///< things the user should know (a perturbation lost in rounding)
  /// the chain's modes (fastest first) exactly still in it: stillModesOf (a run keeps them so)
  std::vector<bool> stillModes = {};
};

/// The modes of the note's chain exactly still in the start `spec` makes, left where it is (no
/// perturbation), fastest first as a chain's start names them: the slow one in the fast mode's data
/// alone (GLO_0, the fast GLOM) on a resonant chain, whose touches at T1 = T2 / 2 the rounded state
/// cannot decide (it holds 1e-17 of the slow mode), so that a run decides them exactly (the modal
/// kernel keeps that mode at 0); none otherwise (the slow mode alone returns at T2, where the
/// note's kernel anchors its return exactly).
template <typename S>
std::vector<bool> stillModesOf(const TwoMassForm<S>& chain, const StartSpec<S>& spec);

/// Either a start, or the one line saying why not.
template <typename S>
struct StartOrProblem {
  std::optional<Start<S>> start;
  std::string problem;
  bool undecided = false;  ///< the precision cannot decide it (a 1IPP orbit's return): a higher one may
};

template <typename S>
StartOrProblem<S> makeStart(const TwoMassForm<S>& chain, const StartSpec<S>& spec);

/// A state on the section H (u2 = gap) of energy `level` with mass 1 at (u1, v1), mass 2
/// leaving the stop (v2 <= 0, as after an impact) at the speed the energy leaves it (a start
/// chosen on the section at the energy of the run shown); nothing when mass 1 and the springs
/// alone hold more than `level`.
std::optional<State> sectionStateAtEnergy(const Model& model, double level, double u1, double v1);

/// A state on H of energy `level` with mass 2 leaving the stop at `speed` and mass 1 at `u1`,
/// moving the way `v1Sign` says (a start chosen on the stop line of the (u2, v2) portrait);
/// nothing when mass 2's speed and the springs alone hold more than `level`.
std::optional<State> stopLineStateAtEnergy(const Model& model, double level, double u1,
                                           double speed, double v1Sign);

/// Where a chain of N masses cannot start from a point chosen on its section H.
enum class ChainSectionProblem {
  None,
  StoppedMassCoordinate,  ///< a coordinate is the stopped mass's own (u_s = d on H, v_s is solved)
  EnergyTooLow,           ///< the chosen coordinates and the springs alone hold more than the energy
};

struct ChainSectionStart {
  ChainState state;
  ChainSectionProblem problem = ChainSectionProblem::None;
};

/// A chain's state on H (u_s = gap) of energy `level` whose coordinates `a` and `b` (0-based in
/// (u_1 ... u_N, v_1 ... v_N)) are `x` and `y`, every other one as in `base`, the stopped mass
/// leaving the stop (v_s <= 0) at the speed the energy leaves it: sectionStateAtEnergy for N
/// masses (on two masses, with base's u1 and v1 chosen, the same state).
ChainSectionStart chainSectionStateAtEnergy(const MassChain& chain, double level, const ChainState& base,
                                            int a, double x, int b, double y);

/// `base` with the stopped mass on the stop leaving it at `speed` (a start chosen on the stop line
/// of its phase portrait): the other masses as in `base`, so the energy is what that makes it.
ChainState chainStopLineState(const MassChain& chain, const ChainState& base, double speed);

}  // namespace grazelab::core
