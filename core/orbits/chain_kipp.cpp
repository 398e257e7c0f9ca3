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

namespace {

// The section's coordinates: every u_j and v_j but the stopped mass's (indices into x = (u, v)).
std::vector<Eigen::Index> sectionIndices(Eigen::Index n, Eigen::Index s) {
  std::vector<Eigen::Index> out;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (j != s) out.push_back(j);
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    if (j != s) out.push_back(n + j);
  }
  return out;
}

// K u, the springs' pull on each mass reversed: the energy's gradient in u
template <typename S>
ChainVector<S> springForce(const BasicMassChain<S>& chain, const ChainVector<S>& u) {
  const Eigen::Index n = u.size();
  ChainVector<S> f = ChainVector<S>::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const S stretch = i == 0 ? u[0] : S(u[i] - u[i - 1]);
    const S k = chain.springs[std::size_t(i)];
    f[i] += k * stretch;
    if (i > 0) f[i - 1] -= k * stretch;
  }
  if (chain.rightSpring > 0) f[n - 1] += chain.rightSpring * u[n - 1];
  return f;
}

// Newton's unknowns: the section's coordinates, then (at a fixed period) the energy.
template <typename S>
struct Unknowns {
  const BasicReadyChain<S>& chain;
  std::vector<Eigen::Index> section;
  ChainOrbitConstraint fixed;
  S value;  // the energy or the period held fixed

  Eigen::Index size() const { return Eigen::Index(section.size()) + (fixed == ChainOrbitConstraint::Period ? 1 : 0); }

  ChainVector<S> of(const BasicChainState<S>& state) const {
    ChainVector<S> z(size());
    const Eigen::Index n = state.u.size();
    for (std::size_t i = 0; i < section.size(); ++i) {
      z[Eigen::Index(i)] = section[i] < n ? state.u[section[i]] : state.v[section[i] - n];
    }
    if (fixed == ChainOrbitConstraint::Period) z[size() - 1] = chainEnergy(chain.numbers, state);
    return z;
  }

  S energy(const ChainVector<S>& z) const { return fixed == ChainOrbitConstraint::Period ? z[size() - 1] : value; }

  // the state on H+ at z: v_s <= 0 from the energy; none when the rest hold more than it
  std::optional<BasicChainState<S>> state(const ChainVector<S>& z, const BasicChainState<S>& like) const {
    using std::sqrt;
    BasicChainState<S> x = like;
    const Eigen::Index n = x.u.size();
    const Eigen::Index s = chain.dynamics.stop;
    for (std::size_t i = 0; i < section.size(); ++i) {
      (section[i] < n ? x.u[section[i]] : x.v[section[i] - n]) = z[Eigen::Index(i)];
    }
    x.u[s] = chain.dynamics.gap;
    x.v[s] = 0;
    const S kinetic = energy(z) - chainEnergy(chain.numbers, x);
    if (!(kinetic >= 0) || !isFinite(kinetic)) return std::nullopt;
    x.v[s] = -sqrt(2 * kinetic / chain.dynamics.mass[s]);
    return x;
  }

  // d x / d z at the state x (2N x size): the section's coordinates move themselves, and v_s keeps
  // the energy: m_s v_s dv_s = dE - (K u)_j du_j - m_j v_j dv_j
  ChainMatrix<S> tangent(const BasicChainState<S>& x) const {
    const Eigen::Index n = x.u.size();
    const Eigen::Index s = chain.dynamics.stop;
    const S momentum = chain.dynamics.mass[s] * x.v[s];
    const ChainVector<S> force = springForce(chain.numbers, x.u);
    ChainMatrix<S> g = ChainMatrix<S>::Zero(2 * n, size());
    for (std::size_t i = 0; i < section.size(); ++i) {
      const Eigen::Index k = section[i];
      g(k, Eigen::Index(i)) = 1;
      const S gradient = k < n ? force[k] : S(chain.dynamics.mass[k - n] * x.v[k - n]);
      g(n + s, Eigen::Index(i)) = -gradient / momentum;
    }
    if (fixed == ChainOrbitConstraint::Period) g(n + s, size() - 1) = 1 / momentum;
    return g;
  }

  // the unit of each unknown: the gap for lengths, the scale's speed for speeds, the energy itself
  ChainVector<S> units(const ChainVector<S>& z) const {
    using std::abs;
    const ChainStateScale<S> scale(chain.dynamics);
    const Eigen::Index n = chain.dynamics.mass.size();
    ChainVector<S> out(size());
    for (std::size_t i = 0; i < section.size(); ++i) out[Eigen::Index(i)] = section[i] < n ? scale.length : scale.speed;
    if (fixed == ChainOrbitConstraint::Period) out[size() - 1] = std::max<S>(abs(z[size() - 1]), S(1e-300));
    return out;
  }

