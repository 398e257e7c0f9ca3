// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/numbers/roots.h: root isolation in an interval, in every precision.
#include "core/numbers/roots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/numbers/scalar.h"

namespace grazelab::core {
namespace {

// coefficients of prod (x - r_i), times a leading factor
std::array<double, 5> fromRoots(const std::array<double, 4>& r, double leading) {
  std::array<double, 5> c = {leading, 0, 0, 0, 0};  // highest first while building
  int degree = 0;
  for (double root : r) {
    for (int i = degree + 1; i > 0; --i) c[i] = c[i] - root * c[i - 1];
    ++degree;
  }
  return {c[4], c[3], c[2], c[1], c[0]};
}

TEST(Roots, FourSeparatedRootsInTheInterval) {
  const auto c = fromRoots({-0.9, -0.2, 0.3, 0.95}, 2.5);
  const auto roots = rootsInInterval(c, -1.0, 1.0);
  ASSERT_EQ(roots.count, 4);
  const double expected[] = {-0.9, -0.2, 0.3, 0.95};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(roots.values[i], expected[i], 1e-15);
}

TEST(Roots, OnlyRootsInsideTheIntervalAreReported) {
  const auto c = fromRoots({-3.0, -0.5, 0.25, 7.0}, 1.0);
  const auto roots = rootsInInterval(c, -1.0, 1.0);
  ASSERT_EQ(roots.count, 2);
  EXPECT_NEAR(roots.values[0], -0.5, 1e-15);
  EXPECT_NEAR(roots.values[1], 0.25, 1e-15);
}

TEST(Roots, FerrarisDegenerateResolventLosesNothing) {
  // the critical-point quartic of a flight with a tiny gap next to the motion: odd coefficients
  // ~1e-9 of the even ones. Ferrari's resolvent root is then ~1e-19 and rounds to <= 0, which lost
  // all four roots (issue 7, class 1); isolation finds the two real ones
  const std::array<double, 5> c = {-1.4142135623730951, -2e-9, 2.8284271247461903, 1e-9,
                                   0.47140452079103173};
  const auto reversed = std::array<double, 5>{c[4], c[3], c[2], c[1], c[0]};
  const auto near = rootsInInterval(c, -1.0, 1.0);
  const auto far = rootsInInterval(reversed, -1.0, 1.0);
  EXPECT_EQ(near.count + far.count, 2);
  for (double x : near) EXPECT_NEAR(c[0] + x * (c[1] + x * (c[2] + x * (c[3] + x * c[4]))), 0, 1e-14);
}

TEST(Roots, StationaryPointsWithATinyLeadingCoefficient) {
  // p' = (eps x - 1)(x - 0.2)(x + 0.6): a third stationary point at 1/eps, far outside. A closed
  // form for the cubic divides by eps and leaves the two inside to cancellation (~1e-4 at
  // eps = 1e-12, ~1e-8 after a Newton step); they must come out to rounding
  for (double eps : {1e-3, 1e-8, 1e-12, 1e-200}) {
    const std::array<double, 5> c = {1.0, 0.12, (-0.12 * eps - 0.4) / 2, (0.4 * eps - 1) / 3,
                                     eps / 4};
    const auto points = stationaryPointsInInterval(c, -1.0, 1.0);
    ASSERT_EQ(points.count, 2) << eps;
    EXPECT_NEAR(points.values[0], -0.6, 1e-15) << eps;
    EXPECT_NEAR(points.values[1], 0.2, 1e-15) << eps;
  }
}

// b^2 - 4ac to a few ulps of its own size on both sides of Kahan's test (the exact products
// only where the difference cancels): random quadratics near a double root and far from one,
// against binary128, where the products are exact
TEST(Roots, DiscriminantIsAccurateOnBothSidesOfKahansTest) {
  std::mt19937_64 random(20261126);
  std::uniform_real_distribution<double> unit(0.5, 2.0);
  std::uniform_real_distribution<double> closeness(-30.0, 0.0);
  for (int trial = 0; trial < 20000; ++trial) {
    const double b = unit(random) * (trial % 2 == 0 ? 1 : -1);
    // 4ac = b^2 (1 - s), s from 1e-30 to 1: a double root up to well separated roots
    const double s = std::pow(10.0, closeness(random));
    const double a = unit(random);
    const double c = b * b * (1 - s) / (4 * a);
    const Quad exact = Quad(b) * Quad(b) - Quad(4) * Quad(a) * Quad(c);
    const double d = roots_detail::discriminant(a, b, c);
    ASSERT_LE(abs(Quad(d) - exact), Quad(4 * epsilon<double>()) * abs(exact))
        << "a = " << a << ", b = " << b << ", c = " << c;
  }
}

TEST(Roots, RandomQuarticsInEveryPrecision) {
  std::mt19937 random(4);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int trial = 0; trial < 500; ++trial) {
    std::array<double, 4> r;
    for (double& x : r) x = uniform(random);
    std::sort(r.begin(), r.end());
    if (r[1] - r[0] < 1e-3 || r[2] - r[1] < 1e-3 || r[3] - r[2] < 1e-3) continue;
    const auto c = fromRoots(r, 1.0 + uniform(random) * 0.5);
    const auto roots = rootsInInterval(c, -1.0, 1.0);
    ASSERT_EQ(roots.count, 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(roots.values[i], r[i], 1e-11);
    std::array<Quad, 5> wide;
    for (int i = 0; i < 5; ++i) wide[i] = c[i];
    const auto quadRoots = rootsInInterval(wide, Quad(-1), Quad(1));
    ASSERT_EQ(quadRoots.count, 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(toDouble(quadRoots.values[i]), r[i], 1e-11);
  }
}

}  // namespace
}  // namespace grazelab::core
