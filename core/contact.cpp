// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/contact.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/polynomial.h"

namespace grazelab::core {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// critical points closer than this fraction of T2 to a start repeat are not resolvable in the
// time variable; the reduced gap handles those windows instead
constexpr double kEndWindow = 1e-9;

// g(x) = (u2(x) - gap) / x^m on a time axis anchored at the start (or at T2, x <= 0)
struct Scaled {
  const Flight& flight;
  int order;
  std::pair<double, double> operator()(double x) const {
    return flight.reducedGapAndRate(x, order);
  }
};

int signOf(double value) { return (value > 0) - (value < 0); }

// A root and |g| at the last iterate evaluated next to it.
struct Root {
  double x;
  double residual;
};

// Safeguarded Newton for a root of g in [a, b], given g(a) and g(b) of opposite signs (or zero).
// `guess` (if inside the bracket) replaces the secant point as the first iterate.
template <typename Function>
Root solveBracketed(const Function& g, double a, double b, double ga, double gb,
                    double guess = std::numeric_limits<double>::quiet_NaN()) {
  if (ga == 0) return {a, 0.0};
  if (gb == 0) return {b, 0.0};
  assert(signOf(ga) != signOf(gb));
  // start from the guess, else the secant point, which is close for a nearly linear bracket
  double x = guess;
  if (!(x > a && x < b)) x = a - ga * (b - a) / (gb - ga);
  if (!(x > a && x < b)) x = 0.5 * (a + b);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const auto [gx, slope] = g(x);
    if (gx == 0) return {x, 0.0};
    if (signOf(gx) == signOf(ga)) {
      a = x;
      ga = gx;
    } else {
      b = x;
    }
    const double newton = slope != 0 ? x - gx / slope : std::numeric_limits<double>::quiet_NaN();
    double next = newton;
    if (!(newton > a && newton < b)) {
      // bisect; toward an end at exactly zero, bisect the exponent instead, since a root there
      // may be many orders of magnitude smaller than the bracket (a near-grazing impact)
      if (a == 0 || b == 0) {
        next = (a == 0 ? b : a) * 0x1p-20;
      } else {
        next = 0.5 * (a + b);
      }
    }
    const double width = b - a;
    if (std::abs(next - x) <= 2 * kEpsilon * std::abs(x) ||
        width <= 2 * kEpsilon * std::max(std::abs(a), std::abs(b))) {
      return {next, std::abs(gx)};
    }
    x = next;
  }
  return {x, std::abs(g(x).first)};
}

Contact tangentAt(const Flight& flight, FlightTime time) {
  return {ContactKind::Tangent, time, std::abs(flight.gap(time.offset))};
}

// a crossing found as a root of g(x) = (u2 - gap) / x^order
Contact crossingAt(const Root& root, int order, bool fromReturn) {
  const double scale = order == 0 ? 1.0 : std::pow(std::abs(root.x), order);
  return {ContactKind::Crossing, {root.x, fromReturn}, root.residual * scale};
}

// the crossing inside the segment (a, b) of the time axis, where u2 - gap goes from negative to
// positive; `order` > 0 only for the segment that starts at the start of the flight (its m-fold
// zero there is divided out). Other segments ending past T2/2 are solved as offsets from T2 for
// a resonant flight, so that a crossing just before the return keeps its relative precision.
Contact solveSegment(const Flight& flight, double a, const CriticalPoint& end, double fa,
                     int order) {
  const double b = end.time;
  const double fb = end.gap;
  const double T2 = flight.modes().T2;
  const bool fromReturn = flight.modes().resonant && order == 0 && b > 0.5 * T2;
  const double anchor = fromReturn ? T2 : 0.0;
  const double xa = a - anchor;  // exact (Sterbenz) for the cases used
  const double xb = b - anchor;
  const Scaled g{flight, order};
  // values at the ends are known from the walk; the start's m-fold zero is divided out
  const double ga = order == 0 ? fa : g(xa).first;
  const double gb = order == 0 ? fb : fb / std::pow(xb, order);
  if (signOf(ga) == signOf(gb) && ga != 0 && gb != 0) {
    // the sign change was decided from f; with the m-fold zero removed it must survive
    return tangentAt(flight, {fromReturn ? xb : b, fromReturn});
  }
  // a segment that ends at a local maximum above the stop: the parabola through that maximum
  // puts the crossing close to b - sqrt(2 f(b) / |f''(b)|), where Newton's slope is not small
  double guess = std::numeric_limits<double>::quiet_NaN();
  if (order == 0 && end.acceleration < 0) guess = xb - std::sqrt(2.0 * gb / -end.acceleration);
  return crossingAt(solveBracketed(g, xa, xb, ga, gb, guess), order, fromReturn);
}

