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
#include <stop_token>
#include <vector>

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
  const ChainSeriesSpec spec{chain, start, 120, 20.0, 400, TrustMode::Off};
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
  // the grid: 400 records of every mass's state over [0, 20], at t = 0 the start
  const StateRecords& grid = series.grid;
  ASSERT_EQ(grid.size(), 400u);
  ASSERT_EQ(grid.masses, 3);
  ASSERT_EQ(grid.values.size(), 400u * 7);
  EXPECT_EQ(grid.t(0), 0.0);
  EXPECT_EQ(grid.t(399), 20.0);
  for (int i = 0; i < 3; ++i) {  // (the flight's closed form at 0)
    EXPECT_NEAR(grid.u(0, i), start.u[i], 1e-14);
    EXPECT_NEAR(grid.v(0, i), start.v[i], 1e-14);
  }
  EXPECT_EQ(grid.u(0, 2), chain.gap);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    EXPECT_LE(grid.u(k, 2), chain.gap * (1 + 1e-12));
    EXPECT_EQ(grid.displacements(k)[2], grid.u(k, 2));
  }
  // each record the run's state: the energy of the start, in flight and at the contacts
  const double level = chainEnergy(chain, start);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    ChainState at{Eigen::VectorXd(3), Eigen::VectorXd(3)};
    for (int i = 0; i < 3; ++i) {
      at.u[i] = grid.u(k, i);
      at.v[i] = grid.v(k, i);
    }
    EXPECT_NEAR(chainEnergy(chain, at), level, 1e-12 * level) << "t = " << grid.t(k);
  }
  EXPECT_EQ(series.trust.verdict, Verdict::Unchecked);
  // the section H: every contact's state, its velocities just before it, in order
  ASSERT_EQ(series.section.size(), 120u);
  std::size_t k = 0;
  for (const ChainEvent& event : series.run.events) {
    if (!isContact(event.type)) continue;
    ASSERT_EQ(series.section.t(k), event.t);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(series.section.u(k, i), event.u[i]);
      EXPECT_EQ(series.section.v(k, i), event.vBefore[i]);
    }
    EXPECT_EQ(series.section.u(k, 2), chain.gap);
    ++k;
  }
}

TEST(ChainSeries, AGloStartGivenByItsWeightsKeepsItsStillModes) {
  // GLOM_2 of a 3:2:1 chain: given by its weights, every contact a grazing after T/2 in double;
  // given as its state alone, double cannot decide its first touch (the still modes' roundings):
  // undecided in every precision, or decided in one where those round to 0 exactly
  MassChain chain;
  chain.masses = {1.0, 0.2, 0.05};
  chain.springs = designSprings(chain.masses, 1.0, {3, 2, 1}).designs.at(0).springs;
  const std::vector<double> weights = {0, 1, 0};
  ChainSeriesSpec spec{chain, chainGloStart(chain, weights).state, 30, 0, 0, TrustMode::Auto};
  spec.gloWeights = weights;
  const ChainSeries series = chainSeries(spec);
  EXPECT_EQ(series.precision, Precision::Double);
  EXPECT_EQ(series.run.grazings, 30);
  ASSERT_EQ(series.flights.size(), 30u);
  for (const ChainFlight& flight : series.flights) EXPECT_NEAR(flight.duration, series.period / 2, 1e-12);
  EXPECT_EQ(series.gloWeights, weights);
  EXPECT_EQ(series.trust.verdict, Verdict::Ok);
  spec.gloWeights.clear();
  const ChainSeries alone = chainSeries(spec);
  EXPECT_NE(alone.precision, Precision::Double);
  if (alone.run.stop == StopReason::Undecided) EXPECT_EQ(alone.run.contacts, 0);
  else EXPECT_EQ(alone.run.grazings, 30);
}

