// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/orbits.cpp.
#include "core/orbits/special_orbits.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/solver/free_flight.h"
#include "support/cases.h"
#include "support/physical_flight.h"

namespace grazelab::core {
namespace {

TEST(Orbits, GlomDataSitOnTheGrazingStartPlane) {
  const Model model = testing::resonantChain(0.5);
  const Modes modes = computeModes(model);
  for (Mode mode : {Mode::Fast, Mode::Slow}) {
    const State state = glomData(model, modes, mode);
    EXPECT_EQ(state.u2, model.gap);
    EXPECT_EQ(state.v1, 0);
    EXPECT_EQ(state.v2, 0);
  }
  // upper branch, m2 = 1/2: shapes (-1, 1) fast and (1/2, 1) slow
  EXPECT_NEAR(glomData(model, modes, Mode::Fast).u1, -1.0, 1e-14);
  EXPECT_NEAR(glomData(model, modes, Mode::Slow).u1, 0.5, 1e-14);
}

TEST(Orbits, GloLambdaFlightIsTheConvexCombinationOfCosines) {
  // u2(t) = gap [(1 - lambda) cos(w1 t) + lambda cos(w2 t)]
  for (const auto& chain : testing::resonantChains()) {
    const Model& model = chain.model;
    const Modes modes = computeModes(model);
    for (double lambda : {-0.5, 0.0, 0.3, 8.0 / 9.0, 4.0 / 3.0, 2.0}) {
      const testing::PhysicalFlight flight(model, gloData(model, modes, lambda));
      for (double fraction : {0.1, 0.37, 0.5, 0.81}) {
        const double t = fraction * modes.T2;
        const double expected = model.gap * ((1 - lambda) * std::cos(modes.omegaFast * t) +
                                             lambda * std::cos(modes.omegaSlow * t));
        EXPECT_NEAR(flight.at(t).u2, expected, 1e-13 * model.gap) << chain.name << " " << lambda;
      }
    }
  }
}

TEST(Orbits, LemmaTwoPointOneClassification) {
  EXPECT_EQ(classifyGlo(-1e-9), GloKind::ImpactsFollow);
  EXPECT_EQ(classifyGlo(0.0), GloKind::Grazing);
  EXPECT_EQ(classifyGlo(1.0), GloKind::Grazing);
  EXPECT_EQ(classifyGlo(4.0 / 3.0), GloKind::Grazing);
  EXPECT_EQ(classifyGlo(1.34), GloKind::StickingStart);
  // lambda > 4/3 means u1 > gap (pressed on the stop), lambda < 4/3 u1 < gap
  const Model model = testing::resonantChain(0.5);
  const Modes modes = computeModes(model);
  EXPECT_GT(gloData(model, modes, 1.34).u1, model.gap);
  EXPECT_LT(gloData(model, modes, 1.33).u1, model.gap);
  EXPECT_NEAR(gloData(model, modes, 4.0 / 3.0).u1, model.gap, 1e-15);
}

TEST(Orbits, LambdaStarClosedForms) {
  // upper branch m2 = 1/2: P21^2 = 2/3, P22^2 = 4/3, lambda* = 8/9
  const Modes upper = computeModes(testing::resonantChain(0.5));
  EXPECT_NEAR(lambdaStar(upper), 8.0 / 9.0, 1e-15);
  for (const auto& chain : testing::resonantChains()) {
    const Modes modes = computeModes(chain.model);
    const double p21 = modes.P(1, 0);
    const double p22 = modes.P(1, 1);
    const double expected = 4 * p22 * p22 / (p21 * p21 + 4 * p22 * p22);
    EXPECT_NEAR(lambdaStar(modes), expected, 1e-15) << chain.name;
    EXPECT_GT(lambdaStar(modes), 0) << chain.name;
    EXPECT_LE(lambdaStar(modes), 1) << chain.name;
  }
}

TEST(Orbits, OnePeriodicDataJustBelowT2AreAdmissible) {
  for (const auto& chain : testing::resonantChains()) {
    const Model& model = chain.model;
    const Modes modes = computeModes(model);
    const OnePeriodicOrbit orbit = onePeriodicOrbit(model, modes, 0.999 * modes.T2);
    EXPECT_TRUE(orbit.admissible) << chain.name << ": " << orbit.reason;
    EXPECT_LT(orbit.V, 0) << chain.name;
    EXPECT_EQ(orbit.postImpact.u2, model.gap);
    EXPECT_EQ(orbit.postImpact.v1, 0);
  }
}

TEST(Orbits, OnePeriodicFlightThatTouchesEarlyIsRejected) {
  // for m2/m1 = 1e-4 the 1IPP data of period 0.95 T2 come back to the stop near T2 / 2
  const Model model = testing::resonantChain(1e-4);
  const Modes modes = computeModes(model);
  const OnePeriodicOrbit orbit = onePeriodicOrbit(model, modes, 0.95 * modes.T2);
  EXPECT_FALSE(orbit.admissible);
  EXPECT_NE(orbit.reason.find("not at the period"), std::string::npos) << orbit.reason;
}

TEST(Orbits, OnePeriodicDataAreRejectedWithAReason) {
  const Model model = testing::resonantChain(0.5);
  const Modes modes = computeModes(model);
  const OnePeriodicOrbit multiple = onePeriodicOrbit(model, modes, modes.T2);
  EXPECT_FALSE(multiple.admissible);
  EXPECT_NE(multiple.reason.find("multiple"), std::string::npos) << multiple.reason;
  const OnePeriodicOrbit above = onePeriodicOrbit(model, modes, 1.05 * modes.T2);
  EXPECT_FALSE(above.admissible);
  EXPECT_FALSE(above.reason.empty());
  EXPECT_FALSE(onePeriodicOrbit(model, modes, -1).admissible);
  EXPECT_FALSE(onePeriodicOrbit(model, modes, std::nan("")).admissible);
}

// The explorer's T/T2 slider starts at this end: every period above it must be admissible
// (sampled finely), the ones just below not, and the end must not depend on the grazing side.
TEST(Orbits, OnePeriodicFamilyLowerEndBoundsTheAdmissiblePeriods) {
  for (const auto& chain : testing::resonantChains()) {
    const Model& model = chain.model;
    const Modes modes = computeModes(model);
    const double low = onePeriodicLowerEnd(model, modes);
    ASSERT_GT(low, 0) << chain.name;
    ASSERT_LT(low, modes.T2) << chain.name;
    for (int i = 1; i < 400; ++i) {
      const double T = low + (modes.T2 - low) * i / 400.0;
      EXPECT_TRUE(onePeriodicOrbit(model, modes, T).admissible) << chain.name << " T/T2 " << T / modes.T2;
    }
    EXPECT_FALSE(onePeriodicOrbit(model, modes, low - 1e-9 * modes.T2).admissible) << chain.name;
  }
  // a value measured with the command line's --onepp by bisection: 0.6024 T2 for m2/m1 = 1/2
  const Model half = testing::resonantChain(0.5);
  EXPECT_NEAR(onePeriodicLowerEnd(half, computeModes(half)) / computeModes(half).T2, 0.6024, 1e-3);
}

}  // namespace
}  // namespace grazelab::core
