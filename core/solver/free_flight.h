// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <array>
#include <span>
#include <utility>

#include "core/model/two_mass_form.h"
#include "core/numbers/scalar.h"
#include "core/model/state.h"

namespace grazelab::core {

/// A time inside a free flight, in scaled time (tau = w2 t): `offset` from the anchor
/// 2 pi `periods`. The slow mode repeats exactly after 2 pi (and, when resonant, the whole
/// motion), so a time close to a return is kept as its small offset from it: a contact a hair
/// before the return keeps full relative precision instead of drowning in the rounding of 2 pi k.
template <typename S>
struct FlightTime {
  long long periods = 0;  ///< k: the anchor is 2 pi k
  S offset = 0;           ///< s: time from the anchor

  /// tau = 2 pi k + s.
  S value() const { return twoPi<S>() * S(periods) + offset; }
  /// The same time with |offset| <= pi.
  static FlightTime nearest(const S& tau);
};

/// Exact free motion of the chain from a start state, in scaled units (docs/model.md sections 3
/// and 7): no time stepping. Modes have unit mass-2 components, so
///   x2(tau) - delta = (x2(0) - delta) + sum_j [c_j (cos w_j tau - 1) + a_j sin w_j tau],
/// w = (ratio, 1), written as increments (cos x - 1 = -2 sin^2(x/2)) so that it never subtracts
/// numbers close to the gap.
///
/// Near the start, and near every return 2 pi k, the motion is also evaluated from the Taylor
/// series of the state at that anchor, x^(n+2) = -A x^(n): its leading coefficients are the
/// departure velocity and the spring force exactly, not differences of modal terms, so tiny
/// departures from the stop stay resolved. The anchor state is the start itself for a resonant
/// chain; for a detuned one it is the start plus the fast mode's increment over its phase slip
/// 2 pi k (w1/w2 - 2), computed to relative precision.
template <typename S>
class Flight {
 public:
  /// Precondition: `start` is a scaled state of `chain`, `gap` the scaled stop delta.
  /// `u1Residual` is exact x1 minus start.u1 (what the start's x1 lost to rounding): the spring
  /// stretch x1 - x2, which sets how a flight from the stop leaves it, uses it.
  Flight(const TwoMassForm<S>& chain, const S& gap, const BasicState<S>& start,
         const S& u1Residual = S(0));

  const TwoMassForm<S>& chain() const { return *m_chain; }
  const BasicState<S>& start() const { return m_start; }
  const S& gapLevel() const { return m_gap; }
  /// True when the flight starts on the contact plane H (x2 == delta exactly).
  bool startsOnStop() const { return m_startsOnStop; }
  /// True when the flight never reaches the stop, whatever the frequencies: x2 is at most the sum
  /// of its modes' amplitudes, and that sum (with its rounding) falls short of delta.
  bool neverReachesStop() const { return m_neverReachesStop; }

  /// State at a flight time; `u1Residual`, when given, receives exact x1 minus the returned u1
  /// (the part of x1 below its rounding, from the start's residual and the last addition).
  BasicState<S> at(const FlightTime<S>& time, S* u1Residual = nullptr) const;
  /// States at the offsets first + k step from the start, k = 0 .. out.size() - 1: dense display
  /// samples. The modal form from the start, its phases advanced by a rotation (a few products
  /// per sample instead of a sine and a cosine) and taken exactly again every 16 samples, so
  /// that rounding grows over 16 rotations at most; equal to at() within 1e-14 of the motion's
  /// size, not to its last bit near the stop (contacts are never found from samples).
  void statesOnGrid(const S& first, const S& step, std::span<BasicState<S>> out) const;
  /// (x2 - delta, y2), evaluated without cancellation.
  std::pair<S, S> gapAndRate(const FlightTime<S>& time) const;
  /// x2'' at a flight time.
  S acceleration2(const FlightTime<S>& time) const;

