// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "core/free_flight.h"
#include "core/polynomial.h"

#include <array>

namespace grazelab::core {

/// How a free flight meets the contact plane H = {u2 = gap}.
enum class ContactKind {
  None,      ///< no contact within the searched time
  Crossing,  ///< u2 - gap changes sign: an impact, arriving with v2 > 0
  Tangent,   ///< u2 reaches the gap with v2 = 0: a grazing touch (double root)
};

/// The first contact of a free flight after its start.
struct Contact {
  ContactKind kind = ContactKind::None;
  FlightTime time;        ///< when, from the start of the flight
  double residual = 0;    ///< |u2 - gap| as evaluated at the returned time
};

/// The first t > 0 with u2(t) = gap (MODEL.md sections 3-4). A flight that starts on the stop
/// must leave it (its first nonzero derivative of u2 - gap is negative).
///
/// Resonant chains: u2(t) - gap is a trigonometric polynomial of degree 2 in theta = w2 t, so its
/// critical points are the real roots of a quartic in tan(theta/2). Between consecutive critical
/// points the gap is monotone: every sign change is bracketed and solved by safeguarded Newton,
/// and a local maximum within rounding of zero is a tangent (grazing) touch, decided there and
/// not by luck. Only one period is searched: the motion repeats after T2, so a flight from the
/// stop is back by T2 (Theorem 2.3), and one from below that stays below never arrives.
/// A crossing in the second half of the period is solved as an offset from T2, so that one a
/// hair before the return keeps its relative precision; for a flight leaving the stop, the
/// zero of order m at the start (and at T2) is divided out first.
///
/// Detuned chains: a march that cannot step over a contact. From a point with u2 - gap = f < 0
/// and rate f', no contact can happen before the positive root h of f + f' h + A h^2 / 2 = 0,
/// A bounding |u2''|; the march stops at `horizon` (time from the start).
Contact nextContact(const Flight& flight, double horizon);

/// A stationary point of u2 - gap of a resonant flight.
struct CriticalPoint {
  double time = 0;          ///< in (0, T2)
  double gap = 0;           ///< u2 - gap there
  double acceleration = 0;  ///< d^2 u2 / dt^2 there: < 0 at a local maximum
};

/// At most four stationary points, ascending in time (a fixed-size list: no allocation).
struct CriticalPoints {
  std::array<CriticalPoint, 4> values;
  int count = 0;

  const CriticalPoint* begin() const { return values.data(); }
  const CriticalPoint* end() const { return values.data() + count; }
  bool empty() const { return count == 0; }
};

/// The stationary points of u2 - gap of a resonant flight in (0, T2), ascending in time.
CriticalPoints criticalPointsResonant(const Flight& flight);

}  // namespace grazelab::core
