// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Template definitions for core/numbers/roots.h (included from it).
#pragma once

#include <cmath>
#include <utility>

#include "core/numbers/scalar.h"

namespace grazelab::core {
namespace roots_detail {

template <typename S>
int signOf(const S& value) {
  return (value > 0) - (value < 0);
}

// (p(x), p'(x)) of a polynomial of degree D (Horner). A value below eps sum |c_i x^i|, the size
// of one rounding of the evaluation, is returned as zero: it cannot be told from a root, and
// Newton would otherwise chase rounding noise. (Higham's worst-case bound, 2 D times that, would
// stop early and cost the roots digits.)
template <int D, typename S>
std::pair<S, S> evaluate(const S* c, const S& x) {
  using std::abs;
  S value = c[D];
  S slope = 0;
  S magnitude = abs(c[D]);
  const S size = abs(x);
  for (int n = D - 1; n >= 0; --n) {
    slope = slope * x + value;
    value = value * x + c[n];
    magnitude = magnitude * size + abs(c[n]);
  }
  if (abs(value) <= epsilon<S>() * magnitude) value = 0;
  return {value, slope};
}

// b^2 - 4 a c with the products formed exactly (Kahan): no cancellation near a double root.
// Far from one (the difference above a third of the terms' sum) the plain difference is
// already accurate to an ulp or two and the exact products are skipped (Kahan's own test):
// an fma is a library call on the baseline x86-64, a sixth of a near-grazing run's time.
template <typename S>
S discriminant(const S& a, const S& b, const S& c) {
  using std::abs;
  using std::fma;
  const S square = b * b;
  const S product = S(4) * a * c;
  const S plain = square - product;
  if (S(3) * abs(plain) >= square + abs(product)) return plain;
  const S squareError = fma(b, b, -square);
  const S productError = fma(S(4) * a, c, -product);
  return (square - product) + (squareError - productError);
}

// Split points for a quartic: the real roots of its derivative c[3] x^3 + ... + c[0] in
// [lo, hi], ascending, in closed form (Viete's trigonometric form for three real roots, Cardano
// for one) and one Newton step each. Only monotone pieces depend on them: a split point off by
// rounding moves the quartic's value there by the square of that error, which matters only
// at a double root, where the value is rounding noise anyway.
template <typename S>
void cubicSplitPoints(const S* c, const S& lo, const S& hi, S* out, int& count) {
  using std::abs;
  using std::acos;
  using std::cbrt;
  using std::cos;
  using std::sqrt;
  const S a = c[2] / c[3];
  const S b = c[1] / c[3];
  const S d = c[0] / c[3];
  // x = t - a/3: t^3 + p t + q = 0
  const S shift = a / S(3);
  const S p = b - a * shift;
  const S q = (S(2) * shift * shift - b) * shift + d;
  const S halfQ = q / S(2);
  const S thirdP = p / S(3);
  const S discriminant = halfQ * halfQ + thirdP * thirdP * thirdP;
  S roots[3];
  int n = 0;
  if (discriminant > 0) {
    const S u = cbrt(-halfQ - (halfQ < 0 ? S(-1) : S(1)) * sqrt(discriminant));
    roots[n++] = (u != 0 ? S(u - thirdP / u) : u) - shift;
  } else if (thirdP < 0) {
    const S m = S(2) * sqrt(-thirdP);
    S cosine = S(3) * q / (p * m);
    cosine = cosine > 1 ? S(1) : (cosine < -1 ? S(-1) : cosine);
    const S angle = acos(cosine) / S(3);
    const S third = twoPi<S>() / S(3);
    // ascending: angle + 2pi/3 (smallest cosine), angle - 2pi/3, angle
    roots[n++] = m * cos(angle + third) - shift;
    roots[n++] = m * cos(angle - third) - shift;
    roots[n++] = m * cos(angle) - shift;
  } else {
    roots[n++] = -shift;  // p = q = 0: a triple root
  }
  for (int i = 0; i < n; ++i) {
    const auto [value, slope] = evaluate<3>(c, roots[i]);
    if (slope != 0) roots[i] -= value / slope;
  }
  if (n == 3) {
    if (roots[1] < roots[0]) std::swap(roots[0], roots[1]);
    if (roots[2] < roots[1]) std::swap(roots[1], roots[2]);
    if (roots[1] < roots[0]) std::swap(roots[0], roots[1]);
  }
  for (int i = 0; i < n; ++i) {
    if (roots[i] >= lo && roots[i] <= hi) out[count++] = roots[i];
  }
}

// A first iterate for the root in the monotone piece [a, b] of a polynomial with derivative
// `derivative` (degree D - 1). An end that is a critical point is flat, where Newton from the
// secant point overshoots; from the flatter end, the parabola p(e) + p''(e) (x - e)^2 / 2 puts
// the root close. NaN (use the secant point) when neither end is critical.
template <int D, typename S>
S firstGuess(const S* derivative, const S& a, const S& b, const S& fa, const S& fb,
             bool aCritical, bool bCritical) {
  using std::abs;
  using std::sqrt;
  if (!aCritical && !bCritical) return S(std::numeric_limits<double>::quiet_NaN());
  const bool fromA = aCritical && (!bCritical || abs(fa) <= abs(fb));
  const S& end = fromA ? a : b;
  const S& value = fromA ? fa : fb;
  S curvature = 0;  // p''(end), from the derivative's own slope
  S slopeValue = derivative[D - 1];
  for (int n = D - 2; n >= 0; --n) {
    curvature = curvature * end + slopeValue;
    slopeValue = slopeValue * end + derivative[n];
  }
  const S reach = curvature != 0 ? S(-2) * value / curvature : S(-1);
  if (!(reach > 0)) return S(std::numeric_limits<double>::quiet_NaN());
  return fromA ? S(a + sqrt(reach)) : S(b - sqrt(reach));
}

template <int D, typename S>
void rootsOfDegree(const S* c, const S& lo, const S& hi, S* out, int& count);

// The roots of a degree-D polynomial's derivative (coefficients `derivative`, degree D - 1) in
// [lo, hi], ascending: for a quartic in closed form, else by isolation. The closed form divides
// by the leading coefficient: a small one (a root far outside, near theta = pi in the contact
// search) would leave the others to cancellation, so isolation takes those too.
template <int D, typename S>
void stationaryPoints(const S* derivative, const S& lo, const S& hi, S* out, int& count) {
  if constexpr (D == 4) {
    using std::abs;
    using std::max;
    const S largest = max(max(abs(derivative[0]), abs(derivative[1])), abs(derivative[2]));
    if (S(64) * abs(derivative[3]) >= largest && derivative[3] != 0) {
      return cubicSplitPoints(derivative, lo, hi, out, count);
    }
  }
  rootsOfDegree<D - 1>(derivative, lo, hi, out, count);
}

// Roots of a degree-D polynomial in [lo, hi], appended to out (ascending). Degree 2 in closed
// form (its roots only split the next degree into monotone pieces); higher degrees by root
// isolation between the roots of the derivative.
template <int D, typename S>
void rootsOfDegree(const S* c, const S& lo, const S& hi, S* out, int& count) {
  if constexpr (D == 0) {
    return;
  } else {
    if (c[D] == 0) return rootsOfDegree<D - 1>(c, lo, hi, out, count);
    if constexpr (D == 1) {
      const S x = -c[0] / c[1];
      if (x >= lo && x <= hi) out[count++] = x;
    } else if constexpr (D == 2) {
      const S d = discriminant(c[2], c[1], c[0]);
      if (d < 0) return;
      using std::sqrt;
      const S q = (c[1] < 0 ? sqrt(d) - c[1] : -c[1] - sqrt(d)) / S(2);
      S roots[2] = {q / c[2], q != 0 ? S(c[0] / q) : q / c[2]};
      if (roots[1] < roots[0]) std::swap(roots[0], roots[1]);
      for (const S& x : roots) {
        if (x >= lo && x <= hi) out[count++] = x;
      }
    } else {
      // the critical points split [lo, hi] into monotone pieces
      S derivative[D];
      for (int n = 1; n <= D; ++n) derivative[n - 1] = S(n) * c[n];
      S breaks[D + 1];
      int criticalCount = 0;
      breaks[0] = lo;
      stationaryPoints<D>(derivative, lo, hi, breaks + 1, criticalCount);
      int breakCount = criticalCount + 1;
      breaks[breakCount++] = hi;
      auto p = [c](const S& x) { return evaluate<D>(c, x); };
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
        if (fb == 0 || signOf(fa) == signOf(fb)) continue;  // a zero at b: the next piece's
        out[count++] = solveBracketed(p, a, b, fa, fb, firstGuess<D>(derivative, a, b, fa, fb,
                                                                  i > 1, i < breakCount - 1))
                           .first;
      }
      if (previousValue == 0 && (count == 0 || out[count - 1] != hi)) out[count++] = hi;
    }
  }
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
  // Newton converges quadratically at a simple root: each step is far shorter than the one
  // before. Near a root of high multiplicity (a high-order touch with a tiny push) it creeps,
  // each step 2/3 of the last: after three such steps, bisect.
  S previousStep = b - a;
  S previousNewton = 0;  // the last Newton step (0 after a bisection)
  int creepingSteps = 0;
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
    S next = slope != 0 ? S(x - gx / slope) : S(a - S(1));
    bool newton = next > a && next < b;
    if (newton) {
      const S step = abs(next - x);
      creepingSteps = step > previousStep / S(2) ? creepingSteps + 1 : 0;
      previousStep = step;
      newton = creepingSteps < 3;
    }
    if (!newton) {
      creepingSteps = 0;
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
      previousStep = abs(next - x);
    }
    const S step = abs(next - x);
    if (step <= S(2) * eps * abs(x) || b - a <= S(2) * eps * max(abs(a), abs(b))) {
      return {next, lastValue};
    }
    // quadratic convergence under way (this Newton step far below the last one): the step just
    // taken leaves an error of about step^3 / last^2; below rounding, no need to evaluate again.
    // |g| there is |g(x)| shrunk by the same factor, (step / last)^2.
    if (newton && previousNewton > 0 &&
        step * step * step <= eps * abs(next) * previousNewton * previousNewton) {
      const S shrink = step / previousNewton;
      return {next, lastValue * shrink * shrink};
    }
    previousNewton = newton ? step : S(0);
    x = next;
  }
  return {x, lastValue};
}

