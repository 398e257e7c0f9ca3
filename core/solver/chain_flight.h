// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <Eigen/Core>

#include <cassert>
#include <optional>
#include <stop_token>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/model/mass_chain.h"
#include "core/model/state.h"
#include "core/solver/sinusoid_zero.h"

namespace grazelab::core {

/// The N-mass solver works in double, long double or binary128 (Quad): every type below is
/// Basic...<S>, with the double one under the plain name.
template <typename S>
using ChainVector = Eigen::Matrix<S, Eigen::Dynamic, 1>;

/// The state of a chain of N masses: displacements and velocities.
template <typename S>
struct BasicChainState {
  ChainVector<S> u;
  ChainVector<S> v;
};
using ChainState = BasicChainState<double>;

/// A two-mass state as the state of a chain of two (u = (u1, u2), v = (v1, v2)), and back: one
/// type where both stacks meet (a start chosen with the mouse, a session's start).
template <typename S>
BasicChainState<S> chainStateOf(const BasicState<S>& state) {
  BasicChainState<S> chain{ChainVector<S>(2), ChainVector<S>(2)};
  chain.u << state.u1, state.u2;
  chain.v << state.v1, state.v2;
  return chain;
}
/// `state` of a chain of two masses (asserted).
template <typename S>
BasicState<S> twoMassStateOf(const BasicChainState<S>& state) {
  assert(state.u.size() == 2 && state.v.size() == 2);
  return {state.u[0], state.u[1], state.v[0], state.v[1]};
}

/// What a chain's free flights are computed from: its modes, with the frequencies of a
/// commensurate chain taken as exact multiples n_j w0 (so that every flight repeats after
/// T = 2 pi / w0 to the last bit, as the two-mass solver does for the 1:2 design), and the stop.
template <typename S>
struct BasicChainDynamics {
  Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> P;  ///< M-orthonormal mode shapes, fastest first
  ChainVector<S> omega;  ///< w_j, fastest first (n_j w0 when commensurate)
  std::vector<bool> nodeAtStop;  ///< mode j+1 does not move the stopped mass (BasicChainModes)
  ChainVector<S> mass;   ///< m_i
  int stop = 0;          ///< the stopped mass, 0-based
  S gap = 1;
  /// the common period 2 pi / w0 of a commensurate chain, 0 otherwise
  S period = 0;
  /// a commensurate chain's harmonic numbers n_j (w_j = n_j w0), fastest first; empty otherwise
  std::vector<int> harmonics;
  S omega0 = 0;
};
using ChainDynamics = BasicChainDynamics<double>;

/// The dynamics of a usable chain (validate(chain) empty): its modes (chainModesIn) and whether
/// its frequencies are commensurate (detectRatios, to 1e-9), in S, from the chain's numbers in S.
template <typename S>
BasicChainDynamics<S> chainDynamicsIn(const BasicMassChain<S>& chain);
inline ChainDynamics chainDynamics(const MassChain& chain) { return chainDynamicsIn<double>(chain); }

/// One free flight, in modal coordinates at its start: u(t) = P (q cos wt + qdot / w sin wt)
/// for t measured from the flight's start.
template <typename S>
struct BasicChainFlight {
  ChainVector<S> q;
  ChainVector<S> qdot;
  bool onStop = false;  ///< it starts with u_s = d exactly
  bool atRest = false;  ///< and v_s = 0 exactly
};
using ChainFlight = BasicChainFlight<double>;

/// A run's start: its state, and the modes known to be exactly still in it. A GLO start with
/// weights 0 on some modes (GLOM_1 alone, say) is such a start: its state, rounded, holds about
/// 1e-17 of those modes again, which its numbers alone cannot tell from a real motion (nor, then,
/// a touch of the stop from a near miss); a start given by its numbers alone has none.
template <typename S>
struct BasicChainStart {
  BasicChainState<S> state;
  std::vector<bool> stillModes;  ///< mode j+1 (fastest first) does not move; empty: none known
  BasicChainStart() = default;
  BasicChainStart(const BasicChainState<S>& at, std::vector<bool> still = {})  // NOLINT: a state is a start
      : state(at), stillModes(std::move(still)) {}
};
using ChainStart = BasicChainStart<double>;

template <typename S>
BasicChainFlight<S> flightFrom(const BasicChainDynamics<S>& dynamics, const BasicChainState<S>& start);
template <typename S>
BasicChainState<S> stateAt(const BasicChainDynamics<S>& dynamics, const BasicChainFlight<S>& flight,
                           std::type_identity_t<S> t);
/// The same into `out`, whose vectors are reused (a run allocates nothing per flight for them).
template <typename S>
void flightInto(const BasicChainDynamics<S>& dynamics, const BasicChainState<S>& start, BasicChainFlight<S>& out);
template <typename S>
void stateInto(const BasicChainDynamics<S>& dynamics, const BasicChainFlight<S>& flight, std::type_identity_t<S> t,
               BasicChainState<S>& out);

/// How many times u_s's motion in a flight repeats within the common period T of a commensurate
/// chain: the gcd g of the harmonics of the modes that move the stopped mass in it (GLOM_1 of a
/// 3:2:1 chain alone returns to the stop after T/3), so u_s - d has period T/g. 1 on a chain that
/// is not commensurate, or when no mode moves the stopped mass.
template <typename S>
int stopRepeats(const BasicChainDynamics<S>& dynamics, const BasicChainFlight<S>& flight);

/// The flight after u_s's own period T/g (stopRepeats): the modes that move the stopped mass
/// exactly as they were (each a whole number of its periods on), the others (those with a node
/// there) turned by 2 pi n_j / g. u_s's flight goes on unchanged through a grazing touch at T/g.
/// True when a mode turned (the flight's start state is then no longer the old one's).
template <typename S>
bool afterStopPeriod(const BasicChainDynamics<S>& dynamics, int repeats, BasicChainFlight<S>& flight);

/// How a flight first meets the stop.
enum class ChainContactKind {
  Impact,     ///< mass s crosses u_s = d moving into the stop
  Touch,      ///< u_s returns to d with v_s = 0 exactly: a start at rest on the stop (or released
              ///< there) coming back after u_s's own period T/g (stopRepeats), T the period of a
              ///< commensurate chain's every free motion
  Unresolved,  ///< u_s comes within rounding of d while v_s is within rounding of 0: a grazing, a
               ///< slow impact and a near miss all fit the computed flight (or, at t = 0, a start on
               ///< the stop not seen to leave it); decided one precision up
  None,       ///< never: a commensurate chain's flight below the stop for a whole period, or any
              ///< flight whose modes' amplitudes together fall short of the stop
  Budget,     ///< not within the search's horizon or window budget (a non-commensurate chain)
};

template <typename S>
struct BasicChainContact {
  ChainContactKind kind = ChainContactKind::None;
  S t = 0;  ///< from the flight's start [time]
};
using ChainContact = BasicChainContact<double>;

/// The first contact of mass s with the stop after the flight's start: the first zero of
/// f(t) = u_s(t) - d by firstZero's certified search (core/solver/sinusoid_zero.h), so that a
/// touch (an even-multiplicity zero no sign-change method sees) is never missed. A touch is only
/// called one where it is exact (the periodic return of a start at rest on the stop, after T/g);
/// any other
/// top within rounding of the stop is Unresolved, never taken for a grazing: the precision cannot
/// tell it from two crossings closer than it resolves (an impact) or a miss. A flight starting on the
/// stop leaves it by its velocity (or, at v_s = 0, its acceleration; after a release, given as
/// `leaving`, its third derivative, or its fourth when the third is 0 too). Commensurate chains are
/// searched over u_s's period T/g (a contact comes by then); others up to `horizon` or
/// `maxWindows` windows.
template <typename S>
BasicChainContact<S> firstContact(const BasicChainDynamics<S>& dynamics, const BasicChainFlight<S>& flight,
                                  std::type_identity_t<S> horizon = 0, long maxWindows = 1'000'000,
                                  std::optional<BasicLeaving<std::type_identity_t<S>>> leaving = std::nullopt);

}  // namespace grazelab::core
