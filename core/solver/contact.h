// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <array>
#include <stop_token>

#include "core/solver/free_flight.h"

namespace grazelab::core {

/// How a free flight meets the contact plane H = {x2 = delta}.
enum class ContactKind {
  None,       ///< no contact within the searched time
  Crossing,   ///< x2 - delta changes sign: an impact, arriving with y2 > 0
  Tangent,    ///< x2 reaches the stop with y2 = 0: a grazing touch (double root)
  Cancelled,  ///< the stop token ended a long (detuned) search
  Budget,     ///< the detuned search took its budget of steps without deciding; `time` is
              ///< how far it got
};

/// Default budget of a detuned flight's march (steps): about a second of search in each
/// precision (a step costs ~0.1 us in double, 0.4 us in long double, 3.5 us in binary128).
template <typename S>
constexpr std::int64_t defaultSearchSteps() {
  if constexpr (std::is_same_v<S, double>) return 10'000'000;
  if constexpr (std::is_same_v<S, long double>) return 3'000'000;
  return 300'000;
}

/// The first contact of a free flight after its start.
template <typename S>
struct Contact {
  ContactKind kind = ContactKind::None;
  FlightTime<S> time;  ///< when, from the start of the flight (scaled time)
  S residual = 0;      ///< |x2 - delta| as evaluated at (or one Newton step before) the time
  /// True when the decision between a touch and a crossing was within rounding (a maximum of
  /// x2 within the rounding level of the stop): the trust estimate reports such runs.
  bool undecided = false;
};

/// The first tau > 0 with x2(tau) = delta (docs/model.md sections 3-4), in scaled units. A flight
/// that starts on the stop must leave it (its first nonzero derivative of x2 - delta is
/// negative).
///
/// Resonant chains: the real roots of the quartic G below are the contacts. Its stationary
/// points split each chart into pieces on which the gap is monotone (closed form; none can be
/// missed), scanned in time order: the first piece at whose end the gap rises above the stop
/// holds the crossing (safeguarded Newton on G, no trigonometric call), and a maximum within
/// rounding of the stop is a tangent (grazing) touch, decided there and not by luck. One period
/// decides: the motion repeats after 2 pi. Times are kept as offsets from the start or from the
/// return, so a crossing a hair before the return keeps its relative precision.
///
/// Detuned chains: a march that cannot step over a contact. From a point with gap f < 0 and rate
/// f', no contact can happen before the positive root h of f + f' h + A h^2 / 2 = 0, A bounding
/// |x2''|. The march runs in (period, offset) coordinates, so near every near-return it uses the
/// anchored Taylor form with relative precision; it stops at `horizon` (scaled time), after
/// `steps` steps (ContactKind::Budget: undecided, not "no contact") or when `stop` is requested.
template <typename S>
Contact<S> nextContact(const Flight<S>& flight, const S& horizon, const std::stop_token& stop = {},
                       std::int64_t steps = defaultSearchSteps<S>());

/// The gap of a resonant flight as a quartic: with x = tan(theta / 2), theta = tau,
///   (1 + x^2)^2 (x2 - delta) = G(x) = sum_i c_i x^i,
/// exactly, since x2 - delta is a trigonometric polynomial of degree 2. The coefficients come
/// from the gap's derivatives g_n at the start (c0 = g0, c1 = 2 g1, c2 = 2 (g0 + g2), ...), so
/// the low ones are exact and G keeps relative precision near the start and the return
/// (x -> 0 from either side), where the zero of a start on the stop divides out exactly.
template <typename S>
std::array<S, 5> resonantGapPolynomial(const Flight<S>& flight);

/// nextContact for a resonant chain (any horizon: one period decides).
template <typename S>
Contact<S> nextContactResonant(const Flight<S>& flight);

}  // namespace grazelab::core
