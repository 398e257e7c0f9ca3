// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The atlas on many chains, not only the note's (issue "The atlas right on every chain"): over
// a sweep of mass ratios in (0, 9/16] on both design branches, two algorithms that must agree
// (the closed form's scan in the period and the pseudo-arclength continuation in the energy)
// give the same flips of the 1IPP family; every located flip, fold and branch point has the
// trace its definition says; every flip in the range gives its own family (twice its period,
// near its orbit) or says why not; no family jumps onto another; narrow ranges keep a flip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/model/two_mass_form.h"
#include "core/orbits/modes_atlas.h"
#include "core/orbits/special_orbits.h"
#include "core/orbits/family_continuation.h"
#include "core/orbits/periodic_orbit.h"
#include "core/orbits/starts.h"

namespace grazelab::core {
namespace {

TwoMassForm<double> resonantChain(double m2, Branch branch) {
  return *makeTwoMassForm(*designedModel(1.0, m2, 1.0, 1.0, branch)).chain;
}

double grazingEnergy(const TwoMassForm<double>& chain) {
  return physicalEnergy(chain, gloData(chain, lambdaStar(chain)));
}

struct Case {
  double m2;
  Branch branch;
};

// chains the note does not name, both branches (the lower one holds close pairs of flips)
std::vector<Case> sweep() {
  std::vector<Case> cases;
  for (const double m2 : {0.05, 0.1, 0.2, 0.3, 0.4, 0.45, 0.5, 0.52, 0.55, 0.5625}) {
    cases.push_back({m2, Branch::Upper});
    cases.push_back({m2, Branch::Lower});
  }
  return cases;
}

std::string name(const Case& c) {
  return "m2/m1 = " + std::to_string(c.m2) + (c.branch == Branch::Upper ? " upper" : " lower");
}

TEST(AtlasChainsTest, theScanAndTheContinuationFindTheSameFlipsOfTheOnePeriodicFamily) {
  for (const Case& c : sweep()) {
    const TwoMassForm<double> chain = resonantChain(c.m2, c.branch);
    const OnePeriodicScan<double> scan = scanOnePeriodicFamily(chain, 400);
    ASSERT_TRUE(scan.complete);
    // the part that ends on the grazing orbit at T2, continued in energy from an orbit of it
    const double E0 = grazingEnergy(chain);
    ContinuationOptions<double> options;
    options.energyLow = E0 / 100;
    options.energyHigh = E0 * 1000;
    const PeriodicOrbit<double>& start = scan.orbits.back();  // nearest T2
    const ContinuedFamily<double> up = continueFamily(chain, start, +1, options);
    double lowest = start.energy, highest = start.energy;
    for (const FamilyOrbit<double>& o : up.orbits) {
      lowest = std::min(lowest, o.energy);
      highest = std::max(highest, o.energy);
    }
    std::vector<double> continued;
    for (const FamilyBifurcation<double>& b : up.bifurcations) {
      if (b.kind != PointKind::PeriodDoubling) continue;
      EXPECT_TRUE(b.checked) << name(c) << ": a flip of the continuation not solved, trace " << b.trace;
      continued.push_back(b.energy);
    }
    // every flip of the scan in the part the continuation covered, and no other
    std::vector<double> closed;
    const double lastPartStart = [&] {
      double T = 0;
      for (const FamilyBifurcation<double>& b : scan.points) {
        if (b.kind == PointKind::InteriorGrazing || b.kind == PointKind::ImpactSpeedZero ||
            b.kind == PointKind::EnergyLimit || b.kind == PointKind::Undecided) {
          T = b.T;
        }
      }
      return T;
    }();
    for (const FamilyBifurcation<double>& b : scan.points) {
      if (b.kind != PointKind::PeriodDoubling || b.T < lastPartStart) continue;
      if (b.energy < lowest || b.energy > highest) continue;
      EXPECT_TRUE(b.checked) << name(c);
      EXPECT_NEAR(b.trace, -2.0, 1e-6) << name(c);
      closed.push_back(b.energy);
    }
    ASSERT_EQ(continued.size(), closed.size()) << name(c);
    std::sort(continued.begin(), continued.end());
    std::sort(closed.begin(), closed.end());
    for (std::size_t i = 0; i < closed.size(); ++i) {
      EXPECT_NEAR(continued[i], closed[i], 1e-8 * closed[i]) << name(c) << ", flip " << i;
    }
  }
}

TEST(AtlasChainsTest, theLowerBranchsClosePairOfFlipsGivesBothFamilies) {
  // m2/m1 = 1/2, lower design: the trace dips below -2 between E = 0.2141 and 0.2337 only
  const TwoMassForm<double> chain = resonantChain(0.5, Branch::Lower);
  const double E0 = grazingEnergy(chain);
  const ModesAtlas<double> atlas = computeModesAtlas(chain, 2, E0 / 100, E0 * 10000);
  ASSERT_TRUE(atlas.complete);
  std::vector<const FamilyBifurcation<double>*> flips;
  for (const ModeFamily<double>& family : atlas.families) {
    if (family.impacts != 1) continue;
    for (const FamilyBifurcation<double>& b : family.bifurcations) {
      if (b.kind == PointKind::PeriodDoubling) flips.push_back(&b);
    }
  }
  ASSERT_EQ(flips.size(), 2u);
  EXPECT_NEAR(flips[0]->energy + flips[1]->energy, 0.2141176470588235 + 0.2337472607742878, 1e-12);
  std::set<int> born;
  for (const FamilyBifurcation<double>* flip : flips) {
    ASSERT_GE(flip->born, 0) << flip->birthProblem;
    born.insert(flip->born);
    const ModeFamily<double>& family = atlas.families[std::size_t(flip->born)];
    EXPECT_EQ(family.impacts, 2);
    // born here: twice this flip's period, not the other's (they differ by 1.4 %)
    EXPECT_NEAR(family.orbits.front().period, 2 * flip->T, 2e-3 * flip->T);
  }
  EXPECT_EQ(born.size(), 2u);  // two families, one per flip
}

// Along every family of the atlas: the rows are admissible orbits of its impacts, neighbours
// are near each other (no jump onto another family), and every located special point has the
// trace its definition says.
void expectSoundAtlas(const TwoMassForm<double>& chain, const ModesAtlas<double>& atlas, const std::string& label) {
  for (const ModeFamily<double>& family : atlas.families) {
    for (std::size_t i = 0; i < family.orbits.size(); i += 5) {
      const PeriodicOrbit<double> again =
          evaluateOrbit(chain, family.orbits[i].state, family.impacts, 1e6 * defaultCloseTolerance<double>());
      EXPECT_TRUE(again.admissible) << label << ", family " << family.id << ", row " << i << ": " << again.reason;
    }
    for (std::size_t i = 1; family.impacts > 1 && i < family.orbits.size(); ++i) {
      const FamilyOrbit<double>& a = family.orbits[i - 1];
      const FamilyOrbit<double>& b = family.orbits[i];
      // steps are at most 0.1 in ln E and in u1 / d
      EXPECT_LT(std::abs(std::log(b.energy / a.energy)), 0.2) << label << ", family " << family.id << ", row " << i;
      EXPECT_LT(std::abs(b.state.u1 - a.state.u1) / chain.model.gap, 0.2) << label << ", family " << family.id;
      // and the period is continuous (an end located in the energy once took a 4-impact orbit
      // of period 27.2 beside the family's 32.6)
      EXPECT_LT(std::abs(b.period / a.period - 1), 0.05) << label << ", family " << family.id << ", row " << i;
    }
    for (const FamilyBifurcation<double>& b : family.bifurcations) {
      if (!b.checked) continue;
      if (b.kind == PointKind::PeriodDoubling) { EXPECT_NEAR(b.trace, -2.0, 1e-6) << label; }
      if (b.kind == PointKind::Fold || b.kind == PointKind::BranchPoint) { EXPECT_NEAR(b.trace, 2.0, 1e-6) << label; }
    }
  }
}

TEST(AtlasChainsTest, onEveryChainEveryFlipGivesItsFamilyOrSaysWhyAndNoFamilyJumps) {
  for (const Case& c : sweep()) {
    const TwoMassForm<double> chain = resonantChain(c.m2, c.branch);
    const double E0 = grazingEnergy(chain);
    const ModesAtlas<double> atlas = computeModesAtlas(chain, 4, E0 / 10, E0 * 100);
    ASSERT_TRUE(atlas.complete);
    expectSoundAtlas(chain, atlas, name(c));
    std::set<int> born;
    for (const ModeFamily<double>& family : atlas.families) {
      if (family.impacts != 1) continue;
      for (const FamilyBifurcation<double>& b : family.bifurcations) {
        if (b.kind != PointKind::PeriodDoubling) continue;
        EXPECT_TRUE(b.born >= 0 || !b.birthProblem.empty()) << name(c) << ": a flip with no family and no word";
        // every flip of these chains has its family (an independent mpmath continuation found
        // each; m2/m1 = 0.52 upper's, at 6 sqrt(offset) from the flip, was once missed)
        EXPECT_GE(b.born, 0) << name(c) << ", flip at E = " << b.energy << ": " << b.birthProblem;
        if (b.born < 0) continue;
        const ModeFamily<double>& child = atlas.families[std::size_t(b.born)];
        EXPECT_EQ(child.impacts, 2) << name(c);
        // the family met again at a second flip was born at the first
        if (child.parent != family.id || child.bornEnergy != b.energy) {
          EXPECT_EQ(child.end.kind, PointKind::PeriodDoubling) << name(c);
          continue;
        }
        EXPECT_NEAR(child.orbits.front().period, 2 * b.T, 1e-2 * b.T) << name(c);
        EXPECT_TRUE(born.insert(b.born).second) << name(c) << ": one family for two flips";
      }
    }
  }
}

TEST(AtlasChainsTest, aNarrowRangeAroundAFlipKeepsItWithItsFamily) {
  const TwoMassForm<double> chain = resonantChain(0.5, Branch::Upper);
  // the default chain's flip at E = 0.7, in a range of +-1e-5 around it and in ranges ending at it
  for (const auto& [low, high] : {std::pair{0.69999, 0.70001}, std::pair{0.5, 0.7}, std::pair{0.7, 1.0}}) {
    const ModesAtlas<double> atlas = computeModesAtlas(chain, 2, low, high);
    ASSERT_TRUE(atlas.complete);
    bool found = false;
    for (const ModeFamily<double>& family : atlas.families) {
      for (const FamilyBifurcation<double>& b : family.bifurcations) {
        if (b.kind != PointKind::PeriodDoubling || std::abs(b.energy - 0.7) > 1e-12) continue;
        found = true;
        EXPECT_GE(b.born, 0) << low << ":" << high << ": " << b.birthProblem;
      }
    }
    EXPECT_TRUE(found) << "the flip at E = 0.7 is missing from " << low << ":" << high;
  }
}

TEST(AtlasChainsTest, theContinuationDoesNotJumpOntoAnotherFamily) {
  // m2/m1 = 0.55, lower design: the 2-impact family of symmetry B goes on to GLOM1 at
  // E = 2.585410196624968 (T -> 3 T1); it once jumped onto the type-A family at E = 2.44
  const TwoMassForm<double> chain = resonantChain(0.55, Branch::Lower);
  const double E0 = grazingEnergy(chain);
  const ModesAtlas<double> atlas = computeModesAtlas(chain, 4, E0 / 100, E0 * 10000);
  ASSERT_TRUE(atlas.complete);
  expectSoundAtlas(chain, atlas, "m2 = 0.55 lower");
  bool glom1 = false;
  for (const ModeFamily<double>& family : atlas.families) {
    if (family.impacts == 2 && family.symmetry == "B") {
      EXPECT_EQ(family.end.kind, PointKind::GrazingOrbit);
      EXPECT_TRUE(family.end.exact);
      EXPECT_NEAR(family.end.energy, 2.585410196624968, 1e-12);
      glom1 = true;
    }
    // the 4-impact family's branch point where the trace is 2 (1.3974598034474)
    for (const FamilyBifurcation<double>& b : family.bifurcations) {
      if (b.kind == PointKind::BranchPoint && family.impacts == 4) {
        EXPECT_NEAR(b.energy, 1.3974598034474, 1e-9);
      }
    }
  }
  EXPECT_TRUE(glom1);
}

TEST(AtlasChainsTest, aScaledChainHasTheSameAtlas) {
  // the physics is scale-free: a gap of 1e-9 or 1e6 gives the same families, ends and flips,
  // energies times d^2 (the birth search once pushed by d twice and found nothing at 1e6)
  for (const Branch branch : {Branch::Upper, Branch::Lower}) {
    const auto atlasOf = [&](double gap) {
      const TwoMassForm<double> chain = *makeTwoMassForm(*designedModel(1.0, 0.5, 1.0, gap, branch)).chain;
      const double E0 = grazingEnergy(chain);
      return computeModesAtlas(chain, 2, E0 / 100, E0 * 10000);
    };
    const ModesAtlas<double> unit = atlasOf(1.0);
    for (const double gap : {1e-9, 1e6}) {
      const ModesAtlas<double> scaled = atlasOf(gap);
      ASSERT_EQ(scaled.families.size(), unit.families.size()) << "gap " << gap;
      for (std::size_t f = 0; f < unit.families.size(); ++f) {
        const ModeFamily<double>& a = unit.families[f];
        const ModeFamily<double>& b = scaled.families[f];
        EXPECT_EQ(b.impacts, a.impacts);
        EXPECT_EQ(b.end.kind, a.end.kind) << "gap " << gap << ", family " << f;
        ASSERT_EQ(b.bifurcations.size(), a.bifurcations.size()) << "gap " << gap << ", family " << f;
        for (std::size_t i = 0; i < a.bifurcations.size(); ++i) {
          EXPECT_EQ(b.bifurcations[i].kind, a.bifurcations[i].kind);
          EXPECT_NEAR(b.bifurcations[i].energy / (gap * gap), a.bifurcations[i].energy, 1e-9 * a.bifurcations[i].energy);
          EXPECT_EQ(b.bifurcations[i].born >= 0, a.bifurcations[i].born >= 0) << "gap " << gap;
        }
      }
    }
  }
}

TEST(AtlasChainsTest, theEnergyErrorOfEverySpecialPointHoldsAgainstALongerPrecision) {
  // on light second masses the 2-impact families' flips are near-degenerate (the trace barely
  // crosses -2, and moves by 1e-9 for a state moved by 1e-14): double misplaces them by up to
  // 1e-10 relative. Each printed energy carries an error estimate that must cover that,
  // checked against long double (2^11 times finer), and not be vacuous
  for (const double m2 : {0.2, 0.35, 0.52}) {
    const auto atlasIn = [m2](auto zero) {
      using S = decltype(zero);
      const TwoMassForm<S> chain = *makeTwoMassForm(*designedModel(S(1), S(m2), S(1), S(1), Branch::Lower)).chain;
      const S E0 = physicalEnergy(chain, gloData(chain, lambdaStar(chain)));
      return computeModesAtlas(chain, 4, S(E0 / 10), S(E0 * 100));
    };
    const ModesAtlas<double> inDouble = atlasIn(0.0);
    const ModesAtlas<long double> inLong = atlasIn(0.0L);
    int compared = 0;
    for (const ModeFamily<double>& family : inDouble.families) {
      for (const FamilyBifurcation<double>& b : family.bifurcations) {
        if (!b.checked || b.kind == PointKind::Undecided) continue;
        ASSERT_LT(b.energyError, 1e-6 * b.energy) << "m2 " << m2;
        long double nearest = INFINITY;
        for (const ModeFamily<long double>& other : inLong.families) {
          if (other.impacts != family.impacts) continue;
          for (const FamilyBifurcation<long double>& c : other.bifurcations) {
            if (c.kind == b.kind) nearest = std::min(nearest, std::abs(c.energy - (long double)b.energy));
          }
        }
        EXPECT_LE(double(nearest), b.energyError) << "m2 " << m2 << ", " << family.impacts << "-impact "
                                                   << toString(b.kind) << " at E = " << b.energy;
        ++compared;
      }
    }
    EXPECT_GE(compared, 4) << "m2 " << m2;
  }
}

TEST(AtlasChainsTest, aNewtonThatStallsOnAPlateauGivesNoOrbit) {
  // next to a near-degenerate flip of a 2-impact family, P^4 is close to the identity along the
  // flip's eigenvector: Newton once stopped there at a residual of 1e-9 (within the tolerance
  // amplified for rounding) with a step as long as the orbit's distance from the flip still to
  // go, and the atlas gave a 4-impact family on the wrong side of the flip, ended after one row
  const TwoMassForm<double> chain = resonantChain(0.2, Branch::Lower);
  const OrbitSearch<double> search = findOrbit(chain, 0.55722626556298327, 1.0434494716098159, 8.17961466548961e-05, 4);
  EXPECT_FALSE(search.orbit.has_value()) << "residual " << search.orbit->checks.periodicityResidual;
  // a converged orbit's step is far below its residual's scale
  const OrbitSearch<double> born = findOrbit(chain, 0.55723741026538198, 1.0434444625270811, 0.0057300888602593606, 4);
  ASSERT_TRUE(born.orbit.has_value()) << born.problem;
  EXPECT_LT(born.correction, 1e-9);
}

}  // namespace
}  // namespace grazelab::core