  // the inverse Jacobian's amplification of a scaled residual (the section's coordinates in their
  // units, the period relative to the one asked for) into a scaled step: |D J^-1 R^-1|, infinity norm
  S inverseSize(const ChainMatrix<S>& inverse, const ChainVector<S>& z) const {
    ChainVector<S> residualUnits = units(z);
    if (fixed == ChainOrbitConstraint::Period) residualUnits[size() - 1] = value;
    const ChainVector<S> unknownUnits = units(z);
    S largest = 0;  // (by loops: GCC 12 sees Eigen's rowwise sum of long doubles as uninitialized)
    for (Eigen::Index i = 0; i < inverse.rows(); ++i) {
      S row = 0;
      for (Eigen::Index j = 0; j < inverse.cols(); ++j) {
        using std::abs;
        row += abs(inverse(i, j)) * residualUnits[j] / unknownUnits[i];
      }
      largest = std::max(largest, row);
    }
    return largest;
  }

  // how big a step dz is: lengths over the gap, speeds over the scale's speed, the energy relative
  S stepSize(const ChainVector<S>& dz, const ChainVector<S>& z) const {
    return size() == 0 ? S(0) : S(dz.cwiseQuotient(units(z)).cwiseAbs().maxCoeff());
  }
};

// the tolerance a path of `impacts` impacts closes to when the return map amplifies its rounding
// `amplification` times (as closeTolerance of two masses: at most a million times the default)
template <typename S>
S chainCloseTolerance(int impacts, const S& amplification) {
  return std::min<S>(defaultCloseTolerance<S>() * S(8 * std::max(1, impacts)) * std::max<S>(S(1), amplification),
                     S(1e6) * defaultCloseTolerance<S>());
}

// Whether an impact before the last comes back to the start within `within` (scaled, relative as
// the periodicity residual): a shorter orbit repeated, as far as the orbit is known. Near a period
// doubling Newton from a guess off the doubled orbit may converge to the shorter one run twice, and
// then knows it only to its step along the flip's direction, far beyond the rounding.
template <typename S>
bool isRepeated(const BasicChainDynamics<S>& dynamics, const BasicChainPeriodicOrbit<S>& orbit, const S& within) {
  const ChainStateScale<S> scale(dynamics);
  const auto scaled = [&](const ChainVector<S>& u, const ChainVector<S>& v) {
    ChainVector<S> x(2 * u.size());
    x << u, v;
    return ChainVector<S>(scale.scaled(x));
  };
  const ChainVector<S> x0 = scaled(orbit.state.u, orbit.state.v);
  for (std::size_t i = 0; i + 1 < orbit.events.size(); ++i) {
    const BasicChainEvent<S>& event = orbit.events[i];
    ChainVector<S> v = event.vBefore;
    v[dynamics.stop] = event.vAfter;
    if ((scaled(event.u, v) - x0).norm() / std::max<S>(S(1), x0.norm()) <= within) return true;
  }
  return false;
}

}  // namespace

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
    // the return map's Jacobian: the monodromy M projected on H along the flow f after the last
    // impact, DP = (I - f e_(u_s)^T / v_s) M, and the period's gradient dT = -e_(u_s)^T M / v_s
    const BasicChainEvent<S>& last = path.events.back();
    BasicChainState<S> end{last.u, last.vBefore};
    end.v[s] = last.vAfter;
    const ChainMatrix<S> m = chainMonodromyMatrix(dynamics, legsOf(dynamics, path.events));
    ChainVector<S> flow(2 * n);
    flow << end.v, -springForce(chain.numbers, end.u).cwiseQuotient(dynamics.mass);
    const ChainMatrix<S> dp = m - flow * m.row(s) / end.v[s];
    const ChainMatrix<S> g = unknowns.tangent(*start);
    const Eigen::Index size = unknowns.size();
    ChainMatrix<S> jacobian(size, size);
    ChainVector<S> f(size);
    const ChainMatrix<S> dpg = dp * g;
    for (std::size_t i = 0; i < unknowns.section.size(); ++i) {
      const Eigen::Index k = unknowns.section[i];
      jacobian.row(Eigen::Index(i)) = dpg.row(k);
      jacobian(Eigen::Index(i), Eigen::Index(i)) -= 1;
      f[Eigen::Index(i)] = (k < n ? end.u[k] : end.v[k - n]) - z[Eigen::Index(i)];
    }
    if (fixed == ChainOrbitConstraint::Period) {
      jacobian.row(size - 1) = -(m.row(s) * g) / end.v[s];
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
