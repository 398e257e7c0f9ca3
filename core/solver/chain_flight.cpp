// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/chain_flight.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <type_traits>

#include "core/solver/sinusoid_zero.h"

namespace grazelab::core {

template <typename S>
BasicChainDynamics<S> chainDynamicsIn(const BasicMassChain<S>& chain) {
  const BasicChainModes<S> modes = chainModesIn<S>(chain);
  BasicChainDynamics<S> dynamics;
  dynamics.P = modes.P;
  dynamics.nodeAtStop = modes.nodeAtStop;
  dynamics.omega = modes.omega;
  const Eigen::Index n = Eigen::Index(chain.masses.size());
  dynamics.mass.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) dynamics.mass[i] = S(chain.masses[std::size_t(i)]);
  dynamics.stop = chain.stopped() - 1;
  dynamics.gap = S(chain.gap);
  Eigen::VectorXd omega(n);
  for (Eigen::Index j = 0; j < n; ++j) omega[j] = static_cast<double>(modes.omega[j]);
  const SpectrumRatios ratios = detectRatios(omega);
  if (ratios.commensurate) {
    // w0 fitted in S to every mode (least squares of w_j = n_j w0); in double, detectRatios' own
    S omega0 = S(ratios.omega0);
    if constexpr (!std::is_same_v<S, double>) {
      S dot = 0, norm = 0;
      for (Eigen::Index j = 0; j < n; ++j) {
        dot += S(ratios.harmonics[std::size_t(j)]) * modes.omega[j];
        norm += S(ratios.harmonics[std::size_t(j)]) * S(ratios.harmonics[std::size_t(j)]);
      }
      omega0 = dot / norm;
    }
    for (Eigen::Index j = 0; j < n; ++j) dynamics.omega[j] = S(ratios.harmonics[std::size_t(j)]) * omega0;
    dynamics.period = twoPi<S>() / omega0;
    dynamics.harmonics = ratios.harmonics;
    dynamics.omega0 = omega0;
  }
  return dynamics;
}

template <typename S>
void flightInto(const BasicChainDynamics<S>& dynamics, const BasicChainState<S>& start, BasicChainFlight<S>& flight) {
  // P^T M P = I: the modal coordinates are P^T M u
  thread_local ChainVector<S> weighted;
  weighted = dynamics.mass.cwiseProduct(start.u);
  flight.q.noalias() = dynamics.P.transpose() * weighted;
  weighted = dynamics.mass.cwiseProduct(start.v);
  flight.qdot.noalias() = dynamics.P.transpose() * weighted;
  flight.onStop = dynamics.stop < start.u.size() && start.u[dynamics.stop] == dynamics.gap;
  flight.atRest = flight.onStop && start.v[dynamics.stop] == 0;
}

template <typename S>
BasicChainFlight<S> flightFrom(const BasicChainDynamics<S>& dynamics, const BasicChainState<S>& start) {
  BasicChainFlight<S> flight;
  flightInto(dynamics, start, flight);
  return flight;
}

template <typename S>
void stateInto(const BasicChainDynamics<S>& dynamics, const BasicChainFlight<S>& flight, std::type_identity_t<S> t,
               BasicChainState<S>& state) {
  using std::cos;
  using std::sin;
  const Eigen::Index n = flight.q.size();
  thread_local ChainVector<S> q, qdot;
  q.resize(n);
  qdot.resize(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const S w = dynamics.omega[j];
    if (w == 0) {  // a floating chain's rigid mode: uniform motion
      q[j] = flight.q[j] + flight.qdot[j] * t;
      qdot[j] = flight.qdot[j];
      continue;
    }
    const S c = cos(w * t), s = sin(w * t);
    q[j] = flight.q[j] * c + flight.qdot[j] / w * s;
    qdot[j] = -flight.q[j] * w * s + flight.qdot[j] * c;
  }
  state.u.noalias() = dynamics.P * q;
  state.v.noalias() = dynamics.P * qdot;
}

template <typename S>
BasicChainState<S> stateAt(const BasicChainDynamics<S>& dynamics, const BasicChainFlight<S>& flight,
                           std::type_identity_t<S> t) {
  BasicChainState<S> state;
  stateInto(dynamics, flight, t, state);
  return state;
}

