// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/chain_run.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "core/solver/chain_stick.h"

namespace grazelab::core {

double chainEnergy(const MassChain& chain, const ChainState& state) {
  const Eigen::MatrixXd M = massMatrix(chain);
  const Eigen::MatrixXd K = stiffnessMatrix(chain);
  return 0.5 * state.v.dot(M * state.v) + 0.5 * state.u.dot(K * state.u);
}

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// the slowest period of a stuck phase's sides (0 when no mass moves)
double slowestPeriod(const ChainStuckPhase& phase) {
  double slowest = 0;
  for (const ChainStuckPhase::Side* side : {&phase.left, &phase.right}) {
    if (side->count > 0) slowest = std::max(slowest, 2 * std::numbers::pi / side->dynamics.omega.minCoeff());
  }
  return slowest;
}

// u_s''' at a release (v_s = 0, F_s = 0): dF_s/dt / m_s = (k_s v_(s-1) + k_(s+1) v_(s+1)) / m_s,
// when its sign is resolved; nothing otherwise
std::optional<double> releaseJerk(const MassChain& chain, const ChainState& at) {
  const Eigen::Index n = chain.size();
  const Eigen::Index s = chain.stopped() - 1;
  const double left = s > 0 ? chain.springs[std::size_t(s)] * at.v[s - 1] : 0.0;
  const double right = s + 1 < n ? chain.springs[std::size_t(s + 1)] * at.v[s + 1] : 0.0;
  const double jerk = (left + right) / chain.masses[std::size_t(s)];
  const double error = 4 * kEps * (std::abs(left) + std::abs(right)) / chain.masses[std::size_t(s)];
  if (!(jerk < -error)) return std::nullopt;
  return jerk;
}

}  // namespace

ChainRun runChain(const MassChain& chain, const ChainState& start, long maxContacts, double tEnd,
                  std::stop_token stop) {
  const ChainDynamics dynamics = chainDynamics(chain);
  const int s = dynamics.stop;
  ChainRun run;
  run.energyInitial = chainEnergy(chain, start);
  ChainState state = start;
  double t = 0;
  const double slowest = 2 * std::numbers::pi / dynamics.omega.minCoeff();
  const auto finish = [&](ChainStop reason, const ChainState& at, double when) {
    run.stop = reason;
    run.final = at;
    run.tFinal = when;
    run.energyFinal = chainEnergy(chain, at);
    return run;
  };
  const auto record = [&](EventType type, const ChainState& at, const Eigen::VectorXd& vBefore, double when) {
    run.events.push_back({when, type, at.u, vBefore, at.v[s]});
    if (isContact(type)) ++run.contacts;
  };
  std::optional<double> jerk;  // set when the flight starts at a release
  // reused from flight to flight: no allocation for them once sized
  ChainFlight flight;
  ChainState at;
  Eigen::VectorXd vBefore;
  while (run.contacts < maxContacts) {
    if (stop.stop_requested()) return finish(ChainStop::Cancelled, state, t);
    // at rest on the stop, pressed into it (a touch, or the start): held until released
    const StopForce force = stopForce(chain, state);
    const bool onStop = state.u[s] == dynamics.gap && state.v[s] == 0;
    if (onStop && !jerk && force.value > force.error) {
      if (run.events.empty() || run.events.back().type != EventType::Stick || run.events.back().t != t) {
        record(EventType::Stick, state, state.v, t);
      }
      const ChainStuckPhase phase = stuckPhase(chain, state);
      const double horizon = tEnd > 0 ? tEnd - t : 1000 * slowestPeriod(phase);
      const FirstZero release = releaseOf(phase, horizon);
      if (stop.stop_requested()) return finish(ChainStop::Cancelled, state, t);
      const bool past = tEnd > 0 && (release.kind == ZeroKind::Budget || t + release.t > tEnd);
      if (past) return finish(ChainStop::TimeLimit, stuckStateAt(phase, tEnd - t), tEnd);
      if (release.kind == ZeroKind::Budget) return finish(ChainStop::SearchBudget, state, t);
      if (release.kind != ZeroKind::Crossing) {
        return finish(ChainStop::Undecided, stuckStateAt(phase, release.t), t + release.t);
      }
      ChainState released = stuckStateAt(phase, release.t);
      t += release.t;
      jerk = releaseJerk(chain, released);
      if (!jerk) return finish(ChainStop::Undecided, released, t);
      record(EventType::Release, released, released.v, t);
      state = released;
      continue;
    }
    if (state.u[s] == dynamics.gap && state.v[s] > 0) {
      // a start on the stop moving into it: the impact at once (as for two masses)
      ChainState reflected = state;
      reflected.v[s] = -reflected.v[s];
      record(EventType::Impact, reflected, state.v, t);
      state = reflected;
      continue;
    }
    flightInto(dynamics, state, flight);
    const double horizon = tEnd > 0 ? tEnd - t : 1000 * slowest;
    const ChainContact contact = firstContact(dynamics, flight, horizon, 1'000'000, jerk);
    jerk.reset();
    const bool past = tEnd > 0 && (contact.kind == ChainContactKind::None || contact.kind == ChainContactKind::Budget ||
                                   t + contact.t > tEnd);
    if (past) return finish(ChainStop::TimeLimit, stateAt(dynamics, flight, tEnd - t), tEnd);
    if (contact.kind == ChainContactKind::None) return finish(ChainStop::NoFurtherContact, state, t);
    if (contact.kind == ChainContactKind::Budget) return finish(ChainStop::SearchBudget, state, t);
    if (contact.kind == ChainContactKind::Touch && contact.t == 0) {
      // a flight that cannot be seen to leave the stop it starts on (neither its velocity nor
      // its acceleration takes it away, within rounding, and no force presses it on)
      return finish(ChainStop::Undecided, state, t);
    }
    stateInto(dynamics, flight, contact.t, at);
    vBefore = at.v;
    const double when = t + contact.t;
    at.u[s] = dynamics.gap;  // on the stop exactly: the next flight starts on it
    if (contact.kind == ChainContactKind::Impact) {
      at.v[s] = -at.v[s];
      record(EventType::Impact, at, vBefore, when);
    } else {
      // at rest on the stop: pulled away (grazing) or pressed into it (a stick)
      at.v[s] = 0;
      const StopForce pressed = stopForce(chain, at);
      if (pressed.value > pressed.error) {
        record(EventType::Stick, at, vBefore, when);
      } else if (pressed.value < -pressed.error) {
        record(EventType::Grazing, at, vBefore, when);
      } else {
        return finish(ChainStop::Undecided, at, when);
      }
    }
    state = at;
    t = when;
  }
  return finish(ChainStop::ContactLimit, state, t);
}

}  // namespace grazelab::core
