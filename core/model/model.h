// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/model/resonance.h"
#include "core/model/state.h"

namespace grazelab::core {

/// The chain  wall --k1-- [m1] --k2-- [m2] |<- gap ->| stop  (docs/model.md section 1).
/// Plain parameters; every one must be positive and finite (see validate()).
///
/// `design` says where k2 comes from. Set, the chain IS the 1:2 resonant chain of that branch:
/// k2 holds the design value rounded to S for display, and the solver uses the exact resonance
/// (w1 = 2 w2). Unset, k2 is taken as given and the chain is resonant only if these numbers
/// satisfy the 1:2 condition exactly; anything else is solved as the detuned chain it is.
template <typename S>
struct BasicModel {
  S m1 = 1.0;   ///< mass 1 [mass]
  S m2 = 0.5;   ///< mass 2, the one that hits the stop [mass]
  S k1 = 1.0;   ///< stiffness wall--m1 [force/length]
  S k2 = 0.5;   ///< stiffness m1--m2 [force/length]
  S gap = 1.0;  ///< distance d from equilibrium of mass 2 to the stop [length]
  std::optional<Branch> design;  ///< k2 from the 1:2 design of this branch

  friend bool operator==(const BasicModel&, const BasicModel&) = default;
};

using Model = BasicModel<double>;

/// The same model in another precision.
template <typename To, typename From>
BasicModel<To> convertModel(const BasicModel<From>& m) {
  return {To(m.m1), To(m.m2), To(m.k1), To(m.k2), To(m.gap), m.design};
}

/// One reason why an input is unusable: which field, and why.
struct Problem {
  std::string field;   ///< the offending parameter, e.g. "m2" or "initial.u2"
  std::string reason;  ///< a sentence fragment, e.g. "must be positive (got -1)"
};

/// Returns every problem with the model parameters; empty when the model is usable. A design
/// model also needs m2/m1 <= 9/16.
template <typename S>
std::vector<Problem> validate(const BasicModel<S>& model);

/// Returns the problems of an initial state for this model: non-finite values, or a state past
/// the stop (u2 > gap).
template <typename S>
std::vector<Problem> validateState(const BasicModel<S>& model, const BasicState<S>& state,
                                   const std::string& name);

/// Joins problems into one line: "m1 must be positive (got 0); gap must be finite (got nan)".
std::string describe(const std::vector<Problem>& problems);

/// The 1:2 resonant chain of a branch: k2 from the design (the model remembers it, so the solver
/// uses the exact resonance). Nothing when m2/m1 > 9/16 or an input is unusable.
template <typename S>
std::optional<BasicModel<S>> designedModel(const S& m1, const S& m2, const S& k1, const S& gap,
                                           Branch branch);

}  // namespace grazelab::core
