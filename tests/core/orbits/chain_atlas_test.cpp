// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/orbits/chain_atlas.cpp, the atlas of any chain's nonsmooth modes. On two-mass
// chains of both design branches it is the two-mass atlas (an independent code: the note's 2 x 2
// traces and its own continuation): the same families, the same period doublings, the same
// ends. On random chains of three and four masses every family is made of admissible orbits of
// its impacts, every doubling is switched at or said why not, and a family born there starts
// next to it with twice its period. A chain scaled in mass and in length has the same atlas, its
// energies scaled.
#include "core/orbits/chain_atlas.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/model/two_mass_form.h"
#include "core/orbits/chain_onepp.h"
#include "core/orbits/modes_atlas.h"
#include "core/orbits/periodic_orbit.h"
#include "core/orbits/special_orbits.h"
#include "support/random_chains.h"

namespace grazelab::core {
namespace {

using test_chains::randomChain;

template <typename S>
std::vector<const ChainAtlasFamily<S>*> familiesOf(const ChainAtlas<S>& atlas, int impacts) {
  std::vector<const ChainAtlasFamily<S>*> out;
  for (const ChainAtlasFamily<S>& family : atlas.families) {
    if (family.path.impacts == impacts) out.push_back(&family);
  }
  return out;
}

// The atlas's options over the chain's default energy range.
ChainAtlasOptions<double> defaultOptions(const ReadyChain& ready, int maxImpacts, int maxOrbitsPerFamily) {
  const AtlasEnergyRange<double> range = defaultChainAtlasEnergyRange(ready);
  ChainAtlasOptions<double> options;
  options.maxImpacts = maxImpacts;
  options.energyLow = range.low;
  options.energyHigh = range.high;
  options.maxOrbitsPerFamily = maxOrbitsPerFamily;
  return options;
}

// A designed two-mass chain's atlas to `maxImpacts` by the two-mass code and by the chain atlas,
// over the two-mass atlas's default energy range
struct BothAtlases {
  std::string name;
  TwoMassForm<double> form;
  ModesAtlas<double> two;
  ChainAtlas<double> atlas;
};
BothAtlases bothAtlases(double m2, Branch branch, int maxImpacts) {
  BothAtlases both{"m2 " + std::to_string(m2) + (branch == Branch::Upper ? " upper" : " lower"),
                   *makeTwoMassForm(*designedModel(1.0, m2, 1.0, 1.0, branch)).chain, {}, {}};
  const AtlasEnergyRange<double> range = defaultAtlasEnergyRange(both.form);
  both.two = computeModesAtlas(both.form, maxImpacts, range.low, range.high);
  const ReadyChain ready = readyChain(both.form.model);
  ChainAtlasOptions<double> options = defaultOptions(ready, maxImpacts, 2000);
  options.energyLow = range.low;
  options.energyHigh = range.high;
  both.atlas = computeChainAtlas(ready, options);
  return both;
}

TEST(ChainAtlas, OnTwoMassChainsItIsTheTwoMassAtlas) {
  int doublings = 0, born = 0;
  for (const double m2 : {0.1, 0.3, 0.4, 0.5, 0.55}) {
    for (const Branch branch : {Branch::Upper, Branch::Lower}) {
      const auto [name, form, two, atlas] = bothAtlases(m2, branch, 2);
      ASSERT_TRUE(atlas.complete);
      // every flip of the two-mass atlas's 1IPP parts is a doubling of the chain atlas's, at
      // the same energy, and the other way round
      std::vector<double> flips, changes;
      for (const ModeFamily<double>& family : two.families) {
        if (family.impacts != 1) continue;
        for (const FamilyBifurcation<double>& b : family.bifurcations) {
          if (b.kind == PointKind::PeriodDoubling) flips.push_back(b.energy);
        }
      }
      for (const ChainAtlasFamily<double>* family : familiesOf(atlas, 1)) {
        for (const ChainFamilyChange<double>& change : family->path.changes) {
          EXPECT_EQ(change.kind, ChainBifurcationKind::PeriodDoubling)
              << name << ": two masses change only so";
          changes.push_back(change.energy);
          EXPECT_LT(change.energyError, 1e-10 * change.energy) << name;
        }
      }
      ASSERT_EQ(flips.size(), changes.size()) << name;
      std::sort(flips.begin(), flips.end());
      std::sort(changes.begin(), changes.end());
      for (std::size_t i = 0; i < flips.size(); ++i) {
        EXPECT_NEAR(changes[i], flips[i], 1e-10 * flips[i]) << name;
        ++doublings;
      }
      // a 2IPP family born at each of them, as the two-mass atlas has, ending as it does
      for (const ModeFamily<double>& family : two.families) {
        if (family.impacts != 2) continue;
        const ChainAtlasFamily<double>* same = nullptr;
        for (const ChainAtlasFamily<double>* other : familiesOf(atlas, 2)) {
          const ChainFamilyChange<double>& at = atlas.families[std::size_t(other->parent)]
                                                    .path.changes[std::size_t(other->parentChange)];
          if (std::abs(at.energy - family.bornEnergy) < 1e-9 * family.bornEnergy) same = other;
        }
        ASSERT_NE(same, nullptr) << name << ": the family born at E " << family.bornEnergy;
        ++born;
        // each of its orbits admissible by the two-mass code's own evaluator
        double lowest = same->path.orbits.front().energy, highest = lowest;
        for (const ChainPeriodicOrbit& orbit : same->path.orbits) {
          const BasicState<double> state{orbit.state.u[0], orbit.state.u[1], orbit.state.v[0],
                                         orbit.state.v[1]};
          EXPECT_EQ(evaluateOrbit(form, state, 2, 1e-9).refusal, OrbitRefusal::None)
              << name << " E " << orbit.energy;
          lowest = std::min(lowest, orbit.energy);
          highest = std::max(highest, orbit.energy);
        }
        const double last = same->path.orbits.back().energy;
        if (family.end.kind == PointKind::EnergyLimit) {
          EXPECT_EQ(same->lastEnd.kind, ChainFamilyEnd::EnergyLimit) << name;
        } else if (family.end.kind == PointKind::InteriorGrazing) {
          // the same end, or one beyond it: the two-mass continuation names an end where its
          // steps stall next to a flight's maximum nearing the stop, which may be short of a
          // grazing orbit (m2 = 0.1, lower: its end at E 4.27975, the family admissible on to
          // 4.2841, where the impact speeds and the clearance tend to 0 together)
          if (same->lastEnd.kind == ChainFamilyEnd::InteriorGrazing) {
            EXPECT_NEAR(last, family.end.energy, 1e-7 * family.end.energy) << name;
          } else {
            EXPECT_EQ(same->lastEnd.kind, ChainFamilyEnd::GrazingOrbit) << name;
            EXPECT_LE(lowest, family.end.energy) << name;
            EXPECT_GE(highest, family.end.energy) << name;
          }
        } else if (family.end.kind == PointKind::PeriodDoubling) {
          EXPECT_EQ(same->lastEnd.kind, ChainFamilyEnd::MeetsDoubling) << name;
          EXPECT_NEAR(last, family.end.energy, 1e-3 * family.end.energy) << name;
        }
      }
      EXPECT_EQ(familiesOf(atlas, 2).size(),
                std::size_t(std::count_if(two.families.begin(), two.families.end(),
                                          [](const auto& f) { return f.impacts == 2; })))
          << name;
    }
  }
  EXPECT_GE(doublings, 10);
  EXPECT_GE(born, 10);
}

TEST(ChainAtlas, ToFourImpactsItSwitchesAtEveryFlipTheTwoMassAtlasSwitchesAt) {
  // (m2 = 0.1, lower design: the 2IPP family born at E 0.026547, its period near 18.49323 all
  // along, doubles at E 0.52604, where the pair at -1 is one Jordan block: pushed along the vector
  // inverse iteration gives there, no branch was found; the two-mass atlas's 4IPP family is born
  // there)
  int switched = 0;
  for (const double m2 : {0.1, 0.3, 0.5}) {
    for (const Branch branch : {Branch::Upper, Branch::Lower}) {
      const auto [name, form, two, atlas] = bothAtlases(m2, branch, 4);
      ASSERT_TRUE(atlas.complete) << name;
      for (const ModeFamily<double>& family : two.families) {
        if (2 * family.impacts > 4) continue;
        for (const FamilyBifurcation<double>& flip : family.bifurcations) {
          if (flip.kind != PointKind::PeriodDoubling || flip.born < 0) continue;
          // the chain atlas's doubling at that energy, of a family of as many impacts
          const ChainAtlasBranch* same = nullptr;
          for (const ChainAtlasFamily<double>* other : familiesOf(atlas, family.impacts)) {
            for (const ChainAtlasBranch& b : other->branches) {
              const ChainFamilyChange<double>& at = other->path.changes[b.change];
              if (std::abs(at.energy - flip.energy) < 1e-9 * flip.energy) same = &b;
            }
          }
          ASSERT_NE(same, nullptr) << name << ": the flip at E " << flip.energy;
          EXPECT_TRUE(same->outcome == ChainBranchOutcome::Born || same->outcome == ChainBranchOutcome::Reached)
              << name << ": the flip at E " << flip.energy << " gave " << toString(same->outcome) << " ("
              << toString(same->problem) << ")";
          ++switched;
        }
      }
    }
  }
  EXPECT_GE(switched, 14);
}

TEST(ChainAtlas, OnChainsOfThreeAndFourMassesEveryFamilyIsAdmissibleAndEveryDoublingSwitched) {
  std::mt19937 rng(20261206);
  int families = 0, bornHere = 0, doublings = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const MassChain chain = randomChain(rng, 3 + trial % 2);
    const ReadyChain ready = readyChain(chain);
    const ChainAtlasOptions<double> options = defaultOptions(ready, 2, 600);
    const ChainAtlas<double> atlas = computeChainAtlas(ready, options);
    ASSERT_TRUE(atlas.complete);
    for (const ChainAtlasFamily<double>& family : atlas.families) {
      ++families;
      const int k = family.path.impacts;
      for (const ChainPeriodicOrbit& orbit : family.path.orbits) {
        ASSERT_TRUE(orbit.admissible()) << "trial " << trial;
        EXPECT_EQ(orbit.events.size(), std::size_t(k));
        EXPECT_GE(orbit.energy, options.energyLow);
        EXPECT_LE(orbit.energy, options.energyHigh);
      }
      std::size_t branches = 0;
      for (const ChainFamilyChange<double>& change : family.path.changes) {
        ASSERT_LT(change.after + 1, family.path.orbits.size());
        branches += change.kind == ChainBifurcationKind::PeriodDoubling;
      }
      ASSERT_EQ(family.branches.size(), branches)
          << "trial " << trial << ": one outcome per doubling";
      for (const ChainAtlasBranch& branch : family.branches) {
        ++doublings;
        const ChainFamilyChange<double>& at = family.path.changes[branch.change];
        EXPECT_EQ(at.kind, ChainBifurcationKind::PeriodDoubling);
        if (2 * k > options.maxImpacts) {
          EXPECT_EQ(branch.outcome, ChainBranchOutcome::BeyondImpacts);
          continue;
        }
        EXPECT_NE(branch.outcome, ChainBranchOutcome::BeyondImpacts);
        if (branch.outcome == ChainBranchOutcome::NotFound) continue;
        ASSERT_GE(branch.family, 0);
        const ChainAtlasFamily<double>& child = atlas.families[std::size_t(branch.family)];
        EXPECT_EQ(child.path.impacts, 2 * k);
        if (branch.outcome != ChainBranchOutcome::Born) continue;
        ++bornHere;
        EXPECT_EQ(child.parent, family.id);
        const ChainPeriodicOrbit& first = child.path.orbits.front();
        EXPECT_NEAR(first.period, 2 * at.period, 1e-2 * at.period) << "trial " << trial;
        EXPECT_NEAR(first.energy, at.energy, 2e-3 * at.energy) << "trial " << trial;
      }
    }
  }
  EXPECT_GE(families, 8);
  EXPECT_GE(doublings, 3);
  EXPECT_GE(bornHere, 2);
}

TEST(ChainAtlas, EachFamilyIsHeardOnceAsItIsFoundWithThePathTheAtlasKeeps) {
  std::mt19937 rng(20261206);
  const ReadyChain ready = readyChain(randomChain(rng, 3));
  std::vector<ChainAtlasFamily<double>> heard;
  const ChainAtlas<double> atlas =
      computeChainAtlas<double>(ready, defaultOptions(ready, 2, 600), std::stop_token{},
                                [&](const ChainAtlasFamily<double>& family) { heard.push_back(family); });
  ASSERT_TRUE(atlas.complete);
  ASSERT_EQ(heard.size(), atlas.families.size());
  ASSERT_GE(heard.size(), 2u);
  for (std::size_t i = 0; i < heard.size(); ++i) {
    const ChainAtlasFamily<double>& now = heard[i];
    const ChainAtlasFamily<double>& kept = atlas.families[i];
    EXPECT_EQ(now.id, int(i));
    EXPECT_EQ(now.birth, kept.birth);
    EXPECT_EQ(now.parent, kept.parent);
    EXPECT_EQ(now.parentChange, kept.parentChange);
    EXPECT_EQ(now.onePeriod, kept.onePeriod);
    ASSERT_EQ(now.path.orbits.size(), kept.path.orbits.size()) << "family " << i;
    EXPECT_EQ(now.path.orbits.back().energy, kept.path.orbits.back().energy);
    EXPECT_EQ(now.path.changes.size(), kept.path.changes.size());
    EXPECT_EQ(now.lastEnd.kind, kept.lastEnd.kind);
    // (a parent is heard before the families born at its doublings)
    if (now.parent >= 0) {
      EXPECT_LT(now.parent, now.id);
    }
  }
}

TEST(ChainAtlas, AChainScaledInMassAndLengthHasTheSameAtlasItsEnergiesScaled) {
  // masses and springs times a (the frequencies unchanged), the gap times g: every orbit is the
  // same motion in units of g, its energy a g^2 times
  std::mt19937 rng(11);
  const MassChain chain = randomChain(rng, 3);
  MassChain scaled = chain;
  const double a = 7.5, g = 0.03;
  for (double& m : scaled.masses) m *= a;
  for (double& k : scaled.springs) k *= a;
  scaled.rightSpring *= a;
  scaled.gap *= g;
  const ReadyChain one = readyChain(chain), other = readyChain(scaled);
  ChainAtlasOptions<double> options;
  options.maxImpacts = 2;
  const AtlasEnergyRange<double> range = defaultChainAtlasEnergyRange(one);
  options.energyLow = range.low;
  options.energyHigh = range.high;
  const ChainAtlas<double> first = computeChainAtlas(one, options);
  options.energyLow *= a * g * g;
  options.energyHigh *= a * g * g;
  const ChainAtlas<double> second = computeChainAtlas(other, options);
  ASSERT_TRUE(first.complete && second.complete);
  ASSERT_GE(first.families.size(), 2u);
  int changes = 0;
  ASSERT_EQ(first.families.size(), second.families.size());
  for (std::size_t f = 0; f < first.families.size(); ++f) {
    const auto& x = first.families[f].path;
    const auto& y = second.families[f].path;
    EXPECT_EQ(x.impacts, y.impacts);
    ASSERT_EQ(x.changes.size(), y.changes.size()) << "family " << f;
    for (std::size_t c = 0; c < x.changes.size(); ++c) {
      EXPECT_EQ(x.changes[c].kind, y.changes[c].kind);
      EXPECT_NEAR(y.changes[c].energy, a * g * g * x.changes[c].energy, 1e-9 * y.changes[c].energy);
      EXPECT_NEAR(y.changes[c].period, x.changes[c].period, 1e-9 * x.changes[c].period);
    }
    EXPECT_EQ(first.families[f].lastEnd.kind, second.families[f].lastEnd.kind);
    changes += int(x.changes.size());
  }
  EXPECT_GE(changes, 1);
}

}  // namespace
}  // namespace grazelab::core

