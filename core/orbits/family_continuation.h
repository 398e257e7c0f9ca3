// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <limits>
#include <stop_token>
#include <string>
#include <vector>

#include "core/orbits/onepp_family_points.h"
#include "core/orbits/periodic_orbit.h"

/// A family of k-impact orbits followed in energy by pseudo-arclength continuation on
/// (u1, v1, E) with the exact Jacobian [DP^k - I | dP^k/dE] (docs/model.md section 10): a
/// predictor along the tangent, a Newton corrector on the family and the arclength, step
/// control, and the special points located by bisection of the step to the precision of S.
namespace grazelab::core {

/// One orbit of a continued family, in the few numbers a table keeps (its full path is
/// recomputed on demand from `state`).
template <typename S>
struct FamilyOrbit {
  S energy = 0;
  S period = 0;
  S trace = 0;
  Stability stability = Stability::Elliptic;
  BasicState<S> state;  ///< just after an impact
  S minImpactSpeed = 0;
  S minClearance = 0;
};

/// The few numbers a table keeps of `orbit`.
template <typename S>
FamilyOrbit<S> summaryOf(const PeriodicOrbit<S>& orbit) {
  return {orbit.energy, orbit.period, orbit.trace, orbit.stability, orbit.state, orbit.minImpactSpeed,
          orbit.minClearance};
}

/// Where a continued family ends.
template <typename S>
struct FamilyEnd {
  /// GrazingOrbit (every impact speed, or an impact speed and a clearance, tend to 0: the
  /// family becomes a grazing linear orbit), InteriorGrazing (a flight touches the stop),
  /// ImpactSpeedZero (one impact fades), PeriodDoubling (a 2k-impact family meets a flip of a
  /// k-impact family: its orbit becomes that one run twice), EnergyLimit (the energy range
  /// asked for), StepLimit, Undecided (the corrector fails with no event in sight, or a
  /// contact cannot be decided in S), Stopped
  PointKind kind = PointKind::Undecided;
  S energy = 0;
  S period = 0;
  BasicState<S> state;
  /// a grazing-orbit end: the lambda of the grazing linear orbit GLO_lambda that the family
  /// tends to, from the last orbit's impact data u1 = d [(1 - lambda) rho_fast + lambda rho_slow]
  /// (as near to the limit as the last orbit is); NaN for other ends
  S gloLambda = std::numeric_limits<S>::quiet_NaN();
  /// energy, period, state and gloLambda are the limit orbit's, exactly, not the last orbit's:
  /// a family whose period tends to an odd number of fast periods T1 can only end on GLOM1 (a
  /// free motion repeats after T2; only the pure fast mode after T1), the one-impact family
  /// ends on GLO_lambda* at T2 (Theorem 2.1), and a family meeting a flip ends on the flip's
  /// orbit (its period twice the flip's)
  bool exact = false;
  S lastEnergy = 0;  ///< the energy of the last orbit computed, to see how near it came
  int family = -1;   ///< in an atlas: the family whose flip a PeriodDoubling end meets
};

/// An end of kind `kind` at `orbit` (its energy, period and state; the last energy its own).
template <typename S>
FamilyEnd<S> familyEndAt(PointKind kind, const PeriodicOrbit<S>& orbit) {
  FamilyEnd<S> end;
  end.kind = kind;
  end.energy = orbit.energy;
  end.period = orbit.period;
  end.state = orbit.state;
  end.lastEnergy = orbit.energy;
  return end;
}

template <typename S>
struct ContinuationOptions {
  S energyLow = 0;                 ///< the family is followed while its energy stays in
  S energyHigh = 0;                ///< [energyLow, energyHigh]
  int maxSteps = 4000;
  /// the first step along (u1 / d, v1 / (w2 d), ln E); steps grow to `maxStep` and shrink on
  /// their own. A step is taken only when its corrected end stays near the predictor, is
  /// admissible, and the orbit halfway is near the chord with a trace that bends little where
  /// it could cross +-2 (no jump onto another family, no pair of crossings unseen). An end is
  /// approached until the step is at the resolution of S, then classified from the last
  /// orbit (within 5 % of the speed w2 d or of the gap)
  double firstStep = 1e-3;
  double maxStep = 0.1;
};

template <typename S>
struct ContinuedFamily {
  int impacts = 0;
  std::vector<FamilyOrbit<S>> orbits;              ///< in the order followed
  std::vector<FamilyBifurcation<S>> bifurcations;  ///< flips, folds, branch points, in order
  FamilyEnd<S> end;
};

/// A grazing-orbit end (its gloLambda and period those of the last orbit) named by its limit
/// when that is known exactly: a period tending to an odd number of fast periods T1 (GLOM1), or
/// the one-impact family tending to T2 (GLO_lambda*); `exact` says whether it was.
template <typename S>
void nameGrazingEnd(const TwoMassForm<S>& chain, int impacts, FamilyEnd<S>& end);

/// Follows the family through `start` (an admissible k-impact orbit) with its energy first
/// moving the way of `direction` (+1: up, -1: down), until it ends.
template <typename S>
ContinuedFamily<S> continueFamily(const TwoMassForm<S>& chain, const PeriodicOrbit<S>& start,
                                  int direction, const ContinuationOptions<S>& options,
                                  std::stop_token stop = {});

}  // namespace grazelab::core
