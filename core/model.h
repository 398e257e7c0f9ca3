// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <string>
#include <vector>

#include "core/state.h"

namespace grazelab::core {

/// The chain  wall --k1-- [m1] --k2-- [m2] |<- gap ->| stop  (MODEL.md section 1).
/// Plain parameters; every one must be positive and finite (see validate()).
struct Model {
  double m1 = 1.0;   ///< mass 1 [mass]
  double m2 = 0.5;   ///< mass 2, the one that hits the stop [mass]
  double k1 = 1.0;   ///< stiffness wall--m1 [force/length]
  double k2 = 0.5;   ///< stiffness m1--m2 [force/length]
  double gap = 1.0;  ///< distance d from equilibrium of mass 2 to the stop [length]

  friend bool operator==(const Model&, const Model&) = default;
};

/// One reason why an input is unusable: which field, and why.
struct Problem {
  std::string field;   ///< the offending parameter, e.g. "m2" or "initial.u2"
  std::string reason;  ///< a sentence fragment, e.g. "must be positive (got -1)"
};

/// Returns every problem with the model parameters; empty when the model is usable.
std::vector<Problem> validate(const Model& model);

/// Returns the problems of an initial state for this model: non-finite values, or a state past
/// the stop (u2 > gap).
std::vector<Problem> validateState(const Model& model, const State& state, const std::string& name);

/// Joins problems into one line: "m1 must be positive (got 0); gap must be finite (got nan)".
std::string describe(const std::vector<Problem>& problems);

/// Mechanical energy E = 1/2 v^T M v + 1/2 u^T K u, written as 1/2 (k1 u1^2 + k2 (u2 - u1)^2)
/// for the potential so that no large terms cancel.
double energy(const Model& model, const State& state);

/// Acceleration of mass 2 in free flight, (k2 (u1 - u2)) / m2.
double freeAcceleration2(const Model& model, const State& state);

}  // namespace grazelab::core
