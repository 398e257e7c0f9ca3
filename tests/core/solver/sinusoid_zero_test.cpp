// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/solver/sinusoid_zero.cpp, the certified first zero of a sum of sinusoids: no zero
// is missed that a dense scan in long double sees, on sums that come within a hair of 0 again and
// again (a slow mode carrying the motion to the stop, fast ones on top), and a periodic sum whose
// top passes 0 by a hair reaches it.
#include "core/solver/sinusoid_zero.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

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

}  // namespace
}  // namespace grazelab::core