Contact nextContactResonant(const Flight& flight) {
  const double T2 = flight.modes().T2;
  const int order = flight.contactOrder();
  const double tolerance = flight.gapTolerance();

  const CriticalPoints critical = criticalPointsResonant(flight);
  if (critical.empty() && order > 0) {
    // cannot happen for a motion that leaves the stop (it has a lowest point before T2)
    return {ContactKind::Tangent, {0.0, true}, 0.0};
  }
  double previous = 0;
  double previousValue = flight.gapDerivative(0);  // u2 - gap at the start
  for (const CriticalPoint& point : critical) {
    // near the start or the return the gap is evaluated from its Taylor series, to relative
    // precision; elsewhere values within rounding of zero are indistinguishable from a touch
    const double reduced = point.time < 0.5 * T2 ? point.time : point.time - T2;
    const double band = std::abs(reduced) <= flight.taylorRadius() ? 0.0 : tolerance;
    if (point.gap > band) {
      return solveSegment(flight, previous, point, previousValue, previous == 0 ? order : 0);
    }
    if (point.gap >= -band && point.acceleration <= 0) {
      return {ContactKind::Tangent, {point.time, false}, std::abs(point.gap)};
    }
    previous = point.time;
    previousValue = point.gap;
  }

  if (order == 0) return {};  // below the stop at T2 as at 0: the periodic motion never touches

  // last segment (previous, T2]: u2 - gap = s^m g(s) with s = t - T2, so its sign just before the
  // return is (-1)^m sign(g(0)); a change of sign of g inside means a crossing before T2
  const Scaled g{flight, order};
  const double start = previous - T2;
  const double gStart = previousValue / std::pow(start, order);
  const double gReturn = g(0.0).first;
  if (signOf(gStart) != signOf(gReturn)) {
    return crossingAt(solveBracketed(g, start, 0.0, gStart, gReturn), order, true);
  }
  // no crossing: the flight comes back tangentially exactly at T2 (a grazing linear orbit)
  return {ContactKind::Tangent, {0.0, true}, 0.0};
}

Contact nextContactDetuned(const Flight& flight, double horizon) {
  const int order = flight.contactOrder();
  const double tolerance = flight.gapTolerance();
  const double bound = flight.accelerationBound();
  const Scaled scaled{flight, order};

  double t = 0;
  if (order > 0) {
    // inside the Taylor window the gap is s^m g(s): look for a sign change of g there
    const double window = std::min(flight.taylorRadius(), horizon);
    const double gStart = scaled(0.0).first;
    const double gEnd = scaled(window).first;
    if (signOf(gEnd) != signOf(gStart)) {
      return crossingAt(solveBracketed(scaled, 0.0, window, gStart, gEnd), order, false);
    }
    t = window;
  }

  // a chain at rest stays where it is: below the stop, it never arrives
  if (!(bound > 0)) return {};

  const Scaled plain{flight, 0};
  double previous = t;
  for (long step = 0; step < 100'000'000 && t <= horizon; ++step) {
    const auto [value, rate] = flight.gapAndRate(t);
    if (value > 0) {
      // the march never steps over a contact, so the crossing lies after the previous point
      return crossingAt(solveBracketed(plain, previous, t, plain(previous).first, value), 0, false);
    }
    if (value >= -tolerance) {
      // within rounding of the stop: first try a crossing just ahead...
      if (rate > 0) {
        const double ahead = t + 2.0 * (tolerance - value) / rate;
        const double valueAhead = flight.gap(ahead);
        if (valueAhead > 0) {
          return crossingAt(solveBracketed(plain, t, ahead, value, valueAhead), 0, false);
        }
      }
      // ...else this is a touch from below: find the highest point nearby (Newton on the rate)
      double peak = t;
      for (int iteration = 0; iteration < 20; ++iteration) {
        const double curvature = flight.acceleration2(peak);
        if (!(curvature < 0)) break;
        const double move = -flight.gapAndRate(peak).second / curvature;
        peak += move;
        if (std::abs(move) <= kEpsilon * std::abs(peak)) break;
      }
      if (std::abs(peak - t) < flight.taylorRadius()) {
        const double peakValue = flight.gap(peak);
        if (peakValue > 0 && peak > t) {
          return crossingAt(solveBracketed(plain, t, peak, value, peakValue), 0, false);
        }
        if (peakValue >= -tolerance && peakValue <= tolerance) {
          return tangentAt(flight, {peak, false});
        }
      }
      // clearly below the stop after all: march on
    }
    // the largest step that cannot pass a contact: f + f' h + A h^2 / 2 < 0 for all shorter h
    const double depth = std::max(-value, tolerance);
    const double discriminant = std::sqrt(rate * rate + 2.0 * bound * depth);
    const double safe = rate > 0 ? 2.0 * depth / (rate + discriminant) : (discriminant - rate) / bound;
    previous = t;
    t += safe;
  }
  return {};
}

}  // namespace

