// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/model/linear_modes.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/model/two_mass_form.h"

namespace grazelab::core {

Modes computeModes(const Model& model) {
  Modes modes;
  const TwoMassFormOrProblem<double> formed = makeTwoMassForm(model);
  if (!formed.chain) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    modes.omegaFast = modes.omegaSlow = modes.T1 = modes.T2 = nan;
    modes.P.setConstant(nan);
    modes.Pinv.setConstant(nan);
    return modes;
  }
  const TwoMassForm<double>& chain = *formed.chain;
  modes.omegaSlow = chain.omegaSlow;
  modes.omegaFast = chain.ratio * chain.omegaSlow;
  modes.T1 = 2 * std::numbers::pi / modes.omegaFast;
  modes.T2 = 2 * std::numbers::pi / modes.omegaSlow;
  modes.detuning = chain.detuning;
  modes.resonant = chain.resonant;
  // M-normalised columns (rho_j, 1) p_j with p_j = 1 / sqrt(m1 (rho_j^2 + beta))
  const double rho[2] = {chain.rhoFast, chain.rhoSlow};
  for (int j = 0; j < 2; ++j) {
    const double p = 1.0 / (std::sqrt(model.m1) * std::sqrt(rho[j] * rho[j] + chain.beta));
    modes.P(0, j) = rho[j] * p;
    modes.P(1, j) = p;
  }
  // P^-1 = P^T M
  modes.Pinv << modes.P(0, 0) * model.m1, modes.P(1, 0) * model.m2, modes.P(0, 1) * model.m1,
      modes.P(1, 1) * model.m2;
  return modes;
}

}  // namespace grazelab::core
