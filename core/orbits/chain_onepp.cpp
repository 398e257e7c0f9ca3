// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/chain_onepp.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/solver/chain_run.h"
#include "core/solver/sinusoid_zero.h"

namespace grazelab::core {

template <typename S>
BasicChainOnePeriodicOrbit<S> chainOnePeriodicOrbitIn(const BasicMassChain<S>& chain, std::type_identity_t<S> T) {
  if (!(T > 0) || !isFinite(T)) return {};
  return chainOnePeriodicOrbitIn<S>(chain, chainDynamicsIn<S>(chain), T);
}

template <typename S>
BasicChainOnePeriodicOrbit<S> chainOnePeriodicOrbitIn(const BasicMassChain<S>& chain,
                                                      const BasicChainDynamics<S>& dynamics,
                                                      std::type_identity_t<S> T, bool checkReturn) {
  using std::abs;
  using std::cos;
  using std::sin;
  BasicChainOnePeriodicOrbit<S> orbit;
  if (!(T > 0) || !isFinite(T)) return orbit;
  const Eigen::Index n = dynamics.omega.size();
  const int s = dynamics.stop;
  const S ms = chain.masses[std::size_t(s)];
  // g(T) = sum_j a_.j Phi_j(T), a_kj = m_s P[k][j] P[s][j]; a mode with a node at the stop adds 0
  ChainVector<S> g = ChainVector<S>::Zero(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    if (dynamics.nodeAtStop[std::size_t(j)]) continue;
    const S half = dynamics.omega[j] * T / 2;
    const S sine = sin(half);
    // within a few roundings of a multiple of the mode's period: no data there
    if (abs(sine) <= 64 * std::numeric_limits<S>::epsilon() * (1 + half)) {
      orbit.refusal = OnePeriodicRefusal::MultipleOfPeriod;
      return orbit;
    }
    const S phi = cos(half) / sine / dynamics.omega[j];
    g += ms * dynamics.P(s, j) * phi * dynamics.P.col(j);
  }
  orbit.V = chain.gap / g[s];
  orbit.postImpact.u = orbit.V * g;
  orbit.postImpact.u[s] = chain.gap;
  orbit.postImpact.v = ChainVector<S>::Zero(n);
  orbit.postImpact.v[s] = orbit.V;
  orbit.energy = chainEnergy(chain, orbit.postImpact);
  if (!(orbit.V < 0)) {
    orbit.refusal = OnePeriodicRefusal::LeavesIntoStop;
    return orbit;
  }
  if (!checkReturn) {
    orbit.refusal = OnePeriodicRefusal::None;
    return orbit;
  }
  // the flight from the data must meet the stop first at T: searched a little beyond it, not as
  // a periodic flight (T is the orbit's period, not the chain's)
  BasicChainDynamics<S> open = dynamics;
  open.period = 0;
  const BasicChainContact<S> contact = firstContact(open, flightFrom(open, orbit.postImpact), S(T * S(1 + 1e-6)));
  const S tolerance = S(1e-9) * T;
  switch (contact.kind) {
    case ChainContactKind::Impact:
      orbit.refusal = abs(contact.t - T) <= tolerance ? OnePeriodicRefusal::None
                      : contact.t < T                      ? OnePeriodicRefusal::ReturnsEarly
                                                           : OnePeriodicRefusal::NotDecided;
      break;
    case ChainContactKind::Touch:
      orbit.refusal = contact.t < T - tolerance ? OnePeriodicRefusal::ReturnsEarly : OnePeriodicRefusal::NotDecided;
      break;
    case ChainContactKind::Unresolved:
      // a top within rounding of the stop: an early touch or a near miss, not told apart
      orbit.refusal = OnePeriodicRefusal::NotDecided;
      break;
    case ChainContactKind::None:
      orbit.refusal = OnePeriodicRefusal::NeverReturns;
      break;
    case ChainContactKind::Budget:
      // not searched to T: it may come back there or not (never said "never returns")
      orbit.refusal = OnePeriodicRefusal::SearchBudget;
      break;
  }
  return orbit;
}

template BasicChainOnePeriodicOrbit<double> chainOnePeriodicOrbitIn<double>(const BasicMassChain<double>&,
                                                                            const BasicChainDynamics<double>&, double,
                                                                            bool);
template BasicChainOnePeriodicOrbit<long double> chainOnePeriodicOrbitIn<long double>(
    const BasicMassChain<long double>&, const BasicChainDynamics<long double>&, long double, bool);
template BasicChainOnePeriodicOrbit<Quad> chainOnePeriodicOrbitIn<Quad>(const BasicMassChain<Quad>&,
                                                                        const BasicChainDynamics<Quad>&, Quad, bool);
template BasicChainOnePeriodicOrbit<double> chainOnePeriodicOrbitIn<double>(const BasicMassChain<double>&, double);
template BasicChainOnePeriodicOrbit<long double> chainOnePeriodicOrbitIn<long double>(const BasicMassChain<long double>&,
                                                                                      long double);
template BasicChainOnePeriodicOrbit<Quad> chainOnePeriodicOrbitIn<Quad>(const BasicMassChain<Quad>&, Quad);

std::vector<double> onePeriodicGrazingWeights(const MassChain& chain, double periodStar) {
  const ChainModes modes = chainModes(chain);
  const int s = chain.stopped() - 1;
  const double ms = chain.masses[std::size_t(s)];
  std::vector<double> weights(std::size_t(modes.omega.size()), 0.0);
  double total = 0;
  for (Eigen::Index j = 0; j < modes.omega.size(); ++j) {
    if (modes.nodeAtStop[std::size_t(j)]) continue;
    // in I when T* is a whole number of the mode's periods (to 1e-9)
    const double turns = modes.omega[j] * periodStar / (2 * std::numbers::pi);
    if (std::abs(turns - std::round(turns)) > 1e-9 * std::max(1.0, turns) || std::round(turns) < 1) continue;
    const double w = modes.omega[j];
    weights[std::size_t(j)] = ms * modes.P(s, j) * modes.P(s, j) / (w * w);
    total += weights[std::size_t(j)];
  }
  if (total > 0) {
    for (double& weight : weights) weight /= total;
  }
  return weights;
}

double chainOnePeriodicEnd(const MassChain& chain) {
  const ChainDynamics dynamics = chainDynamics(chain);
  return dynamics.period > 0 ? dynamics.period : 2 * std::numbers::pi / slowestFrequency(dynamics.omega);
}

std::vector<ChainFamilyRow> chainOnePeriodicFamily(const MassChain& chain, std::int64_t count,
                                                   std::stop_token stop) {
  const double end = chainOnePeriodicEnd(chain);
  std::vector<double> periods;
  for (std::int64_t k = 1; k <= count; ++k) periods.push_back(end * double(k) / double(count + 1));
  for (int k = 8; k <= 30; ++k) periods.push_back(end * (1 - std::ldexp(1.0, -k)));
  std::sort(periods.begin(), periods.end());
  const ChainDynamics dynamics = chainDynamics(chain);  // (made once: each row's data from it)
  std::vector<ChainFamilyRow> rows;
  rows.reserve(periods.size());
  int outOfBudget = 0;
  for (double T : periods) {
    if (stop.stop_requested()) break;
    rows.push_back({T, chainOnePeriodicOrbitIn<double>(chain, dynamics, T)});
    // a chain whose first rows' searches all ran out of windows is one no row can be searched
    // for (each costs the whole budget, a family of them minutes): stop there
    const OnePeriodicRefusal refusal = rows.back().orbit.refusal;
    if (refusal == OnePeriodicRefusal::SearchBudget) ++outOfBudget;
    if (refusal == OnePeriodicRefusal::None || refusal == OnePeriodicRefusal::NotDecided) outOfBudget = -1000000;
    if (outOfBudget >= kFamilySearchBudgetRows) break;
  }
  return rows;
}

}  // namespace grazelab::core