CriticalPoints criticalPointsResonant(const Flight& flight) {
  // d/dtheta of alpha1 cos 2th + beta1 sin 2th + alpha2 cos th + beta2 sin th, times
  // (1 + x^2)^2 with x = tan(theta/2), is this quartic in x
  const double a1 = flight.alpha()(0);
  const double b1 = flight.beta()(0);
  const double a2 = flight.alpha()(1);
  const double b2 = flight.beta()(1);
  std::array<double, 5> c = {2 * b1 + b2, -8 * a1 - 2 * a2, -12 * b1, 8 * a1 - 2 * a2,
                             2 * b1 - b2};
  // roots near theta = pi are large in x: solve for y = 1/x = cot(theta/2) when that is better
  const bool reversed = std::abs(c[4]) < std::abs(c[0]);
  if (reversed) std::reverse(c.begin(), c.end());
  const double omega = flight.modes().omegaSlow;
  const double T2 = flight.modes().T2;
  // within the Taylor window of the start or the return, values come from the Taylor form
  const double window = flight.taylorRadius();

  CriticalPoints points;
  auto add = [&](double theta, double sine, double cosineMinusOne) {
    if (theta < 0) theta += kTwoPi;
    const double time = theta / omega;
    if (time <= kEndWindow * T2 || time >= (1.0 - kEndWindow) * T2) return;
    if (time <= window || time >= T2 - window) {
      points.values[points.count++] = {time, flight.gap(time), flight.acceleration2(time)};
      return;
    }
    const auto [gap, acceleration] = flight.gapAndAccelerationAtPhase(sine, cosineMinusOne);
    points.values[points.count++] = {time, gap, acceleration};
  };
  // a negligible leading coefficient (after choosing the better orientation, both ends are
  // negligible) puts a critical point at x = infinity: theta = pi
  double largest = 0;
  for (double value : c) largest = std::max(largest, std::abs(value));
  if (!reversed && std::abs(c[4]) <= 1e-14 * largest) add(std::numbers::pi, 0.0, -2.0);
  // no polishing: a critical time only splits the period into monotone pieces, and the gap is
  // evaluated exactly wherever the split falls (at a maximum, an error d in time changes the
  // value by f'' d^2 / 2 only)
  for (double root : realRootsQuartic(c, false)) {
    if (points.count == 4) break;
    // sin(theta) and cos(theta) - 1 are rational in tan(theta/2) (or its inverse)
    const double denominator = 1.0 + root * root;
    if (reversed) {
      add(2.0 * std::atan2(1.0, root), 2.0 * root / denominator, -2.0 / denominator);
    } else {
      add(2.0 * std::atan(root), 2.0 * root / denominator, -2.0 * root * root / denominator);
    }
  }
  // at most four values: insertion sort
  for (int i = 1; i < points.count; ++i) {
    for (int j = i; j > 0 && points.values[j].time < points.values[j - 1].time; --j) {
      std::swap(points.values[j], points.values[j - 1]);
    }
  }
  return points;
}

Contact nextContact(const Flight& flight, double horizon) {
  return flight.modes().resonant ? nextContactResonant(flight)
                                 : nextContactDetuned(flight, horizon);
}

}  // namespace grazelab::core
