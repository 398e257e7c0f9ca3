// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <Eigen/Core>

#include "core/model/model.h"

namespace grazelab::core {

/// Normal modes of the chain in physical units, for display and reports (docs/model.md section 2):
/// P^T M P = I, P^T K P = diag(w1^2, w2^2). Mode 1 is the FAST mode and mode 2 the SLOW one (the
/// "Labelling" note of docs/model.md): the proofs need w1 = 2 w2, so T2 = 2 T1 and every free
/// motion of a resonant chain is T2-periodic. Eigen indices are 0-based: P(0, j) is the mass-1 row,
/// P(1, j) the mass-2 row, column 0 the fast mode, column 1 the slow mode; P(1, j) > 0.
/// Built from the closed forms of core/model/two_mass_form.h (the solver itself works with those).
struct Modes {
  double omegaFast = 0;  ///< w1 [1/time]; exactly 2 * omegaSlow when resonant
  double omegaSlow = 0;  ///< w2 [1/time]
  double T1 = 0;         ///< 2 pi / w1 [time]
  double T2 = 0;         ///< 2 pi / w2 [time]; the period of every resonant free motion
  Eigen::Matrix2d P;     ///< mode shapes, columns (fast, slow), M-orthonormal
  Eigen::Matrix2d Pinv;  ///< P^-1 = P^T M
  double detuning = 0;   ///< w1/w2 - 2, from the exact resonance defect
  bool resonant = false; ///< w1 = 2 w2 exactly (1:2 design, or numbers that satisfy it exactly)
};

/// The modes of a valid model (precondition: validate(model) is empty). A model whose ratios
/// are beyond double range gives NaN entries.
Modes computeModes(const Model& model);

}  // namespace grazelab::core
