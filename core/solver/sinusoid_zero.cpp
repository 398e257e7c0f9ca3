// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/sinusoid_zero.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace grazelab::core {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// cos x and sin x less their Taylor polynomials of degree below m (m = 0 .. 3): C_m and S_m.
// C_m' = -S_(m-1), S_m' = C_(m-1). Below |x| = 1/2 from their series, so that each keeps its
// relative precision as x -> 0; above, by subtraction (no cancellation there).
struct Remainders {
  double C[4], S[4];
};
Remainders remainders(double x, double c, double s) {
  Remainders r{{c, c - 1, c - 1, c - 1 + x * x / 2}, {s, s, s - x, s - x}};
  if (std::abs(x) < 0.5) {
    // the series in y = x^2 by Horner, to x^17 (the next term is below 2^-60 of x^3 / 3!):
    // C_3 = y^2 sum_m (-1)^m y^(m-2) / (2m)!, S_2 = x y sum_m (-1)^m y^(m-1) / (2m+1)!
    static constexpr double kCos[] = {1.0 / 24,        -1.0 / 720,         1.0 / 40320,         -1.0 / 3628800,
                                      1.0 / 479001600, -1.0 / 87178291200, 1.0 / 20922789888000};
    static constexpr double kSin[] = {-1.0 / 6,         1.0 / 120,            -1.0 / 5040,          1.0 / 362880,
                                      -1.0 / 39916800,  1.0 / 6227020800,     -1.0 / 1307674368000, 1.0 / 355687428096000};
    const double y = x * x;
    double cosine = kCos[6], sine = kSin[7];
    for (int m = 5; m >= 0; --m) cosine = cosine * y + kCos[m];
    for (int m = 6; m >= 0; --m) sine = sine * y + kSin[m];
    r.C[3] = y * y * cosine;
    r.C[1] = r.C[2] = r.C[3] - y / 2;
    r.S[2] = r.S[3] = x * y * sine;
  }
  return r;
}

// bounds of |C_m(x)| and |S_m(x)| for m = 0 .. 3, and the scale their rounding is relative to
struct RemainderScales {
  double of[4];
};
RemainderScales remainderScales(double x) {
  const double ax = std::abs(x);
  if (ax < 0.5) return {{1, ax, ax * ax / 2, ax * ax * ax / 6}};
  return {{2, 2, 2 + ax, 2 + ax + ax * ax / 2}};
}

// f, its first two derivatives with their rounding errors, and bounds of |f'|, |f''|, |f'''|
struct Evaluator {
  const SinusoidSum& sum;
  double period = 0;
  Eigen::VectorXd& amplitude;  // R_j = hypot(a_j, b_j), in a buffer reused by the thread's searches
  double bound2 = 0, bound3 = 0, bound4 = 0;
  double fastest = 0;  // the largest w_j
  int highest = 0;  // the highest harmonic, 0 when evaluated mode by mode
  // the plain sum's rounding bounds of f, f', f'' are linear in |t|: roundings[m] + |t| growth[m]
  // (sum_j w_j^m R_j (2 + 2 n_j) and sum_j w_j^(m+1) R_j), summed once here
  double roundings[4] = {0, 0, 0, 0}, growth[4] = {0, 0, 0, 0};

