// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>
#include <stop_token>
#include <vector>

#include "core/model/mass_chain.h"
#include "core/model/model.h"
#include "core/solver/chain_flight.h"

namespace grazelab::core {

/// An elastic bar thrown at a rigid wall (docs/model.md section 13), the benchmark of contact
/// dynamics whose continuum answer is exact: with c = sqrt(E / rho), the contact lasts 2L/c, the
/// wall pushes with E S v0 / c throughout, and the bar leaves at -v0 with no vibration. The
/// defaults are the steel bar of the literature (385.45 us, 1270.8 N).
struct Bar {
  double youngModulus = 210e9;  ///< E [Pa]
  double density = 7800;        ///< rho [kg/m^3]
  double area = 3.14e-4;        ///< S [m^2]
  double length = 1;            ///< L [m]
  double speed = 0.1;           ///< v0 [m/s], onto the wall
};

/// Every problem with the bar (each number positive and finite).
std::vector<Problem> validate(const Bar& bar);

/// Where the wall is: ahead of the bar's last mass, or behind its first (the mirror image, the
/// same motion with the masses numbered the other way: a check of the engine, not of the bar).
enum class BarEnd { Last, First };

/// The bar lumped into N equal masses m = rho S L / N joined by N - 1 springs k = E S N / L: each
/// mass a cell L/N long and each spring a cell's stiffness, so that the total mass is rho S L and
/// long waves travel at c (sqrt(k/m) L/N = c); floating (no wall holds it), stopped at `end`. The
/// gap is v0 L / c, the distance the bar's middle travels while it is in contact (a floating
/// chain's motion does not depend on it: it only sets the scale its roundings are relative to).
MassChain barChain(const Bar& bar, int masses, BarEnd end = BarEnd::Last);
/// The bar at the instant its end meets the wall: every mass at the gap, moving onto it at v0.
ChainState barStart(const Bar& bar, int masses, BarEnd end = BarEnd::Last);

/// The continuum's answer: contact 2L/c, force E S v0 / c, impulse 2 rho S L v0, rebound -v0.
struct BarContinuum {
  double waveSpeed = 0;  ///< c [m/s]
  double duration = 0;   ///< [s]
  double force = 0;      ///< [N]
  double impulse = 0;    ///< [N s]
  double rebound = 0;    ///< the centre of mass's velocity after [m/s]
};
BarContinuum barContinuum(const Bar& bar);

enum class BarStatus {
  Computed,   ///< the bar left the wall for good (no further contact, decided exactly)
  Undecided,  ///< a contact binary128 could not decide (a touch within its rounding)
  Unfinished, ///< still in contact after the impacts allowed
  Cancelled,
};

/// How a lumped bar's impact went, every impact of the end mass found by the exact engine.
struct BarImpact {
  BarStatus status = BarStatus::Computed;
  int masses = 0;
  Precision precision = Precision::Double;  ///< the run's (raised from double when undecided)
  long impacts = 0;
  double duration = 0;     ///< first to last impact [s]
  double impulse = 0;      ///< the wall's on the bar, sum of 2 m |v_end| over the impacts [N s]
  double rebound = 0;      ///< the centre of mass's velocity after [m/s]
  double vibration = 0;    ///< the energy left in vibration over the bar's kinetic energy before
  double meanForce = 0;    ///< impulse / duration [N] (0 for one mass: a single impact)
  double energyDrift = 0;  ///< the run's largest relative energy error at its events
  std::vector<double> times;     ///< each impact's time [s] (the first at 0)
  std::vector<double> impulses;  ///< each impact's impulse [N s]
};

/// The bar of N masses thrown at the wall, in double, raised to long double and binary128 where a
/// contact is undecided; at most `maxImpacts` impacts (0: 100 N + 100).
BarImpact throwBar(const Bar& bar, int masses, BarEnd end = BarEnd::Last, std::stop_token stop = {},
                   long maxImpacts = 0);

/// How a quantity approaches its limit over N: the order p measured between successive N from its
/// errors (e ~ N^-p), and the limit extrapolated from the last three values alone (x = x_inf +
/// C N^-p solved for x_inf, C and p, without the known limit); none where the differences change
/// sign (the approach is not yet of that form).
struct Convergence {
  std::vector<double> orders;            ///< between N_i and N_(i+1); NaN where an error is 0
  std::optional<double> extrapolated;    ///< x_inf
  std::optional<double> extrapolatedOrder;
};
Convergence convergence(const std::vector<int>& masses, const std::vector<double>& values, double limit);

}  // namespace grazelab::core
