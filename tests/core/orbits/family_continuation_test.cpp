// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Families of periodic impacting orbits continued in energy (docs/model.md section 10): the
// 1IPP family continued in energy is the closed form's family in the period, point for point;
// its flips are where the closed form's are; it ends on GLO_lambda*; the atlas's families born
// at flips have twice the impacts and period, and every orbit on them is admissible.
#include <gtest/gtest.h>

#include <cmath>

#include "core/model/two_mass_form.h"
#include "core/orbits/modes_atlas.h"
#include "core/orbits/special_orbits.h"
#include "core/orbits/family_continuation.h"
#include "core/orbits/starts.h"

namespace grazelab::core {
namespace {

TwoMassForm<double> resonantChain(double m2, Branch branch = Branch::Upper) {
  return *makeTwoMassForm(*designedModel(1.0, m2, 1.0, 1.0, branch)).chain;
}

double slowPeriod(const TwoMassForm<double>& chain) { return twoPi<double>() / chain.omegaSlow; }

double grazingEnergy(const TwoMassForm<double>& chain) {
  return physicalEnergy(chain, gloData(chain, lambdaStar(chain)));
}

ContinuationOptions<double> range(const TwoMassForm<double>& chain) {
  ContinuationOptions<double> options;
  options.energyLow = grazingEnergy(chain) / 100;
  options.energyHigh = grazingEnergy(chain) * 1000;
  return options;
}

TEST(PeriodicContinuationTest, theOnePeriodicFamilyInEnergyIsTheClosedFormInThePeriod) {
  for (const double m2 : {0.3, 0.5}) {
    const TwoMassForm<double> chain = resonantChain(m2);
    const double T2 = slowPeriod(chain);
    const PeriodicOrbit<double> start = *onePeriodicOrbitStability(chain, 0.9 * T2).orbit;
    for (int direction : {-1, 1}) {
      const ContinuedFamily<double> family = continueFamily(chain, start, direction, range(chain));
      ASSERT_GT(family.orbits.size(), 20u);
      for (std::size_t i = 0; i < family.orbits.size(); i += 7) {
        const FamilyOrbit<double>& orbit = family.orbits[i];
        // the closed form at the continued orbit's period: the same orbit
        const OrbitSearch<double> closed = onePeriodicOrbitStability(chain, orbit.period);
        ASSERT_TRUE(closed.orbit) << closed.problem << " at T/T2 = " << orbit.period / T2;
        EXPECT_NEAR(orbit.state.u1, closed.orbit->state.u1, 1e-9 * std::max(1.0, std::abs(orbit.state.u1)));
        EXPECT_NEAR(orbit.energy, closed.orbit->energy, 1e-9 * orbit.energy);
        EXPECT_NEAR(orbit.trace, closed.orbit->trace, 1e-7 * std::max(1.0, std::abs(orbit.trace)));
        EXPECT_NEAR(orbit.state.v1, 0.0, 1e-9);  // type A all along
      }
    }
  }
}

TEST(PeriodicContinuationTest, itsFlipsAreTheClosedFormsAndItEndsOnTheGrazingOrbit) {
  const TwoMassForm<double> chain = resonantChain(0.5);
  const double T2 = slowPeriod(chain);
  const PeriodicOrbit<double> start = *onePeriodicOrbitStability(chain, 0.9 * T2).orbit;
  const ContinuedFamily<double> up = continueFamily(chain, start, 1, range(chain));
  const ContinuedFamily<double> down = continueFamily(chain, start, -1, range(chain));
  std::vector<double> continued;
  for (const auto& b : up.bifurcations) {
    if (b.kind == PointKind::PeriodDoubling) continued.push_back(b.energy);
  }
  std::vector<double> closed;
  for (const auto& b : onePeriodicBifurcations(chain, 2000)) {
    if (b.kind == PointKind::PeriodDoubling) closed.push_back(b.energy);
  }
  std::sort(continued.begin(), continued.end());
  std::sort(closed.begin(), closed.end());
  ASSERT_EQ(continued.size(), 2u);
  ASSERT_EQ(closed.size(), continued.size());
  for (std::size_t i = 0; i < closed.size(); ++i) EXPECT_NEAR(continued[i], closed[i], 1e-9 * closed[i]);
  // this chain's flips: T = 2 T2 / 3 at E = 2, and E = 0.7
  EXPECT_NEAR(closed[0], 0.7, 1e-12);
  EXPECT_NEAR(closed[1], 2.0, 1e-12);
  EXPECT_EQ(down.end.kind, PointKind::GrazingOrbit);
  EXPECT_NEAR(down.end.gloLambda, lambdaStar(chain), 1e-6);  // Theorem 2.1: it ends on GLO(lambda*)
  // located in the energy past where the arclength steps stall (impact speeds go like the root
  // of the distance to the end)
  EXPECT_NEAR(down.end.lastEnergy, grazingEnergy(chain), 1e-12 * grazingEnergy(chain));
  // and named by its limit, GLO(lambda*) exactly (Theorem 2.1)
  EXPECT_TRUE(down.end.exact);
  EXPECT_EQ(down.end.energy, grazingEnergy(chain));
  EXPECT_EQ(down.end.period, T2);
  EXPECT_EQ(up.end.kind, PointKind::EnergyLimit);
}

TEST(PeriodicContinuationTest, theAtlasFamiliesBornAtFlipsHaveTwiceTheImpactsAndAreAdmissible) {
  const TwoMassForm<double> chain = resonantChain(0.5);
  std::vector<int> seen;
  const ModesAtlas<double> atlas = computeModesAtlas<double>(chain, 4, grazingEnergy(chain) / 100, grazingEnergy(chain) * 1e4, {},
                                                     [&](const ModeFamily<double>& f) { seen.push_back(f.id); });
  ASSERT_TRUE(atlas.complete);
  EXPECT_EQ(seen.size(), atlas.families.size());
  int born = 0;
  for (const ModeFamily<double>& family : atlas.families) {
    ASSERT_FALSE(family.orbits.empty());
    EXPECT_TRUE(family.symmetry == "A" || family.symmetry == "B") << family.id;
    if (family.birth == Birth::PeriodDoubling) {
      ++born;
      const ModeFamily<double>& parent = atlas.families[std::size_t(family.parent)];
      EXPECT_EQ(family.impacts, 2 * parent.impacts);
      EXPECT_NEAR(family.orbits.front().period, 2 * family.bornPeriod, 1e-2 * family.bornPeriod);
      EXPECT_NEAR(family.orbits.front().energy, family.bornEnergy, 1e-2 * family.bornEnergy);
    }
    // every orbit of the family, taken again from its table's state, is an admissible orbit
    for (std::size_t i = 0; i < family.orbits.size(); i += 5) {
      const PeriodicOrbit<double> orbit =
          evaluateOrbit(chain, family.orbits[i].state, family.impacts, 1e6 * defaultCloseTolerance<double>());
      EXPECT_TRUE(orbit.admissible) << "family " << family.id << " orbit " << i << ": " << orbit.reason;
      EXPECT_LT(std::abs(orbit.checks.detMinus1), 1e-10) << "family " << family.id << " orbit " << i;
    }
  }
  EXPECT_GE(born, 3);  // two 2-impact families from the 1IPP flips, a 4-impact one from a 2-impact flip
}

// The default chain's atlas has symmetric families of both kinds; on a type-B orbit the
// impacts come in mirror pairs (u1, v1), (u1, -v1), on a type-A one every impact has v1 = 0,
// checked on the orbit's own path.
TEST(PeriodicContinuationTest, theAtlasHasSymmetricFamiliesOfBothTypes) {
  const TwoMassForm<double> chain = resonantChain(0.5);
  const ModesAtlas<double> atlas = computeModesAtlas<double>(chain, 2, grazingEnergy(chain) / 100, grazingEnergy(chain) * 1e4);
  bool a = false, b = false;
  for (const ModeFamily<double>& family : atlas.families) {
    const FamilyOrbit<double>& middle = family.orbits[family.orbits.size() / 2];
    const PeriodicOrbit<double> orbit = evaluateOrbit(chain, middle.state, family.impacts, 1e-9);
    ASSERT_TRUE(orbit.admissible) << orbit.reason;
    const double speed = chain.omegaSlow * chain.model.gap;
    if (family.symmetry == "A") {
      a = true;
      for (const auto& event : orbit.events) EXPECT_LT(std::abs(event.after.v1), 1e-9 * speed);
    }
    if (family.symmetry == "B") {
      b = true;
      ASSERT_EQ(orbit.events.size(), 2u);
      const auto& first = orbit.events[0].after;
      const auto& second = orbit.events[1].after;
      EXPECT_NEAR(first.u1, second.u1, 1e-9);
      EXPECT_NEAR(first.v1, -second.v1, 1e-9 * speed);
      EXPECT_GT(std::abs(first.v1), 1e-3 * speed);  // not type A in disguise
    }
  }
  EXPECT_TRUE(a);
  EXPECT_TRUE(b);
  // the 2-impact family born at E = 2 and the 1IPP part below T1 end on GLOM1 (lambda = 0,
  // E = 1.5 for this chain)
  int onGlom1 = 0;
  for (const ModeFamily<double>& family : atlas.families) {
    for (const FamilyEnd<double>* end : {&family.end, &family.startEnd}) {
      if (end->kind != PointKind::GrazingOrbit || std::abs(end->gloLambda) > 1e-3) continue;
      ++onGlom1;
      // Newton at fixed energy cannot follow the family to this end (DP - I turns singular):
      // the last orbit is where the arclength steps stalled, and the end, whose period tends
      // to an odd number of fast periods, is GLOM1 itself
      EXPECT_NEAR(end->lastEnergy, 1.5, 1e-5);
      EXPECT_TRUE(end->exact);
      EXPECT_EQ(end->gloLambda, 0.0);
      EXPECT_NEAR(end->energy, 1.5, 1e-15);
    }
  }
  EXPECT_EQ(onGlom1, 2);
}

TEST(PeriodicContinuationTest, aStopLeavesTheAtlasIncomplete) {
  const TwoMassForm<double> chain = resonantChain(0.5);
  std::stop_source stopper;
  const ModesAtlas<double> atlas = computeModesAtlas<double>(chain, 4, grazingEnergy(chain) / 100, grazingEnergy(chain) * 1e4,
                                                     stopper.get_token(),
                                                     [&](const ModeFamily<double>&) { stopper.request_stop(); });
  EXPECT_FALSE(atlas.complete);
}

}  // namespace
}  // namespace grazelab::core
