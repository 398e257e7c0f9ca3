// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <Eigen/Core>

#include <optional>
#include <stop_token>
#include <vector>

#include "core/model/mass_chain.h"

namespace grazelab::core {

/// The state of a chain of N masses: displacements and velocities.
struct ChainState {
  Eigen::VectorXd u;
  Eigen::VectorXd v;
};

/// What a chain's free flights are computed from: its modes, with the frequencies of a
/// commensurate chain taken as exact multiples n_j w0 (so that every flight repeats after
/// T = 2 pi / w0 to the last bit, as the two-mass solver does for the 1:2 design), and the stop.
struct ChainDynamics {
  Eigen::MatrixXd P;      ///< M-orthonormal mode shapes, fastest first
  Eigen::VectorXd omega;  ///< w_j, fastest first (n_j w0 when commensurate)
  Eigen::VectorXd mass;   ///< m_i
  int stop = 0;           ///< the stopped mass, 0-based
  double gap = 1;
  /// the common period 2 pi / w0 of a commensurate chain, 0 otherwise
  double period = 0;
  /// a commensurate chain's harmonic numbers n_j (w_j = n_j w0), fastest first; empty otherwise
  std::vector<int> harmonics;
  double omega0 = 0;
};

/// The dynamics of a usable chain (validate(chain) empty): its modes (chainModes) and whether
/// its frequencies are commensurate (detectRatios, to 1e-9).
ChainDynamics chainDynamics(const MassChain& chain);

/// One free flight, in modal coordinates at its start: u(t) = P (q cos wt + qdot / w sin wt)
/// for t measured from the flight's start.
struct ChainFlight {
  Eigen::VectorXd q;
  Eigen::VectorXd qdot;
  bool onStop = false;  ///< it starts with u_s = d exactly
  bool atRest = false;  ///< and v_s = 0 exactly
};

ChainFlight flightFrom(const ChainDynamics& dynamics, const ChainState& start);
ChainState stateAt(const ChainDynamics& dynamics, const ChainFlight& flight, double t);
/// The same into `out`, whose vectors are reused (a run allocates nothing per flight for them).
void flightInto(const ChainDynamics& dynamics, const ChainState& start, ChainFlight& out);
void stateInto(const ChainDynamics& dynamics, const ChainFlight& flight, double t, ChainState& out);

/// How a flight first meets the stop.
enum class ChainContactKind {
  Impact,     ///< mass s crosses u_s = d moving into the stop
  Touch,      ///< u_s reaches d with v_s = 0 within what double resolves (a grazing contact)
  None,       ///< never: a commensurate chain's flight below the stop for a whole period
  Budget,     ///< not within the search's horizon or window budget (a non-commensurate chain)
};

struct ChainContact {
  ChainContactKind kind = ChainContactKind::None;
  double t = 0;  ///< from the flight's start [time]
};

/// The first contact of mass s with the stop after the flight's start: the first zero of
/// f(t) = u_s(t) - d by firstZero's certified search (core/solver/sinusoid_zero.h), so that a
/// touch (an even-multiplicity zero no sign-change method sees) is never missed, only possibly
/// called a touch when two crossings lie closer than double resolves. A flight starting on the
/// stop leaves it by its velocity (or, at v_s = 0, its acceleration; after a release, given as
/// `releaseJerk`, its third derivative). Commensurate chains are searched over one period (a
/// contact comes by T); others up to `horizon` or `maxWindows` windows.
ChainContact firstContact(const ChainDynamics& dynamics, const ChainFlight& flight, double horizon = 0,
                          long maxWindows = 1'000'000, std::optional<double> releaseJerk = std::nullopt);

}  // namespace grazelab::core
