// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/model/mass_chain.cpp: the chain of N masses and its spectrum, against the
// two-mass closed forms, the uniform chains' closed forms and the modes' defining identities.
#include "core/model/mass_chain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/model/linear_modes.h"

namespace grazelab::core {
namespace {

constexpr double kPi = std::numbers::pi;

MassChain uniform(int n, double m, double k, bool rightWall, int stop = 0) {
  MassChain chain;
  chain.masses.assign(std::size_t(n), m);
  chain.springs.assign(std::size_t(n), k);
  chain.rightSpring = rightWall ? k : 0;
  chain.stopMass = stop;
  return chain;
}

TEST(MassChain, TwoMassesAreTheNotesChain) {
  // the note's closed forms (linear_modes.h), for designed and detuned chains
  std::vector<Model> models;
  for (double ratio : {0.05, 0.3, 0.5, 0.5625}) {
    for (Branch branch : {Branch::Upper, Branch::Lower}) {
      models.push_back(*designedModel(1.0, ratio, 1.3, 0.7, branch));
    }
  }
  models.push_back(Model{2.0, 0.7, 1.5, 0.52, 1.0, std::nullopt});
  models.push_back(Model{1.0, 3.0, 0.2, 5.0, 2.0, std::nullopt});
  for (const Model& model : models) {
    const Modes expected = computeModes(model);
    const ChainModes modes = chainModes(massChainOf(model));
    EXPECT_NEAR(modes.omega(0), expected.omegaFast, 1e-14 * expected.omegaFast);
    EXPECT_NEAR(modes.omega(1), expected.omegaSlow, 1e-14 * expected.omegaFast);
    EXPECT_LT((modes.P - expected.P).norm(), 1e-13 * expected.P.norm()) << "m2 = " << model.m2;
    EXPECT_FALSE(modes.nodeAtStop[0] || modes.nodeAtStop[1]);
  }
}

TEST(MassChain, ModesAreMassOrthonormalAndDiagonaliseTheStiffness) {
  std::mt19937_64 random(20261126);
  std::uniform_real_distribution<double> logValue(-2.3, 2.3);  // 0.1 to 10
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 8;
    MassChain chain;
    for (int i = 0; i < n; ++i) {
      chain.masses.push_back(std::exp(logValue(random)));
      chain.springs.push_back(std::exp(logValue(random)));
    }
    chain.rightSpring = trial % 3 == 0 ? std::exp(logValue(random)) : 0;
    chain.stopMass = 1 + trial % n;
    ASSERT_TRUE(validate(chain).empty());
    const ChainModes modes = chainModes(chain);
    const Eigen::MatrixXd M = massMatrix(chain);
    const Eigen::MatrixXd K = stiffnessMatrix(chain);
    const double fastest = modes.omega(0) * modes.omega(0);
    EXPECT_LT((modes.P.transpose() * M * modes.P - Eigen::MatrixXd::Identity(n, n)).norm(), 1e-12 * n);
    const Eigen::MatrixXd diagonal = modes.omega.cwiseAbs2().asDiagonal();
    EXPECT_LT((modes.P.transpose() * K * modes.P - diagonal).norm(), 1e-12 * n * fastest);
    for (int j = 0; j < n; ++j) {
      if (j > 0) {
        EXPECT_GE(modes.omega(j - 1), modes.omega(j));  // fastest first
      }
      if (!modes.nodeAtStop[std::size_t(j)]) {
        EXPECT_GT(modes.P(chain.stopped() - 1, j), 0);
      }
    }
  }
}

// A stiff chain's slowest frequency to relative precision, not only to a fraction of the
// fastest: the product of the w_j^2 is det K / det M, and det K of a chain is a sum of
// positive products of springs (the product of all N, fixed-free; with a right wall the sum
// over i of the products of all N + 1 springs but k_i), both exact to a few ulps. A solver in
// double missed it by up to 1e-10 on these chains (masses and springs from 1e-3 to 1e3).
TEST(MassChain, SlowFrequenciesOfStiffChainsKeepTheirRelativeAccuracy) {
  std::mt19937_64 random(20261127);
  std::uniform_real_distribution<double> logValue(-6.9, 6.9);  // 1e-3 to 1e3
  double worst = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 2 + trial % 7;
    MassChain chain;
    for (int i = 0; i < n; ++i) {
      chain.masses.push_back(std::exp(logValue(random)));
      chain.springs.push_back(std::exp(logValue(random)));
    }
    chain.rightSpring = trial % 2 == 0 ? std::exp(logValue(random)) : 0;
    const ChainModes modes = chainModes(chain);
    std::vector<double> springs = chain.springs;
    if (chain.rightSpring > 0) springs.push_back(chain.rightSpring);
    long double detK = 0;
    if (chain.rightSpring > 0) {
      for (std::size_t skip = 0; skip < springs.size(); ++skip) {
        long double product = 1;
        for (std::size_t i = 0; i < springs.size(); ++i) {
          if (i != skip) product *= springs[i];
        }
        detK += product;
      }
    } else {
      detK = 1;
      for (double k : springs) detK *= k;
    }
    long double detM = 1;
    for (double m : chain.masses) detM *= m;
    long double product = 1;
    for (int j = 0; j < n; ++j) product *= (long double)modes.omega(j) * modes.omega(j);
    const double error = double(std::abs(product / (detK / detM) - 1));
    worst = std::max(worst, error);
    EXPECT_LT(error, 4e-15 * n) << "trial " << trial << ", slowest/fastest "
                                << modes.omega(n - 1) / modes.omega(0);
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(MassChain, UniformChainsHaveTheirClosedFormFrequencies) {
  // N equal masses and springs: fixed at both ends w_j = 2 sqrt(k/m) sin(j pi / (2 (N + 1))),
  // free at the right end w_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2N + 1))) (j = 1 slowest)
  for (int n = 1; n <= 8; ++n) {
    const double m = 0.3, k = 7.0;
    const ChainModes fixed = chainModes(uniform(n, m, k, true));
    const ChainModes free = chainModes(uniform(n, m, k, false));
    for (int j = 1; j <= n; ++j) {
      const double scale = 2 * std::sqrt(k / m);
      EXPECT_NEAR(fixed.omega(n - j), scale * std::sin(j * kPi / (2 * (n + 1))), 1e-13 * scale) << n << " " << j;
      EXPECT_NEAR(free.omega(n - j), scale * std::sin((2 * j - 1) * kPi / (2 * (2 * n + 1))), 1e-13 * scale);
    }
  }
}

TEST(MassChain, ScalingMassesAndSpringsScalesTheModes) {
  MassChain chain{{1.0, 0.4, 2.5}, {3.0, 0.7, 1.1}, 0.9, 2, 1.0};
  MassChain scaled = chain;
  const double a = 1e6, b = 3e-5;  // masses times a, springs times b
  for (double& m : scaled.masses) m *= a;
  for (double& k : scaled.springs) k *= b;
  scaled.rightSpring *= b;
  const ChainModes modes = chainModes(chain);
  const ChainModes other = chainModes(scaled);
  EXPECT_LT((other.omega - modes.omega * std::sqrt(b / a)).norm(), 1e-13 * other.omega.norm());
  EXPECT_LT((other.P - modes.P / std::sqrt(a)).norm(), 1e-13 * other.P.norm());
}

TEST(MassChain, AModeWithANodeAtTheStopIsNamed) {
  // three equal masses between two walls, stopped in the middle: the middle frequency's shape
  // is (1, 0, -1) / sqrt(2 m), which never moves mass 2
  const MassChain chain = uniform(3, 1.0, 1.0, true, 2);
  const ChainModes modes = chainModes(chain);
  EXPECT_EQ(modes.nodeAtStop, (std::vector<bool>{false, true, false}));
  EXPECT_NEAR(std::abs(modes.P(0, 1)), std::sqrt(0.5), 1e-14);
  EXPECT_GT(modes.P(0, 1), 0);  // signed by its first component that moves
  // stopped at an end, every mode moves the stopped mass
  const ChainModes atEnd = chainModes(uniform(3, 1.0, 1.0, true, 3));
  EXPECT_EQ(atEnd.nodeAtStop, (std::vector<bool>{false, false, false}));
}

TEST(MassChain, RatiosAreDetectedWithTheirDetuning) {
  // the 1:2 design: harmonics (2, 1) to the last bits, T = T2
  const Model designed = *designedModel(1.0, 0.4, 1.0, 1.0, Branch::Upper);
  const SpectrumRatios resonant = detectRatios(chainModes(massChainOf(designed)).omega);
  EXPECT_TRUE(resonant.commensurate);
  EXPECT_EQ(resonant.harmonics, (std::vector<int>{2, 1}));
  EXPECT_LT(resonant.detuning, 1e-14);
  EXPECT_NEAR(2 * kPi / resonant.omega0, computeModes(designed).T2, 1e-13 * computeModes(designed).T2);
  // a detuned chain: not commensurate, the nearest ratios and how far
  const Model detuned{1.0, 0.5, 1.0, 0.52, 1.0, std::nullopt};
  const Modes near = computeModes(detuned);
  const SpectrumRatios off = detectRatios(chainModes(massChainOf(detuned)).omega);
  EXPECT_FALSE(off.commensurate);
  EXPECT_EQ(off.harmonics, (std::vector<int>{2, 1}));
  const double ratio = near.omegaFast / near.omegaSlow;
  // w0 = (2 w1 + w2) / 5 fitted to both: the slow mode is the farther, 2 |r - 2| / (2 r + 1)
  EXPECT_NEAR(off.detuning, 2 * std::abs(ratio - 2) / (2 * ratio + 1), 1e-12);
  // two walls, two equal masses: w1/w2 = sqrt(3), no small ratio
  EXPECT_FALSE(detectRatios(chainModes(uniform(2, 1.0, 1.0, true)).omega).commensurate);
  // spectra given directly: gcd 1, the slowest not necessarily harmonic 1
  Eigen::VectorXd omega(3);
  omega << 3.0 * 0.7, 2.0 * 0.7, 1.0 * 0.7;
  EXPECT_EQ(detectRatios(omega).harmonics, (std::vector<int>{3, 2, 1}));
  Eigen::VectorXd twoThree(2);
  twoThree << 3.0 * 1.1, 2.0 * 1.1;
  const SpectrumRatios m23 = detectRatios(twoThree);
  EXPECT_TRUE(m23.commensurate);
  EXPECT_EQ(m23.harmonics, (std::vector<int>{3, 2}));
  EXPECT_NEAR(m23.omega0, 1.1, 1e-15);
}

TEST(MassChain, BadChainsAreRefusedWithTheirReasons) {
  EXPECT_FALSE(validate(MassChain{}).empty());
  MassChain chain{{1.0, -2.0}, {1.0, 1.0}, 0.0, 0, 1.0};
  EXPECT_EQ(describe(validate(chain)), "m2 must be positive and finite (got -2)");
  chain = {{1.0, 2.0}, {1.0}, 0.0, 3, 1.0};
  EXPECT_EQ(validate(chain).size(), 2u);  // a spring missing, a stop mass out of range
  chain = {{1.0}, {1.0}, std::nan(""), 1, 0.0};
  EXPECT_EQ(validate(chain).size(), 2u);
}

}  // namespace
}  // namespace grazelab::core
