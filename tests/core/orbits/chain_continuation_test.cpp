// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/orbits/chain_continuation.cpp: pseudo-arclength continuation of kIPP families of
// any chain. The 1IPP family it follows from one orbit is, row by row, the closed form's at the
// row's period (random chains of 2 to 6 masses, walls or not, any stopped mass: an independent
// algorithm), and its stability changes are the closed form's; a 2IPP family born at a period
// doubling of three masses is, row by row, the orbit Newton reaches at that row's energy from the
// row before (two algorithms); the branch born at each doubling passes through the doubled orbit.
#include "core/orbits/chain_continuation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <cmath>
#include <random>
#include <vector>

#include "core/orbits/chain_bifurcations.h"
#include "core/orbits/chain_onepp.h"
#include "core/orbits/chain_return_map.h"
#include "support/random_chains.h"

namespace grazelab::core {
namespace {

using test_chains::flipDirection;
using test_chains::randomChain;
using test_chains::stateDistance;

// The first admissible 1IPP orbit of `ready` at k/20 of its slowest period T_max, k from `from`
// up, with its stability (none admissible: its refusal)
template <typename S>
ChainOnePeriodicStability<S> firstOnePeriodic(const BasicReadyChain<S>& ready, double tMax, int from) {
  ChainOnePeriodicStability<S> first;
  for (int k = from; k < 20 && !first.orbit.admissible(); ++k) first = chainOnePeriodicStability(ready, S(tMax * k / 20));
  return first;
}

// The 1IPP families of 10 random chains of 2 to 6 masses, each followed both ways (120 orbits at
// most, energies within 20 times the first's) from its first admissible closed-form orbit.
struct FollowedFamily {
  int trial = 0;
  std::shared_ptr<const ReadyChain> ready;
  ContinuedChainFamily<double> family;
};
const std::vector<FollowedFamily>& randomOnePeriodicFamilies() {
  static const std::vector<FollowedFamily> families = [] {
    std::vector<FollowedFamily> out;
    std::mt19937 rng(20261203);
    for (int trial = 0; trial < 10; ++trial) {
      const MassChain chain = randomChain(rng, 2 + trial % 5);
      auto ready = std::make_shared<const ReadyChain>(readyChain(chain));
      const ChainOnePeriodicStability<double> first = firstOnePeriodic(*ready, chainOnePeriodicEnd(chain), 5);
      if (!first.orbit.admissible()) continue;
      for (const int direction : {-1, 1}) {
        ChainContinuationOptions<double> options;
        options.energyLow = first.orbit.energy / 20;
        options.energyHigh = first.orbit.energy * 20;
        options.maxOrbits = 120;
        out.push_back({trial, ready, continueChainFamily(*ready, first.orbit, direction, options)});
        EXPECT_GT(direction * (out.back().family.orbits.at(1).energy - first.orbit.energy), 0) << "the first step's way";
      }
    }
    return out;
  }();
  return families;
}

TEST(ChainContinuation, TheOneImpactFamilyFollowedIsTheClosedFormsOfRandomChains) {
  int rows = 0, families = 0, folds = 0;
  for (const auto& [trial, readyChain, family] : randomOnePeriodicFamilies()) {
    const ReadyChain& ready = *readyChain;
    ++families;
    EXPECT_GE(family.orbits.size(), 5u) << "trial " << trial << " ends " << toString(family.end);
    for (const ChainPeriodicOrbit& orbit : family.orbits) {
      const ChainOnePeriodicStability<double> exact = chainOnePeriodicStability(ready, orbit.period);
      ASSERT_TRUE(exact.orbit.admissible()) << "trial " << trial << " T " << orbit.period;
      EXPECT_LT(stateDistance(ready.dynamics, orbit.state, exact.orbit.state), 1e-8)
          << "trial " << trial << " T " << orbit.period;
      EXPECT_NEAR(orbit.energy, exact.orbit.energy, 1e-9 * exact.orbit.energy);
      EXPECT_EQ(orbit.events.size(), 1u);
      ++rows;
    }
    // a fold in energy passed: the energy turns back along the family
    for (std::size_t i = 2; i < family.orbits.size(); ++i) {
      const double before = family.orbits[i - 1].energy - family.orbits[i - 2].energy;
      const double after = family.orbits[i].energy - family.orbits[i - 1].energy;
      if (before * after < 0) {
        ++folds;
        break;
      }
    }
  }
  EXPECT_GE(families, 12);
  EXPECT_GE(folds, 2);
  EXPECT_GE(rows, 300);
}

TEST(ChainContinuation, AFamilysStabilityChangesAreTheClosedFormsNoneMissedNoneInvented) {
  // the changes located along continued 1IPP families (bisection along the chord, each middle
  // corrected onto the family; halves searched where two changes could hide between two orbits)
  // against the closed form's bisection in T over the same periods (its own hidden-pair search):
  // the same kind at the same period, none invented, none missed
  int found = 0;
  for (const auto& [trial, readyChain, family] : randomOnePeriodicFamilies()) {
    const ReadyChain& ready = *readyChain;
    EXPECT_EQ(family.unsearched, 0);
    double low = family.orbits.front().period, high = low;
    for (const ChainPeriodicOrbit& orbit : family.orbits) {
      low = std::min(low, orbit.period);
      high = std::max(high, orbit.period);
    }
    std::vector<double> periods;
    for (int i = 0; i <= 3000; ++i) periods.push_back(low + (high - low) * i / 3000);
    const ChainBifurcations<double> closed = chainOnePeriodicBifurcations(ready, periods);
    for (const ChainFamilyChange<double>& change : family.changes) {
      ASSERT_LT(change.after + 1, family.orbits.size());
      const double a = family.orbits[change.after].period, b = family.orbits[change.after + 1].period;
      EXPECT_GE(change.period, std::min(a, b) - change.periodError);
      EXPECT_LE(change.period, std::max(a, b) + change.periodError);
      EXPECT_LT(change.periodError, 1e-9 * change.period);
      const ChainBifurcation<double>* nearest = nullptr;
      for (const ChainBifurcation<double>& other : closed.changes) {
        if (!nearest || std::abs(other.T - change.period) < std::abs(nearest->T - change.period)) nearest = &other;
      }
      ASSERT_NE(nearest, nullptr) << "trial " << trial << ": a change the closed form does not have";
      EXPECT_LT(std::abs(nearest->T - change.period), 1e-9 * change.period) << "trial " << trial;
      EXPECT_EQ(nearest->kind, change.kind) << "trial " << trial << " T " << change.period;
      // leaving the circle as the family is followed is leaving it as T grows where T grows
      EXPECT_EQ(nearest->leaves, change.leaves == (b > a)) << "trial " << trial << " T " << change.period;
      EXPECT_NEAR(nearest->energy, change.energy, 1e-8 * change.energy + change.energyError + nearest->energyError);
      ++found;
    }
    for (const ChainBifurcation<double>& other : closed.changes) {
      int matches = 0;
      for (const ChainFamilyChange<double>& change : family.changes) {
        matches += std::abs(other.T - change.period) < 1e-9 * other.T && other.kind == change.kind;
      }
      EXPECT_EQ(matches, 1) << "trial " << trial << ": the closed form's " << toString(other.kind) << " at T "
                            << other.T;
    }
  }
  EXPECT_GE(found, 30);
}

template <typename S>
void expectTheClosedFormsFamilyIn(const MassChain& chain, int orbits, const S& within) {
  const BasicReadyChain<S> ready = readyChain(chainCast<S>(chain));
  const double end = chainOnePeriodicEnd(chain);
  const ChainOnePeriodicStability<S> first = firstOnePeriodic(ready, end, 9);
  ASSERT_TRUE(first.orbit.admissible());
  ChainContinuationOptions<S> options;
  options.energyLow = first.orbit.energy / 10;
  options.energyHigh = first.orbit.energy * 10;
  options.maxOrbits = orbits;
  const ContinuedChainFamily<S> family = continueChainFamily(ready, first.orbit, 1, options);
  EXPECT_EQ(int(family.orbits.size()), orbits) << toString(family.end);
  for (const BasicChainPeriodicOrbit<S>& orbit : family.orbits) {
    const ChainOnePeriodicStability<S> exact = chainOnePeriodicStability(ready, orbit.period);
    ASSERT_TRUE(exact.orbit.admissible());
    EXPECT_LT(stateDistance(ready.dynamics, orbit.state, exact.orbit.state), within) << double(orbit.period);
  }
}

TEST(ChainContinuation, LongDoubleAndBinaryOneTwentyEightFollowTheClosedFormToTheirDigits) {
  // in S the family's orbits are the closed form's in S to S's digits, not double's
  const MassChain chain{{1.0, 0.4, 0.2}, {1.0, 0.7, 0.3}, 0.5, 2, 1.0};
  expectTheClosedFormsFamilyIn<long double>(chain, 20, 1e-14L);
  expectTheClosedFormsFamilyIn<Quad>(chain, 4, Quad(1e-28));
}

TEST(ChainContinuation, ATwoImpactFamilyIsNewtonsOrbitAtEachOfItsEnergies) {
  const MassChain chain{{0.6865, 1.9630, 0.8236}, {0.8423, 1.0745, 0.7486}, 0, 2, 1.0};
  const ReadyChain ready = readyChain(chain);
  const ChainStateScale<double> scale(ready.dynamics);
  const double end = chainOnePeriodicEnd(chain);
  std::vector<double> periods;
  for (int k = 1; k < 300; ++k) periods.push_back(end * k / 300);
  int followed = 0;
  for (const ChainBifurcation<double>& b : chainOnePeriodicBifurcations(ready, periods).changes) {
    if (b.kind != ChainBifurcationKind::PeriodDoubling) continue;
    // the 2IPP orbit next to the doubling, from Newton seeded along the flip's eigenvector
    std::optional<ChainPeriodicOrbit> seed;
    for (const double side : {-1.0, 1.0}) {
      const double T = b.T * (1 + side * 1e-4);
      const ChainOnePeriodicStability<double> one = chainOnePeriodicStability(ready, T);
      if (!one.orbit.admissible()) continue;
      const ChainVector<double> push = flipDirection(one.orbit.monodromy.matrix);
      for (int k = 1; k <= 20 && !seed; ++k) {
        ChainState guess = one.orbit.state;
        guess.u += 0.01 * k * scale.length * push.head(3);
        guess.v += 0.01 * k * scale.speed * push.tail(3);
        guess.u[ready.dynamics.stop] = chain.gap;
        const ChainOrbitSearch<double> two = findChainOrbit(ready, guess, 2, ChainOrbitConstraint::Energy, one.orbit.energy);
        if (two.orbit && std::abs(two.orbit->period - 2 * T) < 1e-2 * T) seed = two.orbit;
      }
    }
    if (!seed) continue;
    for (const int direction : {-1, 1}) {
      ChainContinuationOptions<double> options;
      options.energyLow = seed->energy / 4;
      options.energyHigh = seed->energy * 4;
      options.maxOrbits = 40;
      const ContinuedChainFamily<double> family = continueChainFamily(ready, *seed, direction, options);
      EXPECT_GE(family.orbits.size(), 3u) << "T* " << b.T << " ends " << toString(family.end);
      // each orbit is the one Newton comes back to at its energy from a guess pushed 1e-5 off it
      // (scaled), and the next one lies within two of the largest steps of it (no jump onto
      // another family). (Newton from the orbit before may reach the branch's other half: next to
      // the doubling both halves have orbits of nearly one energy.)
      std::mt19937 rng(7);
      std::uniform_real_distribution<double> unitPush(-1e-5, 1e-5);
      for (std::size_t i = 0; i < family.orbits.size(); ++i) {
        const ChainPeriodicOrbit& orbit = family.orbits[i];
        ASSERT_EQ(orbit.events.size(), 2u);
        ChainState guess = orbit.state;
        for (Eigen::Index j = 0; j < 3; ++j) {
          if (j == ready.dynamics.stop) continue;
          guess.u[j] += unitPush(rng) * scale.length;
          guess.v[j] += unitPush(rng) * scale.speed;
        }
        const ChainOrbitSearch<double> newton = findChainOrbit(ready, guess, 2, ChainOrbitConstraint::Energy, orbit.energy);
        // (next to the doubled orbit, where the family meets a doubling of its parent again, the
        // multiplier near 1 there makes the orbit ill-conditioned: Newton from 1e-5 off may reach
        // the parent run twice, stall, or stop 1e-8 away; the orbit's two halves then differ by
        // less than 1e-2)
        const bool nearDoubled = return_map::halfPeriodShift(ready.dynamics, orbit).norm() < 1e-2;
        if (!newton.orbit && nearDoubled) {
          EXPECT_EQ(family.end, ChainFamilyEnd::MeetsDoubling);
          continue;
        }
        ASSERT_TRUE(newton.orbit) << toString(newton.problem) << " at E " << orbit.energy;
        EXPECT_LT(stateDistance(ready.dynamics, orbit.state, newton.orbit->state), nearDoubled ? 1e-6 : 1e-8)
            << "E " << orbit.energy;
        EXPECT_NEAR(orbit.period, newton.orbit->period, 1e-9 * orbit.period);
        if (i > 0) {
          EXPECT_LT(stateDistance(ready.dynamics, orbit.state, family.orbits[i - 1].state), 2 * options.maxStep);
          EXPECT_LT(std::abs(std::log(orbit.energy / family.orbits[i - 1].energy)), 2 * options.maxStep);
        }
      }
      ++followed;
    }
  }
  EXPECT_GE(followed, 2);
}

TEST(ChainContinuation, AtEachDoublingOfAFamilyABranchOfTwiceTheImpactsIsBornAndPassesThroughIt) {
  // the 1IPP family of three masses continued through its doublings; at each, the branch of 2IPP
  // orbits (branchAtDoubling, seeded 1e-5 of the energy away), followed both ways: one way it
  // passes through the doubled orbit (a pitchfork of P^2: the branch's two halves are one family,
  // each the other shifted by an impact), ten times nearer the doubling's energy than its seed, at
  // twice its period
  const MassChain chain{{0.6865, 1.9630, 0.8236}, {0.8423, 1.0745, 0.7486}, 0, 2, 1.0};
  const ReadyChain ready = readyChain(chain);
  const double end = chainOnePeriodicEnd(chain);
  const ChainOnePeriodicStability<double> first = firstOnePeriodic(ready, end, 9);
  ASSERT_TRUE(first.orbit.admissible());
  int doublings = 0, branches = 0, through = 0;
  for (const int direction : {-1, 1}) {
    ChainContinuationOptions<double> options;
    options.energyLow = first.orbit.energy / 30;
    options.energyHigh = first.orbit.energy * 30;
    options.maxOrbits = 300;
    const ContinuedChainFamily<double> family = continueChainFamily(ready, first.orbit, direction, options);
    for (const ChainFamilyChange<double>& change : family.changes) {
      if (change.kind != ChainBifurcationKind::PeriodDoubling) continue;
      ++doublings;
      const ChainOrbitSearch<double> branch = branchAtDoubling(ready, change, 1);
      if (!branch.orbit) continue;
      ++branches;
      EXPECT_EQ(branch.orbit->events.size(), 2u);
      EXPECT_NEAR(branch.orbit->period, 2 * change.period, 1e-2 * change.period);
      bool back = false;
      for (const int way : {-1, 1}) {
        ChainContinuationOptions<double> along;
        along.energyLow = change.energy / 30;
        along.energyHigh = change.energy * 30;
        along.maxOrbits = 200;
        const ContinuedChainFamily<double> born = continueChainFamily(ready, *branch.orbit, way, along);
        EXPECT_NE(born.end, ChainFamilyEnd::NotConverging);
        for (const ChainPeriodicOrbit& orbit : born.orbits) {
          EXPECT_EQ(orbit.events.size(), 2u);
          back = back || (std::abs(orbit.period - 2 * change.period) < 1e-6 * change.period &&
                          std::abs(orbit.energy - change.energy) < 1e-6 * change.energy);
        }
      }
      through += back;
    }
  }
  EXPECT_GE(doublings, 2);
  EXPECT_EQ(branches, doublings);
  EXPECT_EQ(through, branches);
}

}  // namespace
}  // namespace grazelab::core
