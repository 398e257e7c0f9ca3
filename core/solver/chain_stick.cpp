// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/chain_stick.h"

#include <cmath>
#include <limits>

namespace grazelab::core {
namespace {

// the masses first .. first+count-1 with their springs as a chain of their own; `wallSpring` on
// the left (k of the spring from the left wall or clamp), `rightSpring` on the right (0: free)
ChainStuckPhase::Side makeSide(const MassChain& chain, Eigen::Index first, Eigen::Index count,
                               double rightSpring) {
  ChainStuckPhase::Side side;
  side.first = first;
  side.count = count;
  if (count == 0) return side;
  MassChain part;
  part.masses.assign(chain.masses.begin() + first, chain.masses.begin() + first + count);
  part.springs.assign(chain.springs.begin() + first, chain.springs.begin() + first + count);
  part.rightSpring = rightSpring;
  part.gap = chain.gap;
  side.dynamics = chainDynamics(part);
  return side;
}

}  // namespace

ChainStuckPhase stuckPhase(const MassChain& chain, const ChainState& start) {
  ChainStuckPhase phase;
  const Eigen::Index n = chain.size();
  const Eigen::Index s = chain.stopped() - 1;
  const double d = chain.gap;
  phase.stop = int(s);
  phase.gap = d;
  // left: masses 0 .. s-1 between the wall and the clamp (springs k_0 .. k_s); right: masses
  // s+1 .. n-1 between the clamp (spring k_(s+1)) and the right wall or a free end
  phase.left = makeSide(chain, 0, s, chain.springs[std::size_t(s)]);
  phase.left.clampSpring = s > 0 ? chain.springs[std::size_t(s)] : 0;
  phase.left.clampMass = s - 1;
  phase.right = makeSide(chain, s + 1, n - 1 - s, chain.rightSpring);
  phase.right.clampSpring = s + 1 < n ? chain.springs[std::size_t(s + 1)] : 0;
  phase.right.clampMass = 0;
  // at rest the springs of each side share the clamp's displacement d in proportion to their
  // compliances (springs in series): u_i = d (compliance from the wall to i) / (the side's)
  double leftCompliance = 0;
  for (Eigen::Index j = 0; j <= s; ++j) leftCompliance += 1 / chain.springs[std::size_t(j)];
  phase.left.rest.resize(s);
  double below = 0;
  for (Eigen::Index i = 0; i < s; ++i) {
    below += 1 / chain.springs[std::size_t(i)];
    phase.left.rest[i] = d * (below / leftCompliance);
  }
  phase.restForce = -d / leftCompliance;
  phase.right.rest.resize(n - 1 - s);
  if (chain.rightSpring > 0) {
    double rightCompliance = 1 / chain.rightSpring;
    for (Eigen::Index j = s + 1; j < n; ++j) rightCompliance += 1 / chain.springs[std::size_t(j)];
    double beyond = 1 / chain.rightSpring;
    for (Eigen::Index i = n - 1; i > s; --i) {
      phase.right.rest[i - s - 1] = d * (beyond / rightCompliance);
      beyond += 1 / chain.springs[std::size_t(i)];
    }
    phase.restForce -= d / rightCompliance;
  } else {
    phase.right.rest.setConstant(d);  // a free end follows the clamp
  }
  for (ChainStuckPhase::Side* side : {&phase.left, &phase.right}) {
    if (side->count == 0) continue;
    const ChainState local{start.u.segment(side->first, side->count) - side->rest,
                           start.v.segment(side->first, side->count)};
    side->flight = flightFrom(side->dynamics, local);
  }
  return phase;
}

ChainState stuckStateAt(const ChainStuckPhase& phase, double t) {
  const Eigen::Index n = phase.left.count + 1 + phase.right.count;
  ChainState state{Eigen::VectorXd(n), Eigen::VectorXd(n)};
  state.u[phase.stop] = phase.gap;
  state.v[phase.stop] = 0;
  for (const ChainStuckPhase::Side* side : {&phase.left, &phase.right}) {
    if (side->count == 0) continue;
    const ChainState local = stateAt(side->dynamics, side->flight, t);
    state.u.segment(side->first, side->count) = side->rest + local.u;
    state.v.segment(side->first, side->count) = local.v;
  }
  return state;
}

StopForce stopForce(const MassChain& chain, const ChainState& state) {
  // -(K u)_s term by term: k_s (u_(s-1) - u_s) + k_(s+1) (u_(s+1) - u_s), walls at 0
  const Eigen::Index n = chain.size();
  const Eigen::Index s = chain.stopped() - 1;
  const double us = state.u[s];
  const double leftK = chain.springs[std::size_t(s)];
  const double leftU = s > 0 ? state.u[s - 1] : 0.0;
  const double rightK = s + 1 < n ? chain.springs[std::size_t(s + 1)] : chain.rightSpring;
  const double rightU = s + 1 < n ? state.u[s + 1] : 0.0;
  const double left = leftK * (leftU - us), right = rightK * (rightU - us);
  constexpr double eps = std::numeric_limits<double>::epsilon();
  // a few roundings in the sum, and the displacements' own: a state at a touch comes from the
  // flight's closed form, its u within some tens of roundings of the motion's
  const double size = leftK * (std::abs(leftU) + std::abs(us)) + rightK * (std::abs(rightU) + std::abs(us));
  return {left + right, 64 * eps * size};
}

FirstZero releaseOf(const ChainStuckPhase& phase, double horizon, long maxWindows) {
  // -F_s(t) = -restForce - sum over the sides of k_clamp (u_clampMass(t) - rest), which starts
  // below 0 (pressed) and must rise through it
  SinusoidSum pull;
  const Eigen::Index modes = phase.left.count + phase.right.count;
  pull.a.resize(modes);
  pull.b.resize(modes);
  pull.w.resize(modes);
  pull.offset = -phase.restForce;
  Eigen::Index j = 0;
  for (const ChainStuckPhase::Side* side : {&phase.left, &phase.right}) {
    for (Eigen::Index mode = 0; mode < side->count; ++mode, ++j) {
      const double w = side->dynamics.omega[mode];
      const double p = side->clampSpring * side->dynamics.P(side->clampMass, mode);
      pull.w[j] = w;
      pull.a[j] = -p * side->flight.q[mode];
      pull.b[j] = -p * side->flight.qdot[mode] / w;
    }
  }
  return firstZero(pull, 0, horizon, maxWindows);
}

}  // namespace grazelab::core
