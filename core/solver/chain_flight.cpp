// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/chain_flight.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace grazelab::core {

ChainDynamics chainDynamics(const MassChain& chain) {
  const ChainModes modes = chainModes(chain);
  ChainDynamics dynamics;
  dynamics.P = modes.P;
  dynamics.omega = modes.omega;
  dynamics.mass = Eigen::Map<const Eigen::VectorXd>(chain.masses.data(), Eigen::Index(chain.masses.size()));
  dynamics.stop = chain.stopped() - 1;
  dynamics.gap = chain.gap;
  const SpectrumRatios ratios = detectRatios(modes.omega);
  if (ratios.commensurate) {
    for (Eigen::Index j = 0; j < dynamics.omega.size(); ++j) {
      dynamics.omega[j] = ratios.harmonics[std::size_t(j)] * ratios.omega0;
    }
    dynamics.period = 2 * std::numbers::pi / ratios.omega0;
    dynamics.harmonics = ratios.harmonics;
    dynamics.omega0 = ratios.omega0;
  }
  return dynamics;
}

ChainFlight flightFrom(const ChainDynamics& dynamics, const ChainState& start) {
  // P^T M P = I: the modal coordinates are P^T M u
  return {dynamics.P.transpose() * dynamics.mass.cwiseProduct(start.u),
          dynamics.P.transpose() * dynamics.mass.cwiseProduct(start.v)};
}

ChainState stateAt(const ChainDynamics& dynamics, const ChainFlight& flight, double t) {
  const Eigen::Index n = flight.q.size();
  Eigen::VectorXd q(n), qdot(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double w = dynamics.omega[j];
    const double c = std::cos(w * t), s = std::sin(w * t);
    q[j] = flight.q[j] * c + flight.qdot[j] / w * s;
    qdot[j] = -flight.q[j] * w * s + flight.qdot[j] * c;
  }
  return {dynamics.P * q, dynamics.P * qdot};
}

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// f(t) = u_s(t) - d = sum_j (A_j cos w_j t + B_j sin w_j t) - d, its derivatives and bounds
struct StopDistance {
  Eigen::VectorXd a, b, w;
  Eigen::VectorXd amplitude;  // R_j = hypot(A_j, B_j)
  double gap = 0;
  double bound1 = 0, bound2 = 0, bound3 = 0;  // max |f'|, |f''|, |f'''|

  // a commensurate chain: cos and sin of n w0 t from those of w0 t by the angle-addition
  // recurrence (one sincos an evaluation instead of N; each step adds a rounding, counted below)
  std::vector<int> harmonics;
  double omega0 = 0;
  int highest = 0;

  StopDistance(const ChainDynamics& dynamics, const ChainFlight& flight)
      : gap(dynamics.gap), harmonics(dynamics.harmonics), omega0(dynamics.omega0) {
    for (int n : harmonics) highest = std::max(highest, n);
    const Eigen::Index n = flight.q.size();
    a.resize(n), b.resize(n), amplitude.resize(n);
    w = dynamics.omega;
    for (Eigen::Index j = 0; j < n; ++j) {
      const double p = dynamics.P(dynamics.stop, j);
      a[j] = p * flight.q[j];
      b[j] = p * flight.qdot[j] / w[j];
      amplitude[j] = std::hypot(a[j], b[j]);
      bound1 += w[j] * amplitude[j];
      bound2 += w[j] * w[j] * amplitude[j];
      bound3 += w[j] * w[j] * w[j] * amplitude[j];
    }
  }
  struct Value {
    double f, df, error, dfError;
    double d2f = 0, d2fError = 0;
  };
  Value at(double t) const {
    Value value{-gap, 0, 0, 0};
    double size = gap, dSize = 0, d2Size = 0;
    // cos and sin of each mode's angle: directly, or by the recurrence up to the highest harmonic
    double cosines[64], sines[64];
    const bool recur = highest > 0 && highest <= 64;
    if (recur) {
      const double c1 = std::cos(omega0 * t), s1 = std::sin(omega0 * t);
      double c = c1, s = s1;
      for (int k = 1; k <= highest; ++k) {
        cosines[k - 1] = c;
        sines[k - 1] = s;
        const double next = c * c1 - s * s1;
        s = s * c1 + c * s1;
        c = next;
      }
    }
    for (Eigen::Index j = 0; j < a.size(); ++j) {
      const int n = recur ? harmonics[std::size_t(j)] : 0;
      const double c = recur ? cosines[n - 1] : std::cos(w[j] * t);
      const double s = recur ? sines[n - 1] : std::sin(w[j] * t);
      value.f += a[j] * c + b[j] * s;
      value.df += w[j] * (b[j] * c - a[j] * s);
      value.d2f -= w[j] * w[j] * (a[j] * c + b[j] * s);
      // the argument w t is rounded (an error of w t eps moves the term by R w t eps), each
      // product and sum once more; the recurrence adds about 2 roundings a harmonic
      const double rounding = 2 + w[j] * t + 2 * n;
      size += amplitude[j] * rounding;
      dSize += w[j] * amplitude[j] * rounding;
      d2Size += w[j] * w[j] * amplitude[j] * rounding;
    }
    value.error = 8 * kEps * size;
    value.dfError = 8 * kEps * dSize;
    value.d2fError = 8 * kEps * d2Size;
    return value;
  }
};

struct Search {
  const StopDistance& f;
  long windows = 0;
  long maxWindows = 0;
  double resolution = 0;  // windows narrower than this are not halved again
  // where f came within rounding of 0 while rising, undecided until f is seen again resolvably
  // above 0 (a crossing there) or below it (a touch there: its top within rounding of the stop)
  std::optional<double> pending;