namespace grazelab::core {
namespace {

TEST(ChainAtlas, TheOnePeriodicPartsInLongDoubleAreThoseOfDoubleToItsBars) {
  // a chain of three masses, the atlas to K = 1 in double and in long double (each with its own
  // chain in S): the same parts, the same changes of the same kinds, their energies within the
  // double's bars (the long double's no wider)
  std::mt19937 rng(5);
  const MassChain chain = randomChain(rng, 3);
  const ReadyChain ready = readyChain(chain);
  const BasicReadyChain<long double> readyLong = readyChain(chainCast<long double>(chain));
  const AtlasEnergyRange<double> range = defaultChainAtlasEnergyRange(ready);
  ChainAtlasOptions<double> options;
  options.maxImpacts = 1;
  options.energyLow = range.low;
  options.energyHigh = range.high;
  ChainAtlasOptions<long double> optionsLong;
  optionsLong.maxImpacts = 1;
  optionsLong.energyLow = range.low;
  optionsLong.energyHigh = range.high;
  const ChainAtlas<double> inDouble = computeChainAtlas(ready, options);
  const ChainAtlas<long double> inLong = computeChainAtlas(readyLong, optionsLong);
  ASSERT_EQ(inDouble.families.size(), inLong.families.size());
  int changes = 0;
  for (std::size_t f = 0; f < inDouble.families.size(); ++f) {
    const auto& x = inDouble.families[f];
    const auto& y = inLong.families[f];
    // the same ends, each named: the rows just past an end are looked at further out until one
    // is decided and not in the part (double once said `undecided` where long double named the
    // end; and on this chain long double said `energy-limit` at two grazing ends, at E 3.2995
    // where V -> 0, and double at one, where an admissible row in the range lay just past an
    // undecided one)
    ASSERT_TRUE(x.firstEnd && y.firstEnd);
    for (const auto& [a, b] : {std::pair{x.lastEnd.kind, y.lastEnd.kind},
                               std::pair{x.firstEnd->kind, y.firstEnd->kind}}) {
      EXPECT_EQ(a, b) << "part " << f;
      EXPECT_NE(a, ChainFamilyEnd::Undecided) << "part " << f;
    }
    ASSERT_EQ(x.path.changes.size(), y.path.changes.size()) << "part " << f;
    for (std::size_t c = 0; c < x.path.changes.size(); ++c) {
      EXPECT_EQ(x.path.changes[c].kind, y.path.changes[c].kind);
      EXPECT_NEAR(double(y.path.changes[c].energy), x.path.changes[c].energy,
                  x.path.changes[c].energyError + 1e-13 * x.path.changes[c].energy);
      EXPECT_NEAR(double(y.path.changes[c].period), x.path.changes[c].period,
                  x.path.changes[c].periodError + 1e-13 * x.path.changes[c].period);
      EXPECT_LE(double(y.path.changes[c].periodError), x.path.changes[c].periodError);
      ++changes;
    }
  }
  EXPECT_GE(changes, 1);
}

// A family followed both ways from one of its own orbits (followChainFamily, `family --impacts`)
// is the atlas's family: from an orbit a third of the way along a family born at a doubling, the
// path runs down to one end and up to the other, passes through the start, meets the atlas's
// stability changes beyond the start at the same energies (two bisections on two paths), each
// between the two orbits it names, and reaches the atlas's far end.
TEST(ChainAtlas, AFamilyFollowedBothWaysFromOneOfItsOrbitsIsTheAtlassFamily) {
  std::mt19937 rng(20261206);
  int followed = 0, changesMet = 0;
  for (int trial = 0; trial < 8 && followed < 4; ++trial) {
    const MassChain chain = randomChain(rng, 3 + trial % 2);
    const ReadyChain ready = readyChain(chain);
    const ChainAtlasOptions<double> options = defaultOptions(ready, 2, 600);
    const ChainAtlas<double> atlas = computeChainAtlas(ready, options);
    ASSERT_TRUE(atlas.complete);
    for (const ChainAtlasFamily<double>& family : atlas.families) {
      const std::vector<ChainPeriodicOrbit>& orbits = family.path.orbits;
      if (family.birth != ChainBirth::PeriodDoubling || orbits.size() < 12) continue;
      const std::size_t at = orbits.size() / 3;
      ChainContinuationOptions<double> continuation;
      continuation.energyLow = options.energyLow;
      continuation.energyHigh = options.energyHigh;
      continuation.maxOrbits = 600;
      const ChainAtlasFamily<double> both = followChainFamily(ready, orbits[at], continuation);
      SCOPED_TRACE("trial " + std::to_string(trial) + ", family " + std::to_string(family.id));
      ++followed;
      EXPECT_EQ(both.birth, ChainBirth::GivenOrbit);
      ASSERT_TRUE(both.firstEnd);
      const std::vector<ChainPeriodicOrbit>& path = both.path.orbits;
      ASSERT_GE(path.size(), 3u);
      // the start is on the path, and the path goes down in energy before it, up after it
      const auto start = std::find_if(path.begin(), path.end(), [&](const ChainPeriodicOrbit& o) {
        return o.energy == orbits[at].energy && o.period == orbits[at].period;
      });
      ASSERT_NE(start, path.end());
      // it leaves the start downwards first, upwards after (a fold may turn it later)
      if (start != path.begin()) {
        EXPECT_LT((start - 1)->energy, orbits[at].energy);
      }
      if (start + 1 != path.end()) {
        EXPECT_GT((start + 1)->energy, orbits[at].energy);
      }
      // each change between the two orbits it names: in energy, or at a fold (the energy's
      // turning point, beyond both) in period; to the orbits' own closing (1e-9: a fold's bracket
      // collapses to its bisection's rounding, 5e-12 beside its neighbour once)
      for (const ChainFamilyChange<double>& change : both.path.changes) {
        ASSERT_LT(change.after + 1, path.size());
        const bool fold = change.kind == ChainBifurcationKind::Fold;
        const double a = fold ? path[change.after].period : path[change.after].energy;
        const double b = fold ? path[change.after + 1].period : path[change.after + 1].energy;
        const double x = fold ? change.period : change.energy;
        const double error = (fold ? change.periodError : change.energyError) + 1e-9 * x;
        EXPECT_GE(x + error, std::min(a, b)) << toString(change.kind);
        EXPECT_LE(x - error, std::max(a, b)) << toString(change.kind);
      }
      // the atlas's changes beyond the start are met again, where the atlas met them
      for (const ChainFamilyChange<double>& change : family.path.changes) {
        if (change.after < at) continue;
        const auto same = std::find_if(both.path.changes.begin(), both.path.changes.end(),
                                       [&](const ChainFamilyChange<double>& c) {
                                         return c.kind == change.kind &&
                                                std::abs(c.energy - change.energy) < 1e-9 * change.energy;
                                       });
        EXPECT_NE(same, both.path.changes.end()) << "a change at E = " << change.energy;
        ++changesMet;
      }
      // the far end: the atlas's last orbit, and its kind, on whichever side the family went on
      // (an end where an impact fades is the last orbit Newton reached on its way, not a point
      // located: its energy to 1e-4, 1.2e-5 met)
      const bool wentUp = family.path.orbits.back().energy > orbits[at].energy;
      const ChainPeriodicOrbit& far = wentUp ? path.back() : path.front();
      const ChainAtlasEnd& farEnd = wentUp ? both.lastEnd : *both.firstEnd;
      if (family.lastEnd.kind != ChainFamilyEnd::StepLimit) {
        EXPECT_EQ(farEnd.kind, family.lastEnd.kind);
        const bool fades = farEnd.kind == ChainFamilyEnd::ImpactFades || farEnd.kind == ChainFamilyEnd::GrazingOrbit;
        EXPECT_NEAR(far.energy, family.path.orbits.back().energy, (fades ? 1e-4 : 1e-6) * far.energy)
            << toString(farEnd.kind);
      }
    }
  }
  EXPECT_GE(followed, 2);
  EXPECT_GE(changesMet, 1);
}

// A chain whose modes are 1e25 apart cannot have its flights searched within the contact
// search's budget: the atlas says so (searchBudgetExhausted, no family) after its first periods,
// where it once scanned all 423 of them for 13 s and handed back an empty atlas as if the chain
// had no mode with impacts.
TEST(ChainAtlas, AChainTooStiffToSearchIsSaidSoNotGivenAnEmptyAtlas) {
  MassChain chain;
  chain.masses = {1, 1e-25, 1};
  chain.springs = {1e25, 1, 1};
  const ReadyChain ready = readyChain(chain);
  const ChainAtlas<double> atlas = computeChainAtlas(ready, defaultOptions(ready, 2, 2000));
  EXPECT_TRUE(atlas.complete);
  EXPECT_TRUE(atlas.searchBudgetExhausted);
  EXPECT_TRUE(atlas.families.empty());
  EXPECT_GE(atlas.undecidedPeriods, kFamilySearchBudgetRows);
  // and a chain it can search says nothing of the kind
  std::mt19937 rng(5);
  const ReadyChain fine = readyChain(randomChain(rng, 3));
  const ChainAtlas<double> searched = computeChainAtlas(fine, defaultOptions(fine, 2, 2000));
  EXPECT_FALSE(searched.searchBudgetExhausted);
  EXPECT_FALSE(searched.families.empty());
}

// A family whose period stays that of its first orbit while its energy moves is flagged
// (onePeriod): on the 3:2:1 chain of masses 1, 0.7, 0.4 two of the 2-impact families keep
// twice their doubling's period all along; no 1IPP part is flagged (their period moves with the
// energy), nor the 2-impact family whose period wanders.
TEST(ChainAtlas, AFamilyOfOnePeriodIsSaidSo) {
  MassChain chain;
  chain.masses = {1, 0.7, 0.4};
  chain.springs = {1, 0.6082683391547987, 0.25011944924612495};  // (the 3:2:1 design, as the CLI gives it)
  const ReadyChain ready = readyChain(chain);
  const ChainAtlas<double> atlas = computeChainAtlas(ready, defaultOptions(ready, 2, 2000));
  int flagged = 0;
  for (const ChainAtlasFamily<double>& family : atlas.families) {
    const auto [shortest, longest] = std::minmax_element(
        family.path.orbits.begin(), family.path.orbits.end(),
        [](const ChainPeriodicOrbit& a, const ChainPeriodicOrbit& b) { return a.period < b.period; });
    const double spread = (longest->period - shortest->period) / longest->period;
    if (family.path.impacts == 1) {
      EXPECT_FALSE(family.onePeriod) << family.id;
      continue;
    }
    EXPECT_EQ(family.onePeriod, spread <= 1e-9) << family.id << " spread " << spread;
    if (!family.onePeriod) continue;
    ++flagged;
    // twice the period of the doubling it was born at
    const ChainFamilyChange<double>& doubling =
        atlas.families[std::size_t(family.parent)].path.changes[std::size_t(family.parentChange)];
    EXPECT_NEAR(family.path.orbits.front().period, 2 * doubling.period, 1e-9 * doubling.period);
  }
  EXPECT_EQ(flagged, 2);
}

}  // namespace
}  // namespace grazelab::core