template <typename S>
int stopRepeats(const BasicChainDynamics<S>& dynamics, const BasicChainFlight<S>& flight) {
  if (!(dynamics.period > 0)) return 1;
  int repeats = 0;
  for (Eigen::Index j = 0; j < flight.q.size(); ++j) {
    const S p = dynamics.P(dynamics.stop, j);
    if (p * flight.q[j] != 0 || p * flight.qdot[j] != 0) {
      repeats = std::gcd(repeats, dynamics.harmonics[std::size_t(j)]);
    }
  }
  return std::max(repeats, 1);
}

template <typename S>
bool afterStopPeriod(const BasicChainDynamics<S>& dynamics, int repeats, BasicChainFlight<S>& flight) {
  using std::cos;
  using std::sin;
  bool turned = false;
  for (Eigen::Index j = 0; j < flight.q.size(); ++j) {
    const int turns = dynamics.harmonics.empty() ? 0 : dynamics.harmonics[std::size_t(j)] % repeats;
    // a whole number of its periods, or still: as it was, exactly
    if (turns == 0 || (flight.q[j] == 0 && flight.qdot[j] == 0)) continue;
    const S w = dynamics.omega[j], angle = twoPi<S>() * S(turns) / S(repeats);
    const S c = cos(angle), s = sin(angle), q = flight.q[j], qdot = flight.qdot[j];
    flight.q[j] = q * c + qdot / w * s;
    flight.qdot[j] = -q * w * s + qdot * c;
    turned = true;
  }
  return turned;
}

