// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "core/model/two_mass_form.h"
#include "core/model/state.h"

namespace grazelab::core {

/// The stuck phase, in scaled units (docs/model.md section 4): mass 2 held at x2 = delta (reaction
/// R = -k2 (u1 - gap) <= 0) while mass 1 oscillates alone about the centre
/// kappa delta / (1 + kappa) < delta, at the frequency chain.stuckOmega. It ends when x1 falls
/// back to delta (R reaches 0), always in finite time.
///
/// The release time solves (x1(0) - delta) + A (cos W t - 1) + B sin W t = 0 as a quadratic in
/// z = tan(W t / 2) with the cancellation-free root, so a stick that releases a tiny time later
/// keeps the relative precision of that time and of the release velocity.
template <typename S>
class StuckMotion {
 public:
  /// Precondition: pressedOnStop(start, gap, u1Residual). `u1Residual` is exact x1 minus
  /// start.u1 (a pressing below the rounding of u1 lasts accordingly short).
  StuckMotion(const TwoMassForm<S>& chain, const S& gap, const BasicState<S>& start,
              const S& u1Residual = S(0));

  /// State tau after the start of the phase (x2 = delta, y2 = 0 throughout).
  BasicState<S> at(const S& tau) const;
  /// Duration of the phase: the first tau > 0 with x1(tau) = delta and x1 decreasing.
  const S& releaseTime() const { return m_releaseTime; }
  /// The state at release: x1 = delta exactly, y1 <= 0, on the stop at rest.
  BasicState<S> releaseState() const;

 private:
  BasicState<S> atPhase(const S& sine, const S& cosineMinusOne) const;

  S m_gap;
  BasicState<S> m_start;
  S m_omega;      // frequency of mass 1 alone
  S m_amplitude;  // A = x1(0) - centre
  S m_rate;       // B = y1(0) / omega
  S m_releaseTime = 0;
  S m_releaseZ = 0;  // tan(omega release / 2)
};

}  // namespace grazelab::core