  Evaluator(const SinusoidSum& f, double periodOfF, Eigen::VectorXd& buffer)
      : sum(f), period(periodOfF), amplitude(buffer) {
    amplitude.resize(f.a.size());
    for (int n : f.harmonics) highest = std::max(highest, n);
    if (highest > 64 || f.harmonics.size() != std::size_t(f.a.size())) highest = 0;
    for (Eigen::Index j = 0; j < f.a.size(); ++j) {
      const double w = f.w[j];
      amplitude[j] = std::sqrt(f.a[j] * f.a[j] + f.b[j] * f.b[j]);
      bound2 += w * w * amplitude[j];
      bound3 += w * w * w * amplitude[j];
      bound4 += w * w * w * w * amplitude[j];
      fastest = std::max(fastest, w);
    }
    for (Eigen::Index j = 0; j < f.a.size(); ++j) {
      const double w = f.w[j];
      const int n = highest > 0 ? f.harmonics[std::size_t(j)] : 0;
      double power = amplitude[j];  // w^m R_j
      for (int m = 0; m < 4; ++m, power *= w) {
        roundings[m] += power * (2 + 2 * n);
        growth[m] += power * w;
      }
    }
  }
  struct Value {
    double f, df, error, dfError;
    double d2f = 0, d2fError = 0;
    double d3f = 0, d3fError = 0;
  };
  Value at(double t) const {
    // a periodic f at the nearest multiple of its period: f(T + tau) = f(tau), and near its
    // return to the start f keeps the precision it has near t = 0
    const double tau = period > 0 && t > period / 2 ? t - period : t;
    // the Taylor form only where it matters: away from 0 (every |w_j tau| >= 1/2) f is of the
    // size of its terms and the plain sum is as precise, and cheaper
    const int k = std::abs(tau) * fastest < 0.5 ? sum.startTerms : 0;
    Value value{k == 0 ? sum.offset : 0.0, 0, 0, 0};
    double size = k == 0 ? std::abs(sum.offset) : 0.0, dSize = 0, d2Size = 0;
    // cos and sin of each mode's angle: directly, or by the recurrence up to the highest harmonic
    double cosines[64], sines[64];
    if (highest > 0) {
      const double c1 = std::cos(sum.omega0 * tau), s1 = std::sin(sum.omega0 * tau);
      double c = c1, s = s1;
      for (int h = 1; h <= highest; ++h) {
        cosines[h - 1] = c;
        sines[h - 1] = s;
        const double next = c * c1 - s * s1;
        s = s * c1 + c * s1;
        c = next;
      }
    }
    for (Eigen::Index j = 0; j < sum.a.size(); ++j) {
      const double w = sum.w[j], a = sum.a[j], b = sum.b[j], x = w * tau;
      const int n = highest > 0 ? sum.harmonics[std::size_t(j)] : 0;
      const double c = n > 0 ? cosines[n - 1] : std::cos(x);
      const double s = n > 0 ? sines[n - 1] : std::sin(x);
      // each product and sum rounds once, the recurrence about twice a harmonic; the argument's
      // rounding (|x| eps) moves a term by that times its derivative
      const double termRoundings = 2 + 2 * n;
      if (k == 0) {
        value.f += a * c + b * s;
        value.df += w * (b * c - a * s);
        value.d2f -= w * w * (a * c + b * s);
        value.d3f += w * w * w * (a * s - b * c);
        continue;  // its rounding bound after the loop
      }
      // f's first k Taylor coefficients at 0 are 0 exactly: f = sum a_j C_k + b_j S_k
      const Remainders r = remainders(x, c, s);
      const int k1 = k - 1, k2 = std::max(k - 2, 0);
      value.f += a * r.C[k] + b * r.S[k];
      value.df += w * (b * r.C[k1] - a * r.S[k1]);
      value.d2f -= w * w * (a * r.C[k2] + b * r.S[k2]);
      value.d3f += w * w * w * (a * s - b * c);  // the Taylor terms below degree 3 add nothing to f'''
      const RemainderScales scale = remainderScales(x);
      const double ax = std::abs(x);
      size += amplitude[j] * (termRoundings * scale.of[k] + ax * scale.of[k1]);
      dSize += w * amplitude[j] * (termRoundings * scale.of[k1] + ax * scale.of[k2]);
      d2Size += w * w * amplitude[j] * (termRoundings * scale.of[k2] + ax * scale.of[std::max(k2 - 1, 0)]);
    }
    if (k == 0) {
      const double at = std::abs(tau);
      size += roundings[0] + at * growth[0];
      dSize += roundings[1] + at * growth[1];
      d2Size += roundings[2] + at * growth[2];
    }
    value.error = 8 * kEps * size;
    value.dfError = 8 * kEps * dSize;
    value.d2fError = 8 * kEps * d2Size;
    value.d3fError = 8 * kEps * (roundings[3] + std::abs(tau) * growth[3]);
    return value;
  }
};

struct Search {
  const Evaluator& f;
  long windows = 0;
  long maxWindows = 0;
  double resolution = 0;  // windows narrower than this are not halved again
  // where f came within rounding of 0 while rising, undecided until f is seen again resolvably
  // above 0 (a crossing there) or below it (a touch there: its top within rounding of 0)
  std::optional<double> pending;

