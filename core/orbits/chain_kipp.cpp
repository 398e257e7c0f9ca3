// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/chain_kipp.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "core/numbers/eigen_quad.h"
#include "core/orbits/chain_return_map.h"

namespace grazelab::core {

std::string_view toString(ChainOrbitProblem problem) {
  switch (problem) {
    case ChainOrbitProblem::None: return "found";
    case ChainOrbitProblem::NoImpacts: return "no impact asked for";
    case ChainOrbitProblem::NoStateAtGuess:
      return "the guess has no state just after an impact on H (the other masses hold more than the energy, or "
             "its v_s is not below 0)";
    case ChainOrbitProblem::GuessOffSequence:
      return "the guess's own path makes another sequence of contacts: give a guess nearer the orbit";
    case ChainOrbitProblem::LeftEnergyLevel: return "Newton left the energy level: give a guess nearer the orbit";
    case ChainOrbitProblem::LeftImpactSequence:
      return "Newton left the orbits of this many impacts: give a guess nearer the orbit";
    case ChainOrbitProblem::Singular:
      return "the return map's Jacobian is singular here (a multiplier at 1: a fold or branch point; at a fixed "
             "period also where the family's period does not change with its energy: try a fixed energy)";
    case ChainOrbitProblem::NotConverging: return "Newton does not converge from this guess";
    case ChainOrbitProblem::Stalled:
      return "Newton stalled: the path closes to its rounding with a large step still to go (a bifurcation is near)";
    case ChainOrbitProblem::NotAdmissible: return "the orbit found is not admissible";
    case ChainOrbitProblem::Stopped: return "stopped";
  }
  return "unknown";
}

using namespace return_map;

template <typename S>
ChainOrbitSearch<S> findChainOrbit(const BasicReadyChain<S>& chain, const BasicChainState<S>& guess, int impacts,
                                   ChainOrbitConstraint fixed, const std::type_identity_t<S>& value,
                                   std::stop_token stop) {
  using std::sqrt;
  ChainOrbitSearch<S> search;
  const BasicChainDynamics<S>& dynamics = chain.dynamics;
  const Eigen::Index n = dynamics.mass.size();
  const Eigen::Index s = dynamics.stop;
  const Unknowns<S> unknowns{chain, sectionIndices(n, s), fixed, value};
  if (impacts < 1) {
    search.problem = ChainOrbitProblem::NoImpacts;
    return search;
  }
  if (fixed == ChainOrbitConstraint::Period && !(guess.v[s] <= 0)) {
    search.problem = ChainOrbitProblem::NoStateAtGuess;
    return search;
  }
  ChainVector<S> z = unknowns.of(guess);
  constexpr int kIterations = 60;
  // a residual that has not improved on its best for this many iterations is wandering
  constexpr int kPatience = 8;
  S bestResidual = std::numeric_limits<S>::infinity();
  int bestIteration = 0;
  std::optional<BasicChainState<S>> closed;  // the last iterate that closed within the tolerance
  S closedResidual = std::numeric_limits<S>::infinity();
  S closedStep = 0;  // the step that led to it (how far it may be, where its own step is not known)
  // how far the closed iterate may be along the return map's softest direction: the tolerance
  // times |(DP^k - I)^-1| in scaled units (next to a period doubling of the shorter orbit, 1e4
  // times the rounding: double cannot tell that orbit run twice from a k-impact one there)
  S closedSpread = 0;
  S tolerance = chainCloseTolerance<S>(impacts, S(1));
  const auto accept = [&]() {
    if (closedResidual == 0) search.correction = 0;  // closed exactly
    if (search.correction > sqrt(tolerance)) {
      search.problem = ChainOrbitProblem::Stalled;
      return search;
    }
    BasicChainPeriodicOrbit<S> orbit = evaluateChainOrbit(chain, *closed, impacts, tolerance);
    if (orbit.admissible() && isRepeated(dynamics, orbit, std::max({tolerance, S(8 * search.correction), closedSpread}))) {
      orbit.refusal = OrbitRefusal::Repeated;
    }
    if (!orbit.admissible()) {
      search.problem = ChainOrbitProblem::NotAdmissible;
      search.refusal = orbit.refusal;
      return search;
    }
    search.orbit = std::move(orbit);
    return search;
  };
  // a damped Newton: a step that leaves the energy level or the impact sequence, or makes the
  // residual a thousand times larger (beyond where the linear model holds), is taken back by half;
  // near a bifurcation, where orbits of interest lie, the basin of the full step is small. (Not
  // monotone: next to a parabolic orbit the residual may rise on the way to converging.)
  constexpr int kHalvings = 8;
  ChainVector<S> from;  // the iterate the last step was taken from
  ChainVector<S> step;
  S fromResidual = std::numeric_limits<S>::infinity();
  int halvings = 0;
  const auto backtrack = [&]() {
    if (step.size() == 0 || halvings >= kHalvings) return false;
    ++halvings;
    step /= 2;
    z = from - step;
    return true;
  };
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    search.iterations = iteration + 1;
    if (stop.stop_requested()) {
      search.problem = ChainOrbitProblem::Stopped;
      return search;
    }
    const std::optional<BasicChainState<S>> start = unknowns.state(z, guess);
    if (!start && closed) return accept();
    if (!start && backtrack()) continue;
    if (!start) {
      search.problem = iteration == 0 ? ChainOrbitProblem::NoStateAtGuess : ChainOrbitProblem::LeftEnergyLevel;
      return search;
    }
    const BasicChainPeriodicOrbit<S> path = evaluateChainPath(chain, *start, impacts, tolerance);
    const bool sequenceHeld = path.refusal == OrbitRefusal::None || path.refusal == OrbitRefusal::NotClosed;
    if (!sequenceHeld && closed) return accept();
    if (!sequenceHeld && path.refusal != OrbitRefusal::Repeated && backtrack()) continue;
    if (!sequenceHeld) {
      search.problem = path.refusal == OrbitRefusal::Repeated ? ChainOrbitProblem::NotAdmissible
                       : iteration == 0                       ? ChainOrbitProblem::GuessOffSequence
                                                              : ChainOrbitProblem::LeftImpactSequence;
      search.refusal = path.refusal;
      return search;
    }
    // at a fixed period the path must also take that long
    using std::abs;
    const S residual = fixed == ChainOrbitConstraint::Period
                           ? std::max<S>(path.periodicityResidual, abs(path.period - value) / value)
                           : path.periodicityResidual;
    // within the tolerance Newton goes on while the residual still halves: an iterate passing
    // through it may be on its way to another orbit (near a flip, the k/2-impact orbit twice)
    const bool closes = residual <= tolerance;
    if (closed && !(closes && residual < closedResidual / 2)) return accept();
    if (!closes && !(residual < S(1000) * fromResidual) && backtrack()) continue;
    halvings = 0;
    if (closes) {
      closed = *start;
      closedResidual = residual;
      closedStep = search.correction;
      if (residual == 0) return accept();
      search.correction = std::numeric_limits<S>::infinity();  // until its step is known
    }
    if (residual < bestResidual) {
      bestResidual = residual;
      bestIteration = iteration;
    } else if (iteration - bestIteration >= kPatience) {
      search.problem = ChainOrbitProblem::NotConverging;
      return search;
    }
    const ReturnMapAt<S> map = returnMapAt(unknowns, z, *start, path);
    const ChainMatrix<S>& dp = map.projected;
    const Eigen::Index size = unknowns.size();
    ChainMatrix<S> jacobian(size, size);
    ChainVector<S> f(size);
    jacobian.topRows(map.jacobian.rows()) = map.jacobian;
    f.head(map.residual.size()) = map.residual;
    if (fixed == ChainOrbitConstraint::Period) {
      jacobian.row(size - 1) = map.periodRow;
      f[size - 1] = path.period - value;
    }
    // the rounding of the path grows by how much the return map amplifies it (scaled units)
    const ChainStateScale<S> scale(dynamics);
    tolerance = chainCloseTolerance<S>(impacts, S(scale.scaled(dp).cwiseAbs().maxCoeff()));
    if (size == 0) {  // one mass: the energy is the orbit, nothing is left to solve
      closed = *start;
      search.correction = 0;
      return accept();
    }
    const Eigen::FullPivLU<ChainMatrix<S>> lu(jacobian);
    if (!lu.isInvertible() || !isFinite(S(jacobian.cwiseAbs().maxCoeff()))) {
      if (closed) {  // (singular at an orbit that closes: a degenerate one, known to its last step)
        search.correction = closedStep;
        return accept();
      }
      search.problem = ChainOrbitProblem::Singular;
      return search;
    }
    step = lu.solve(f);
    search.correction = unknowns.stepSize(step, z);
    if (closes) closedSpread = tolerance * unknowns.inverseSize(lu.inverse(), z);
    from = z;
    fromResidual = residual;
    z -= step;
  }
  if (closed) return accept();
  search.problem = ChainOrbitProblem::NotConverging;
  return search;
}

#define GRAZELAB_INSTANTIATE(S)                                                                                 \
  template ChainOrbitSearch<S> findChainOrbit<S>(const BasicReadyChain<S>&, const BasicChainState<S>&, int, \
                                                 ChainOrbitConstraint, const S&, std::stop_token);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)

}  // namespace grazelab::core
