// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/chain_flight.h"

#include <cmath>
#include <numbers>

#include "core/solver/sinusoid_zero.h"

namespace grazelab::core {

ChainDynamics chainDynamics(const MassChain& chain) {
  const ChainModes modes = chainModes(chain);
  ChainDynamics dynamics;
  dynamics.P = modes.P;
  dynamics.omega = modes.omega;
  dynamics.mass = Eigen::Map<const Eigen::VectorXd>(chain.masses.data(), Eigen::Index(chain.masses.size()));
  dynamics.stop = chain.stopped() - 1;
  dynamics.gap = chain.gap;
  const SpectrumRatios ratios = detectRatios(modes.omega);
  if (ratios.commensurate) {
    for (Eigen::Index j = 0; j < dynamics.omega.size(); ++j) {
      dynamics.omega[j] = ratios.harmonics[std::size_t(j)] * ratios.omega0;
    }
    dynamics.period = 2 * std::numbers::pi / ratios.omega0;
    dynamics.harmonics = ratios.harmonics;
    dynamics.omega0 = ratios.omega0;
  }
  return dynamics;
}

void flightInto(const ChainDynamics& dynamics, const ChainState& start, ChainFlight& flight) {
  // P^T M P = I: the modal coordinates are P^T M u
  thread_local Eigen::VectorXd weighted;
  weighted = dynamics.mass.cwiseProduct(start.u);
  flight.q.noalias() = dynamics.P.transpose() * weighted;
  weighted = dynamics.mass.cwiseProduct(start.v);
  flight.qdot.noalias() = dynamics.P.transpose() * weighted;
  flight.onStop = dynamics.stop < start.u.size() && start.u[dynamics.stop] == dynamics.gap;
  flight.atRest = flight.onStop && start.v[dynamics.stop] == 0;
}

ChainFlight flightFrom(const ChainDynamics& dynamics, const ChainState& start) {
  ChainFlight flight;
  flightInto(dynamics, start, flight);
  return flight;
}

void stateInto(const ChainDynamics& dynamics, const ChainFlight& flight, double t, ChainState& state) {
  const Eigen::Index n = flight.q.size();
  thread_local Eigen::VectorXd q, qdot;
  q.resize(n);
  qdot.resize(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double w = dynamics.omega[j];
    const double c = std::cos(w * t), s = std::sin(w * t);
    q[j] = flight.q[j] * c + flight.qdot[j] / w * s;
    qdot[j] = -flight.q[j] * w * s + flight.qdot[j] * c;
  }
  state.u.noalias() = dynamics.P * q;
  state.v.noalias() = dynamics.P * qdot;
}

ChainState stateAt(const ChainDynamics& dynamics, const ChainFlight& flight, double t) {
  ChainState state;
  stateInto(dynamics, flight, t, state);
  return state;
}

ChainContact firstContact(const ChainDynamics& dynamics, const ChainFlight& flight, double horizon, long maxWindows,
                          std::optional<double> releaseJerk) {
  // u_s(t) - d = sum_j P[s][j] (q_j cos w_j t + qdot_j / w_j sin w_j t) - d
  // one per thread, reused: a run's flights then allocate nothing here (a quarter of the time of
  // a small chain's contact went to malloc and free)
  thread_local SinusoidSum distance;
  const Eigen::Index n = flight.q.size();
  distance.w = dynamics.omega;
  distance.a.resize(n);
  distance.b.resize(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double p = dynamics.P(dynamics.stop, j);
    distance.a[j] = p * flight.q[j];
    distance.b[j] = p * flight.qdot[j] / dynamics.omega[j];
  }
  distance.offset = -dynamics.gap;
  distance.harmonics = dynamics.harmonics;
  distance.omega0 = dynamics.omega0;
  // a flight from the stop (after an impact, u_s = d set exactly), at rest there (a grazing
  // touch, v_s = 0 too), or released there (f''(0) = F_s / m_s = 0 as well): those Taylor
  // terms at 0 are 0, not the rounding of the modal sums
  distance.startTerms = releaseJerk ? 3 : flight.onStop ? (flight.atRest ? 2 : 1) : 0;
  const FirstZero zero = firstZero(distance, dynamics.period, horizon, maxWindows, releaseJerk);
  switch (zero.kind) {
    case ZeroKind::Crossing: return {ChainContactKind::Impact, zero.t};
    case ZeroKind::Touch: return {ChainContactKind::Touch, zero.t};
    case ZeroKind::None: return {ChainContactKind::None, zero.t};
    case ZeroKind::Budget: break;
  }
  return {ChainContactKind::Budget, zero.t};
}

}  // namespace grazelab::core
