// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/orbits/chain_bifurcations.cpp: where the 1IPP family of N masses changes
// stability. Two masses: its period doublings are the note's flips (the two-mass trace's -2,
// located independently) to 1e-9 of T. Three masses: a Krein collision happens where two
// multipliers of opposite signatures meet on the circle, the family leaves it as a quadruplet,
// and double and binary128 put it at the same period.
#include "core/orbits/chain_bifurcations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/model/model.h"
#include "core/model/two_mass_form.h"
#include "core/orbits/chain_onepp.h"
#include "core/orbits/onepp_family_points.h"

namespace grazelab::core {
namespace {

template <typename S>
std::vector<S> grid(const S& end, int count) {
  std::vector<S> periods;
  for (int k = 1; k < count; ++k) periods.push_back(end * S(k) / S(count));
  return periods;
}

TEST(ChainBifurcations, TwoMassPeriodDoublingsAreTheNotesFlips) {
  int matched = 0;
  for (const double m2 : {0.3, 0.5}) {
    const auto model = designedModel<double>(1.0, m2, 1.0, 1.0, Branch::Upper);
    ASSERT_TRUE(model);
    const TwoMassForm<double> form = *makeTwoMassForm(*model).chain;
    const double T2 = twoPi<double>() / form.omegaSlow;
    std::vector<double> flips;
    for (const auto& b : onePeriodicBifurcations(form, 400)) {
      if (b.kind == PointKind::PeriodDoubling && b.checked) flips.push_back(b.T);
    }
    const ReadyChain ready = readyChain(massChainOf(*model), Kernel::Modal);
    const auto found = chainOnePeriodicBifurcations(ready, grid(T2, 400)).changes;
    std::vector<double> doublings;
    for (const ChainBifurcation<double>& b : found) {
      EXPECT_NE(b.kind, ChainBifurcationKind::KreinCollision) << "two masses have one pair: no quadruplet";
      if (b.kind == ChainBifurcationKind::PeriodDoubling) doublings.push_back(b.T);
    }
    ASSERT_FALSE(flips.empty());
    ASSERT_EQ(doublings.size(), flips.size()) << "m2 " << m2;
    for (std::size_t i = 0; i < flips.size(); ++i) {
      EXPECT_NEAR(doublings[i], flips[i], 1e-9 * flips[i]) << "m2 " << m2;
      ++matched;
    }
  }
  EXPECT_GT(matched, 1);
}

// the two multipliers nearest each other on the circle's upper half, at period T
std::vector<ChainMultiplier<double>> nearestPairAbove(const ReadyChain& chain, double T) {
  const auto found = chainOnePeriodicStability(chain, T);
  std::vector<ChainMultiplier<double>> upper;
  for (const auto& m : found.orbit.monodromy.multipliers) {
    if (m.im > 0) upper.push_back(m);
  }
  std::vector<ChainMultiplier<double>> best;
  double apart = INFINITY;
  for (std::size_t i = 0; i < upper.size(); ++i) {
    for (std::size_t j = i + 1; j < upper.size(); ++j) {
      const double d = std::abs(std::complex<double>(upper[i].re - upper[j].re, upper[i].im - upper[j].im));
      if (d < apart) {
        apart = d;
        best = {upper[i], upper[j]};
      }
    }
  }
  return best;
}

TEST(ChainBifurcations, AKreinCollisionOfThreeMassesMeetsOppositeSignatures) {
  const MassChain chain{{0.6865, 1.9630, 0.8236}, {0.8423, 1.0745, 0.7486}, 0, 2, 1.0};
  const ReadyChain ready = readyChain(chain);
  const double end = chainOnePeriodicEnd(chain);
  const auto found = chainOnePeriodicBifurcations(ready, grid(end, 300)).changes;
  const BasicReadyChain<Quad> quad = readyChain(chainCast<Quad>(chain));
  int collisions = 0;
  for (const ChainBifurcation<double>& b : found) {
    EXPECT_LT(b.periodError, 1e-9 * b.T);
    EXPECT_LT(b.energyError, 1e-9 * b.energy);
    EXPECT_GT(b.energyError, 0.0);
    if (b.kind != ChainBifurcationKind::KreinCollision) continue;
    // on the side where both pairs are on the circle, the two that meet have opposite signatures
    const double side = b.leaves ? -1 : 1;
    const auto pair = nearestPairAbove(ready, b.T + side * 1e-4 * b.T);
    ASSERT_EQ(pair.size(), 2u);
    EXPECT_TRUE(pair[0].onCircle && pair[1].onCircle);
    EXPECT_EQ(pair[0].krein, -pair[1].krein) << "T* " << b.T;
    EXPECT_NE(pair[0].krein, 0);
    // on the other side, a quadruplet
    EXPECT_GT(censusOf(chainOnePeriodicStability(ready, b.T - side * 1e-4 * b.T).orbit.monodromy).complex, 0);
    // binary128 puts it at the same period (bisected in its own precision around it)
    const Quad width = Quad(1e-6) * Quad(b.T);
    const auto exact =
        chainOnePeriodicBifurcations(quad, std::vector<Quad>{Quad(b.T) - width, Quad(b.T) + width}).changes;
    ASSERT_EQ(exact.size(), 1u);
    EXPECT_NEAR(double(exact[0].T), b.T, 1e-9 * b.T);
    // the energy within its bar of binary128's
    EXPECT_LE(std::abs(double(exact[0].energy) - b.energy), b.energyError + double(exact[0].energyError));
    EXPECT_EQ(exact[0].kind, ChainBifurcationKind::KreinCollision);
    ++collisions;
  }
  EXPECT_GT(collisions, 0);
}

// the chain and the changes found near T, for a failure's message
std::string describe(const MassChain& chain, const std::vector<ChainBifurcation<double>>& found, double T) {
  std::ostringstream text;
  text.precision(17);
  text << "(near:";
  for (const auto& b : found) {
    if (std::abs(b.T - T) < 0.05 * T) text << " " << toString(b.kind) << "@" << b.T;
  }
  text << "; masses";
  for (double m : chain.masses) text << " " << m;
  text << ", springs";
  for (double k : chain.springs) text << " " << k;
  text << ", stop " << chain.stopMass << ")";
  return text.str();
}

TEST(ChainBifurcations, ACoarseFamilyMissesNoChangeADenseOneFinds) {
  // two changes that undo each other between two rows (a Krein collision and its return, a pair
  // at -1 leaving and coming back, a fold and a doubling of two pairs) are looked for where the
  // multipliers could hide them: 200 rows (a tenth of `family`'s default) find what 3000 find,
  // wherever the coarse rows around it are admissible, and what they find a fine grid around it
  // finds too. (With 40 rows, 4 of about 150 were missed on 13 chains: the halving follows where
  // the multipliers were at the rows, not where they went in between.)
  std::mt19937 rng(4902);
  std::uniform_real_distribution<double> logUniform(-0.5, 0.5);
  std::vector<MassChain> chains{{{0.6865, 1.9630, 0.8236}, {0.8423, 1.0745, 0.7486}, 0, 2, 1.0}};
  for (int c = 0; c < 7; ++c) {
    MassChain chain;
    for (int i = 0; i < 3 + c % 2; ++i) {
      chain.masses.push_back(std::pow(10.0, logUniform(rng)));
      chain.springs.push_back(std::pow(10.0, logUniform(rng)));
    }
    chain.stopMass = int(rng() % unsigned(chain.masses.size())) + 1;
    chains.push_back(chain);
  }
  int compared = 0, refined = 0, unsearched = 0;
  for (const MassChain& chain : chains) {
    const ReadyChain ready = readyChain(chain);
    const double end = chainOnePeriodicEnd(chain);
    const auto dense = chainOnePeriodicBifurcations(ready, grid(end, 3000)).changes;
    const std::vector<double> rows = grid(end, 200);
    const ChainBifurcations<double> search = chainOnePeriodicBifurcations(ready, rows);
    const auto& coarse = search.changes;
    unsearched += int(search.unsearched.size());
    for (const ChainBifurcation<double>& b : dense) {
      // the coarse rows around it, both admissible and decided (else nothing is claimed there)
      const auto above = std::upper_bound(rows.begin(), rows.end(), b.T);
      if (above == rows.begin() || above == rows.end()) continue;
      const auto before = chainOnePeriodicStability(ready, *(above - 1));
      const auto after = chainOnePeriodicStability(ready, *above);
      if (!before.orbit.admissible() || !after.orbit.admissible()) continue;
      const MultiplierCensus from = censusOf(before.orbit.monodromy), to = censusOf(after.orbit.monodromy);
      if (!from.decided || !to.decided) continue;
      ++compared;
      refined += from.onCircle == to.onCircle;  // (a pair between the two rows)
      const bool found = std::any_of(coarse.begin(), coarse.end(), [&](const ChainBifurcation<double>& c) {
        return c.kind == b.kind && std::abs(c.T - b.T) <= 1e-9 * b.T;
      });
      EXPECT_TRUE(found) << toString(b.kind) << " at T = " << b.T << " " << describe(chain, coarse, b.T);
    }
    for (const ChainBifurcation<double>& c : coarse) {
      // and none invented: a fine grid around it finds it too (the dense one may have no admissible
      // row just before it, where the family's part begins)
      std::vector<double> local;
      for (int k = 0; k < 400; ++k) local.push_back(c.T * (1 + 2e-3 * (k - 199.5) / 200));  // (no row on it)
      const auto fine = chainOnePeriodicBifurcations(ready, local).changes;
      EXPECT_TRUE(std::any_of(fine.begin(), fine.end(), [&](const ChainBifurcation<double>& b) {
        return c.kind == b.kind && std::abs(c.T - b.T) <= 1e-9 * b.T;
      })) << toString(c.kind) << " at T = " << c.T << " " << describe(chain, fine, c.T);
    }
  }
  EXPECT_GT(compared, 10);
  EXPECT_GT(refined, 0) << "no pair hid between two coarse rows: the test shows nothing";
  EXPECT_EQ(unsearched, 0) << "the search ran out of its budget (so a pair may hide there, said)";
}

}  // namespace
}  // namespace grazelab::core
