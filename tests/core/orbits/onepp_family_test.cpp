// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The 1IPP family (issue 10): its energy from the plain formula, its admissible members really
// one impact per period, and its grazing end on the GLO_lambda* data.
#include <gtest/gtest.h>

#include <cmath>

#include "core/orbits/onepp_family.h"
#include "core/orbits/special_orbits.h"
#include "core/orbits/starts.h"
#include "core/solver/simulate.h"

namespace grazelab::core {
namespace {

TwoMassForm<double> designedChain(double m2) {
  return *makeTwoMassForm(*designedModel(1.0, m2, 1.0, 1.0, Branch::Upper)).chain;
}

TEST(FamilyTest, energyIsTheMechanicalEnergyOfThePostImpactState) {
  const TwoMassForm<double> chain = designedChain(0.3);
  const Model& m = chain.model;
  for (const OnePeriodicOrbit<double>& p : onePeriodicFamily(chain, 200)) {
    // E = 1/2 m2 V^2 + 1/2 k1 u1^2 + 1/2 k2 (gap - u1)^2 (mass 1 at rest at the impact)
    const double u1 = p.postImpact.u1;
    const double E = 0.5 * m.m2 * p.V * p.V + 0.5 * m.k1 * u1 * u1 + 0.5 * m.k2 * (m.gap - u1) * (m.gap - u1);
    EXPECT_NEAR(p.energy, E, 1e-12 * E) << "T = " << p.T;
    EXPECT_EQ(p.postImpact.u2, m.gap);
    EXPECT_EQ(p.postImpact.v1, 0);
    EXPECT_EQ(p.postImpact.v2, p.V);
  }
}

TEST(FamilyTest, admissibleMembersHitTheStopOncePerPeriodAndRepeat) {
  const TwoMassForm<double> chain = designedChain(0.5);
  const std::vector<OnePeriodicOrbit<double>> family = onePeriodicFamily(chain, 64);
  int checked = 0;
  for (const OnePeriodicOrbit<double>& p : family) {
    if (!p.admissible) continue;
    Request request;
    request.initial = p.postImpact;
    request.maxContacts = 3;
    const Result result = simulate(chain.model, request);
    ASSERT_EQ(result.events.size(), 3u);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(result.events[k].t, (k + 1) * p.T, 1e-9 * (k + 1) * p.T) << "T = " << p.T;
      EXPECT_EQ(result.events[k].type, EventType::Impact);
      EXPECT_NEAR(result.events[k].after.u1, p.postImpact.u1, 1e-8 * (1 + std::abs(p.postImpact.u1)));
      EXPECT_NEAR(result.events[k].after.v2, p.V, 1e-8 * (1 + std::abs(p.V)));
    }
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

TEST(FamilyTest, theGrazingEndMeetsTheLambdaStarData) {
  for (double m2 : {0.05, 0.3, 0.5, 0.56}) {
    const TwoMassForm<double> chain = designedChain(m2);
    const OnePeriodicOrbit<double> end = grazingEnd(chain);
    const State star = gloData(chain, lambdaStar(chain));
    EXPECT_EQ(end.postImpact.u1, star.u1);
    EXPECT_EQ(end.T, twoPi<double>() / chain.omegaSlow);
    const std::vector<OnePeriodicOrbit<double>> family = onePeriodicFamily(chain, 100);
    const OnePeriodicOrbit<double>& last = family.back();  // T = T2 (1 - 2^-40)
    ASSERT_TRUE(last.admissible) << "m2 = " << m2;
    EXPECT_LT(last.V, 0);
    EXPECT_LT(std::abs(last.V), 1e-10);
    EXPECT_NEAR(last.postImpact.u1, end.postImpact.u1, 1e-10 * (1 + std::abs(end.postImpact.u1))) << "m2 = " << m2;
    EXPECT_NEAR(last.energy, end.energy, 1e-10 * end.energy) << "m2 = " << m2;
    // the approach is monotone in V: |V| shrinks as T -> T2
    double previous = INFINITY;
    for (const OnePeriodicOrbit<double>& p : family) {
      if (p.T < 0.99 * end.T || !p.admissible) continue;
      EXPECT_LT(std::abs(p.V), previous);
      previous = std::abs(p.V);
    }
  }
}

TEST(FamilyTest, periodsAreSortedInsideTheOpenInterval) {
  const TwoMassForm<double> chain = designedChain(0.5);
  const double T2 = twoPi<double>() / chain.omegaSlow;
  const std::vector<OnePeriodicOrbit<double>> family = onePeriodicFamily(chain, 99);
  ASSERT_GE(family.size(), 99u);
  for (std::size_t i = 0; i < family.size(); ++i) {
    EXPECT_GT(family[i].T, 0);
    EXPECT_LT(family[i].T, T2);
    if (i > 0) { EXPECT_GT(family[i].T, family[i - 1].T); }
  }
}

}  // namespace
}  // namespace grazelab::core