  /// (g, g') for g(s) = (x2 - delta) / s^m at offset s from anchor 0 (the start) or, when
  /// resonant, anchor 1 (the return, s <= 0): the m-fold zero of a flight that leaves the stop
  /// divided out.
  std::pair<S, S> reducedGapAndRate(long long anchor, const S& s, int m) const;

  /// d^n (x2 - delta) / dtau^n at the start.
  S gapDerivative(int n) const;
  /// d^n (x2 - delta) / dtau^n at the start for n = 0 .. 4, without filling the whole series
  /// (equal to gapDerivative(n), rounding included).
  std::array<S, 5> lowGapDerivatives() const;
  /// Order of the zero of x2 - delta at the start: the lowest n >= 1 with a nonzero derivative
  /// (0 when the start is below the stop).
  int contactOrder() const { return m_contactOrder; }

  /// Half-width of the Taylor window around each anchor: ratio |s| <= 1/20.
  const S& taylorRadius() const { return m_taylorRadius; }
  /// Bound on |x2''| over all times.
  const S& accelerationBound() const { return m_accelerationBound; }
  /// Rounding level of x2 - delta in the modal form: values within it are indistinguishable
  /// from a touch there.
  const S& gapTolerance() const { return m_gapTolerance; }

  /// Modal coefficients of the gap at the start: c_j and a_j, j = 0 fast, 1 slow.
  const std::array<S, 2>& cosineCoefficients() const { return m_anchors[0].c; }
  const std::array<S, 2>& sineCoefficients() const { return m_anchors[0].a; }

  static constexpr int kMaxTaylorOrder = 18;

 private:
  struct Anchor {
    long long periods = -1;
    BasicState<S> state;  // the state at 2 pi k
    std::array<S, 2> c{}, a{};  // modal position amplitudes and velocity amplitudes / w_j
    S gapValue = 0;             // x2 - delta at the anchor, kept without rounding x2 first
    bool taylorReady = false;
    // d^n x / dtau^n at the anchor (u1 and u2 rows), n = 0 .. order + 1
    // (left uninitialised: fillTaylor writes every row that is read, and a flight is built per
    // contact)
    std::array<std::array<S, 2>, kMaxTaylorOrder + 2> derivatives;
  };
  // the anchor at 2 pi `periods`: the start, or the cached other one (built on a miss)
  const Anchor& anchor(long long periods) const {
    if (periods == 0 || m_chain->resonant) return m_anchors[0];
    return m_anchors[1].periods == periods ? m_anchors[1] : newAnchor(periods);
  }
  const Anchor& newAnchor(long long periods) const;
  void fillTaylor(const Anchor& anchor) const;
  int taylorTerms(const S& s) const;
  // per-mode (sin(w_j s), cos(w_j s) - 1)
  void modalPhases(const S& s, std::array<S, 2>& sine, std::array<S, 2>& cosineMinusOne) const;
  BasicState<S> modalAt(const Anchor& anchor, const S& s, S* u1Residual) const;
  // the state from the anchor's modal terms at phases (sin(w_j s), cos(w_j s) - 1)
  BasicState<S> stateFromPhases(const Anchor& anchor, const std::array<S, 2>& sine,
                                const std::array<S, 2>& cosineMinusOne, S* u1Residual) const;
  BasicState<S> taylorAt(const Anchor& anchor, const S& s, S* u1Residual) const;

  const TwoMassForm<S>* m_chain;
  S m_gap;
  BasicState<S> m_start;
  S m_startU1Residual = 0;
  S m_startStretch = 0;  ///< x1 - x2 at the start, with the residual
  bool m_startsOnStop = false;
  int m_contactOrder = 0;
  int m_taylorOrder = 11;
  S m_taylorRadius = 0;
  S m_accelerationBound = 0;
  S m_gapTolerance = 0;
  bool m_neverReachesStop = false;
  // anchor 0 (the start) and a cache of one other anchor (detuned flights); mutable: a cache,
  // a Flight is used by one thread
  mutable std::array<Anchor, 2> m_anchors;
};

}  // namespace grazelab::core
