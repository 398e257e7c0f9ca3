// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/modes.h"

#include <Eigen/Eigenvalues>

#include <cassert>
#include <cmath>
#include <numbers>

namespace grazelab::core {

Modes computeModes(const Model& model) {
  Eigen::Matrix2d mass;
  mass << model.m1, 0, 0, model.m2;
  Eigen::Matrix2d stiffness;
  stiffness << model.k1 + model.k2, -model.k2, -model.k2, model.k2;

  // eigenvectors come M-orthonormal, eigenvalues ascending: column 1 is the fast mode
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> solver(stiffness, mass);
  assert(solver.info() == Eigen::Success);
  const Eigen::Vector2d omegaSquared = solver.eigenvalues();
  const Eigen::Matrix2d vectors = solver.eigenvectors();

  Modes modes;
  modes.P.col(0) = vectors.col(1);
  modes.P.col(1) = vectors.col(0);
  for (int j = 0; j < 2; ++j) {
    if (modes.P(1, j) < 0) modes.P.col(j) = -modes.P.col(j);
  }
  // the exact inverse of the rounded P, not P^T M: the product P P^-1 then equals I to rounding,
  // and free flights (u -> q -> u) do not pick up a fixed bias that drifts the energy
  modes.Pinv = modes.P.inverse();

  double fast = std::sqrt(omegaSquared(1));
  double slow = std::sqrt(omegaSquared(0));
  modes.detuning = fast / slow - 2.0;
  modes.resonant = std::abs(modes.detuning) <= kResonanceTolerance;
  if (modes.resonant) {
    // snap to an exact 1:2 ratio so that free motions are exactly T2-periodic in floating point
    slow = 0.5 * (slow + 0.5 * fast);
    fast = 2.0 * slow;
  }
  modes.omegaFast = fast;
  modes.omegaSlow = slow;
  modes.T1 = 2.0 * std::numbers::pi / fast;
  modes.T2 = 2.0 * std::numbers::pi / slow;
  return modes;
}

}  // namespace grazelab::core
