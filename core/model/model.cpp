// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/model/model.h"

#include "core/numbers/scalar.h"

namespace grazelab::core {
namespace {

template <typename S>
std::string got(const S& value) {
  return "(got " + formatScalar(value) + ")";
}

template <typename S>
void requirePositiveFinite(std::vector<Problem>& problems, const char* field, const S& value) {
  if (!isFinite(value)) {
    problems.push_back({field, "must be a finite number " + got(value)});
  } else if (value <= 0) {
    problems.push_back({field, "must be positive " + got(value)});
  }
}

}  // namespace

template <typename S>
std::vector<Problem> validate(const BasicModel<S>& model) {
  std::vector<Problem> problems;
  requirePositiveFinite(problems, "m1", model.m1);
  requirePositiveFinite(problems, "m2", model.m2);
  requirePositiveFinite(problems, "k1", model.k1);
  if (!model.design) requirePositiveFinite(problems, "k2", model.k2);
  requirePositiveFinite(problems, "gap", model.gap);
  if (problems.empty() && model.design && !designFeasible(model.m1, model.m2)) {
    problems.push_back({"m2", "gives m2/m1 = " + formatScalar(S(model.m2 / model.m1)) +
                                  " > 9/16: no 1:2 resonant chain exists for these masses"});
  }
  return problems;
}

template <typename S>
std::vector<Problem> validateState(const BasicModel<S>& model, const BasicState<S>& state,
                                   const std::string& name) {
  std::vector<Problem> problems;
  const S values[] = {state.u1, state.u2, state.v1, state.v2};
  const char* fields[] = {"u1", "u2", "v1", "v2"};
  for (int i = 0; i < 4; ++i) {
    if (!isFinite(values[i])) {
      problems.push_back({name + "." + fields[i], "must be a finite number " + got(values[i])});
    }
  }
  if (isFinite(state.u2) && isFinite(model.gap) && state.u2 > model.gap) {
    problems.push_back({name + ".u2", "is past the stop: u2 = " + formatScalar(state.u2) +
                                          " > gap = " + formatScalar(model.gap)});
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

template <typename S>
std::optional<BasicModel<S>> designedModel(const S& m1, const S& m2, const S& k1, const S& gap,
                                           Branch branch) {
  BasicModel<S> model{m1, m2, k1, S(1), gap, branch};
  if (!validate(model).empty()) return std::nullopt;
  model.k2 = designKappa(S(m2 / m1), branch) * k1;
  return model;
}

#define GRAZELAB_INSTANTIATE(S)                                                               \
  template std::optional<BasicModel<S>> designedModel<S>(const S&, const S&, const S&, const S&, Branch); \
  template std::vector<Problem> validate<S>(const BasicModel<S>&);                            \
  template std::vector<Problem> validateState<S>(const BasicModel<S>&, const BasicState<S>&, \
                                                 const std::string&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
