// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/solver/sinusoid_zero.cpp, the certified first zero of a sum of sinusoids: no zero
// is missed that a dense scan in long double sees, on sums that come within a hair of 0 again and
// again (a slow mode carrying the motion to the stop, fast ones on top), a periodic sum whose
// top passes 0 by a hair reaches it, and so does a long search whose windows turn their phases.
#include "core/solver/sinusoid_zero.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

namespace grazelab::core {
namespace {

// A sum of `n` modes whose top comes within `gap` of 0: a dominant slow mode, fast ones of
// amplitudes `spread` of it, frequencies not commensurate; from the stop (f(0) = 0) when `fromStop`.
template <typename S>
BasicSinusoidSum<S> nearGrazingSum(int n, double gap, double spread, bool fromStop, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  BasicSinusoidSum<S> f;
  f.a.resize(n);
  f.b.resize(n);
  f.w.resize(n);
  double amplitudes = 0;
  for (int j = 0; j < n; ++j) {
    const double w = j == 0 ? 0.2 + 0.1 * unit(random) : 0.5 + 2.5 * unit(random);
    const double amplitude = j == 0 ? 1.0 : spread * unit(random);
    const double phase = 2 * std::numbers::pi * unit(random);
    f.w[j] = S(w);
    f.a[j] = S(amplitude * std::cos(phase));
    f.b[j] = S(amplitude * std::sin(phase));
    amplitudes += amplitude;
  }
  if (fromStop) {
    f.offset = -f.a.sum();
    f.startTerms = 1;
    // leaving the stop downward: f'(0) = sum w_j b_j < 0
    if (f.w.cwiseProduct(f.b).sum() > 0) f.b = -f.b;
  } else {
    f.offset = S(-(amplitudes + gap));
  }
  return f;
}

// f in long double, whatever S it was made in
template <typename S>
long double valueAt(const BasicSinusoidSum<S>& f, long double t) {
  long double value = static_cast<long double>(f.offset);
  for (Eigen::Index j = 0; j < f.a.size(); ++j) {
    const long double x = static_cast<long double>(f.w[j]) * t;
    value += static_cast<long double>(f.a[j]) * std::cos(x) + static_cast<long double>(f.b[j]) * std::sin(x);
  }
  return value;
}

// The top of f over a period: the best of a scan, refined by Newton's method on f' (long double)
long double topOf(const SinusoidSum& f, double period) {
  long double best = 0;
  long double top = -1e300L;
  for (int k = 0; k < 4000; ++k) {
    const long double t = period * k / 4000.0L;
    if (valueAt(f, t) > top) {
      top = valueAt(f, t);
      best = t;
    }
  }
  for (int step = 0; step < 30; ++step) {
    long double d1 = 0, d2 = 0;
    for (Eigen::Index j = 0; j < f.a.size(); ++j) {
      const long double w = f.w[j], x = w * best;
      d1 += w * (f.b[j] * std::cos(x) - f.a[j] * std::sin(x));
      d2 -= w * w * (f.a[j] * std::cos(x) + f.b[j] * std::sin(x));
    }
    if (!(d2 < 0)) break;
    best -= d1 / d2;
  }
  return std::max(top, valueAt(f, best));
}

TEST(SinusoidZero, APeriodicSumWhoseTopPassesZeroByAHairReachesIt) {
  // harmonics of w0 = 0.3: the sum repeats, its top near 0 once a period
  std::mt19937 random(4);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int c = 0; c < 200; ++c) {
    SinusoidSum f;
    const int n = 2 + c % 5;
    f.a.resize(n);
    f.b.resize(n);
    f.w.resize(n);
    f.omega0 = 0.3;
    double amplitudes = 0;
    f.offset = 0;
    for (int j = 0; j < n; ++j) {
      const int harmonic = j + 1 + (j > 0 ? c % 3 : 0);
      f.harmonics.push_back(harmonic);
      f.w[j] = harmonic * f.omega0;
      const double amplitude = j == 0 ? 1.0 : 0.05 * unit(random);
      const double phase = 2 * std::numbers::pi * unit(random);
      f.a[j] = amplitude * std::cos(phase);
      f.b[j] = amplitude * std::sin(phase);
      amplitudes += amplitude;
    }
    // its top (a scan, then Newton's method on f' in long double) below 0 by a hair, or above
    // it by one
    const double period = 2 * std::numbers::pi / f.omega0;
    const long double top = topOf(f, period);
    const double hair = std::pow(10.0, -3.0 - 9.0 * unit(random)) * amplitudes;
    f.offset = double(-(top + (c % 2 == 0 ? hair : -hair)));
    const FirstZero zero = firstZero(f, period, period);
    if (c % 2 == 1) {
      // above 0: reached, at a zero of f
      EXPECT_TRUE(zero.kind == ZeroKind::Crossing || zero.kind == ZeroKind::Touch) << "case " << c;
      EXPECT_LT(std::abs(valueAt(f, zero.t)), 1e-10) << "case " << c;
    } else {
      EXPECT_EQ(zero.kind, ZeroKind::None) << "case " << c << " hair " << hair;  // below 0: never
    }
  }
}

TEST(SinusoidZero, NoZeroIsMissedThatADenseScanSees) {
  // the first sign change a scan finds (f in long double every 1/100 of the fastest period, well
  // above its rounding) is never before the zero the search reports, and the search reports one
  // (the top above 0 by a hair to a tenth of the fast modes' amplitude: reached when the modes
  // line up well enough, after a while)
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int scanned = 0, nearGrazing = 0;
  for (int c = 0; c < 60; ++c) {
    const int n = 2 + c % 7;
    const double spread = std::pow(10.0, -3.0 + 2.0 * unit(random));
    const SinusoidSum f =
        nearGrazingSum<double>(n, -spread * std::pow(10.0, -2.0 * unit(random)), spread, c % 3 == 0, random);
    const double horizon = 30 * 2 * std::numbers::pi / 0.2;
    const FirstZero zero = firstZero(f, 0.0, horizon);
    const double step = 2 * std::numbers::pi / f.w.maxCoeff() / 100;
    // a zero reported is one: f is 0 there within rounding (not an early or invented zero)
    if (zero.kind == ZeroKind::Crossing || zero.kind == ZeroKind::Touch) {
      EXPECT_LT(std::abs(valueAt(f, zero.t)), 1e-10) << "case " << c;
      EXPECT_GT(zero.t, 0.0) << "case " << c;  // (a flight from the stop leaves it downward)
    }
    for (double t = step; t < horizon; t += step) {
      if (valueAt(f, t) > 1e-12) {
        ++scanned;
        nearGrazing += c % 3 != 0;
        ASSERT_TRUE(zero.kind == ZeroKind::Crossing || zero.kind == ZeroKind::Touch) << "case " << c << " t " << t;
        EXPECT_LE(zero.t, t) << "case " << c;
        break;
      }
    }
  }
  EXPECT_GT(scanned, 25);
  EXPECT_GT(nearGrazing, 10);  // (not only the flights from the stop)
}

// The tops of f (its local maxima) over (0, horizon), refined by Newton's method on f' (long
// double), each as (t, f(t)).
template <typename S>
std::vector<std::pair<long double, long double>> topsOf(const BasicSinusoidSum<S>& f, long double horizon) {
  const auto derivative = [&f](long double t, int order) {
    long double value = 0;
    for (Eigen::Index j = 0; j < f.a.size(); ++j) {
      const long double w = static_cast<long double>(f.w[j]), x = w * t;
      const long double a = static_cast<long double>(f.a[j]), b = static_cast<long double>(f.b[j]);
      value += order == 1 ? w * (b * std::cos(x) - a * std::sin(x)) : -w * w * (a * std::cos(x) + b * std::sin(x));
    }
    return value;
  };
  std::vector<std::pair<long double, long double>> tops;
  const long double step = 2 * std::numbers::pi_v<long double> / static_cast<long double>(f.w.maxCoeff()) / 64;
  long double before = derivative(step, 1);
  for (long double t = 2 * step; t < horizon; t += step) {
    const long double now = derivative(t, 1);
    if (before > 0 && now <= 0) {
      long double top = t - step / 2;
      for (int i = 0; i < 40; ++i) top -= derivative(top, 1) / derivative(top, 2);
      if (std::abs(top - t) < 2 * step) tops.emplace_back(top, valueAt(f, top));
    }
    before = now;
  }
  return tops;
}

// Far into a long search (hundreds of pieces, windows halved some 15 times near a top), the
// first top of f that passes 0, by 1e-9 of its size, is reached: the phases turned from window to
// window and from piece to piece (a chain with no common period: sincos only every 17th piece's
// middle, a window's ends and the refinements) clear nothing that holds a zero, and the crossing
// is found where f, evaluated, changes sign.
TEST(SinusoidZero, TurnedPhasesReachATopThatPassesZeroByAHairFarAway) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int reached = 0;
  for (int c = 0; c < 24; ++c) {
    SinusoidSum f = nearGrazingSum<double>(2 + c % 8, 0.0, 0.02 + 0.3 * unit(random), false, random);
    f.offset = 0;
    const double horizon = 60 * 2 * std::numbers::pi / f.w.minCoeff();
    const auto tops = topsOf(f, horizon);
    // the highest top, in the search's second half, and clear of the next highest
    std::vector<std::pair<long double, long double>> sorted = tops;
    std::sort(sorted.begin(), sorted.end(), [](const auto& x, const auto& y) { return x.second > y.second; });
    if (sorted.size() < 2 || sorted[0].first < horizon / 2 || sorted[0].second - sorted[1].second < 1e-6) continue;
    const long double top = sorted[0].first, height = sorted[0].second;
    f.offset = -static_cast<double>(height) + 1e-9 * static_cast<double>(height);  // passes 0 by a hair
    const long double over = valueAt(f, top);
    ASSERT_GT(over, 0.0L) << "case " << c;
    const FirstZero zero = firstZero(f, 0.0, horizon);
    ASSERT_EQ(zero.kind, ZeroKind::Crossing) << "case " << c << " top at " << static_cast<double>(top);
    // the crossing just before that top: f rises through 0 within the width of its excursion
    long double curvature = 0;
    for (Eigen::Index j = 0; j < f.a.size(); ++j) {
      const long double w = f.w[j], x = w * top;
      curvature -= w * w * (f.a[j] * std::cos(x) + f.b[j] * std::sin(x));
    }
    const long double width = std::sqrt(2 * over / -curvature);
    EXPECT_LT(zero.t, top) << "case " << c;
    EXPECT_GT(zero.t, top - 1.5L * width) << "case " << c;
    EXPECT_LT(std::abs(valueAt(f, zero.t)), 1e-12L * height) << "case " << c;
    ++reached;
  }
  EXPECT_GE(reached, 12);
}

}  // namespace
}  // namespace grazelab::core