template <typename S>
BasicChainContact<S> firstContact(const BasicChainDynamics<S>& dynamics, const BasicChainFlight<S>& flight,
                                  std::type_identity_t<S> horizon, long maxWindows,
                                  std::optional<BasicLeaving<std::type_identity_t<S>>> leaving) {
  // u_s(t) - d = sum_j P[s][j] (q_j cos w_j t + qdot_j / w_j sin w_j t) - d
  // one per thread, reused: a run's flights then allocate nothing here (a quarter of the time of
  // a small chain's contact went to malloc and free)
  thread_local BasicSinusoidSum<S> distance;
  const Eigen::Index n = flight.q.size();
  distance.w = dynamics.omega;
  distance.a.resize(n);
  distance.b.resize(n);
  distance.slope = 0;
  // a floating chain's rigid mode (w = 0) moves u_s by p (q + qdot t): a constant and a slope
  S rigid = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    const S p = dynamics.P(dynamics.stop, j);
    distance.a[j] = p * flight.q[j];
    if (dynamics.omega[j] == 0) {
      distance.b[j] = 0;
      distance.slope += p * flight.qdot[j];
      rigid += distance.a[j];
    } else {
      distance.b[j] = p * flight.qdot[j] / dynamics.omega[j];
    }
  }
  distance.offset = -dynamics.gap;
  // a flight whose modes together cannot reach the stop never meets it, commensurate or not:
  // u_s(t) <= rigid + slope t + sum_j R_j over the vibrating modes (R_j = hypot(a_j, b_j), the
  // sum's rounding within (n + 2) eps of it), so a chain that is not commensurate says so at
  // once, where its search ran out of its budget; a floating chain drifting away from the stop
  // (slope < 0) can reach it only before t = (rigid + sum R_j - d) / |slope|, its search's end.
  // (In units of the gap: a tiny gap's squares would underflow to a reach of 0, a huge one's
  // overflow to no decision.) A flight from the stop is on it: only the drift's end applies.
  using std::abs;
  using std::sqrt;
  const S offset = rigid / dynamics.gap;
  S vibration = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (dynamics.omega[j] == 0) continue;
    const S a = distance.a[j] / dynamics.gap, b = distance.b[j] / dynamics.gap;
    vibration += sqrt(a * a + b * b);
  }
  const S reachError = (abs(offset) + vibration) * S(4 * (n + 2)) * epsilon<S>();
  const S reach = offset + vibration;
  const S slope = distance.slope / dynamics.gap;  // [1/time]
  if (!flight.onStop && reach + reachError < 1 && !(slope > 0)) return {ChainContactKind::None, horizon};
  // the drift's end: past it u_s stays below the stop, or (drifting onto it) has met it, as
  // u_s - d lies within offset - 1 + slope t -+ vibration (pushed out by a part in 1e6 against
  // the time's rounding)
  S driftEnd = 0;
  if (slope < 0) driftEnd = (reach + reachError - 1) / -slope * (1 + S(1e-6));
  if (slope > 0) driftEnd = (1 - offset + vibration + reachError) / slope * (1 + S(1e-6));
  if (!(dynamics.omega.maxCoeff() > 0)) {
    // one floating mass: u_s - d = (u_s(0) - d) + v_s t
    if (!(slope > 0) || flight.onStop) return {ChainContactKind::None, horizon};
    return {ChainContactKind::Impact, S((1 - rigid / dynamics.gap) / slope)};
  }
  const bool driftEnds = driftEnd > 0 && (!(horizon > 0) || driftEnd < horizon);
  if (driftEnds) horizon = driftEnd;
  distance.harmonics = dynamics.harmonics;
  distance.omega0 = dynamics.omega0;
  // a flight from the stop (after an impact, u_s = d set exactly), at rest there (a grazing
  // touch, v_s = 0 too), or released there (f''(0) = F_s / m_s = 0 as well, and f'''(0) when it
  // leaves by its fourth derivative): those Taylor terms at 0 are 0, not the rounding of the
  // modal sums
  distance.startTerms = leaving ? leaving->order : flight.onStop ? (flight.atRest ? 2 : 1) : 0;
  // u_s's own period: T/g when only harmonics that g divides move the stopped mass (T/1 is T)
  const S period = dynamics.period / S(stopRepeats(dynamics, flight));
  const BasicFirstZero<S> zero = firstZero<S>(distance, period, horizon, maxWindows, leaving);
  switch (zero.kind) {
    case ZeroKind::Crossing: return {ChainContactKind::Impact, zero.t};
    case ZeroKind::Touch: {
      // exact only as the periodic return of a start at rest on the stop (a release's too): u_s
      // after its period is its start again, in a chain whose frequencies are exact multiples of w0
      const bool periodicReturn = period > 0 && zero.t == period && flight.atRest;
      return {periodicReturn ? ChainContactKind::Touch : ChainContactKind::Unresolved, zero.t};
    }
    case ZeroKind::None: return {ChainContactKind::None, zero.t};
    case ZeroKind::Budget:
      // searched to the drift's end: a chain drifting away never comes back (one drifting onto
      // the stop must have met it: the search's bounds say otherwise, so no answer is given)
      if (driftEnds && slope < 0 && zero.t >= horizon) return {ChainContactKind::None, zero.t};
      break;
  }
  return {ChainContactKind::Budget, zero.t};
}

#define GRAZELAB_INSTANTIATE(S)                                                                                  \
  template BasicChainDynamics<S> chainDynamicsIn<S>(const BasicMassChain<S>&);                                            \
  template BasicChainFlight<S> flightFrom<S>(const BasicChainDynamics<S>&, const BasicChainState<S>&);             \
  template BasicChainState<S> stateAt<S>(const BasicChainDynamics<S>&, const BasicChainFlight<S>&,                 \
                                         std::type_identity_t<S>);                                                 \
  template void flightInto<S>(const BasicChainDynamics<S>&, const BasicChainState<S>&, BasicChainFlight<S>&);      \
  template void stateInto<S>(const BasicChainDynamics<S>&, const BasicChainFlight<S>&, std::type_identity_t<S>,    \
                             BasicChainState<S>&);                                                                 \
  template int stopRepeats<S>(const BasicChainDynamics<S>&, const BasicChainFlight<S>&);                           \
  template bool afterStopPeriod<S>(const BasicChainDynamics<S>&, int, BasicChainFlight<S>&);                       \
  template BasicChainContact<S> firstContact<S>(const BasicChainDynamics<S>&, const BasicChainFlight<S>&,          \
                                                std::type_identity_t<S>, long,                                     \
                                                std::optional<BasicLeaving<std::type_identity_t<S>>>);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
