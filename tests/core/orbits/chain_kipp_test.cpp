// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/orbits/chain_kipp.cpp: Newton on the exact return map of a chain of N masses.
// From a guess near a 1IPP orbit of random chains (3 to 6 masses, walls or not, any stopped
// mass) it converges quadratically back to the closed form's orbit, at a fixed energy and at a
// fixed period; on two masses it finds what the note's own Newton finds (two algorithms); at a
// period doubling of three masses the branch it switches to is a 2IPP orbit whose distance from
// the doubled 1IPP orbit grows like the square root of the distance from the bifurcation; in
// binary128 it closes to 1e-30.
#include "core/orbits/chain_kipp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "core/model/model.h"
#include "core/model/two_mass_form.h"
#include "core/orbits/chain_bifurcations.h"
#include "core/orbits/chain_onepp.h"
#include "core/orbits/periodic_orbit.h"
#include "support/random_chains.h"

namespace grazelab::core {
namespace {

using test_chains::flipDirection;
using test_chains::randomChain;
using test_chains::stateDistance;

TwoMassForm<double> resonantChain(double m2 = 0.5, Branch branch = Branch::Upper) {
  return *makeTwoMassForm(*designedModel(1.0, m2, 1.0, 1.0, branch)).chain;
}

// the state moved off the orbit by `by` (scaled) in every coordinate but the stopped mass's
BasicChainState<double> pushed(const BasicChainDynamics<double>& dynamics, BasicChainState<double> x, double by,
                               std::mt19937& rng) {
  const ChainStateScale<double> scale(dynamics);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (Eigen::Index j = 0; j < x.u.size(); ++j) {
    if (j == dynamics.stop) continue;
    x.u[j] += by * scale.length * unit(rng);
    x.v[j] += by * scale.speed * unit(rng);
  }
  return x;
}

TEST(ChainKipp, NewtonComesBackToTheClosedFormsOrbitsOfRandomChains) {
  std::mt19937 rng(20261202);
  int converged = 0, tried = 0;
  for (int trial = 0; trial < 16; ++trial) {
    const MassChain chain = randomChain(rng, 3 + trial % 4);
    const ReadyChain ready = readyChain(chain);
    const double end = chainOnePeriodicEnd(chain);
    for (int k = 1; k < 12; ++k) {
      const double T = end * k / 12;
      const ChainOnePeriodicStability<double> exact = chainOnePeriodicStability(ready, T);
      if (exact.onePeriodic != OnePeriodicRefusal::None || !exact.orbit.admissible()) continue;
      if (exact.orbit.monodromy.stability == ChainStability::Undecided) continue;
      const BasicChainState<double> guess = pushed(ready.dynamics, exact.orbit.state, 1e-4, rng);
      for (const ChainOrbitConstraint fixed : {ChainOrbitConstraint::Energy, ChainOrbitConstraint::Period}) {
        ++tried;
        const double value = fixed == ChainOrbitConstraint::Energy ? exact.orbit.energy : T;
        const ChainOrbitSearch<double> found = findChainOrbit(ready, guess, 1, fixed, value);
        if (!found.orbit) continue;  // (near a fold a multiplier is at 1: counted below)
        ++converged;
        EXPECT_LT(stateDistance(ready.dynamics, found.orbit->state, exact.orbit.state), 1e-9) << "T " << T;
        EXPECT_NEAR(found.orbit->period, T, 1e-10 * T);
        EXPECT_NEAR(found.orbit->energy, exact.orbit.energy, 1e-10 * exact.orbit.energy);
        EXPECT_LE(found.iterations, 8) << "quadratic convergence";
        // the path's monodromy and the closed form's: the same multipliers within their bars
        const auto& mine = found.orbit->monodromy.multipliers;
        const auto& theirs = exact.orbit.monodromy.multipliers;
        ASSERT_EQ(mine.size(), theirs.size());
        for (std::size_t i = 0; i < mine.size(); ++i) {
          const double apart = std::abs(std::complex<double>(mine[i].re - theirs[i].re, mine[i].im - theirs[i].im));
          EXPECT_LE(apart, 2 * (mine[i].error + theirs[i].error) + 1e-9) << "T " << T << " multiplier " << i;
        }
      }
    }
  }
  EXPECT_GT(tried, 100);
  EXPECT_GE(converged, tried * 9 / 10);
}

TEST(ChainKipp, TwoMassesAreWhatTheNotesNewtonFinds) {
  struct Case {
    TwoMassForm<double> chain;
    double energy, u1, v1;
    int impacts;
  };
  const Case cases[] = {
      {resonantChain(), 1.99998, 0.8, 0.05, 2},
      {resonantChain(0.2, Branch::Lower), 0.55723741026538198, 1.0434444625270811, 0.0057300888602593606, 4},
      {resonantChain(0.8, Branch::Upper), 0.9, 0.3, 0.1, 2},
  };
  int compared = 0;
  for (const Case& c : cases) {
    const OrbitSearch<double> note = findOrbit(c.chain, c.energy, c.u1, c.v1, c.impacts);
    if (!note.orbit) continue;
    const ReadyChain ready = readyChain(c.chain);
    BasicChainState<double> guess{ChainVector<double>(2), ChainVector<double>(2)};
    guess.u << c.u1, c.chain.model.gap;
    guess.v << c.v1, 0.0;
    const ChainOrbitSearch<double> mine = findChainOrbit(ready, guess, c.impacts, ChainOrbitConstraint::Energy, c.energy);
    ASSERT_TRUE(mine.orbit) << toString(mine.problem);
    const BasicChainState<double> theirs = chainStateOf(note.orbit->state);
    EXPECT_LT(stateDistance(ready.dynamics, mine.orbit->state, theirs), 1e-9);
    EXPECT_NEAR(mine.orbit->period, note.orbit->period, 1e-10 * note.orbit->period);
    ASSERT_EQ(mine.orbit->monodromy.multipliers.size(), 2u);
    const double sum = mine.orbit->monodromy.multipliers[0].re + mine.orbit->monodromy.multipliers[1].re;
    EXPECT_NEAR(sum, note.orbit->trace, 1e-7 * std::max(1.0, std::abs(note.orbit->trace)));
    ++compared;
  }
  EXPECT_GE(compared, 2);
}

TEST(ChainKipp, BinaryOneTwentyEightClosesToItsRounding) {
  const MassChain chain{{1.0, 0.4, 0.2}, {1.0, 0.7, 0.3}, 0.5, 2, 1.0};
  const BasicReadyChain<Quad> ready = readyChain(chainCast<Quad>(chain));
  // the first admissible 1IPP orbit from 0.6 of the slowest period down
  Quad T = 0;
  ChainOnePeriodicStability<Quad> exact;
  for (int k = 60; k > 0 && !exact.orbit.admissible(); --k) {
    T = Quad(chainOnePeriodicEnd(chain)) * Quad(k) / 100;
    exact = chainOnePeriodicStability(ready, T);
  }
  ASSERT_TRUE(exact.orbit.admissible());
  BasicChainState<Quad> guess = exact.orbit.state;
  guess.u[0] += Quad(1e-3);
  guess.v[2] -= Quad(1e-3);
  const ChainOrbitSearch<Quad> found = findChainOrbit(ready, guess, 1, ChainOrbitConstraint::Period, T);
  ASSERT_TRUE(found.orbit) << toString(found.problem);
  EXPECT_LT(double(stateDistance(ready.dynamics, found.orbit->state, exact.orbit.state)), 1e-28);
  EXPECT_LT(double(found.orbit->periodicityResidual), 1e-30);
}

TEST(ChainKipp, AtAPeriodDoublingTheTwoImpactBranchGrowsLikeTheSquareRoot) {
  // on one side of a flip of the 1IPP family a 2IPP family is born: at the energy of the 1IPP
  // orbit of period T its orbit lies at a distance ~ sqrt(|T - T*|) from the 1IPP orbit (a
  // pitchfork of P^2). Newton is seeded along the flip's eigenvector, the nearest orbit kept.
  const MassChain chain{{0.6865, 1.9630, 0.8236}, {0.8423, 1.0745, 0.7486}, 0, 2, 1.0};
  const ReadyChain ready = readyChain(chain);
  const ChainStateScale<double> scale(ready.dynamics);
  const double end = chainOnePeriodicEnd(chain);
  std::vector<double> periods;
  for (int k = 1; k < 300; ++k) periods.push_back(end * k / 300);
  int doublings = 0, branches = 0;
  for (const ChainBifurcation<double>& b : chainOnePeriodicBifurcations(ready, periods).changes) {
    if (b.kind != ChainBifurcationKind::PeriodDoubling) continue;
    ++doublings;
    for (const double side : {-1.0, 1.0}) {
      double distance[2] = {-1, -1};
      for (int i = 0; i < 2; ++i) {
        const double T = b.T * (1 + side * (i == 0 ? 1e-6 : 4e-6));
        const ChainOnePeriodicStability<double> one = chainOnePeriodicStability(ready, T);
        ASSERT_TRUE(one.orbit.admissible());
        const ChainVector<double> push = flipDirection(one.orbit.monodromy.matrix);
        for (int k = -20; k <= 20; ++k) {
          BasicChainState<double> guess = one.orbit.state;
          guess.u += 0.02 * k * scale.length * push.head(3);
          guess.v += 0.02 * k * scale.speed * push.tail(3);
          guess.u[ready.dynamics.stop] = chain.gap;
          const ChainOrbitSearch<double> two =
              findChainOrbit(ready, guess, 2, ChainOrbitConstraint::Energy, one.orbit.energy);
          // (the branch's period is 2T to O(distance^2); other 2IPP orbits are not its)
          if (!two.orbit || std::abs(two.orbit->period - 2 * T) > 1e-2 * T) continue;
          EXPECT_EQ(two.orbit->events.size(), 2u);
          const double apart = stateDistance(ready.dynamics, two.orbit->state, one.orbit.state);
          if (distance[i] < 0 || apart < distance[i]) distance[i] = apart;
        }
      }
      if (distance[0] < 0 || distance[1] < 0) continue;
      ++branches;
      EXPECT_NEAR(distance[1] / distance[0], 2.0, 0.25) << "T* " << b.T << " side " << side;
    }
  }
  EXPECT_GT(doublings, 2);
  EXPECT_GE(branches, doublings / 2);
}

TEST(ChainKipp, AGuessWithNoStateOrAStopGivesTheProblem) {
  const MassChain chain{{1.0, 0.4, 0.2}, {1.0, 0.7, 0.3}, 0.5, 2, 1.0};
  const ReadyChain ready = readyChain(chain);
  BasicChainState<double> guess{ChainVector<double>::Zero(3), ChainVector<double>::Zero(3)};
  guess.u << 5.0, 5.0, 1.0;  // the springs alone hold far more than the energy
  EXPECT_EQ(findChainOrbit(ready, guess, 1, ChainOrbitConstraint::Energy, 0.01).problem,
            ChainOrbitProblem::NoStateAtGuess);
  std::stop_source source;
  source.request_stop();
  guess.u << 0.1, 0.2, 1.0;
  EXPECT_EQ(findChainOrbit(ready, guess, 1, ChainOrbitConstraint::Energy, 1.0, source.get_token()).problem,
            ChainOrbitProblem::Stopped);
}

}  // namespace
}  // namespace grazelab::core
