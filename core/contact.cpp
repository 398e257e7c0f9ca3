// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/contact.h"

#include <algorithm>
#include <cmath>

#include "core/roots.h"

namespace grazelab::core {
namespace {

// critical points closer than this to a start repeat are not resolvable in the time variable
// (a double root of the gap at the start shows up there); the reduced gap handles those windows
template <typename S>
S endWindow() {
  if constexpr (std::is_same_v<S, double>) return S(1e-9) * twoPi<S>();
  if constexpr (std::is_same_v<S, long double>) return S(1e-11L) * twoPi<S>();
  return S(1e-18) * twoPi<S>();
}

template <typename S>
int signOf(const S& value) {
  return (value > 0) - (value < 0);
}

// g(s) = (x2 - delta) / s^m at offsets from one anchor
template <typename S>
struct Reduced {
  const Flight<S>& flight;
  long long anchor;
  int order;
  std::pair<S, S> operator()(const S& s) const {
    return flight.reducedGapAndRate(anchor, s, order);
  }
};

template <typename S>
Contact<S> tangentAt(const Flight<S>& flight, const FlightTime<S>& time, bool undecided) {
  using std::abs;
  return {ContactKind::Tangent, time, abs(flight.gapAndRate(time).first), undecided};
}

// a crossing found as a root of g(s) = (x2 - delta) / s^order
template <typename S>
Contact<S> crossingAt(const std::pair<S, S>& root, int order, long long anchor) {
  using std::abs;
  S scale = 1;
  for (int i = 0; i < order; ++i) scale *= abs(root.first);
  return {ContactKind::Crossing, {anchor, root.first}, root.second * scale, false};
}

// the crossing inside (a, b) where the gap goes from negative to positive; `order` > 0 only for
// the segment that starts at the start of the flight (its m-fold zero is divided out). A segment
// ending in the second half of the period is solved as an offset from 2 pi, so that a crossing
// just before the return keeps its relative precision.
template <typename S>
Contact<S> solveSegment(const Flight<S>& flight, const S& a, const CriticalPoint<S>& end,
                        const S& fa, int order) {
  using std::sqrt;
  const S& b = end.time;
  const S& fb = end.gap;
  const bool fromReturn = order == 0 && b > pi<S>();
  const long long anchor = fromReturn ? 1 : 0;
  const S shift = fromReturn ? twoPi<S>() : S(0);
  const S xa = a - shift;
  const S xb = b - shift;
  const Reduced<S> g{flight, anchor, order};
  S power = 1;
  for (int i = 0; i < order; ++i) power *= xb;
  const S ga = order == 0 ? fa : g(xa).first;
  const S gb = order == 0 ? fb : fb / power;
  if (signOf(ga) == signOf(gb) && ga != 0 && gb != 0) {
    // the sign change was decided from the gap; with the m-fold zero removed it must survive
    return tangentAt(flight, FlightTime<S>{anchor, xb}, true);
  }
  // a segment ending at a local maximum above the stop: the parabola through that maximum puts
  // the crossing close to b - sqrt(2 f(b) / |f''(b)|), where Newton's slope is not small
  S guess = S(std::numeric_limits<double>::quiet_NaN());
  if (order == 0 && end.acceleration < 0) guess = xb - sqrt(S(2) * gb / -end.acceleration);
  return crossingAt(solveBracketed(g, xa, xb, ga, gb, guess), order, anchor);
}

template <typename S>
Contact<S> nextContactResonant(const Flight<S>& flight) {
  using std::abs;
  using std::pow;
  const int order = flight.contactOrder();
  const S tolerance = flight.gapTolerance();

  const CriticalPoints<S> critical = criticalPointsResonant(flight);
  if (critical.empty() && order > 0) {
    // cannot happen for a motion that leaves the stop (it has a lowest point before 2 pi)
    return {ContactKind::Tangent, {1, S(0)}, S(0), true};
  }
  S previous = 0;
  S previousValue = flight.gapDerivative(0);
  for (const CriticalPoint<S>& point : critical) {
    // near the start or the return the gap comes from its Taylor series, to relative
    // precision; elsewhere values within rounding of zero are indistinguishable from a touch
    const S reduced = point.time < pi<S>() ? point.time : S(point.time - twoPi<S>());
    const S band = abs(reduced) <= flight.taylorRadius() ? S(0) : tolerance;
    if (point.gap > band) {
      return solveSegment(flight, previous, point, previousValue, previous == 0 ? order : 0);
    }
    if (point.gap >= -band && point.acceleration <= 0) {
      const FlightTime<S> time = point.time < pi<S>()
                                     ? FlightTime<S>{0, point.time}
                                     : FlightTime<S>{1, S(point.time - twoPi<S>())};
      return tangentAt(flight, time, band > 0);
    }
    previous = point.time;
    previousValue = point.gap;
  }

  if (order == 0) return {};  // below the stop at 2 pi as at 0: the periodic motion never touches

  // last segment (previous, 2 pi]: the gap is s^m g(s) with s = tau - 2 pi, so its sign just
  // before the return is (-1)^m sign(g(0)); a change of sign of g inside means a crossing
  const Reduced<S> g{flight, 1, order};
  const S start = previous - twoPi<S>();
  S power = 1;
  for (int i = 0; i < order; ++i) power *= start;
  const S gStart = previousValue / power;
  const S gReturn = g(S(0)).first;
  if (signOf(gStart) != signOf(gReturn)) {
    return crossingAt(solveBracketed(g, start, S(0), gStart, gReturn,
                                     S(std::numeric_limits<double>::quiet_NaN())),
                      order, 1);
  }
  // no crossing: the flight comes back tangentially exactly at 2 pi (a grazing linear orbit)
  return {ContactKind::Tangent, {1, S(0)}, S(0), false};
}

// a point of the detuned march: the time as (anchor, offset), offset in [-pi, pi]
template <typename S>
struct MarchPoint {
  long long anchor = 0;
  S offset = 0;
};

template <typename S>
Contact<S> nextContactDetuned(const Flight<S>& flight, const S& horizon, std::stop_token stop) {
  using std::abs;
  using std::max;
  using std::min;
  using std::sqrt;
  const int order = flight.contactOrder();
  const S tolerance = flight.gapTolerance();
  const S bound = flight.accelerationBound();
  const S window = flight.taylorRadius();
  const S eps = epsilon<S>();

  MarchPoint<S> point;
  if (order > 0) {
    // inside the Taylor window the gap is s^m g(s): look for a sign change of g there
    const S end = min(window, horizon);
    const Reduced<S> reduced{flight, 0, order};
    const S gStart = reduced(S(0)).first;
    const S gEnd = reduced(end).first;
    if (signOf(gEnd) != signOf(gStart)) {
      return crossingAt(solveBracketed(reduced, S(0), end, gStart, gEnd,
                                       S(std::numeric_limits<double>::quiet_NaN())),
                        order, 0);
    }
    point.offset = end;
  }
  // a chain at rest stays where it is: below the stop, it never arrives
  if (!(bound > 0)) return {};

  auto timeOf = [](const MarchPoint<S>& p) { return twoPi<S>() * S(p.anchor) + p.offset; };
  MarchPoint<S> previous = point;
  for (long long step = 0; step < 2'000'000'000LL && timeOf(point) <= horizon; ++step) {
    if ((step & 4095) == 4095 && stop.stop_requested()) return {ContactKind::Cancelled};
    const FlightTime<S> here{point.anchor, point.offset};
    const auto [value, rate] = flight.gapAndRate(here);
    // Taylor values near an anchor are exact to their own rounding; modal ones to `tolerance`
    const bool nearAnchor = abs(point.offset) <= window;
    const S band = nearAnchor ? S(S(16) * eps * (abs(value) + abs(rate * point.offset))) : tolerance;
    const Reduced<S> plain{flight, point.anchor, 0};
    // the previous point in this point's coordinates
    const S previousOffset = previous.offset + twoPi<S>() * S(previous.anchor - point.anchor);
    if (value > 0) {
      // the march never steps over a contact, so the crossing lies after the previous point
      const S previousValue = plain(previousOffset).first;
      if (previousValue <= 0) {
        return crossingAt(solveBracketed(plain, previousOffset, point.offset, previousValue, value,
                                         S(std::numeric_limits<double>::quiet_NaN())),
                          0, point.anchor);
      }
      return tangentAt(flight, here, true);
    }
    if (value >= -band) {
      // within rounding of the stop: first try a crossing just ahead...
      if (rate > 0) {
        const S ahead = point.offset + S(2) * (band - value) / rate;
        const S valueAhead = plain(ahead).first;
        if (valueAhead > 0) {
          return crossingAt(solveBracketed(plain, point.offset, ahead, value, valueAhead,
                                           S(std::numeric_limits<double>::quiet_NaN())),
                            0, point.anchor);
        }
      }
      // ...else this is a touch from below: find the highest point nearby (Newton on the rate)
      S peak = point.offset;
      for (int iteration = 0; iteration < 40; ++iteration) {
        const S curvature = flight.acceleration2({point.anchor, peak});
        if (!(curvature < 0)) break;
        const S move = -flight.gapAndRate({point.anchor, peak}).second / curvature;
        peak += move;
        if (abs(move) <= eps * max(abs(peak), window)) break;
      }
      if (abs(peak - point.offset) < window) {
        const S peakValue = plain(peak).first;
        if (peakValue > 0 && peak > point.offset) {
          return crossingAt(solveBracketed(plain, point.offset, peak, value, peakValue,
                                           S(std::numeric_limits<double>::quiet_NaN())),
                            0, point.anchor);
        }
        if (peakValue >= -band && peakValue <= band && peak > point.offset - window) {
          return tangentAt(flight, FlightTime<S>{point.anchor, peak}, !nearAnchor);
        }
      }
      // clearly below the stop after all: march on
    }
    // the largest step that cannot pass a contact: f + f' h + A h^2 / 2 < 0 for all shorter h
    const S depth = max(S(-value), band);
    const S discriminant = sqrt(rate * rate + S(2) * bound * depth);
    const S safe = rate > 0 ? S(S(2) * depth / (rate + discriminant))
                            : S((discriminant - rate) / bound);
    previous = point;
    point.offset += safe;
    if (point.offset > pi<S>()) {
      point.anchor += 1;
      point.offset -= twoPi<S>();
    }
  }
  return {};
}

}  // namespace

template <typename S>
CriticalPoints<S> criticalPointsResonant(const Flight<S>& flight) {
  using std::atan;
  using std::atan2;
  using std::abs;
  // d/dtheta of a1 cos 2th + b1 sin 2th + a2 cos th + b2 sin th, times (1 + x^2)^2 with
  // x = tan(theta/2), is this quartic in x
  const S& a1 = flight.cosineCoefficients()[0];
  const S& b1 = flight.sineCoefficients()[0];
  const S& a2 = flight.cosineCoefficients()[1];
  const S& b2 = flight.sineCoefficients()[1];
  const std::array<S, 5> c = {S(2) * b1 + b2, S(-8) * a1 - S(2) * a2, S(-12) * b1,
                              S(8) * a1 - S(2) * a2, S(2) * b1 - b2};
  const std::array<S, 5> reversed = {c[4], c[3], c[2], c[1], c[0]};
  const S window = flight.taylorRadius();
  const S edge = endWindow<S>();

  CriticalPoints<S> points;
  auto add = [&](S theta, const S& sine, const S& cosineMinusOne) {
    if (theta < 0) theta += twoPi<S>();
    if (theta <= edge || theta >= twoPi<S>() - edge || points.count == 4) return;
    if (theta <= window || theta >= twoPi<S>() - window) {
      const FlightTime<S> time = theta < pi<S>() ? FlightTime<S>{0, theta}
                                                 : FlightTime<S>{1, S(theta - twoPi<S>())};
      points.values[points.count++] = {theta, flight.gapAndRate(time).first,
                                       flight.acceleration2(time)};
      return;
    }
    const auto [gap, acceleration] = flight.gapAndAccelerationAtPhase(sine, cosineMinusOne);
    points.values[points.count++] = {theta, gap, acceleration};
  };
  // x = tan(theta/2). A critical time only splits the period into monotone pieces; the gap is
  // then evaluated exactly wherever the split falls.
  auto addFromTangent = [&](const S& x) {
    const S denominator = S(1) + x * x;
    add(S(2) * atan(x), S(2) * x / denominator, S(-2) * x * x / denominator);
  };
  using std::max;
  const S largest = max(max(abs(c[0]), abs(c[1])), max(abs(c[2]), abs(c[3])));
  if (S(15) * abs(c[4]) >= largest) {
    // theta = pi is far from critical: every root lies within Cauchy's bound
    // 1 + max |c_i / c_4| <= 16, and one chart isolates them all
    const S bound = S(1) + largest / abs(c[4]);
    for (const S& x : rootsInInterval(c, -bound, bound)) addFromTangent(x);
  } else {
    // a critical point near theta = pi runs off to infinity in x: two charts on [-1, 1], x for
    // |theta| <= pi/2 and y = cot(theta/2) for the far half
    for (const S& x : rootsInInterval(c, S(-1), S(1))) addFromTangent(x);
    for (const S& y : rootsInInterval(reversed, S(-1), S(1))) {
      if (abs(y) >= 1) continue;  // theta = +-pi/2 belongs to the first chart
      const S denominator = S(1) + y * y;
      add(S(2) * atan2(S(1), y), S(2) * y / denominator, S(-2) / denominator);
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

template <typename S>
Contact<S> nextContact(const Flight<S>& flight, const S& horizon, std::stop_token stop) {
  return flight.chain().resonant ? nextContactResonant(flight)
                                 : nextContactDetuned(flight, horizon, std::move(stop));
}

#define GRAZELAB_INSTANTIATE(S)                                                          \
  template Contact<S> nextContact<S>(const Flight<S>&, const S&, std::stop_token);       \
  template CriticalPoints<S> criticalPointsResonant<S>(const Flight<S>&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
