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
};

ChainFlight flightFrom(const ChainDynamics& dynamics, const ChainState& start);
ChainState stateAt(const ChainDynamics& dynamics, const ChainFlight& flight, double t);

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

/// The first contact of mass s with the stop after the flight's start, by a certified search
/// (docs/model.md section 11): f(t) = u_s(t) - d is a sum of sinusoids whose third derivative
/// is at most B3 = sum w_j^3 R_j (R_j the modal amplitudes at mass s); with r = h/2 a window of
/// width h around t_m holds no zero when |f(t_m)| > |f'(t_m)| r + |f''(t_m)| r^2/2 + B3 r^3/6,
/// and at most one when |f'(t_m)| > |f''(t_m)| r + B3 r^2/2; any other window is halved.
/// Windows are taken from the left, so the first zero found is the first zero: a touch (an
/// even-multiplicity zero no sign-change method sees) is never missed, only possibly called a
/// touch when two crossings lie closer than double resolves. A flight starting on the stop
/// leaves it by its velocity (or, at v_s = 0, its acceleration); near its start the Taylor bound
/// rules out a zero. Commensurate chains are searched over one period (a contact comes by T);
/// others up to `horizon` or `maxWindows` windows.
ChainContact firstContact(const ChainDynamics& dynamics, const ChainFlight& flight, double horizon = 0,
                          long maxWindows = 1'000'000);

}  // namespace grazelab::core
