// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Template definitions for core/roots.h (included from it).
#pragma once

#include <cmath>
#include <utility>

#include "core/scalar.h"

namespace grazelab::core {
namespace roots_detail {

template <typename S>
int signOf(const S& value) {
  return (value > 0) - (value < 0);
}

// (p(x), p'(x)) of a polynomial of degree `degree` (Horner)
template <typename S>
std::pair<S, S> evaluate(const S* c, int degree, const S& x) {
  S value = c[degree];
  S slope = 0;
  for (int n = degree - 1; n >= 0; --n) {
    slope = slope * x + value;
    value = value * x + c[n];
  }
  return {value, slope};
}

template <typename S>
void rootsOfDegree(const S* c, int degree, const S& lo, const S& hi, S* out, int& count) {
  while (degree > 0 && c[degree] == 0) --degree;
  if (degree == 0) return;
  if (degree == 1) {
    const S x = -c[0] / c[1];
    if (x >= lo && x <= hi) out[count++] = x;
    return;
  }
  // the critical points split [lo, hi] into monotone pieces
  S derivative[4];
  for (int n = 1; n <= degree; ++n) derivative[n - 1] = S(n) * c[n];
  S breaks[6];
  int criticalCount = 0;
  breaks[0] = lo;
  rootsOfDegree(derivative, degree - 1, lo, hi, breaks + 1, criticalCount);
  int breakCount = criticalCount + 1;
  breaks[breakCount++] = hi;
  auto p = [&](const S& x) { return evaluate(c, degree, x); };
  S previousValue = p(lo).first;
  for (int i = 1; i < breakCount; ++i) {
    const S a = breaks[i - 1];
    const S b = breaks[i];
    const S fa = previousValue;
    const S fb = p(b).first;
    previousValue = fb;
    if (fa == 0) {
      if (count == 0 || out[count - 1] != a) out[count++] = a;
      continue;
    }
    if (fb == 0 || signOf(fa) == signOf(fb)) continue;  // a zero at b is taken by the next piece
    out[count++] = solveBracketed(p, a, b, fa, fb, S(std::numeric_limits<double>::quiet_NaN())).first;
  }
  if (previousValue == 0 && (count == 0 || out[count - 1] != hi)) out[count++] = hi;
}

}  // namespace roots_detail

template <typename S, typename Function>
std::pair<S, S> solveBracketed(const Function& g, S a, S b, S ga, S gb, S guess) {
  using roots_detail::signOf;
  using std::abs;
  using std::max;
  using std::min;
  if (ga == 0) return {a, S(0)};
  if (gb == 0) return {b, S(0)};
  const S eps = epsilon<S>();
  // start from the guess, else the secant point, which is close for a nearly linear bracket
  S x = guess;
  if (!(x > a && x < b)) x = a - ga * (b - a) / (gb - ga);
  if (!(x > a && x < b)) x = (a + b) / S(2);
  S lastValue = abs(ga);
  // Newton is kept only while it shrinks the bracket fast: near a root of high multiplicity
  // (a high-order touch with a tiny push) it creeps, by 2/3 per step; then bisect
  S widthBefore = b - a;
  int slowSteps = 0;
  for (int iteration = 0; iteration < 400; ++iteration) {
    const auto [gx, slope] = g(x);
    lastValue = abs(gx);
    if (gx == 0) return {x, S(0)};
    if (signOf(gx) == signOf(ga)) {
      a = x;
      ga = gx;
    } else {
      b = x;
    }
    const S width = b - a;
    if (width > widthBefore / S(2)) {
      ++slowSteps;
    } else {
      slowSteps = 0;
      widthBefore = width;
    }
    S next = slope != 0 ? S(x - gx / slope) : S(a - S(1));
    if (!(next > a && next < b) || slowSteps >= 3) {
      slowSteps = 0;
      widthBefore = width;
      // bisect; toward an end at exactly zero, bisect the exponent instead, since a root there
      // may be many orders of magnitude smaller than the bracket (a near-grazing impact)
      if (a == 0 || b == 0) {
        using std::ldexp;
        next = ldexp(a == 0 ? b : a, -20);
      } else if ((a < 0) == (b < 0) && max(abs(a), abs(b)) > S(1024) * min(abs(a), abs(b))) {
        // a bracket spanning many binades: bisect the exponent (geometric mean)
        using std::sqrt;
        next = (a < 0 ? S(-1) : S(1)) * sqrt(abs(a)) * sqrt(abs(b));
      } else {
        next = (a + b) / S(2);
      }
    }
    if (abs(next - x) <= S(2) * eps * abs(x) || b - a <= S(2) * eps * max(abs(a), abs(b))) {
      return {next, lastValue};
    }
    x = next;
  }
  return {x, lastValue};
}

template <typename S>
IntervalRoots<S> rootsInInterval(const std::array<S, 5>& c, const S& lo, const S& hi) {
  IntervalRoots<S> roots;
  S found[8];
  int count = 0;
  roots_detail::rootsOfDegree(c.data(), 4, lo, hi, found, count);
  for (int i = 0; i < count && roots.count < 4; ++i) roots.values[roots.count++] = found[i];
  return roots;
}

}  // namespace grazelab::core
