// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/polynomial.cpp.
#include "core/polynomial.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace grazelab::core {
namespace {

std::vector<double> sorted(const RealRoots& roots) {
  std::vector<double> values(roots.begin(), roots.end());
  std::sort(values.begin(), values.end());
  return values;
}

// coefficients (low to high) of lead * prod (x - r_i)
std::array<double, 5> fromRoots(double lead, const std::array<double, 4>& r) {
  std::array<double, 5> c{lead, 0, 0, 0, 0};  // start with the constant polynomial "lead"
  int degree = 0;
  for (double root : r) {
    for (int n = degree + 1; n >= 0; --n) c[n] = (n > 0 ? c[n - 1] : 0) - root * c[n];
    ++degree;
  }
  return c;
}

TEST(Polynomial, QuarticWithFourRealRoots) {
  const auto roots = sorted(realRootsQuartic(fromRoots(2.5, {-3, 0.5, 1, 2})));
  ASSERT_EQ(roots.size(), 4u);
  const double expected[] = {-3, 0.5, 1, 2};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(roots[i], expected[i], 1e-13);
}

TEST(Polynomial, QuarticWithTwoRealRoots) {
  // (x^2 + 1)(x - 1)(x + 4)
  const std::array<double, 5> c = {-4, 3, -3, 3, 1};
  const auto roots = sorted(realRootsQuartic(c));
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_NEAR(roots[0], -4, 1e-13);
  EXPECT_NEAR(roots[1], 1, 1e-13);
}

TEST(Polynomial, QuarticWithNoRealRoot) {
  EXPECT_EQ(realRootsQuartic({2, 0, 3, 0, 1}).count, 0);  // (x^2+1)(x^2+2)
}

TEST(Polynomial, BiquadraticIsSolved) {
  const auto roots = sorted(realRootsQuartic({4, 0, -5, 0, 1}));  // (x^2-1)(x^2-4)
  ASSERT_EQ(roots.size(), 4u);
  EXPECT_NEAR(roots[0], -2, 1e-14);
  EXPECT_NEAR(roots[3], 2, 1e-14);
}

TEST(Polynomial, NegligibleLeadingCoefficientDropsTheDegree) {
  const auto roots = sorted(realRootsQuartic({-6, 11, -6, 1, 1e-300}));  // (x-1)(x-2)(x-3)
  ASSERT_EQ(roots.size(), 3u);
  EXPECT_NEAR(roots[0], 1, 1e-13);
  EXPECT_NEAR(roots[2], 3, 1e-13);
  EXPECT_EQ(realRootsQuadratic(0, 2, -1).count, 1);
}

TEST(Polynomial, QuadraticAvoidsCancellation) {
  // x^2 - 1e9 x + 1: roots 1e9 and 1e-9, the small one lost by the textbook formula
  const auto roots = sorted(realRootsQuadratic(1, -1e9, 1));
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_NEAR(roots[0], 1e-9, 1e-24);
}

TEST(Polynomial, RandomQuarticsWithSeparatedRoots) {
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> uniform(-5, 5);
  for (int trial = 0; trial < 2000; ++trial) {
    std::array<double, 4> r = {uniform(random), uniform(random), uniform(random), uniform(random)};
    std::sort(r.begin(), r.end());
    if (r[1] - r[0] < 0.05 || r[2] - r[1] < 0.05 || r[3] - r[2] < 0.05) continue;
    const auto roots = sorted(realRootsQuartic(fromRoots(uniform(random), r)));
    ASSERT_EQ(roots.size(), 4u) << "trial " << trial;
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(roots[i], r[i], 1e-9) << "trial " << trial;
  }
}

}  // namespace
}  // namespace grazelab::core