TEST(ChainSeries, AWholeRunGridGoesOnAtTheWindowsStepToTheRunsEndOrItsCap) {
  // the explorer shows a window of the grid at the animation's time, and the whole run on W
  MassChain chain;
  chain.masses = {1.0, 0.2, 0.05};
  chain.springs = designSprings(chain.masses, 1.0, {3, 2, 1}).designs.at(0).springs;
  ChainState start = chainGloStart(chain, {0.5, 0.3, 0.2}).state;
  start.v[2] -= 0.05;
  ChainSeriesSpec spec{chain, start, 60, 20.0, 401, TrustMode::Off};
  const ChainSeries windowOnly = chainSeries(spec);
  spec.maxGridPoints = 1'000'000;
  const ChainSeries whole = chainSeries(spec);
  const double step = 20.0 / 400;
  ASSERT_GT(whole.run.tFinal, 10 * 20.0);
  // to the run's end at the window's step, the window's points the same bits
  ASSERT_EQ(windowOnly.grid.size(), 401u);
  EXPECT_EQ(whole.grid.size(), std::size_t(std::floor(whole.run.tFinal / step)) + 1);
  const std::size_t last = whole.grid.size() - 1;
  EXPECT_LE(whole.grid.t(last), whole.run.tFinal);
  EXPECT_GT(whole.grid.t(last), whole.run.tFinal - step);
  // (every record's numbers: t, u and v)
  ASSERT_GE(whole.grid.values.size(), windowOnly.grid.values.size());
  ASSERT_TRUE(std::equal(windowOnly.grid.values.begin(), windowOnly.grid.values.end(), whole.grid.values.begin()));
  // each point is the run's state then: u_s at the contacts' times is d, in between below it
  const int s = chain.stopped() - 1;
  for (std::size_t k = 0; k <= last; ++k) EXPECT_LE(whole.grid.u(k, s), chain.gap * (1 + 1e-12));
  // and the run itself is the same
  EXPECT_EQ(whole.run.tFinal, windowOnly.run.tFinal);
  // capped: that many points
  spec.maxGridPoints = 1000;
  EXPECT_EQ(chainSeries(spec).grid.size(), 1000u);
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
  const ChainSeries series = chainSeries({chain, start, 30, 0, 0, TrustMode::Auto});
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
  const ChainSeriesSpec spec{chain, start, 5, 30.0, 300, TrustMode::Off};
  const ChainSeries series = chainSeries(spec);
  ASSERT_EQ(series.run.stop, StopReason::SearchBudget);
  EXPECT_EQ(series.run.contacts, 0);
  ASSERT_EQ(series.grid.size(), 300u);
  EXPECT_EQ(series.grid.t(299), 30.0);
  for (std::size_t k = 0; k < 300; ++k) EXPECT_LT(series.grid.u(k, chain.stopped() - 1), chain.gap) << series.grid.t(k);

  MassChain resonant;
  resonant.masses = {1.0, 0.2, 0.05};
  resonant.springs = designSprings(resonant.masses, 1.0, {3, 2, 1}).designs.at(0).springs;
  const ChainState outside = chainGloStart(resonant, {-0.4, 1.2, 0.2}).state;
  ChainSeriesSpec free{resonant, outside, 1, 8.0, 400, TrustMode::Off};
  free.free = true;
  const ChainSeries linear = chainSeries(free);
  EXPECT_TRUE(linear.run.events.empty());
  ASSERT_EQ(linear.grid.size(), 400u);
  double top = 0;
  const int s = resonant.stopped() - 1;
  for (std::size_t k = 0; k < linear.grid.size(); ++k) top = std::max(top, linear.grid.u(k, s));
  EXPECT_GT(top, 1.2 * resonant.gap);  // through the stop, as the closed form has it
  const ChainSeries stopped = chainSeries(ChainSeriesSpec{resonant, outside, 1, 8.0, 400, TrustMode::Off});
  for (std::size_t k = 0; k < stopped.grid.size(); ++k) EXPECT_LE(stopped.grid.u(k, s), resonant.gap * (1 + 1e-12));
}

// Every number of two runs, to the bit.
void expectSameRun(const ChainSeries& a, const ChainSeries& b) {
  ASSERT_EQ(a.run.events.size(), b.run.events.size());
  for (std::size_t i = 0; i < a.run.events.size(); ++i) {
    const ChainEvent& x = a.run.events[i];
    const ChainEvent& y = b.run.events[i];
    ASSERT_EQ(x.t, y.t) << "event " << i;
    ASSERT_EQ(x.type, y.type) << "event " << i;
    ASSERT_EQ(x.u, y.u) << "event " << i;
    ASSERT_EQ(x.vBefore, y.vBefore) << "event " << i;
    ASSERT_EQ(x.vAfter, y.vAfter) << "event " << i;
  }
  EXPECT_EQ(a.run.tFinal, b.run.tFinal);
  EXPECT_EQ(a.run.final.u, b.run.final.u);
  EXPECT_EQ(a.run.final.v, b.run.final.v);
  EXPECT_EQ(a.run.stop, b.run.stop);
  EXPECT_EQ(a.run.energyFinal, b.run.energyFinal);
  ASSERT_EQ(a.grid.size(), b.grid.size());
  ASSERT_EQ(a.grid.values, b.grid.values);
  ASSERT_EQ(a.section.values, b.section.values);
  ASSERT_EQ(a.flights.size(), b.flights.size());
  for (std::size_t i = 0; i < a.flights.size(); ++i) ASSERT_EQ(a.flights[i].duration, b.flights[i].duration);
  EXPECT_EQ(a.trust.verdict, b.trust.verdict);
  EXPECT_EQ(a.trust.stateError, b.trust.stateError);
  EXPECT_EQ(a.trust.horizon, b.trust.horizon);
  EXPECT_EQ(a.precision, b.precision);
}