template <typename S>
IntervalRoots<S> stationaryPointsInInterval(const std::array<S, 5>& c, const S& lo, const S& hi) {
  const S derivative[4] = {c[1], S(2) * c[2], S(3) * c[3], S(4) * c[4]};
  IntervalRoots<S> points;
  S found[4];
  int count = 0;
  roots_detail::stationaryPoints<4>(derivative, lo, hi, found, count);
  for (int i = 0; i < count; ++i) points.values[points.count++] = found[i];
  return points;
}

template <typename S>
PolynomialJet<S> evaluateQuartic(const std::array<S, 5>& c, const S& x) {
  const auto [value, slope] = roots_detail::evaluate<4>(c.data(), x);
  S curvature = S(12) * c[4];
  for (int n = 3; n >= 2; --n) curvature = curvature * x + S(n * (n - 1)) * c[n];
  return {value, slope, curvature};
}

template <typename S>
std::pair<S, S> rootInMonotonePiece(const std::array<S, 5>& c, const S& a, const S& b,
                                    const S& pa, const S& pb, bool aFlat, bool bFlat, S guess) {
  const S derivative[4] = {c[1], S(2) * c[2], S(3) * c[3], S(4) * c[4]};
  if (!(guess > a && guess < b)) {
    guess = roots_detail::firstGuess<4>(derivative, a, b, pa, pb, aFlat, bFlat);
  }
  auto p = [&c](const S& x) { return roots_detail::evaluate<4>(c.data(), x); };
  return solveBracketed(p, a, b, pa, pb, guess);
}

template <typename S>
IntervalRoots<S> rootsInInterval(const std::array<S, 5>& c, const S& lo, const S& hi) {
  IntervalRoots<S> roots;
  S found[8];
  int count = 0;
  roots_detail::rootsOfDegree<4>(c.data(), lo, hi, found, count);
  for (int i = 0; i < count && roots.count < 4; ++i) roots.values[roots.count++] = found[i];
  return roots;
}

}  // namespace grazelab::core
