// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/model.h"

#include <cmath>
#include <sstream>

namespace grazelab::core {
namespace {

std::string got(double value) {
  std::ostringstream out;
  out.precision(17);
  out << "(got " << value << ")";
  return out.str();
}

void requirePositiveFinite(std::vector<Problem>& problems, const char* field, double value) {
  if (!std::isfinite(value)) {
    problems.push_back({field, "must be a finite number " + got(value)});
  } else if (value <= 0) {
    problems.push_back({field, "must be positive " + got(value)});
  }
}

}  // namespace

std::vector<Problem> validate(const Model& model) {
  std::vector<Problem> problems;
  requirePositiveFinite(problems, "m1", model.m1);
  requirePositiveFinite(problems, "m2", model.m2);
  requirePositiveFinite(problems, "k1", model.k1);
  requirePositiveFinite(problems, "k2", model.k2);
  requirePositiveFinite(problems, "gap", model.gap);
  return problems;
}

std::vector<Problem> validateState(const Model& model, const State& state,
                                   const std::string& name) {
  std::vector<Problem> problems;
  const double values[] = {state.u1, state.u2, state.v1, state.v2};
  const char* fields[] = {"u1", "u2", "v1", "v2"};
  for (int i = 0; i < 4; ++i) {
    if (!std::isfinite(values[i])) {
      problems.push_back({name + "." + fields[i], "must be a finite number " + got(values[i])});
    }
  }
  if (std::isfinite(state.u2) && std::isfinite(model.gap) && state.u2 > model.gap) {
    std::ostringstream reason;
    reason.precision(17);
    reason << "is past the stop: u2 = " << state.u2 << " > gap = " << model.gap;
    problems.push_back({name + ".u2", reason.str()});
  }
  return problems;
}

std::string describe(const std::vector<Problem>& problems) {
  std::string line;
  for (const Problem& problem : problems) {
    if (!line.empty()) line += "; ";
    line += problem.field + " " + problem.reason;
  }
  return line;
}

double energy(const Model& model, const State& state) {
  const double kinetic = model.m1 * state.v1 * state.v1 + model.m2 * state.v2 * state.v2;
  const double stretch = state.u2 - state.u1;
  const double potential = model.k1 * state.u1 * state.u1 + model.k2 * stretch * stretch;
  return 0.5 * (kinetic + potential);
}

double freeAcceleration2(const Model& model, const State& state) {
  return model.k2 * (state.u1 - state.u2) / model.m2;
}

}  // namespace grazelab::core
