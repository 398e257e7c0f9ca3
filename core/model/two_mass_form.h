// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>
#include <string>

#include "core/model/model.h"
#include "core/numbers/scalar.h"
#include "core/model/state.h"

namespace grazelab::core {

/// The note's chain of two masses in nondimensional form (docs/model.md sections 2 and 7): what
/// the note's kernel runs (core/solver/exact_stepper.h) and its orbits are computed in; "chain"
/// alone means a chain of N masses (core/model/mass_chain.h). Computed once from a model and
/// const afterwards. Time is measured by the slow frequency (tau = w2 t), so the slow mode has
/// frequency 1 and period 2 pi, the fast one `ratio` (2 exactly when resonant).
///
/// Everything is formed from the ratios beta = m2/m1 and kappa = k2/k1 in closed form, never from
/// differences of nearly equal numbers: the eigenvalues by the cancellation-free root and Vieta,
/// the mode shapes from whichever row of K p = w^2 M p is well conditioned. This keeps every
/// quantity to relative precision for m2/m1 -> 0, stiff springs (k2/k1 -> infinity) and any
/// absolute size of the numbers.
template <typename S>
struct TwoMassForm {
  BasicModel<S> model;  ///< the physical parameters it came from
  S beta = 0;           ///< m2 / m1
  S kappa = 0;          ///< k2 / k1 (the design value when model.design is set)
  S lambdaSlow = 0;     ///< w2^2 m1 / k1
  S lambdaFast = 0;     ///< w1^2 m1 / k1
  S omegaSlow = 0;      ///< w2 [1/time]
  S ratio = 2;          ///< w1 / w2; exactly 2 when resonant
  S detuning = 0;       ///< w1 / w2 - 2, to relative precision (from the exact resonance defect)
  bool resonant = false;  ///< w1 = 2 w2 exactly (by design, or the given numbers satisfy it)
  S rhoFast = 0;        ///< u1 / u2 in the fast mode (< 0: the masses move against each other)
  S rhoSlow = 0;        ///< u1 / u2 in the slow mode (> 0)
  /// Nondimensional free motion: x1'' = -(p x1 + q (x1 - x2)), x2'' = w (x1 - x2).
  S p = 0, q = 0, w = 0;
  S stuckOmega = 0;  ///< frequency of mass 1 alone while mass 2 is held on the stop (units of w2)
};

/// Why a chain cannot be formed in a precision: both may go in a wider one.
enum class TwoMassFormProblem {
  None,
  BeyondRange,    ///< a ratio of its numbers is beyond the precision's range
  PhaseRounding,  ///< the fast mode's phase over a slow period is rounding in the precision
};

/// The form, or the one line saying why it cannot be formed in this precision.
template <typename S>
struct TwoMassFormOrProblem {
  std::optional<TwoMassForm<S>> chain;
  std::string problem;
  TwoMassFormProblem kind = TwoMassFormProblem::None;
};

/// Forms the nondimensional two-mass form. Precondition: validate(model) is empty. Fails (with a reason)
/// only when a ratio of the inputs is beyond the range of S.
template <typename S>
TwoMassFormOrProblem<S> makeTwoMassForm(const BasicModel<S>& model);

/// The scales of one run (docs/model.md section 7): lengths by L = 2^exponent (a power of two, so
/// scaling is exact), velocities by w2 L, time by 1 / w2.
template <typename S>
struct Scale {
  int exponent = 0;   ///< L = 2^exponent
  S omegaSlow = 1;    ///< w2 [1/time]
  S gap = 1;          ///< delta = gap / L, the stop in scaled units

  BasicState<S> toScaled(const BasicState<S>& physical) const;
  BasicState<S> toPhysical(const BasicState<S>& scaled) const;
  S toPhysicalTime(const S& tau) const { return tau / omegaSlow; }
  S toScaledTime(const S& t) const { return t * omegaSlow; }
};

/// L from the gap and the start's own size: the largest of gap, |u1|, |u2|, |v1| / w2, |v2| / w2,
/// rounded to a power of two.
template <typename S>
Scale<S> chooseScale(const TwoMassForm<S>& chain, const BasicState<S>& initial);

/// Scaled energy E / (k1 L^2) = 1/2 [lambdaSlow (y1^2 + beta y2^2) + x1^2 + kappa (x2 - x1)^2]
/// of a scaled state: O(1) numbers whatever the units.
template <typename S>
S scaledEnergy(const TwoMassForm<S>& chain, const BasicState<S>& x);

/// Physical energy E = 1/2 v^T M v + 1/2 u^T K u of a physical state, formed through the scaled
/// variables (it overflows first in physical units); infinite when it is beyond the range of S
/// or the state is infinite, NaN for a state with a NaN.
template <typename S>
S physicalEnergy(const TwoMassForm<S>& chain, const BasicState<S>& physical);

/// Physical energy of a physical state of a model (double precision convenience; forms the
/// chain itself). Infinite when beyond double range or the model is unusable.
double energy(const BasicModel<double>& model, const BasicState<double>& state);

}  // namespace grazelab::core
