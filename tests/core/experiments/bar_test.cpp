// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
//
// A bar thrown at a wall (docs/model.md section 13): the continuum's numbers, the lumped bar's
// closed forms for one and two masses, its mirror image, its units, binary128, and its approach
// to the continuum as N grows.

#include "core/experiments/bar.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/solver/chain_run.h"

namespace grazelab::core {
namespace {

TEST(Bar, TheContinuumIsTheLiteraturesSteelBar) {
  // E = 210 GPa, rho = 7800 kg/m3, S = 3.14e-4 m2, L = 1 m, v0 = 0.1 m/s: 385.45 us and 1270.8 N
  const BarContinuum continuum = barContinuum(Bar{});
  EXPECT_NEAR(continuum.duration * 1e6, 385.45, 0.005);
  EXPECT_NEAR(continuum.force, 1270.8, 0.05);
  // the impulse is the force over the contact, and the bar's momentum reversed
  EXPECT_NEAR(continuum.impulse, continuum.force * continuum.duration, 1e-12 * continuum.impulse);
  EXPECT_EQ(continuum.rebound, -0.1);
}

TEST(Bar, OneAndTwoMassesAreTheirClosedForms) {
  const Bar bar;
  const BarImpact one = throwBar(bar, 1);
  ASSERT_EQ(one.status, BarStatus::Computed);
  EXPECT_EQ(one.impacts, 1);
  EXPECT_EQ(one.duration, 0);
  EXPECT_DOUBLE_EQ(one.rebound, -bar.speed);
  // two masses: the front one bounces, the spring (k = 2ES/L, masses rho S L / 2) swings the pair
  // through half its period pi / w, w = sqrt(2k/m), and the second impact sends both back at -v0
  const BarImpact two = throwBar(bar, 2);
  ASSERT_EQ(two.status, BarStatus::Computed);
  EXPECT_EQ(two.impacts, 2);
  const double m = bar.density * bar.area * bar.length / 2, k = 2 * bar.youngModulus * bar.area / bar.length;
  const double half = std::numbers::pi / std::sqrt(2 * k / m);
  EXPECT_NEAR(two.duration, half, 1e-12 * half);
  EXPECT_NEAR(two.rebound, -bar.speed, 1e-12 * bar.speed);
  EXPECT_NEAR(two.vibration, 0.0, 1e-12);
  EXPECT_NEAR(two.impulse, 2 * 2 * m * bar.speed, 1e-12 * m * bar.speed);
}

TEST(Bar, ItsMirrorImageAndItsUnitsChangeNothing) {
  // the wall behind mass 1 instead of ahead of mass N: the same chain numbered the other way, so
  // the same impacts; and the bar in other units (E, rho, L, v0 scaled) has the same
  // dimensionless answer: times over 2L/c, velocities over v0, energies over the bar's
  const Bar bar;
  Bar other;
  other.youngModulus = 3.0e6;
  other.density = 1.3;
  other.area = 2.0;
  other.length = 0.07;
  other.speed = 40;
  for (const int n : {5, 17, 40}) {
    const BarImpact ahead = throwBar(bar, n, BarEnd::Last);
    const BarImpact behind = throwBar(bar, n, BarEnd::First);
    const BarImpact scaled = throwBar(other, n);
    ASSERT_EQ(ahead.status, BarStatus::Computed);
    ASSERT_EQ(behind.impacts, ahead.impacts) << n;
    ASSERT_EQ(scaled.impacts, ahead.impacts) << n;
    const double t = barContinuum(bar).duration, tOther = barContinuum(other).duration;
    for (std::size_t i = 0; i < ahead.times.size(); ++i) {
      EXPECT_NEAR(behind.times[i], ahead.times[i], 1e-11 * t) << n << " impact " << i;
      EXPECT_NEAR(scaled.times[i] / tOther, ahead.times[i] / t, 1e-11) << n << " impact " << i;
      EXPECT_NEAR(behind.impulses[i], ahead.impulses[i], 1e-10 * std::abs(ahead.impulses[i]));
    }
    EXPECT_NEAR(scaled.rebound / other.speed, ahead.rebound / bar.speed, 1e-11);
    EXPECT_NEAR(scaled.vibration, ahead.vibration, 1e-10);
    EXPECT_NEAR(behind.vibration, ahead.vibration, 1e-10);
    // the wall's impulse is what the impacts gave
    double sum = 0;
    for (double impulse : ahead.impulses) sum += impulse;
    EXPECT_NEAR(sum, ahead.impulse, 1e-11 * ahead.impulse);
    EXPECT_LT(ahead.energyDrift, 1e-12);
  }
}

TEST(Bar, DoubleIsBinary128ToItsRounding) {
  // the same lumped bar run in binary128 (the chain's numbers as double has them): every impact
  // at the same time to 1e-10 of the contact, the same count
  const Bar bar;
  for (const int n : {3, 12, 25}) {
    const BarImpact impact = throwBar(bar, n);
    const MassChain chain = barChain(bar, n);
    const ChainState start = barStart(bar, n);
    const BasicChainRun<Quad> wide = runChain<Quad>(chainCast<Quad>(chain), BasicChainState<Quad>{start.u.cast<Quad>(), start.v.cast<Quad>()},
                                                    1000, Quad(0));
    ASSERT_EQ(wide.stop, StopReason::NoFurtherContact);
    ASSERT_EQ(long(wide.events.size()), impact.impacts) << n;
    for (std::size_t i = 0; i < wide.events.size(); ++i) {
      EXPECT_NEAR(double(wide.events[i].t), impact.times[i], 1e-10 * barContinuum(bar).duration) << n << " impact " << i;
    }
  }
}

TEST(Bar, ItApproachesTheContinuumAsNGrows) {
  // the rebound goes to -v0 and the vibration left to 0, each error shrinking as N grows, at an
  // order between 0.3 and 1.5 (the lumped front disperses: a slow approach); the contact's duration
  // to within 2 % of 2L/c by N = 100
  const Bar bar;
  const BarContinuum limit = barContinuum(bar);
  double reboundError = 1, vibration = 1;
  std::vector<int> masses = {10, 30, 100};
  std::vector<double> rebounds;
  for (const int n : masses) {
    const BarImpact impact = throwBar(bar, n);
    ASSERT_EQ(impact.status, BarStatus::Computed);
    const double error = std::abs(impact.rebound / limit.rebound - 1);
    EXPECT_LT(error, reboundError) << n;
    EXPECT_LT(impact.vibration, vibration) << n;
    EXPECT_GT(impact.vibration, 0) << n;
    reboundError = error;
    vibration = impact.vibration;
    rebounds.push_back(impact.rebound);
    if (n >= 100) {
      EXPECT_NEAR(impact.duration / limit.duration, 1.0, 0.02);
    }
  }
  const Convergence found = convergence(masses, rebounds, limit.rebound);
  for (double order : found.orders) {
    EXPECT_GT(order, 0.3);
    EXPECT_LT(order, 1.5);
  }
}

TEST(Bar, ConvergenceFindsTheOrderAndTheLimitOfAPowerLaw) {
  // x = 2 + 3 N^-0.7: its orders are 0.7 and its limit is found from the values alone
  const std::vector<int> masses = {10, 35, 100, 400};
  std::vector<double> values;
  for (int n : masses) values.push_back(2 + 3 * std::pow(double(n), -0.7));
  const Convergence found = convergence(masses, values, 2.0);
  ASSERT_EQ(found.orders.size(), 3u);
  for (double order : found.orders) EXPECT_NEAR(order, 0.7, 1e-9);
  ASSERT_TRUE(found.extrapolated);
  EXPECT_NEAR(*found.extrapolated, 2.0, 1e-9);
  EXPECT_NEAR(*found.extrapolatedOrder, 0.7, 1e-7);
  // differences of both signs: no extrapolation claimed
  const Convergence wobbling = convergence({10, 20, 40}, {1.1, 0.95, 1.02}, 1.0);
  EXPECT_FALSE(wobbling.extrapolated);
}

}  // namespace
}  // namespace grazelab::core
