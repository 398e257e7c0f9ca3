// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

// The return map to the stopped mass's impacts as Newton and continuation take it (private to
// core/orbits: chain_kipp.cpp, chain_continuation.cpp; docs/model.md section 12): its unknowns
// (the section's coordinates, and the energy where it moves), the residual P^k(x) - x and its
// exact Jacobian from the path's monodromy.

#include <Eigen/Core>

#include <algorithm>
#include <optional>
#include <vector>

#include "core/orbits/chain_kipp.h"

namespace grazelab::core::return_map {

// The section's coordinates: every u_j and v_j but the stopped mass's (indices into x = (u, v)).
inline std::vector<Eigen::Index> sectionIndices(Eigen::Index n, Eigen::Index s) {
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

// For an orbit of an even number k of impacts: its state after k/2 impacts less its start, in
// the scaled units. The two halves of a family born at a period doubling are each other's orbits
// seen from their middle impact, so that this difference changes sign where the family passes
// through the doubled orbit (none for an odd k: empty).
template <typename S>
ChainVector<S> halfPeriodShift(const BasicChainDynamics<S>& dynamics, const BasicChainPeriodicOrbit<S>& orbit) {
  const std::size_t k = orbit.events.size();
  if (k < 2 || k % 2 != 0) return {};
  const ChainStateScale<S> scale(dynamics);
  const BasicChainEvent<S>& middle = orbit.events[k / 2 - 1];
  const Eigen::Index n = middle.u.size();
  ChainVector<S> x(2 * n);
  x << middle.u - orbit.state.u, middle.vBefore - orbit.state.v;
  x[n + dynamics.stop] = middle.vAfter - orbit.state.v[dynamics.stop];
  return scale.scaled(x);
}

// The return map at a path that held its impact sequence: the residual on the section and its
// Jacobian in the unknowns, and the period's gradient.
template <typename S>
struct ReturnMapAt {
  ChainVector<S> residual;     // x_k - x_0 in the section's coordinates (2N - 2)
  ChainMatrix<S> jacobian;     // d residual / d z: (2N - 2) x the unknowns
  ChainMatrix<S> periodRow;    // dT / dz: 1 x the unknowns
  ChainMatrix<S> projected;    // DP = (I - f e_(u_s)^T / v_s) M, 2N x 2N: how the map amplifies
};

// The return map's Jacobian: the monodromy M projected on H along the flow f after the last
// impact, DP = (I - f e_(u_s)^T / v_s) M, and the period's gradient dT = -e_(u_s)^T M / v_s, both
// through the unknowns' tangent g at the start
template <typename S>
ReturnMapAt<S> returnMapAt(const Unknowns<S>& unknowns, const ChainVector<S>& z, const BasicChainState<S>& start,
                           const BasicChainPeriodicOrbit<S>& path) {
  const BasicChainDynamics<S>& dynamics = unknowns.chain.dynamics;
  const Eigen::Index n = dynamics.mass.size();
  const Eigen::Index s = dynamics.stop;
  const BasicChainEvent<S>& last = path.events.back();
  BasicChainState<S> end{last.u, last.vBefore};
  end.v[s] = last.vAfter;
  const ChainMatrix<S> m = chainMonodromyMatrix(dynamics, legsOf(dynamics, path.events));
  ChainVector<S> flow(2 * n);
  flow << end.v, -springForce(unknowns.chain.numbers, end.u).cwiseQuotient(dynamics.mass);
  ReturnMapAt<S> at;
  at.projected = m - flow * m.row(s) / end.v[s];
  const ChainMatrix<S> g = unknowns.tangent(start);
  const Eigen::Index size = unknowns.size();
  const Eigen::Index sectionSize = Eigen::Index(unknowns.section.size());
  at.jacobian = ChainMatrix<S>(sectionSize, size);
  at.residual = ChainVector<S>(sectionSize);
  const ChainMatrix<S> dpg = at.projected * g;
  for (std::size_t i = 0; i < unknowns.section.size(); ++i) {
    const Eigen::Index k = unknowns.section[i];
    at.jacobian.row(Eigen::Index(i)) = dpg.row(k);
    at.jacobian(Eigen::Index(i), Eigen::Index(i)) -= 1;
    at.residual[Eigen::Index(i)] = (k < n ? end.u[k] : end.v[k - n]) - z[Eigen::Index(i)];
  }
  at.periodRow = -(m.row(s) * g) / end.v[s];
  return at;
}

}  // namespace grazelab::core::return_map