  static int sign(double value, double error) { return value > error ? 1 : value < -error ? -1 : 0; }

  // a unit in the last place of x, or up to twice it (cheaper than nextafter, and only a scale)
  static double ulp(double x) { return std::max(std::abs(x), std::numeric_limits<double>::min()) * kEps; }

  // The crossing of f in (left, right], where f(left) < 0 < f(right) and f is monotone. Newton's
  // method from the secant's guess, kept inside the sign bracket [low, high] (a step that leaves
  // it bisects instead), until its step is within a few ulps of the iterate: that iterate is the
  // crossing to the rounding of f (about 5 evaluations; bisection to adjacent doubles took 50).
  // A bracket that closes first ends it at its upper end, where f >= 0.
  double crossing(double left, double right, double fLeft, double fRight) const {
    double low = left, high = right;
    double t = low - fLeft * (high - low) / (fRight - fLeft);
    if (!(t > low && t < high)) t = low + (high - low) / 2;
    for (int step = 0; step < 100; ++step) {
      const Evaluator::Value v = f.at(t);
      (v.f < 0 ? low : high) = t;
      if (!(high - low > 4 * ulp(high))) break;
      const double next = t - v.f / v.df;
      if (std::abs(next - t) <= 2 * ulp(t)) return std::clamp(next, low, high);
      t = next > low && next < high ? next : low + (high - low) / 2;
    }
    return high;
  }

  // the first zero in (left, right], given f there; windows come from the left, one after the
  // other, so `pending` always refers to a point left of this window
  std::optional<FirstZero> first(double left, double right, double fLeft, double fRight) {
    if (++windows > maxWindows) return FirstZero{ZeroKind::Budget, left};
    const double h = right - left;
    const double middle = left + h / 2;
    const Evaluator::Value m = f.at(middle);
    // Taylor about the middle to third order: f and its first two derivatives are known there,
    // only the third is bounded (by sum w_j^3 R_j)
    const double r = h / 2;
    const double slope = std::abs(m.df) + m.dfError;
    const double curve = std::abs(m.d2f) + m.d2fError;
    // no zero: |f| stays away from 0 over the window
    // and to fourth, f''' evaluated there and only the fourth derivative bounded: whichever is
    // tighter (the fourth order in wide windows, where B3 r^3 dominates)
    const double jerk = std::abs(m.d3f) + m.d3fError;
    const double beyondCurve = std::min(f.bound3 * r * r * r / 6, jerk * r * r * r / 6 + f.bound4 * r * r * r * r / 24);
    if (std::abs(m.f) - m.error > slope * r + curve * r * r / 2 + beyondCurve) {
      if (pending) return FirstZero{m.f > 0 ? ZeroKind::Crossing : ZeroKind::Touch, *pending};
      return std::nullopt;
    }
    // monotone: a zero exactly when f changes sign (f(left) is never one: it was searched)
    if (std::abs(m.df) - m.dfError > curve * r + std::min(f.bound3 * r * r / 2, jerk * r * r / 2 + f.bound4 * r * r * r / 6)) {
      const int signLeft = sign(fLeft, m.error), signRight = sign(fRight, m.error);
      if (m.df < 0) {
        // falling: after a rise to within rounding of 0, a touch; from above 0 (never, for an f
        // that starts below it) the zero was crossed at the left
        if (pending) return FirstZero{ZeroKind::Touch, *pending};
        if (signLeft > 0) return FirstZero{ZeroKind::Crossing, left};
        return std::nullopt;
      }
      if (signRight < 0) {
        if (pending) return FirstZero{ZeroKind::Touch, *pending};
        return std::nullopt;
      }
      if (signRight == 0) {
        if (!pending) pending = right;
        return std::nullopt;
      }
      if (signLeft >= 0) return FirstZero{ZeroKind::Crossing, pending.value_or(left)};
      // from below 0 to above it: the one crossing of the window
      return FirstZero{ZeroKind::Crossing, crossing(left, right, fLeft, fRight)};
    }
    if (h <= resolution) {
      // f and f' both zero within rounding: a touch
      return FirstZero{ZeroKind::Touch, pending.value_or(middle)};
    }
    if (auto found = first(left, middle, fLeft, m.f)) return found;
    return first(middle, right, m.f, fRight);
  }
};

}  // namespace

