// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/experiments/chain_map.cpp: maps of a chain of N masses. Two masses given as a
// MassChain map as the two-mass maps do (another solver, another map code); a resonant chain's
// first flights from the stop never last longer than its period; a point is the run it names;
// on all cores the map is the serial one; bad specs are refused.
#include "core/experiments/chain_map.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>

#include <cmath>

#include "core/model/two_mass_form.h"
#include "core/model/chain_design.h"
#include "core/model/resonance.h"
#include "core/orbits/chain_glo.h"
#include "core/solver/chain_run.h"
#include "core/solver/trust.h"
#include "parallel/tbb_parallel_for.h"
#include "support/point_bits.h"

namespace grazelab::core {
namespace {

MassChain threeToOne() {
  MassChain chain;
  chain.masses = {1.0, 0.2, 0.05};
  chain.springs = designSprings(chain.masses, 1.0, {3, 2, 1}).designs.at(0).springs;
  return chain;
}

ChainMapAxis axis(bool velocity, int mass, double from, double to, std::int64_t count) {
  ChainMapAxis result;
  result.kind = velocity ? ChainMapAxis::Kind::Velocity : ChainMapAxis::Kind::Position;
  result.index = mass;
  result.range = {MapVariable::U1, from, to, count};
  return result;
}

ChainMapAxis weightAxis(int mode, double from, double to, std::int64_t count) {
  ChainMapAxis result;
  result.kind = ChainMapAxis::Kind::Weight;
  result.index = mode;
  result.range = {MapVariable::U1, from, to, count};
  return result;
}

// the note's grazing-start plane (u1, d, v1, 0) as a two-mass map and as a map of two masses
TEST(ChainMapTest, TwoMassesMapAsTheTwoMassMaps) {
  MapSpec two;
  two.model.design = Branch::Upper;
  two.x = {MapVariable::U1, -1.0, 2.0, 13};
  two.y = {MapVariable::V1, -1.5, 1.5, 11};
  two.contacts = 12;
  const Model designed = [&] {
    Model m = two.model;
    m.k2 = designKappa(m.m2 / m.m1, *m.design) * m.k1;
    m.design.reset();
    return m;
  }();
  ChainMapSpec chain;
  chain.chain = massChainOf(designed);
  chain.start = {Eigen::Vector2d(0.0, designed.gap), Eigen::Vector2d::Zero()};
  chain.x = axis(false, 1, -1.0, 2.0, 13);
  chain.y = axis(true, 1, -1.5, 1.5, 11);
  chain.contacts = 12;
  ASSERT_EQ(checkChainMap(chain), "");
  const MapRows a = computeMap(two, {0, 11}, serialFor());
  const MapRows b = computeChainMap(chain, {0, 11}, serialFor());
  EXPECT_NEAR(a.period, b.period, 1e-14 * a.period);
  int compared = 0, undecided = 0;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const PointSummary& p = a.points[i];
    const PointSummary& q = b.points[i];
    if (!q.valid) {
      // GLOM_1 (u1 = -d at rest), whose top comes back within rounding of the stop at T/2, a
      // touch no precision decides: no run in either map, said so
      const double x = chain.x.range.at(std::int64_t(i) % 13);
      EXPECT_EQ(x, -1.0) << "point " << i;
      EXPECT_FALSE(p.valid) << "point " << i;
      EXPECT_EQ(chain.y.range.at(std::int64_t(i) / 13), 0.0) << "point " << i;
      EXPECT_EQ(q.impacts, -1);
      EXPECT_TRUE(std::isnan(q.fftFirst));
      ++undecided;
      continue;
    }
    EXPECT_EQ(p.impacts, q.impacts) << "point " << i;
    EXPECT_EQ(p.grazings, q.grazings) << "point " << i;
    EXPECT_EQ(p.sticks, q.sticks) << "point " << i;
    // one run (the note's kernel, whichever way the chain was written), one summary: the times
    // to the bit, the ratios over each map's own rounding of the period
    EXPECT_EQ(std::bit_cast<std::uint64_t>(p.fftFirst), std::bit_cast<std::uint64_t>(q.fftFirst)) << "point " << i;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(p.firstImpactTime), std::bit_cast<std::uint64_t>(q.firstImpactTime))
        << "point " << i;
    for (const auto& [x, y] : {std::pair{p.fftMin, q.fftMin}, std::pair{p.fftMax, q.fftMax},
                               std::pair{p.fftMean, q.fftMean}}) {
      if (std::isnan(x)) {
        EXPECT_TRUE(std::isnan(y)) << "point " << i;
      } else {
        EXPECT_NEAR(x, y, 1e-15 * (1 + std::abs(x))) << "point " << i;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 300);
  EXPECT_LE(undecided, 1);
}

TEST(ChainMapTest, AResonantChainsFlightsFromTheStopLastAtMostItsPeriod) {
  ChainMapSpec spec;
  spec.chain = threeToOne();
  spec.start = {Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d::Zero()};
  spec.x = axis(false, 3, -1.0, 0.9, 24);
  spec.y = axis(true, 3, -2.0, 2.0, 20);
  spec.contacts = 8;
  const MapRows map = computeChainMap(spec, {0, 20}, serialFor());
  const double T = chainMapPeriod(spec.chain);
  EXPECT_NEAR(map.period, T, 0);
  int flights = 0, none = 0;
  for (const PointSummary& p : map.points) {
    ASSERT_TRUE(p.valid);
    if (std::isnan(p.fftFirst)) {
      ++none;  // too little energy: the stopped mass never reaches the stop
      EXPECT_EQ(p.impacts + p.grazings + p.sticks, 0);
      continue;
    }
    EXPECT_LE(p.fftFirst, T * (1 + 1e-12));
    EXPECT_LE(p.fftMax, 1 + 1e-12);
    EXPECT_LE(p.fftMin, p.fftMean);
    EXPECT_LE(p.fftMean, p.fftMax);
    ++flights;
  }
  EXPECT_GT(flights, 100);
  EXPECT_GT(none, 20);
  // one point is the run it names: its events counted here
  const std::int64_t column = 3, row = 17;
  ChainState start = spec.start;
  start.u[2] = spec.x.range.at(column);
  start.v[2] = spec.y.range.at(row);
  const ChainRun run = runChain(spec.chain, start, 8);
  long impacts = 0;
  for (const ChainEvent& event : run.events) impacts += event.type == EventType::Impact;
  const PointSummary p = chainMapPoint(spec, column, row);
  EXPECT_EQ(p.impacts, impacts);
  ASSERT_FALSE(run.events.empty());
  EXPECT_EQ(p.firstImpactTime, run.events.front().t);
  if (run.events.size() > 1) {
    EXPECT_EQ(p.fftFirst, run.events[1].flight);  // as the kernel computed it
    EXPECT_NEAR(p.fftFirst, run.events[1].t - run.events[0].t, 1e-13 * run.events[1].t);
  }
}

// with estimateHorizon each point's horizon is the trust estimate of the run it names, made
// apart from the map by trustOf on the run's whole event list (the map's is made online);
// without it, NaN
TEST(ChainMapTest, HorizonIsTheRunsOwnTrustEstimate) {
  ChainMapSpec spec;
  spec.chain = threeToOne();
  spec.start = {Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d::Zero()};
  spec.x = axis(false, 3, -1.0, 0.9, 6);
  spec.y = axis(true, 3, -8.0, 8.0, 5);
  spec.contacts = 60;
  spec.estimateHorizon = true;
  int estimated = 0;
  for (std::int64_t row = 0; row < 5; ++row) {
    for (std::int64_t column = 0; column < 6; ++column) {
      const PointSummary p = chainMapPoint(spec, column, row);
      ChainState start = spec.start;
      start.u[2] = spec.x.range.at(column);
      start.v[2] = spec.y.range.at(row);
      const ChainRun run = runChain(spec.chain, start, 60);
      const Trust trust = trustOf(readyChain(spec.chain), start, run, 60, 0.0, TrustMode::Auto);
      if (trust.verdict == Verdict::Unchecked) {
        EXPECT_TRUE(std::isnan(p.horizon)) << column << ", " << row;
        continue;
      }
      EXPECT_EQ(p.horizon, trust.horizon) << column << ", " << row;
      if (run.events.empty()) continue;  // (a run without contacts ends at t = 0: horizon 0)
      EXPECT_GT(p.horizon, 0);
      ++estimated;
    }
  }
  EXPECT_GT(estimated, 10);
  spec.estimateHorizon = false;
  EXPECT_TRUE(std::isnan(chainMapPoint(spec, 2, 3).horizon));
}

// over GLO weights: a point is the run from GLO_lambda plus the push, lambda the axes' weights
// and the balancing one; unpushed, a grazing weight's flight from the touch is GLO_lambda's own
// and returns after one period; a crossing weight's that leaves the stop (sum lambda_j n_j^2 > 0)
// returns sooner, one pressed into the stop (< 0) sticks at once
TEST(ChainMapTest, AMapOverGloWeightsIsTheRunsFromTheirGlos) {
  ChainMapSpec spec;
  spec.chain = threeToOne();
  spec.start = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  spec.push = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, -0.05)};
  spec.x = weightAxis(1, -1.0, 1.4, 7);
  spec.y = weightAxis(2, -1.0, 1.4, 5);
  spec.contacts = 12;
  ASSERT_EQ(checkChainMap(spec), "");
  EXPECT_EQ(balancingWeight(spec), 2);
  for (std::int64_t row = 0; row < 5; ++row) {
    for (std::int64_t column = 0; column < 7; ++column) {
      const double l1 = spec.x.range.at(column), l2 = spec.y.range.at(row);
      const ChainGloStart glo = chainGloStart(spec.chain, {l1, l2, 1 - (l1 + l2)});
      ASSERT_EQ(glo.problem, GloStartProblem::None);
      const ChainState start{glo.state.u + spec.push.u, glo.state.v + spec.push.v};
      const ChainRun run = runChain(spec.chain, start, 12);
      const PointSummary p = chainMapPoint(spec, column, row);
      long impacts = 0;
      for (const ChainEvent& event : run.events) impacts += event.type == EventType::Impact;
      EXPECT_EQ(p.impacts, impacts) << l1 << ", " << l2;
      if (!run.events.empty()) {
        EXPECT_EQ(p.fftFirst, run.events.front().t) << l1 << ", " << l2;  // the start is a departure from the stop
      }
    }
  }
  // unpushed: GLO_lambda's flight from its touch returns within the period, at the period
  // exactly when lambda grazes
  spec.push = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  spec.contacts = 1;
  const double T = chainMapPeriod(spec.chain);
  const std::vector<int> harmonics{3, 2, 1};
  int grazing = 0, crossing = 0;
  for (std::int64_t row = 0; row < 5; ++row) {
    for (std::int64_t column = 0; column < 7; ++column) {
      const double l1 = spec.x.range.at(column), l2 = spec.y.range.at(row), l3 = 1 - (l1 + l2);
      const GloGrazing kind = gloGrazing(harmonics, {l1, l2, l3});
      const double curvature = 9 * l1 + 4 * l2 + l3;  // sum lambda_j n_j^2
      if (kind == GloGrazing::Boundary || std::abs(curvature) < 1e-9) continue;
      const PointSummary p = chainMapPoint(spec, column, row);
      if (kind == GloGrazing::Grazes) {
        EXPECT_NEAR(p.fftFirst, T, 1e-9 * T) << l1 << ", " << l2;
        ++grazing;
      } else if (curvature > 0) {
        EXPECT_LT(p.fftFirst, T * (1 - 1e-9)) << l1 << ", " << l2;
        ++crossing;
      } else {
        EXPECT_EQ(p.sticks, 1) << l1 << ", " << l2;
      }
    }
  }
  EXPECT_GT(grazing, 3);
  EXPECT_GT(crossing, 3);
  // weights on both axes or none; three modes at least
  ChainMapSpec mixed = spec;
  mixed.y = axis(true, 3, -1, 1, 3);
  EXPECT_NE(checkChainMap(mixed), "");
  EXPECT_EQ(parseChainMapVariable("w3", 3)->kind, ChainMapAxis::Kind::Weight);
  EXPECT_FALSE(parseChainMapVariable("w4", 3));
}

