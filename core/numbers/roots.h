// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <array>
#include <cmath>

namespace grazelab::core {

/// Real roots of a polynomial found in an interval, ascending.
template <typename S>
struct IntervalRoots {
  std::array<S, 4> values{};
  int count = 0;

  const S* begin() const { return values.data(); }
  const S* end() const { return values.data() + count; }
};

/// Every root of c[4] x^4 + c[3] x^3 + c[2] x^2 + c[1] x + c[0] in [lo, hi] at which the
/// polynomial changes sign (or vanishes at an end), ascending.
///
/// Root isolation by derivatives: the roots of p' split [lo, hi] into pieces on which p is
/// monotone, so every sign change of p is bracketed by a piece and none can be missed (unlike a
/// closed form such as Ferrari's, whose resolvent loses all four roots when it degenerates).
/// The split points come in closed form (they only need to separate); each bracket is then
/// solved by safeguarded Newton from the parabola at its flat end. A double root without sign change (an
/// inflection of the function whose critical points these are) is not reported.
template <typename S>
IntervalRoots<S> rootsInInterval(const std::array<S, 5>& c, const S& lo, const S& hi);

/// The stationary points of c[4] x^4 + ... + c[0] (any leading coefficients may be 0) in
/// [lo, hi], ascending: they split it into pieces on which the polynomial is monotone. Closed
/// form for a cubic derivative (Viete / Cardano and one Newton step), isolation below.
template <typename S>
IntervalRoots<S> stationaryPointsInInterval(const std::array<S, 5>& c, const S& lo, const S& hi);

/// p(x), p'(x) and p''(x) of a polynomial of degree <= 4.
template <typename S>
struct PolynomialJet {
  S value;      ///< 0 when within one rounding of the evaluation (sum |c_i x^i| eps)
  S slope;
  S curvature;
};
template <typename S>
PolynomialJet<S> evaluateQuartic(const std::array<S, 5>& c, const S& x);

/// The root of a polynomial of degree <= 4 in a piece [a, b] on which it is monotone, given
/// p(a), p(b) of opposite signs (or zero). An end flagged flat is a stationary point: the first
/// iterate then comes from the parabola there, unless `guess` lies inside (a, b). Returns the
/// root and |p| at the last iterate.
template <typename S>
std::pair<S, S> rootInMonotonePiece(const std::array<S, 5>& c, const S& a, const S& b,
                                    const S& pa, const S& pb, bool aFlat, bool bFlat, S guess);

/// Safeguarded Newton for a root of g in [a, b], given g(a), g(b) of opposite signs (or zero);
/// g returns (value, derivative). `guess` inside (a, b) is the first iterate. Returns the root
/// and |g| at the last iterate.
template <typename S, typename Function>
std::pair<S, S> solveBracketed(const Function& g, S a, S b, S ga, S gb, S guess);

/// The boundary between `inside` and not inside in [a, b], where `inside(a)` holds and
/// `inside(b)` does not (a may be above b): bisection down to the last bit of S, to a bracket
/// of `tolerance`, or until `stopped()`. Returns the last point found inside (a when none
/// nearer was). The one bisection of the core: `inside` may keep what it found at a point.
template <typename S, typename Inside, typename Stopped>
S bisectBoundary(S a, S b, const Inside& inside, const Stopped& stopped, const S& tolerance = S(0)) {
  using std::abs;
  for (int step = 0; step < 20000; ++step) {
    if (abs(a - b) <= tolerance) break;
    const S middle = (a + b) / S(2);
    if (middle == a || middle == b || stopped()) break;
    if (inside(middle)) a = middle;
    else b = middle;
  }
  return a;
}

}  // namespace grazelab::core

#include "core/numbers/roots_impl.h"