// Chains the explorer's defaults do not use: 3:2:1 with its second design, four masses stopped
// inside with a right wall, eight equal masses stopped on mass 5 near their slowest mode's top.
std::vector<ChainSeriesSpec> streamedSpecs() {
  std::vector<ChainSeriesSpec> specs;
  MassChain three;
  three.masses = {1.0, 0.3, 0.08};
  three.springs = designSprings(three.masses, 1.0, {3, 2, 1}).designs.at(1).springs;
  three.gap = 0.7;
  ChainState start = chainGloStart(three, {0.2, 0.5, 0.3}).state;
  start.v[2] -= 0.03;
  specs.push_back({three, start, 300, 25.0, 300, TrustMode::Auto});
  MassChain four;
  four.masses = {1.0, 0.6, 1.4, 0.9};
  four.springs = {1.0, 2.0, 0.8, 1.1};
  four.rightSpring = 0.5;
  four.stopMass = 2;
  four.gap = 0.5;
  ChainState moving{Eigen::VectorXd::Zero(4), Eigen::VectorXd::Zero(4)};
  moving.u << 0.0, 0.3, 0.0, -0.2;
  moving.v << 0.2, 0.8, -0.1, 0.0;
  specs.push_back({four, moving, 400, 30.0, 500, TrustMode::Auto});
  MassChain eight;
  eight.masses.assign(8, 1.0);
  eight.springs.assign(8, 1.0);
  eight.stopMass = 5;
  std::vector<double> slowest(8, 0.0);
  slowest.back() = 1.0;
  ChainState top = chainGloStart(eight, slowest).state;
  top.v[4] -= 1e-4;
  specs.push_back({eight, top, 100, 40.0, 600, TrustMode::Off});
  return specs;
}

TEST(ChainSeries, InPiecesTheSameBitsAsAtOnceEachReportAPrefixOfTheRun) {
  for (const ChainSeriesSpec& spec : streamedSpecs()) {
    SCOPED_TRACE(testing::Message() << spec.chain.size() << " masses");
    const ChainSeries once = chainSeries(spec);
    ASSERT_EQ(once.run.contacts, spec.contacts);
    std::vector<ChainSeries> reports;
    std::vector<double> fractions;
    // a report after every piece (of at least kMinChunkContacts contacts)
    const ChainSeries streamed = chainSeries(
        spec, {},
        [&](const ChainSeries& sofar, double fraction) {
          reports.push_back(sofar);
          fractions.push_back(fraction);
        },
        1e-12);
    expectSameRun(once, streamed);
    ASSERT_GE(reports.size(), 2u);
    for (std::size_t r = 0; r < reports.size(); ++r) {
      const ChainSeries& sofar = reports[r];
      ASSERT_LE(sofar.run.events.size(), once.run.events.size());
      ASSERT_EQ(sofar.flights.size(), std::size_t(sofar.run.contacts));
      // its section a prefix of the whole run's (each report's points stay where they were drawn)
      ASSERT_EQ(sofar.section.size(), std::size_t(sofar.run.contacts));
      ASSERT_TRUE(std::equal(sofar.section.values.begin(), sofar.section.values.end(), once.section.values.begin()));
      for (std::size_t i = 0; i < sofar.run.events.size(); ++i) {
        ASSERT_EQ(sofar.run.events[i].t, once.run.events[i].t) << "report " << r << ", event " << i;
        ASSERT_EQ(sofar.run.events[i].u, once.run.events[i].u) << "report " << r << ", event " << i;
      }
      EXPECT_EQ(fractions[r], double(sofar.run.contacts) / double(spec.contacts));
      if (r > 0) {
        EXPECT_GE(sofar.run.events.size(), reports[r - 1].run.events.size());
      }
    }
  }
}

