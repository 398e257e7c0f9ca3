// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/chain_stick.h"

#include <cmath>
#include <limits>

namespace grazelab::core {
namespace {

// the masses first .. first+count-1 with their springs as a chain of their own; `wallSpring` on
// the left (k of the spring from the left wall or clamp), `rightSpring` on the right (0: free)
template <typename S>
typename BasicChainStuckPhase<S>::Side makeSide(const BasicMassChain<S>& chain, Eigen::Index first, Eigen::Index count,
                                                const S& rightSpring) {
  typename BasicChainStuckPhase<S>::Side side;
  side.first = first;
  side.count = count;
  if (count == 0) return side;
  BasicMassChain<S> part;
  part.masses.assign(chain.masses.begin() + first, chain.masses.begin() + first + count);
  part.springs.assign(chain.springs.begin() + first, chain.springs.begin() + first + count);
  part.rightSpring = rightSpring;
  part.gap = chain.gap;
  side.dynamics = chainDynamicsIn<S>(part);
  return side;
}

}  // namespace

template <typename S>
BasicChainStuckPhase<S> stuckPhase(const BasicMassChain<S>& chain, const BasicChainState<S>& start) {
  BasicChainStuckPhase<S> phase;
  const Eigen::Index n = chain.size();
  const Eigen::Index s = chain.stopped() - 1;
  const S d = S(chain.gap);
  // a spring's compliance, in S
  const auto compliance = [](const S& k) { return S(1) / k; };
  phase.stop = int(s);
  phase.gap = d;
  // left: masses 0 .. s-1 between the wall and the clamp (springs k_0 .. k_s); right: masses
  // s+1 .. n-1 between the clamp (spring k_(s+1)) and the right wall or a free end
  phase.left = makeSide<S>(chain, 0, s, chain.springs[std::size_t(s)]);
  phase.left.clampSpring = s > 0 ? S(chain.springs[std::size_t(s)]) : S(0);
  phase.left.clampMass = s - 1;
  phase.right = makeSide<S>(chain, s + 1, n - 1 - s, chain.rightSpring);
  phase.right.clampSpring = s + 1 < n ? S(chain.springs[std::size_t(s + 1)]) : S(0);
  phase.right.clampMass = 0;
  // at rest the springs of each side share the clamp's displacement d in proportion to their
  // compliances (springs in series): u_i = d (compliance from the wall to i) / (the side's)
  phase.left.rest.resize(s);
  phase.restForce = 0;
  if (chain.springs[0] > 0) {
    S leftCompliance = 0;
    for (Eigen::Index j = 0; j <= s; ++j) leftCompliance += compliance(chain.springs[std::size_t(j)]);
    S below = 0;
    for (Eigen::Index i = 0; i < s; ++i) {
      below += compliance(chain.springs[std::size_t(i)]);
      phase.left.rest[i] = d * (below / leftCompliance);
    }
    phase.restForce = -d / leftCompliance;
  } else {
    phase.left.rest.setConstant(d);  // a free left end follows the clamp, as a free right end does
  }
  phase.right.rest.resize(n - 1 - s);
  if (chain.rightSpring > 0) {
    S rightCompliance = compliance(chain.rightSpring);
    for (Eigen::Index j = s + 1; j < n; ++j) rightCompliance += compliance(chain.springs[std::size_t(j)]);
    S beyond = compliance(chain.rightSpring);
    for (Eigen::Index i = n - 1; i > s; --i) {
      phase.right.rest[i - s - 1] = d * (beyond / rightCompliance);
      beyond += compliance(chain.springs[std::size_t(i)]);
    }
    phase.restForce -= d / rightCompliance;
  } else {
    phase.right.rest.setConstant(d);  // a free end follows the clamp
  }
  for (typename BasicChainStuckPhase<S>::Side* side : {&phase.left, &phase.right}) {
    if (side->count == 0) continue;
    const BasicChainState<S> local{start.u.segment(side->first, side->count) - side->rest,
                                   start.v.segment(side->first, side->count)};
    side->flight = flightFrom(side->dynamics, local);
  }
  return phase;
}

template <typename S>
BasicChainState<S> stuckStateAt(const BasicChainStuckPhase<S>& phase, std::type_identity_t<S> t) {
  const Eigen::Index n = phase.left.count + 1 + phase.right.count;
  BasicChainState<S> state{ChainVector<S>(n), ChainVector<S>(n)};
  state.u[phase.stop] = phase.gap;
  state.v[phase.stop] = S(0);
  for (const typename BasicChainStuckPhase<S>::Side* side : {&phase.left, &phase.right}) {
    if (side->count == 0) continue;
    const BasicChainState<S> local = stateAt<S>(side->dynamics, side->flight, t);
    state.u.segment(side->first, side->count) = side->rest + local.u;
    state.v.segment(side->first, side->count) = local.v;
  }
  return state;
}

template <typename S>
BasicStopForce<S> stopForce(const BasicMassChain<S>& chain, const BasicChainState<S>& state) {
  using std::abs;
  // -(K u)_s term by term: k_s (u_(s-1) - u_s) + k_(s+1) (u_(s+1) - u_s), walls at 0
  const Eigen::Index n = chain.size();
  const Eigen::Index s = chain.stopped() - 1;
  const S us = state.u[s];
  const S leftK = S(chain.springs[std::size_t(s)]);
  const S leftU = s > 0 ? S(state.u[s - 1]) : S(0);
  const S rightK = S(s + 1 < n ? chain.springs[std::size_t(s + 1)] : chain.rightSpring);
  const S rightU = s + 1 < n ? S(state.u[s + 1]) : S(0);
  const S left = leftK * (leftU - us), right = rightK * (rightU - us);
  constexpr S eps = std::numeric_limits<S>::epsilon();
  // a few roundings in the sum, and the displacements' own: a state at a touch comes from the
  // flight's closed form, its u within some tens of roundings of the motion's
  const S size = leftK * (abs(leftU) + abs(us)) + rightK * (abs(rightU) + abs(us));
  return {left + right, 64 * eps * size};
}

template <typename S>
BasicFirstZero<S> releaseOf(const BasicChainStuckPhase<S>& phase, std::type_identity_t<S> horizon, long maxWindows) {
  // -F_s(t) = -restForce - sum over the sides of k_clamp (u_clampMass(t) - rest), which starts
  // below 0 (pressed) and must rise through it
  BasicSinusoidSum<S> pull;
  const Eigen::Index modes = phase.left.count + phase.right.count;
  pull.a.resize(modes);
  pull.b.resize(modes);
  pull.w.resize(modes);
  pull.offset = -phase.restForce;
  Eigen::Index j = 0;
  for (const typename BasicChainStuckPhase<S>::Side* side : {&phase.left, &phase.right}) {
    for (Eigen::Index mode = 0; mode < side->count; ++mode, ++j) {
      const S w = side->dynamics.omega[mode];
      const S p = side->clampSpring * side->dynamics.P(side->clampMass, mode);
      pull.w[j] = w;
      pull.a[j] = -p * side->flight.q[mode];
      pull.b[j] = -p * side->flight.qdot[mode] / w;
    }
  }
  return firstZero<S>(pull, S(0), horizon, maxWindows);
}

#define GRAZELAB_INSTANTIATE(S)                                                                                  \
  template BasicChainStuckPhase<S> stuckPhase<S>(const BasicMassChain<S>&, const BasicChainState<S>&);                    \
  template BasicChainState<S> stuckStateAt<S>(const BasicChainStuckPhase<S>&, std::type_identity_t<S>);           \
  template BasicStopForce<S> stopForce<S>(const BasicMassChain<S>&, const BasicChainState<S>&);                           \
  template BasicFirstZero<S> releaseOf<S>(const BasicChainStuckPhase<S>&, std::type_identity_t<S>, long);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
