// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/experiments/chain_series.cpp: the run of a chain of N masses as the explorer's
// N-mass scenes draw it. Its flights tile the run (they add up to the last contact's time), each
// from the stop of a resonant chain ends by the common period (Theorem 2.3 for N masses), and
// the grid is the run's own closed form (every mass; the stopped mass on the stop at contacts).
#include "core/experiments/chain_series.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/model/chain_design.h"
#include "core/orbits/chain_glo.h"

namespace grazelab::core::experiments {
namespace {

TEST(ChainSeries, FlightsTileTheRunAndStayBelowThePeriod) {
  MassChain chain;
  chain.masses = {1.0, 0.2, 0.05};
  chain.springs = designSprings(chain.masses, 1.0, {3, 2, 1}).designs.at(0).springs;
  ChainState start = chainGloStart(chain, {0.5, 0.3, 0.2}).state;
  start.v[2] -= 0.05;
  const ChainSeriesSpec spec{chain, start, 120, 20.0, 400, 1, TrustMode::Off};
  const ChainSeries series = chainSeries(spec);
  ASSERT_TRUE(series.ratios.commensurate);
  EXPECT_NEAR(series.period, 2 * std::numbers::pi / series.ratios.omega0, 1e-15 * series.period);
  ASSERT_EQ(series.run.contacts, 120);
  ASSERT_EQ(series.flights.size(), 120u);
  double sum = 0;
  for (const ChainFlight& flight : series.flights) {
    sum += flight.duration;
    EXPECT_TRUE(flight.fromStop);  // the GLO start is on the stop
    EXPECT_LE(flight.duration, series.period) << "contact " << flight.contact;
  }
  EXPECT_NEAR(sum, series.run.events.back().t, 1e-9 * sum);
  // the grid: 400 points over [0, 20], mass 1 chosen, every mass kept, at t = 0 the start
  ASSERT_EQ(series.grid.size(), 400u);
  EXPECT_EQ(series.grid.front().u.size(), 3u);
  EXPECT_NEAR(series.grid.front().uChosen, start.u[0], 1e-14);  // (the flight's closed form at 0)
  EXPECT_EQ(series.grid.front().us, chain.gap);
  for (const ChainGridPoint& point : series.grid) {
    EXPECT_LE(point.us, chain.gap * (1 + 1e-12));
    EXPECT_EQ(point.us, point.u[2]);
    EXPECT_EQ(point.uChosen, point.u[0]);
  }
  EXPECT_EQ(series.trust.verdict, Verdict::Unchecked);
}

TEST(ChainSeries, AChainWithNoCommonPeriodHasNoBound) {
  MassChain chain;
  chain.masses.assign(4, 1.0);
  chain.springs.assign(4, 1.0);
  chain.stopMass = 2;
  std::vector<double> weights(4, 0.0);
  weights.back() = 1;
  ChainState start = chainGloStart(chain, weights).state;
  start.v[1] -= 1e-3;
  const ChainSeries series = chainSeries({chain, start, 30, 0, 0, 0, TrustMode::Auto});
  EXPECT_FALSE(series.ratios.commensurate);
  EXPECT_EQ(series.period, 0);
  EXPECT_EQ(series.run.contacts, 30);
  EXPECT_TRUE(series.grid.empty());
  EXPECT_NE(series.trust.verdict, Verdict::Unchecked);  // the estimate asked for is made
}

// A run that meets no contact within its search (no common period, pushed off the stop: the
// next approach stays below it for 1000 slowest periods) still draws its motion: the flight is
// contact-free as far as the search went, so the grid covers the window. And `free`: the linear
// motion alone, through the stop (a GLO outside its grazing set passes it).
TEST(ChainSeries, ARunWithoutContactsStillDrawsItsMotionAndFreeIgnoresTheStop) {
  MassChain chain;
  chain.masses = {1.0, 0.2, 0.05, 0.05};
  chain.springs = {1.0, 1.0, 1.0, 1.0};
  ChainState start = chainGloStart(chain, {0.25, 0.25, 0.25, 0.25}).state;
  start.v[3] -= 0.05;
  const ChainSeriesSpec spec{chain, start, 5, 30.0, 300, 0, TrustMode::Off};
  const ChainSeries series = chainSeries(spec);
  ASSERT_EQ(series.run.stop, ChainStop::SearchBudget);
  EXPECT_EQ(series.run.contacts, 0);
  ASSERT_EQ(series.grid.size(), 300u);
  EXPECT_EQ(series.grid.back().t, 30.0);
  for (const ChainGridPoint& point : series.grid) EXPECT_LT(point.us, chain.gap) << point.t;

  MassChain resonant;
  resonant.masses = {1.0, 0.2, 0.05};
  resonant.springs = designSprings(resonant.masses, 1.0, {3, 2, 1}).designs.at(0).springs;
  const ChainState outside = chainGloStart(resonant, {-0.4, 1.2, 0.2}).state;
  ChainSeriesSpec free{resonant, outside, 1, 8.0, 400, 0, TrustMode::Off};
  free.free = true;
  const ChainSeries linear = chainSeries(free);
  EXPECT_TRUE(linear.run.events.empty());
  ASSERT_EQ(linear.grid.size(), 400u);
  double top = 0;
  for (const ChainGridPoint& point : linear.grid) top = std::max(top, point.us);
  EXPECT_GT(top, 1.2 * resonant.gap);  // through the stop, as the closed form has it
  const ChainSeries stopped = chainSeries(ChainSeriesSpec{resonant, outside, 1, 8.0, 400, 0, TrustMode::Off});
  for (const ChainGridPoint& point : stopped.grid) EXPECT_LE(point.us, resonant.gap * (1 + 1e-12));
}

}  // namespace
}  // namespace grazelab::core::experiments