TEST(ChainMapTest, OnAllCoresTheMapIsTheSerialOne) {
  ChainMapSpec spec;
  spec.chain = MassChain{{1.0, 0.7, 0.4}, {1.0, 0.8, 0.6}, 0, 2, 1.0};
  spec.start = {Eigen::Vector3d(0.2, 0.5, -0.1), Eigen::Vector3d(0.1, 0, 0)};
  spec.x = axis(false, 2, -1.0, 1.0, 17);  // the last column on the stop: u2 = d
  spec.y = axis(true, 3, -1.0, 1.0, 13);
  spec.contacts = 6;
  const MapRows serial = computeChainMap(spec, {0, 13}, serialFor());
  const MapRows parallel = computeChainMap(spec, {0, 13}, parallel::tbbParallelFor(2));
  ASSERT_TRUE(parallel.complete);
  int onStop = 0;
  for (std::size_t i = 0; i < serial.points.size(); ++i) {
    ASSERT_TRUE(testing::sameBits(serial.points[i], parallel.points[i])) << "point " << i;
    ASSERT_TRUE(serial.points[i].valid) << "point " << i;
    if (spec.x.range.at(std::int64_t(i) % 17) == 1.0) {
      // a start on the stop leaves it (pulled off): its first flight is from the stop
      EXPECT_TRUE(std::isfinite(serial.points[i].fftFirst)) << "point " << i;
      ++onStop;
    }
  }
  EXPECT_EQ(onStop, 13);
  // a start past the stop is no run
  spec.x = axis(false, 2, 1.5, 2.0, 2);
  EXPECT_FALSE(chainMapPoint(spec, 0, 0).valid);
  EXPECT_EQ(chainMapPoint(spec, 1, 0).impacts, -1);
}

TEST(ChainMapTest, SpecsThatMakeNoSenseAreRefused) {
  ChainMapSpec spec;
  spec.chain = threeToOne();
  spec.start = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  spec.x = axis(false, 3, 0, 1, 4);
  spec.y = axis(false, 3, 0, 1, 4);
  EXPECT_NE(checkChainMap(spec), "");  // the same coordinate twice
  spec.y = axis(true, 4, 0, 1, 4);
  EXPECT_NE(checkChainMap(spec), "");  // no mass 4
  spec.y = axis(true, 1, 0, std::nan(""), 4);
  EXPECT_NE(checkChainMap(spec), "");
  spec.y = axis(true, 1, 0, 1, 0);
  EXPECT_NE(checkChainMap(spec), "");
  spec.y = axis(true, 1, 0, 1, 4);
  EXPECT_EQ(checkChainMap(spec), "");
  EXPECT_FALSE(parseChainMapVariable("u0", 3));
  EXPECT_FALSE(parseChainMapVariable("v4", 3));
  ASSERT_TRUE(parseChainMapVariable("v3", 3));
  EXPECT_EQ(parseChainMapVariable("v3", 3)->name(), "v3");
}

}  // namespace
}  // namespace grazelab::core
