// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/contact.h"

#include <algorithm>
#include <cmath>

#include "core/numbers/roots.h"

namespace grazelab::core {
namespace {

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

// a point of the detuned march: the time as (anchor, offset), offset in [-pi, pi]
template <typename S>
struct MarchPoint {
  long long anchor = 0;
  S offset = 0;
};

template <typename S>
Contact<S> nextContactDetuned(const Flight<S>& flight, const S& horizon, const std::stop_token& stop,
                              std::int64_t steps) {
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
  for (std::int64_t step = 0; timeOf(point) <= horizon; ++step) {
    if (step >= steps) return {ContactKind::Budget, {point.anchor, point.offset}, S(0), false};
    if ((step & 4095) == 4095 && stop.stop_requested()) return {ContactKind::Cancelled, {}, S(0), false};
    const FlightTime<S> here{point.anchor, point.offset};
    const auto [value, rate] = flight.gapAndRate(here);
    // Taylor values near an anchor are exact to their own rounding; modal ones to `tolerance`
    const bool nearAnchor = abs(point.offset) <= window;
    const S band = nearAnchor ? S(S(16) * eps * (abs(value) + abs(rate * point.offset))) : tolerance;
    const Reduced<S> plain{flight, point.anchor, 0};
    if (value > 0) {
      // the march never steps over a contact, so the crossing lies after the previous point
      // (taken in this point's coordinates)
      const S previousOffset = previous.offset + twoPi<S>() * S(previous.anchor - point.anchor);
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
        // a flight that leaves the stop has its own zero at s = 0, decided inside the Taylor
        // window by the reduced gap above: a "touch" there is the start, not a contact (with a
        // horizon below the window, 1e-300, it was recorded again and again at t = 0)
        const bool theStart = order > 0 && point.anchor == 0 && peak <= window;
        if (!theStart && peakValue >= -band && peakValue <= band && peak > point.offset - window) {
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
Contact<S> nextContact(const Flight<S>& flight, const S& horizon, const std::stop_token& stop,
                       std::int64_t steps) {
  return flight.chain().resonant ? nextContactResonant(flight)
                                 : nextContactDetuned(flight, horizon, stop, steps);
}

#define GRAZELAB_INSTANTIATE(S) \
  template Contact<S> nextContact<S>(const Flight<S>&, const S&, const std::stop_token&, std::int64_t);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
