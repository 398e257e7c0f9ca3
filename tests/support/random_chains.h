// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

// What the tests of periodic orbits of N masses share: random chains, the distance of two states
// in a chain's scaled units, and the direction of a multiplier -1.

#include <Eigen/Eigenvalues>

#include <cmath>
#include <random>

#include "core/model/mass_chain.h"
#include "core/orbits/chain_monodromy.h"

namespace grazelab::core::test_chains {

/// A random chain of n masses (masses and springs from 0.3 to 3), a right wall or not, the stop
/// on any mass, the gap from 0.5 to 1.5.
inline MassChain randomChain(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> logUniform(-0.5, 0.5);
  MassChain chain;
  for (int i = 0; i < n; ++i) {
    chain.masses.push_back(std::pow(10.0, logUniform(rng)));
    chain.springs.push_back(std::pow(10.0, logUniform(rng)));
  }
  chain.rightSpring = rng() % 2 ? std::pow(10.0, logUniform(rng)) : 0.0;
  chain.stopMass = int(rng() % unsigned(n)) + 1;
  chain.gap = 0.5 + double(rng() % 1000) / 1000.0;
  return chain;
}

/// The largest difference of two states in the scaled units of the chain (lengths over the gap,
/// speeds over the scale's speed).
template <typename S>
S stateDistance(const BasicChainDynamics<S>& dynamics, const BasicChainState<S>& a, const BasicChainState<S>& b) {
  const ChainStateScale<S> scale(dynamics);
  ChainVector<S> x(2 * a.u.size());
  x << a.u - b.u, a.v - b.v;
  return scale.scaled(x).cwiseAbs().maxCoeff();
}

/// The unit eigenvector of the eigenvalue of `m` nearest -1 (real: a period doubling's).
inline ChainVector<double> flipDirection(const ChainMatrix<double>& m) {
  const Eigen::EigenSolver<ChainMatrix<double>> solver(m);
  Eigen::Index best = 0;
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    if (std::abs(solver.eigenvalues()[i] + 1.0) < std::abs(solver.eigenvalues()[best] + 1.0)) best = i;
  }
  return solver.eigenvectors().col(best).real().normalized();
}

}  // namespace grazelab::core::test_chains
