// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/orbits/chain_glo.cpp: grazing linear orbits of any resonance. The note's Lemma
// 2.1 (1:2 grazes exactly for lambda in [0, 4/3]); the sets of other resonances against brute
// force (the largest of sum lambda_j cos(n_j theta) over a fine grid, each sampled maximum
// refined); resonances whose modes all have harmonics >= 2 graze only on the simplex; the
// three-mode region's boundary; and runs from GLO data: inside the set grazing touches at T,
// outside an impact before it.
#include "core/orbits/chain_glo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "core/model/chain_design.h"
#include "core/solver/chain_run.h"

namespace grazelab::core {
namespace {

// max over theta of sum_j lambda_j cos(n_j theta) - 1, in long double: a grid of 20 000 points a
// period, each local maximum refined by golden section (skipping the one at theta = 0)
long double largestExcess(const std::vector<int>& harmonics, const std::vector<double>& weights) {
  const auto g = [&](long double theta) {
    long double sum = -1;
    for (std::size_t j = 0; j < weights.size(); ++j) sum += weights[j] * std::cos(harmonics[j] * theta);
    return sum;
  };
  const int samples = 20000;
  const long double step = 2 * std::numbers::pi_v<long double> / samples;
  long double best = -1e9L;
  for (int i = 2; i < samples - 1; ++i) {
    const long double a = g((i - 1) * step), b = g(i * step), c = g((i + 1) * step);
    if (b >= a && b >= c) {
      long double low = (i - 1) * step, high = (i + 1) * step;
      for (int k = 0; k < 100; ++k) {
        const long double m1 = low + (high - low) * 0.381966L, m2 = high - (high - low) * 0.381966L;
        (g(m1) < g(m2) ? low : high) = (g(m1) < g(m2) ? m1 : m2);
      }
      best = std::max(best, g((low + high) / 2));
    }
  }
  return best;
}

TEST(ChainGlo, TheNotesResonanceGrazesExactlyOnZeroToFourThirds) {
  // each end bracketed within 1e-13: [certainly grazes, certainly crosses] around the exact end
  const GrazingInterval interval = grazingInterval(2, 1);
  EXPECT_LE(interval.lowOut, 0.0);
  EXPECT_GE(interval.low, 0.0);
  EXPECT_LE(interval.low - interval.lowOut, 1e-13);
  EXPECT_LE(interval.high, 4.0 / 3);
  EXPECT_GE(interval.highOut, 4.0 / 3);
  EXPECT_LE(interval.highOut - interval.high, 1e-13);
}

TEST(ChainGlo, TwoModeSetsAgreeWithBruteForce) {
  // 1:n resonances reach beyond lambda = 1; m:n with both harmonics >= 2 stay on [0, 1]
  // (at theta = 2 pi / n2 the slow mode is back at its top while the fast one is not)
  for (const auto& [fast, slow] : {std::pair{2, 1}, {3, 1}, {4, 1}, {5, 1}, {3, 2}, {5, 2}, {4, 3}, {7, 3}}) {
    const GrazingInterval interval = grazingInterval(fast, slow);
    const std::vector<int> harmonics{fast, slow};
    EXPECT_LE(interval.highOut - interval.high, 1e-13) << fast << ":" << slow;
    EXPECT_LE(interval.low - interval.lowOut, 1e-13) << fast << ":" << slow;
    if (slow >= 2) {
      EXPECT_TRUE(interval.high <= 1 && 1 <= interval.highOut) << fast << ":" << slow;
    } else {
      EXPECT_GT(interval.high, 1.0) << fast << ":" << slow;
      EXPECT_LE(interval.high, double(fast * fast) / (fast * fast - slow * slow) * (1 + 1e-15));
    }
    EXPECT_TRUE(interval.lowOut <= 0 && 0 <= interval.low) << fast << ":" << slow;
    for (double lambda : {interval.high, interval.low}) {
      // the end certain to graze: no theta takes the sum past 1; 1e-9 outside: one does (or the
      // top at 0 turns into a minimum)
      const double outward = lambda == interval.high ? 1e-9 : -1e-9;
      EXPECT_LT(largestExcess(harmonics, {1 - lambda, lambda}), 1e-15L) << fast << ":" << slow << " at " << lambda;
      const double beyond = lambda + outward;
      const bool rises = (1 - beyond) * fast * fast + beyond * slow * slow < 0;
      EXPECT_TRUE(rises || largestExcess(harmonics, {1 - beyond, beyond}) > 0) << fast << ":" << slow << " past " << lambda;
    }
  }
}

TEST(ChainGlo, ThreeModeRegionsAreBoundedByTouches) {
  for (const auto& harmonics : std::vector<std::vector<int>>{{3, 2, 1}, {4, 2, 1}, {5, 3, 1}}) {
    const auto region = grazingRegion(harmonics[0], harmonics[1], harmonics[2], 12);
    ASSERT_EQ(region.size(), 12u);
    for (const GrazingRegionPoint& point : region) {
      const std::vector<double> inside{1 - point.lambda2 - point.lambda3, point.lambda2, point.lambda3};
      EXPECT_LT(largestExcess(harmonics, inside), 1e-14L) << point.angle;
      EXPECT_LE(point.radiusOut - point.radius, 2e-13);  // in lambda: the edge known to 1e-13
      // 1e-8 further along the ray the sum passes 1 (or the top at 0 turns into a minimum)
      const double r = point.radius * (1 + 1e-8);
      const double l2 = 1.0 / 3 + r * std::cos(point.angle), l3 = 1.0 / 3 + r * std::sin(point.angle);
      const std::vector<double> beyond{1 - l2 - l3, l2, l3};
      double curvature = 0;
      for (std::size_t j = 0; j < 3; ++j) curvature -= beyond[j] * harmonics[j] * harmonics[j];
      EXPECT_TRUE(curvature > 0 || largestExcess(harmonics, beyond) > 0) << point.angle;
      // the simplex (every lambda_j >= 0) grazes, so it lies inside
      EXPECT_GE(point.radius, 1.0 / (3 * std::sqrt(2.0)) * (1 - 1e-12));
    }
  }
}

TEST(ChainGlo, RunsFromGloDataGrazeInsideTheSetAndImpactOutside) {
  // the designed 3:2:1 chain: GLO_lambda started at its touch; inside the set it is a grazing
  // orbit (touches only, one period apart), outside an impact comes before T
  const ChainDesigns designs = designSprings({1.0, 0.2, 0.05}, 1.0, {3, 2, 1});
  ASSERT_FALSE(designs.designs.empty());
  const MassChain chain{{1.0, 0.2, 0.05}, designs.designs[0].springs, 0, 0, 1.0};
  const double period = chainDynamics(chain).period;
  const auto region = grazingRegion(3, 2, 1, 8);
  for (const GrazingRegionPoint& point : region) {
    for (double scale : {0.9, 1.1}) {
      const double r = point.radius * scale;
      const double l2 = 1.0 / 3 + r * std::cos(point.angle), l3 = 1.0 / 3 + r * std::sin(point.angle);
      const ChainGloStart start = chainGloStart(chain, {1 - l2 - l3, l2, l3});
      ASSERT_EQ(start.problem, GloStartProblem::None);
      const ChainRun run = runChain(chain, start.state, 3);
      ASSERT_FALSE(run.events.empty()) << int(run.stop);
      if (scale < 1) {
        EXPECT_EQ(run.events[0].type, EventType::Grazing) << point.angle;
        EXPECT_NEAR(run.events[0].t, period, 1e-12 * period) << point.angle;
      } else {
        EXPECT_LT(run.events[0].t, period * (1 - 1e-9)) << point.angle;
        EXPECT_NE(run.events[0].type, EventType::Grazing) << point.angle;
      }
    }
  }
  EXPECT_EQ(chainGloStart(chain, {0.5, 0.5}).problem, GloStartProblem::WrongCount);
  EXPECT_EQ(chainGloStart(chain, {0.5, 0.5, 0.5}).problem, GloStartProblem::NotAffine);
}

// The start from a ready chain's dynamics (the modes made once, as the command line and Python
// take it for every run of one chain) is the start from the chain's numbers, to the bit: chains
// of 2 to 6 masses, stops inside and at the end, with and without a right wall, in double, long
// double and binary128; a weight on a mode with a node at the stop is refused by both.
template <typename S>
void expectSameStarts(const MassChain& given, const std::vector<double>& weights) {
  const BasicMassChain<S> chain = chainCast<S>(given);
  const BasicReadyChain<S> ready = readyChain(chain);
  std::vector<S> w(weights.begin(), weights.end());
  const BasicChainGloStart<S> fromNumbers = chainGloStartIn<S>(chain, w);
  const BasicChainGloStart<S> fromReady = chainGloStartIn<S>(ready.dynamics, w);
  ASSERT_EQ(fromReady.problem, fromNumbers.problem);
  EXPECT_EQ(fromReady.stillModes, fromNumbers.stillModes);
  if (fromNumbers.problem != GloStartProblem::None) return;
  for (Eigen::Index i = 0; i < chain.size(); ++i) {
    EXPECT_TRUE(fromReady.state.u[i] == fromNumbers.state.u[i]) << chain.size() << " masses, u" << i + 1;
    EXPECT_TRUE(fromReady.state.v[i] == fromNumbers.state.v[i]) << chain.size() << " masses, v" << i + 1;
  }
}

TEST(ChainGlo, AReadyChainsModesGiveTheStartOfItsNumbersToTheBit) {
  std::uint64_t seed = 12345;
  const auto uniform = [&seed](double low, double high) {
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return low + (high - low) * double(seed >> 11) * 0x1p-53;
  };
  for (int n = 2; n <= 6; ++n) {
    for (int stop : {n, (n + 1) / 2}) {
      for (bool wall : {false, true}) {
        MassChain chain;
        for (int i = 0; i < n; ++i) {
          chain.masses.push_back(uniform(0.2, 3));
          chain.springs.push_back(uniform(0.5, 4));
        }
        chain.rightSpring = wall ? uniform(0.5, 4) : 0;
        chain.stopMass = stop;
        chain.gap = uniform(0.1, 2);
        std::vector<double> weights(std::size_t(n), 0.0);
        double sum = 0;
        for (int j = 0; j + 1 < n; j += 2) sum += weights[std::size_t(j)] = uniform(-0.5, 0.8);
        weights.back() = 1 - sum;  // some modes left still
        expectSameStarts<double>(chain, weights);
        expectSameStarts<long double>(chain, weights);
        expectSameStarts<Quad>(chain, weights);
      }
    }
  }
  // a symmetric chain stopped in its middle: its antisymmetric modes have a node there
  const MassChain symmetric{{1, 1, 1}, {1, 1, 1}, 1, 2, 1.0};
  ASSERT_TRUE(readyChain(symmetric).dynamics.nodeAtStop[1]);
  expectSameStarts<double>(symmetric, {0.2, 0.3, 0.5});
  expectSameStarts<double>(symmetric, {0.4, 0.0, 0.6});
  EXPECT_EQ(chainGloStartIn<double>(readyChain(symmetric).dynamics, {0.2, 0.3, 0.5}).problem,
            GloStartProblem::WeightOnNode);
}

}  // namespace
}  // namespace grazelab::core
