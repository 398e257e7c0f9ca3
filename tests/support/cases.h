// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Canonical chains and starts shared by tests and benchmarks, and the tolerances they use.
#pragma once

#include <cmath>
#include <cstdlib>
#include <ostream>
#include <string>
#include <vector>

#include "core/model/model.h"
#include "core/model/linear_modes.h"
#include "core/orbits/special_orbits.h"
#include "core/model/resonance.h"
#include "core/orbits/starts.h"

namespace grazelab::testing {

/// Multiplies every tolerance; set GRAZELAB_TOLERANCE_SCALE to loosen or tighten for diagnosis.
inline double toleranceScale() {
  const char* text = std::getenv("GRAZELAB_TOLERANCE_SCALE");
  return text ? std::atof(text) : 1.0;
}

/// A tolerance relative to a scale (T2, the gap, a velocity scale).
inline double tolerance(double relative, double scale) {
  return relative * toleranceScale() * scale;
}

/// The 1:2 resonant chain with m1 = k1 = 1 and the given m2, gap, branch.
inline core::Model resonantChain(double m2 = 0.5, double gap = 1.0,
                                 core::Branch branch = core::Branch::Upper) {
  return *core::designedModel(1.0, m2, 1.0, gap, branch);
}

/// A named chain for parameterized suites.
struct Chain {
  std::string name;
  core::Model model;
};

/// GoogleTest prints a parameter by its name (test names stay readable in ctest).
inline void PrintTo(const Chain& chain, std::ostream* out) { *out << chain.name; }

/// Resonant chains: both branches, an extreme mass ratio, a tiny and a huge gap, the merge point.
inline std::vector<Chain> resonantChains() {
  return {
      {"Upper", resonantChain(0.5)},
      {"Lower", resonantChain(0.5, 1.0, core::Branch::Lower)},
      {"MassRatio1em4", resonantChain(1e-4)},
      {"MassRatio1em4Lower", resonantChain(1e-4, 1.0, core::Branch::Lower)},
      {"Gap1em9", resonantChain(0.5, 1e-9)},
      {"Gap1e6", resonantChain(0.5, 1e6)},
      {"MergePoint", resonantChain(9.0 / 16.0)},
  };
}

/// A chain off the 1:2 design (k2 = 0.45 instead of 0.5): free motion is quasi-periodic.
inline core::Model detunedChain() { return {1.0, 0.5, 1.0, 0.45, 1.0, {}}; }

/// GLO_lambda data pushed off the grazing-start plane by dv2 = -push * w2 * gap (v2 < 0), so
/// that it impacts (a push along the plane gives another grazing orbit, docs/model.md section 5).
inline core::State nearGrazingStart(const core::Model& model, double lambda, double push) {
  const core::Modes modes = core::computeModes(model);
  core::State state = core::gloData(model, modes, lambda);
  state.v2 = -push * modes.omegaSlow * model.gap;
  return state;
}

}  // namespace grazelab::testing
