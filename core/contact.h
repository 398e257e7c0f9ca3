// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <array>
#include <stop_token>

#include "core/free_flight.h"

namespace grazelab::core {

/// How a free flight meets the contact plane H = {x2 = delta}.
enum class ContactKind {
  None,       ///< no contact within the searched time
  Crossing,   ///< x2 - delta changes sign: an impact, arriving with y2 > 0
  Tangent,    ///< x2 reaches the stop with y2 = 0: a grazing touch (double root)
  Cancelled,  ///< the stop token ended a long (detuned) search
};

/// The first contact of a free flight after its start.
template <typename S>
struct Contact {
  ContactKind kind = ContactKind::None;
  FlightTime<S> time;  ///< when, from the start of the flight (scaled time)
  S residual = 0;      ///< |x2 - delta| as evaluated at the returned time (scaled)
  /// True when the decision between a touch and a crossing was within rounding (a maximum of
  /// x2 within the rounding level of the stop): the trust estimate reports such runs.
  bool undecided = false;
};

/// The first tau > 0 with x2(tau) = delta (MODEL.md sections 3-4), in scaled units. A flight that
/// starts on the stop must leave it (its first nonzero derivative of x2 - delta is negative).
///
/// Resonant chains: x2 - delta is a trigonometric polynomial of degree 2 in theta = tau, so its
/// critical points are the real roots of a quartic in tan(theta/2) (or cot(theta/2) on the far
/// half of the circle), found by root isolation, which cannot miss one. Between consecutive
/// critical points the gap is monotone: every sign change is bracketed and solved by safeguarded
/// Newton, and a local maximum within rounding of zero is a tangent (grazing) touch, decided
/// there and not by luck. One period decides: the motion repeats after 2 pi. A crossing in the
/// second half of the period is solved as an offset from 2 pi; for a flight leaving the stop,
/// the zero of order m at the start (and at 2 pi) is divided out first.
///
/// Detuned chains: a march that cannot step over a contact. From a point with gap f < 0 and rate
/// f', no contact can happen before the positive root h of f + f' h + A h^2 / 2 = 0, A bounding
/// |x2''|. The march runs in (period, offset) coordinates, so near every near-return it uses the
/// anchored Taylor form with relative precision; it stops at `horizon` (scaled time) or when
/// `stop` is requested.
template <typename S>
Contact<S> nextContact(const Flight<S>& flight, const S& horizon, std::stop_token stop = {});

/// A stationary point of x2 - delta of a resonant flight.
template <typename S>
struct CriticalPoint {
  S time = 0;          ///< in (0, 2 pi)
  S gap = 0;           ///< x2 - delta there
  S acceleration = 0;  ///< x2'' there: < 0 at a local maximum
};

/// At most four stationary points, ascending in time (a fixed-size list: no allocation).
template <typename S>
struct CriticalPoints {
  std::array<CriticalPoint<S>, 4> values;
  int count = 0;

  const CriticalPoint<S>* begin() const { return values.data(); }
  const CriticalPoint<S>* end() const { return values.data() + count; }
  bool empty() const { return count == 0; }
};

/// The stationary points of x2 - delta of a resonant flight in (0, 2 pi), ascending in time.
template <typename S>
CriticalPoints<S> criticalPointsResonant(const Flight<S>& flight);

}  // namespace grazelab::core