FirstZero firstZero(const SinusoidSum& sum, double period, double horizon, long maxWindows,
                    std::optional<double> releaseJerk) {
  thread_local Eigen::VectorXd amplitudes;
  const Evaluator f(sum, period, amplitudes);
  const double end = period > 0 ? period : horizon;
  if (!(end > 0)) return {ZeroKind::Budget, 0};
  if (sum.a.size() == 0) {
    // a constant: below 0 forever, or 0 (a touch at the start)
    if (sum.offset < 0) return {period > 0 ? ZeroKind::None : ZeroKind::Budget, end};
    return {ZeroKind::Touch, 0};
  }
  const double fastest = 2 * std::numbers::pi / sum.w.maxCoeff();
  Search search{f, 0, maxWindows, 0, std::nullopt};
  // the fastest mode's period over 2^40: below that a window holds f's zero and critical
  // point within double's resolution of the time
  search.resolution = std::max(end, fastest) * 0x1p-40;
  // f(0) = 0 (on the stop just after an impact, or released at rest) and f leaves it: Taylor's
  // bound keeps f < 0 on (0, t0], with t0 from f'(0) < 0, or from f''(0) < 0 when f'(0) = 0
  Evaluator::Value start = f.at(0);
  double t0 = 0;
  // a periodic f that starts at rest on 0 (f'(0) = 0, f''(0) < 0) is the same on either side of
  // its period's end: the interval Taylor's bound clears after 0 is clear before T as well, and
  // f's return to 0 at T is that start again (searched up to it, a flat return would only halve
  // windows down to the resolution)
  bool flatReturn = false;
  if (releaseJerk) {
    if (!(*releaseJerk < 0) || sum.startTerms != 3) return {ZeroKind::Touch, 0};
    t0 = std::min(2 * std::abs(*releaseJerk) / f.bound4, end / 2);
    start = f.at(t0);
    if (!(start.f < -start.error)) return {ZeroKind::Touch, 0};
  } else if (std::abs(start.f) <= start.error) {
    double d2 = 0;
    for (Eigen::Index j = 0; j < sum.a.size(); ++j) d2 -= sum.w[j] * sum.w[j] * sum.a[j];
    if (start.df < -start.dfError) {
      t0 = std::abs(start.df) / f.bound2;  // f(t) <= f'(0) t + bound2 t^2 / 2 < 0 below 2|f'(0)|/bound2
    } else if (d2 < -8 * kEps * f.bound2 && std::abs(start.df) <= start.dfError) {
      t0 = 1.5 * std::abs(d2) / f.bound3;  // f(t) <= f''(0) t^2 / 2 + bound3 |t|^3 / 6 < 0 below 3|f''(0)|/bound3
      flatReturn = period > 0 && sum.startTerms >= 2;
    } else {
      return {ZeroKind::Touch, 0};  // it does not leave 0
    }
    t0 = std::min(t0, end / 2);
    start = f.at(t0);
    if (!(start.f < -start.error)) return {ZeroKind::Touch, 0};
  }
  // periodic: a whole period at most (f(T) = f(0), so the search sees the return); the halving
  // runs over [t0, end] in pieces a fraction of the fastest period wide, so that a long horizon
  // does not start from one huge window
  const double searchEnd = flatReturn ? end - t0 : end;
  const double piece = std::min(searchEnd - t0, fastest);
  double left = t0;
  double fLeft = start.f;
  while (left < searchEnd) {
    const double right = std::min(searchEnd, left + piece);
    const double fRight = f.at(right).f;
    if (auto found = search.first(left, right, fLeft, fRight)) return *found;
    left = right;
    fLeft = fRight;
  }
  // within rounding of 0 at the very end (a periodic orbit's return at T)
  if (search.pending) return {ZeroKind::Touch, *search.pending};
  if (flatReturn) return {ZeroKind::Touch, end};
  return {period > 0 ? ZeroKind::None : ZeroKind::Budget, end};
}

}  // namespace grazelab::core
