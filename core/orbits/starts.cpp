// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/starts.h"

#include <cmath>

#include "core/solver/chain_run.h"

namespace grazelab::core {

template <typename S>
StartOrProblem<S> makeStart(const TwoMassForm<S>& chain, const StartSpec<S>& spec) {
  Start<S> start;
  using Kind = typename StartSpec<S>::Kind;
  switch (spec.kind) {
    case Kind::Glo: {
      if (!isFinite(spec.lambda)) return {std::nullopt, "lambda must be a finite number"};
      start.state = gloData(chain, spec.lambda);
      start.description = "GLO_lambda data, lambda = " + formatScalar(spec.lambda);
      if (chain.resonant) start.description += " (as such: " + describe(classifyGlo(spec.lambda)) + ")";
      break;
    }
    case Kind::Glom:
      start.state = glomData(chain, spec.mode);
      start.description = spec.mode == Mode::Fast ? "GLOM1 data (fast mode)" : "GLOM2 data (slow mode)";
      break;
    case Kind::OnePeriodic: {
      const OnePeriodicOrbit<S> orbit = onePeriodicOrbit(chain, spec.period);
      if (!orbit.admissible) return {std::nullopt, orbit.reason, orbit.refusal == OnePeriodicRefusal::NotDecided};
      start.state = orbit.postImpact;
      start.description = "1IPP orbit of period T = " + formatScalar(spec.period);
      break;
    }
    case Kind::Explicit:
      start.state = spec.state;
      start.description = "explicit state";
      break;
  }
  if (spec.perturbation) {
    const BasicState<S>& delta = *spec.perturbation;
    const BasicState<S> perturbed = start.state + delta;
    const S deltas[] = {delta.u1, delta.u2, delta.v1, delta.v2};
    const S before[] = {start.state.u1, start.state.u2, start.state.v1, start.state.v2};
    const S after[] = {perturbed.u1, perturbed.u2, perturbed.v1, perturbed.v2};
    const char* names[] = {"u1", "u2", "v1", "v2"};
    for (int i = 0; i < 4; ++i) {
      if (deltas[i] != 0 && after[i] == before[i]) {
        start.notes.push_back("the perturbation d" + std::string(names[i]) + " = " +
                              formatScalar(deltas[i]) + " is below one ulp of " + names[i] +
                              " = " + formatScalar(before[i]) +
                              " and vanishes in this precision");
      }
    }
    start.description += ", perturbed by (" + formatScalar(delta.u1) + ", " +
                         formatScalar(delta.u2) + ", " + formatScalar(delta.v1) + ", " +
                         formatScalar(delta.v2) + ")";
    if (!start.notes.empty()) start.description += " [partly lost in rounding]";
    start.state = perturbed;
  }
  if (!spec.perturbation || *spec.perturbation == BasicState<S>{}) start.stillModes = stillModesOf(chain, spec);
  return {start, {}};
}

template <typename S>
std::vector<bool> stillModesOf(const TwoMassForm<S>& chain, const StartSpec<S>& spec) {
  using Kind = typename StartSpec<S>::Kind;
  const bool fastAlone = (spec.kind == Kind::Glo && spec.lambda == 0) || (spec.kind == Kind::Glom && spec.mode == Mode::Fast);
  if (!fastAlone || !chain.resonant) return {};
  return {false, true};
}

#define GRAZELAB_INSTANTIATE(S)                                                                \
  template StartOrProblem<S> makeStart<S>(const TwoMassForm<S>&, const StartSpec<S>&);                \
  template std::vector<bool> stillModesOf<S>(const TwoMassForm<S>&, const StartSpec<S>&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

std::optional<State> sectionStateAtEnergy(const Model& model, double level, double u1, double v1) {
  State state{u1, model.gap, v1, 0.0};
  // what is left for v2 after the springs and mass 1 take their share of the energy
  const double rest = level - energy(model, state);
  if (!(rest >= 0)) return std::nullopt;
  state.v2 = -std::sqrt(2 * rest / model.m2);
  return state;
}

std::optional<State> stopLineStateAtEnergy(const Model& model, double level, double u1,
                                           double speed, double v1Sign) {
  State state{u1, model.gap, 0.0, -std::abs(speed)};
  // what is left for mass 1's speed once its position and mass 2 take their share
  const double rest = level - energy(model, state);
  if (!(rest >= 0)) return std::nullopt;
  state.v1 = std::copysign(std::sqrt(2 * rest / model.m1), v1Sign);
  return state;
}

ChainSectionStart chainSectionStateAtEnergy(const MassChain& chain, double level, const ChainState& base,
                                            int a, double x, int b, double y) {
  const int n = chain.size();
  const int s = chain.stopped() - 1;
  ChainSectionStart start{base};
  if (a == s || a == n + s || b == s || b == n + s) {
    start.problem = ChainSectionProblem::StoppedMassCoordinate;
    return start;
  }
  ChainState& state = start.state;
  const auto set = [&](int c, double value) { (c < n ? state.u[c] : state.v[c - n]) = value; };
  set(a, x);
  set(b, y);
  state.u[s] = chain.gap;
  state.v[s] = 0;
  // what is left for the stopped mass's speed once the springs and the others take their share
  const double rest = level - chainEnergy(chain, state);
  if (!(rest >= 0)) {
    start.problem = ChainSectionProblem::EnergyTooLow;
    return start;
  }
  state.v[s] = -std::sqrt(2 * rest / chain.masses[std::size_t(s)]);
  return start;
}

ChainState chainStopLineState(const MassChain& chain, const ChainState& base, double speed) {
  ChainState state = base;
  const int s = chain.stopped() - 1;
  state.u[s] = chain.gap;
  state.v[s] = -std::abs(speed);
  return state;
}

}  // namespace grazelab::core
