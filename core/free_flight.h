// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <array>
#include <utility>

#include <Eigen/Core>

#include "core/model.h"
#include "core/modes.h"
#include "core/state.h"

namespace grazelab::core {

/// A time inside a free flight. For a resonant chain the motion repeats after T2, so a time
/// close to T2 is kept as its (small, negative) offset from T2: a contact a hair before the return
/// then keeps full relative precision instead of drowning in the rounding of T2.
struct FlightTime {
  double offset = 0;        ///< time from the start, or from T2 when fromReturn
  bool fromReturn = false;  ///< offset is measured from the return time T2 (resonant only)

  /// The time from the start of the flight.
  double value(double T2) const { return fromReturn ? T2 + offset : offset; }
};

/// Exact free motion of the chain from a start state (MODEL.md section 3): no time stepping.
///
/// Two evaluations of the same motion are kept, each used where it is exact to rounding:
/// - the modal closed form q_j(t) = q_j cos(w_j t) + (q'_j / w_j) sin(w_j t), written as increments
///   from the start (cos x - 1 = -2 sin^2(x/2)) so that u2(t) - gap never subtracts numbers close
///   to the gap;
/// - near the start (and, for a resonant chain, near every multiple of T2, where the motion
///   repeats exactly) the Taylor series built from the state itself, u^(2n) = A^n u,
///   u^(2n+1) = A^n v with A = -M^-1 K. Its leading coefficients are v2 and k2 (u1 - u2) / m2
///   exactly, not differences of modal terms, so tiny departures from the stop stay resolved.
class Flight {
 public:
  /// Precondition: the model is valid and `modes` are its modes.
  Flight(const Model& model, const Modes& modes, const State& start);

  const Model& model() const { return m_model; }
  const Modes& modes() const { return m_modes; }
  const State& start() const { return m_start; }
  /// True when the flight starts on the contact plane H (u2 == gap exactly).
  bool startsOnStop() const { return m_startsOnStop; }

  /// State at time t >= 0 after the start.
  State at(double t) const;
  /// State at a flight time; a time anchored at T2 is evaluated through the exact periodicity.
  State at(FlightTime time) const { return at(time.offset); }

  /// (u2(t) - gap, v2(t)), evaluated without cancellation.
  std::pair<double, double> gapAndRate(double t) const;
  /// u2(t) - gap.
  double gap(double t) const { return gapAndRate(t).first; }
  /// d^2 u2 / dt^2 at time t (modal form).
  double acceleration2(double t) const;

  /// Resonant flights only: (u2 - gap, d^2 u2 / dt^2) at the slow phase theta = w2 t, given
  /// sin(theta) and cos(theta) - 1. The contact search knows these rationally from tan(theta/2),
  /// so no trigonometric function is called.
  std::pair<double, double> gapAndAccelerationAtPhase(double sine, double cosineMinusOne) const;

  /// (g, g') for g(x) = (u2(x) - gap) / x^m, the gap with its m-fold zero at the start removed.
  /// Used for flights that start on the stop, where u2 - gap has a zero of order m at x = 0
  /// (and at x = T2 in the resonant case). For a resonant chain x may be negative (time before
  /// a return).
  std::pair<double, double> reducedGapAndRate(double x, int m) const;

  /// d^n (u2 - gap) / dt^n at the start, n = 0 .. kTaylorOrder.
  double gapDerivative(int n) const;
  /// Order of the zero of u2 - gap at the start: the lowest n >= 1 with a nonzero derivative
  /// (0 when the start is below the stop).
  int contactOrder() const { return m_contactOrder; }

  /// Half-width of the time window around the start (and its T2 repeats) where the Taylor form
  /// is used: w_fast |t| <= 1/20.
  double taylorRadius() const { return m_taylorRadius; }
  /// Bound on |u2(t) - u2(0)| / 2: the amplitude of the gap function.
  double gapAmplitude() const { return m_gapAmplitude; }
  /// Bound on |d^2 u2 / dt^2| over all times.
  double accelerationBound() const { return m_accelerationBound; }
  /// Rounding level of u2(t) - gap: values within it are indistinguishable from a touch.
  double gapTolerance() const { return m_gapTolerance; }

  /// Modal coefficients of u2(t) - gap as a trigonometric polynomial in the phase of each mode:
  /// alpha_j cos(w_j t) + beta_j sin(w_j t) + constant; j = 0 fast, 1 slow.
  const Eigen::Vector2d& alpha() const { return m_alpha; }
  const Eigen::Vector2d& beta() const { return m_beta; }

  static constexpr int kTaylorOrder = 11;

 private:
  // (sin(w_j s), cos(w_j s) - 1) for both modes, j = 0 fast, 1 slow
  struct Increments {
    std::array<double, 2> sine;
    std::array<double, 2> cosineMinusOne;
  };
  Increments modalPhases(double s) const;
  State modalAt(double t) const;
  State taylorAt(double s) const;
  // time reduced to the nearest start repeat: t itself, or t - k T2 for a resonant chain
  double reduce(double t) const;
  // highest order needed for the Taylor sums at offset s (|s| <= taylorRadius)
  int taylorTerms(double s) const;
  // computes the Taylor coefficients on first use: many flights never need them
  void ensureTaylor() const;

  Model m_model;
  Modes m_modes;
  State m_start;
  bool m_startsOnStop = false;
  Eigen::Vector2d m_q;     // modal coordinates P^-1 u at the start
  Eigen::Vector2d m_qDot;  // modal velocities P^-1 v at the start
  Eigen::Vector2d m_omega;           // (w_fast, w_slow)
  Eigen::Vector2d m_amplitudeRatio;  // q'_j / w_j
  Eigen::Vector2d m_alpha;
  Eigen::Vector2d m_beta;
  // Taylor data, filled by ensureTaylor() (mutable: a cache; a Flight is used by one thread)
  mutable bool m_taylorReady = false;
  // d^n u / dt^n at the start, n = 0 .. kTaylorOrder + 1 (the extra one for velocities)
  mutable std::array<Eigen::Vector2d, kTaylorOrder + 2> m_derivatives;
  // interleaved (c_n / n!, c_(n+1) / n!), c_0 = u2 - gap: the Taylor sums of u2 - gap and v2
  mutable std::array<double, 2 * (kTaylorOrder + 1)> m_gapAndRateSeries;
  int m_contactOrder = 0;
  double m_taylorRadius = 0;
  double m_gapAmplitude = 0;
  double m_accelerationBound = 0;
  double m_gapTolerance = 0;
};

}  // namespace grazelab::core
