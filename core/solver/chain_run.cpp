// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/chain_run.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace grazelab::core {

double chainEnergy(const MassChain& chain, const ChainState& state) {
  const Eigen::MatrixXd M = massMatrix(chain);
  const Eigen::MatrixXd K = stiffnessMatrix(chain);
  return 0.5 * state.v.dot(M * state.v) + 0.5 * state.u.dot(K * state.u);
}

ChainRun runChain(const MassChain& chain, const ChainState& start, long maxContacts, double tEnd,
                  std::stop_token stop) {
  const ChainDynamics dynamics = chainDynamics(chain);
  const Eigen::MatrixXd K = stiffnessMatrix(chain);
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
  while (long(run.events.size()) < maxContacts) {
    if (stop.stop_requested()) return finish(ChainStop::Cancelled, state, t);
    const ChainFlight flight = flightFrom(dynamics, state);
    const double horizon = tEnd > 0 ? tEnd - t : 1000 * slowest;
    const ChainContact contact = firstContact(dynamics, flight, horizon);
    const bool past = tEnd > 0 && (contact.kind == ChainContactKind::None || contact.kind == ChainContactKind::Budget ||
                                   t + contact.t > tEnd);
    if (past) return finish(ChainStop::TimeLimit, stateAt(dynamics, flight, tEnd - t), tEnd);
    if (contact.kind == ChainContactKind::None) return finish(ChainStop::NoFurtherContact, state, t);
    if (contact.kind == ChainContactKind::Budget) return finish(ChainStop::SearchBudget, state, t);
    if (contact.kind == ChainContactKind::Touch && contact.t == 0) {
      // a flight that cannot leave the stop it starts on (neither its velocity nor its
      // acceleration takes it away, within rounding): pressed into it, or undecided
      const double force = -(K.row(s) * state.u)(0);
      return finish(force > 0 ? ChainStop::Sticking : ChainStop::Undecided, state, t);
    }
    ChainState at = stateAt(dynamics, flight, contact.t);
    ChainEvent event;
    event.t = t + contact.t;
    event.vBefore = at.v;
    at.u[s] = dynamics.gap;  // on the stop exactly: the next flight starts on it
    if (contact.kind == ChainContactKind::Impact) {
      event.type = EventType::Impact;
      at.v[s] = -at.v[s];
    } else {
      // at rest on the stop: pulled away (grazing) or pressed into it (a stick)
      at.v[s] = 0;
      const double force = -(K.row(s) * at.u)(0);
      const double scale = (K.row(s).cwiseAbs() * at.u.cwiseAbs())(0);
      if (force > 64 * std::numeric_limits<double>::epsilon() * scale) {
        return finish(ChainStop::Sticking, at, event.t);
      }
      if (!(force < -64 * std::numeric_limits<double>::epsilon() * scale)) {
        return finish(ChainStop::Undecided, at, event.t);
      }
      event.type = EventType::Grazing;
    }
    event.u = at.u;
    event.vAfter = at.v[s];
    run.events.push_back(event);
    state = at;
    t = event.t;
  }
  return finish(ChainStop::ContactLimit, state, t);
}

}  // namespace grazelab::core
