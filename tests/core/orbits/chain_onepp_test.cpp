// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/orbits/chain_onepp.cpp: 1IPP orbits of chains of N masses. N = 2 is the note's
// family (the two-mass closed form and its admissibility); an admissible orbit is periodic when
// run exactly (impacts at T, 2T, 3T, the same data each time); as T tends to the common period
// the data tend to the GLO of Theorem 2.1's weights, to first order in the distance.
#include "core/orbits/chain_onepp.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/model/chain_design.h"
#include "core/model/linear_modes.h"
#include "core/model/model.h"
#include "core/orbits/chain_glo.h"
#include "core/solver/chain_run.h"

namespace grazelab::core {
namespace {

MassChain designed(const std::vector<double>& masses, const std::vector<int>& ratios) {
  const ChainDesigns designs = designSprings(masses, 1.0, ratios);
  EXPECT_FALSE(designs.designs.empty());
  return MassChain{masses, designs.designs.at(0).springs, 0, 0, 1.0};
}

TEST(ChainOnePeriodic, TwoMassesAreTheNotesFamily) {
  for (const Branch branch : {Branch::Upper, Branch::Lower}) {
    const auto model = designedModel<double>(1.0, 0.3, 1.0, 1.0, branch);
    ASSERT_TRUE(model);
    const Modes modes = computeModes(*model);
    const MassChain chain = massChainOf(*model);
    int admissible = 0;
    for (int k = 1; k < 200; ++k) {
      const double T = modes.T2 * k / 200.0;
      const ChainOnePeriodicOrbit n = chainOnePeriodicOrbit(chain, T);
      const OnePeriodicOrbit<double> two = onePeriodicOrbit(*model, modes, T);
      ASSERT_EQ(n.refusal, two.refusal) << "T = " << T;
      if (n.refusal == OnePeriodicRefusal::MultipleOfPeriod) continue;
      EXPECT_NEAR(n.V, two.V, 1e-11 * std::abs(two.V)) << T;
      EXPECT_NEAR(n.postImpact.u[0], two.postImpact.u1, 1e-11 * (1 + std::abs(two.postImpact.u1))) << T;
      admissible += n.admissible();
    }
    EXPECT_GT(admissible, 10);
    // Theorem 2.1's weights: the note's lambda* on the slow mode
    const std::vector<double> weights = onePeriodicGrazingWeights(chain, modes.T2);
    EXPECT_NEAR(weights[1], lambdaStar(modes), 1e-14);
    EXPECT_NEAR(weights[0] + weights[1], 1.0, 1e-15);
  }
}

TEST(ChainOnePeriodic, AdmissibleOrbitsArePeriodicAndTendToTheirGrazingLimit) {
  for (const auto& [masses, ratios] : std::vector<std::pair<std::vector<double>, std::vector<int>>>{
           {{1.0, 0.2, 0.05}, {3, 2, 1}}, {{1.0, 0.4, 0.2}, {5, 3, 1}}, {{1.0, 0.6, 0.36, 0.216}, {4, 3, 2, 1}}}) {
    const MassChain chain = designed(masses, ratios);
    const double period = chainDynamics(chain).period;
    const std::vector<double> weights = onePeriodicGrazingWeights(chain, period);
    double sum = 0;
    for (double weight : weights) {
      EXPECT_GT(weight, 0);  // a convex combination of every mode
      sum += weight;
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    const ChainGloStart glo = chainGloStart(chain, weights);
    ASSERT_EQ(glo.problem, GloStartProblem::None);
    double previous = 0;
    for (int k = 10; k <= 22; k += 4) {
      const double T = period * (1 - std::ldexp(1.0, -k));
      const ChainOnePeriodicOrbit orbit = chainOnePeriodicOrbit(chain, T);
      ASSERT_TRUE(orbit.admissible()) << "T = T*(1 - 2^-" << k << "): " << int(orbit.refusal);
      // run exactly: impacts at T, 2T, 3T with the same data
      const ChainRun run = runChain(chain, orbit.postImpact, 3);
      ASSERT_EQ(run.events.size(), 3u);
      for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(run.events[i].type, EventType::Impact);
        EXPECT_NEAR(run.events[i].t, double(i + 1) * T, 1e-9 * T);
        EXPECT_LT((run.events[i].u - orbit.postImpact.u).cwiseAbs().maxCoeff(), 1e-8);
      }
      // the grazing limit: the distance shrinks as (T* - T)^2 on these chains (256-fold per 4
      // halvings; at least 16-fold asked), down to the data's rounding (u = V g(T), g of order
      // 1 / (T* - T): 3e-11 at k = 22)
      const double distance = (orbit.postImpact.u - glo.state.u).cwiseAbs().maxCoeff();
      if (previous > 0 && k <= 18) {
        EXPECT_GT(previous / distance, 15.0) << k;
      }
      EXPECT_LT(distance, std::max(20 * std::ldexp(1.0, -2 * k), 1e-9)) << k;
      previous = distance;
      EXPECT_LT(std::abs(orbit.V), 10 * std::ldexp(1.0, -k) * period);
    }
  }
}

TEST(ChainOnePeriodic, RefusesPeriodsWithoutAnOrbit) {
  const MassChain chain = designed({1.0, 0.2, 0.05}, {3, 2, 1});
  const double period = chainDynamics(chain).period;
  EXPECT_EQ(chainOnePeriodicOrbit(chain, period).refusal, OnePeriodicRefusal::MultipleOfPeriod);
  EXPECT_EQ(chainOnePeriodicOrbit(chain, period / 3).refusal, OnePeriodicRefusal::MultipleOfPeriod);
  EXPECT_EQ(chainOnePeriodicOrbit(chain, -1).refusal, OnePeriodicRefusal::BadPeriod);
  // beyond the common period no flight after an impact lasts T (Theorem 2.3)
  const ChainOnePeriodicOrbit beyond = chainOnePeriodicOrbit(chain, 1.3 * period);
  EXPECT_FALSE(beyond.admissible());
}

}  // namespace
}  // namespace grazelab::core

namespace grazelab::core {
namespace {

// Springs 1e25 apart: the certified search for a flight's return runs out of its windows long
// before T. That is undecided (SearchBudget), never "the flight never returns"; and a family
// of such a chain stops once 8 rows ran out of it before any was admissible.
TEST(ChainOnePeriodic, AReturnTheSearchCannotReachIsOutOfBudgetNotNeverReturns) {
  const MassChain stiff{{1, 1e-25, 1}, {1e25, 1, 1}, 0, 0, 1.0};
  const std::vector<ChainFamilyRow> rows = chainOnePeriodicFamily(stiff, 2000);
  ASSERT_FALSE(rows.empty());
  EXPECT_LT(rows.size(), 2023u) << "it stops once 8 rows ran out of the budget before any was admissible";
  int outOfBudget = 0;
  for (const ChainFamilyRow& row : rows) {
    EXPECT_NE(row.orbit.refusal, OnePeriodicRefusal::NeverReturns) << "T " << row.T;
    outOfBudget += row.orbit.refusal == OnePeriodicRefusal::SearchBudget;
  }
  EXPECT_EQ(outOfBudget, kFamilySearchBudgetRows);
  EXPECT_EQ(rows.back().orbit.refusal, OnePeriodicRefusal::SearchBudget);
}

}  // namespace
}  // namespace grazelab::core