  static int sign(double value, double error) { return value > error ? 1 : value < -error ? -1 : 0; }

  // the first zero in (left, right], given f there; windows come from the left, one after the
  // other, so `pending` always refers to a point left of this window
  std::optional<ChainContact> first(double left, double right, double fLeft, double fRight) {
    if (++windows > maxWindows) return ChainContact{ChainContactKind::Budget, left};
    const double h = right - left;
    const double middle = left + h / 2;
    const StopDistance::Value m = f.at(middle);
    // Taylor about the middle to third order: f and its first two derivatives are known there,
    // only the third is bounded (by sum w_j^3 R_j)
    const double r = h / 2;
    const double slope = std::abs(m.df) + m.dfError;
    const double curve = std::abs(m.d2f) + m.d2fError;
    // no zero: |f| stays away from 0 over the window
    if (std::abs(m.f) - m.error > slope * r + curve * r * r / 2 + f.bound3 * r * r * r / 6) {
      if (pending) return ChainContact{m.f > 0 ? ChainContactKind::Impact : ChainContactKind::Touch, *pending};
      return std::nullopt;
    }
    // monotone: a zero exactly when f changes sign (f(left) is never one: it was searched)
    if (std::abs(m.df) - m.dfError > curve * r + f.bound3 * r * r / 2) {
      const int signLeft = sign(fLeft, m.error), signRight = sign(fRight, m.error);
      if (m.df < 0) {
        // falling: after a rise to within rounding of 0, a touch; from above the stop (never,
        // for a flight that starts below it) the stop was crossed at the left
        if (pending) return ChainContact{ChainContactKind::Touch, *pending};
        if (signLeft > 0) return ChainContact{ChainContactKind::Impact, left};
        return std::nullopt;
      }
      if (signRight < 0) {
        if (pending) return ChainContact{ChainContactKind::Touch, *pending};
        return std::nullopt;
      }
      if (signRight == 0) {
        if (!pending) pending = right;
        return std::nullopt;
      }
      if (signLeft >= 0) return ChainContact{ChainContactKind::Impact, pending.value_or(left)};
      // from below the stop to above it: the crossing, by bisection on f's sign
      double low = left, high = right;
      for (int step = 0; step < 200; ++step) {
        const double mid = low + (high - low) / 2;
        if (mid <= low || mid >= high) break;
        (f.at(mid).f < 0 ? low : high) = mid;
      }
      return ChainContact{ChainContactKind::Impact, high};
    }
    if (h <= resolution) {
      // f and f' both zero within rounding: the mass reaches the stop at rest
      return ChainContact{ChainContactKind::Touch, pending.value_or(middle)};
    }
    if (auto found = first(left, middle, fLeft, m.f)) return found;
    return first(middle, right, m.f, fRight);
  }
};

}  // namespace

ChainContact firstContact(const ChainDynamics& dynamics, const ChainFlight& flight, double horizon, long maxWindows) {
  const StopDistance f(dynamics, flight);
  const double end = dynamics.period > 0 ? dynamics.period : horizon;
  if (!(end > 0)) return {ChainContactKind::Budget, 0};
  Search search{f, 0, maxWindows, 0, std::nullopt};
  // the fastest mode's period over 2^40: below that a window holds f's zero and critical
  // point within double's resolution of the time
  search.resolution = std::max(end, 2 * std::numbers::pi / f.w.maxCoeff()) * 0x1p-40;
  // the start: on the stop (just after an impact, or released at rest) f(0) = 0 and the flight
  // leaves it; Taylor's bound keeps f < 0 on (0, t0], with t0 from f'(0) < 0, or from f''(0) < 0
  // when the mass leaves at rest
  StopDistance::Value start = f.at(0);
  double t0 = 0;
  if (std::abs(start.f) <= start.error) {
    double d2 = 0;
    for (Eigen::Index j = 0; j < f.a.size(); ++j) d2 -= f.w[j] * f.w[j] * f.a[j];
    if (start.df < -start.dfError) {
      t0 = std::abs(start.df) / f.bound2;  // f(t) <= f'(0) t + bound2 t^2 / 2 < 0 below 2|f'(0)|/bound2
    } else if (d2 < -8 * kEps * f.bound2 && std::abs(start.df) <= start.dfError) {
      t0 = 1.5 * std::abs(d2) / f.bound3;  // f(t) <= f''(0) t^2 / 2 + bound3 t^3 / 6 < 0 below 3|f''(0)|/bound3
    } else {
      return {ChainContactKind::Touch, 0};  // it does not leave: pressed on the stop
    }
    t0 = std::min(t0, end / 2);
    start = f.at(t0);
    if (!(start.f < -start.error)) return {ChainContactKind::Touch, 0};
  }
  // commensurate: a whole period at most (f(T) = f(0), so the search sees the return); the
  // halving runs over [t0, end] in pieces a fraction of the fastest period wide, so that a
  // long horizon does not start from one huge window
  const double piece = std::min(end - t0, 2 * std::numbers::pi / f.w.maxCoeff());
  double left = t0;
  double fLeft = start.f;
  while (left < end) {
    const double right = std::min(end, left + piece);
    const double fRight = f.at(right).f;
    if (auto found = search.first(left, right, fLeft, fRight)) return *found;
    left = right;
    fLeft = fRight;
  }
  // within rounding of the stop at the very end (a periodic orbit's return at T)
  if (search.pending) return {ChainContactKind::Touch, *search.pending};
  return {dynamics.period > 0 ? ChainContactKind::None : ChainContactKind::Budget, end};
}

}  // namespace grazelab::core