TEST(ChainSeries, AContactDoubleCannotDecideIsRunAgainInAHigherPrecision) {
  // mass 1 pressed one ulp past the gap with mass 2 on the stop (mass 3 beside it at the gap): the
  // force on mass 2 is within the modal kernel's bound of double's rounding (undecided); long
  // double or binary128 decides it, from the same start. (On two masses the note's kernel takes
  // u1 - u2 exactly and decides it in double.)
  MassChain chain;
  chain.masses = {1.0, 0.5, 0.5};
  chain.springs = {1.0, 0.5, 0.5};
  chain.stopMass = 2;
  ChainState start{Eigen::Vector3d(std::nextafter(1.0, 2.0), 1.0, 1.0), Eigen::Vector3d::Zero()};
  const ChainRun inDoubleAlone = runChain(chain, start, 3);
  ASSERT_EQ(inDoubleAlone.stop, StopReason::Undecided);
  const ChainSeriesSpec spec{chain, start, 3, 10.0, 200, TrustMode::Auto};
  const ChainSeries series = chainSeries(spec);
  ASSERT_NE(series.precision, Precision::Double);
  // said where the precision below ended, undecided
  const BasicChainRun<long double> inLong = runChain(
      chainCast<long double>(chain), BasicChainState<long double>{start.u.cast<long double>(), start.v.cast<long double>()}, 3);
  const bool longDecides = inLong.stop != StopReason::Undecided;
  EXPECT_EQ(series.precision, longDecides ? Precision::Long : Precision::Quad);
  EXPECT_EQ(series.undecidedAt, longDecides ? inDoubleAlone.tFinal : double(inLong.tFinal));
  EXPECT_EQ(series.run.stop, StopReason::ContactLimit);
  EXPECT_EQ(series.run.contacts, 3);
  // the run is that precision's own run, each number rounded once to double
  const ChainRun expected =
      series.precision == Precision::Long
          ? inDouble(runChain(chainCast<long double>(chain),
                              BasicChainState<long double>{start.u.cast<long double>(), start.v.cast<long double>()}, 3))
          : inDouble(runChain(chainCast<Quad>(chain), BasicChainState<Quad>{start.u.cast<Quad>(), start.v.cast<Quad>()}, 3));
  ASSERT_EQ(series.run.events.size(), expected.events.size());
  for (std::size_t i = 0; i < expected.events.size(); ++i) {
    EXPECT_EQ(series.run.events[i].t, expected.events[i].t);
    EXPECT_EQ(series.run.events[i].type, expected.events[i].type);
  }
  EXPECT_EQ(series.grid.size(), 200u);  // the grid is the raised run's
  EXPECT_NE(series.trust.verdict, Verdict::Unchecked);
}

TEST(ChainSeries, ARaisedDesignedChainIsItsDesignRefinedInThatPrecision) {
  // a designed 3:2:1 chain, mass 3 held on the stop by mass 2 one ulp past the gap: undecided in
  // double; the run raised takes the design refined for its numbers in that precision (as the
  // command line's --frequencies does), not double's springs widened
  const DesignChoice design = chooseDesign({1.0, 0.2, 0.05}, 1.0, 0.0, {3, 2, 1}, 1);
  ASSERT_EQ(design.problem, DesignChoiceProblem::None);
  const MassChain chain{{1.0, 0.2, 0.05}, design.chosen().springs, 0, 0, 1.0};
  const ChainState start{Eigen::Vector3d(1.0, std::nextafter(1.0, 2.0), 1.0), Eigen::Vector3d::Zero()};
  ChainSeriesSpec spec{chain, start, 4, 10.0, 50, TrustMode::Off};
  spec.design = design;
  const ChainSeries series = chainSeries(spec);
  ASSERT_NE(series.precision, Precision::Double);
  const auto runIn = [&]<typename S>(bool refined) {
    BasicMassChain<S> inS = chainCast<S>(chain);
    if (refined) inS.springs = *designedSpringsIn<S>(inS.masses, inS.springs.front(), inS.rightSpring, design);
    return inDouble(runChain(inS, BasicChainState<S>{start.u.cast<S>(), start.v.cast<S>()}, 4));
  };
  const ChainRun expected = series.precision == Precision::Long ? runIn.operator()<long double>(true)
                                                                : runIn.operator()<Quad>(true);
  ASSERT_EQ(series.run.events.size(), expected.events.size());
  for (std::size_t i = 0; i < expected.events.size(); ++i) {
    EXPECT_EQ(series.run.events[i].t, expected.events[i].t) << i;
    EXPECT_EQ(series.run.events[i].u, expected.events[i].u) << i;
  }
  // (the refined springs are another chain than double's widened: not the same run to the bit)
  const ChainRun widened = series.precision == Precision::Long ? runIn.operator()<long double>(false)
                                                               : runIn.operator()<Quad>(false);
  bool differs = widened.events.size() != expected.events.size();
  for (std::size_t i = 0; !differs && i < expected.events.size(); ++i) {
    differs = widened.events[i].t != expected.events[i].t || widened.events[i].u != expected.events[i].u;
  }
  EXPECT_TRUE(differs);
}

TEST(ChainSeries, AStopEndsTheSeriesCancelled) {
  const ChainSeriesSpec spec = streamedSpecs().front();
  std::stop_source source;
  int reports = 0;
  const ChainSeries series = chainSeries(
      spec, source.get_token(),
      [&](const ChainSeries&, double) {
        if (++reports == 2) source.request_stop();
      },
      1e-12);
  EXPECT_EQ(reports, 2);
  EXPECT_EQ(series.run.stop, StopReason::Cancelled);
}

}  // namespace
}  // namespace grazelab::core::experiments
