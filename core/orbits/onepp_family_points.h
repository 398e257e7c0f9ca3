// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "core/orbits/periodic_orbit.h"

/// Along the 1IPP family: where its stability changes and where its admissible parts end, each
/// located to the precision of S by bisection in the period (docs/model.md section 10); and the
/// switch at a flip onto the 2k-impact family born there.
namespace grazelab::core {

/// What a special point of a family is, or how a family ends.
enum class PointKind {
  PeriodDoubling,   ///< tr DP = -2: a flip (as an end: the family meets its parent's flip)
  Fold,             ///< tr DP = +2 where the energy turns back
  BranchPoint,      ///< tr DP = +2 where the energy goes on: another family crosses
  InteriorGrazing,  ///< a flight touches the stop between impacts: the admissible part ends
  ImpactSpeedZero,  ///< an impact speed tends to 0 (not all of them): the part ends
  EnergyLimit,      ///< the energy grows without bound, or the energy range asked for ends
  GrazingOrbit,     ///< every impact speed (or one and a clearance) tends to 0: a GLO
  Undecided,        ///< not a bifurcation: the precision of S cannot say more beyond here
  StepLimit,        ///< the continuation's step budget ran out
  Stopped,          ///< a stop was requested
};
/// "period-doubling", "fold", "branch-point", "interior-grazing", "impact-speed-zero",
/// "energy-limit", "grazing-orbit", "undecided", "step-limit", "stopped".
std::string_view toString(PointKind kind);

/// A special point of a family.
template <typename S>
struct FamilyBifurcation {
  PointKind kind = PointKind::Undecided;
  S T = 0;
  S energy = 0;
  S trace = 0;
  BasicState<S> state;  ///< the orbit's state just after its impact (the admissible side's)
  /// a flip, fold or branch point: its trace meets the level within traceLevelTolerance (false:
  /// the search could not solve it there in S; the point is where it stopped, not a result)
  bool checked = true;
  /// an estimate of the energy's error: the trace's error over the trace's slope in the energy
  /// (from the neighbours the point was located between), plus the last bracket's width; large
  /// where the trace barely moves with the energy (a near-degenerate flip)
  S energyError = 0;
  /// a flip in an atlas: the family born there (its id), or -1 with `birthProblem` saying why
  /// none was found (empty when no search was made, e.g. beyond the impacts asked for)
  int born = -1;
  std::string birthProblem;
};

/// The special point of kind `kind` at `orbit` (period, energy, trace, state).
template <typename S>
FamilyBifurcation<S> specialPoint(PointKind kind, const PeriodicOrbit<S>& orbit) {
  FamilyBifurcation<S> point;
  point.kind = kind;
  point.T = orbit.period;
  point.energy = orbit.energy;
  point.trace = orbit.trace;
  point.state = orbit.state;
  return point;
}

/// The energy and trace of an orbit met while locating a special point.
template <typename S>
struct TraceSample {
  S energy = 0;
  S trace = 0;
};

/// The energy error of a point located where the trace meets a level: the trace's error at
/// the point (`traceError`, from locatedTraceError) over the trace's slope in the energy. The
/// slope is the secant to the nearest of `met` (orbits of the family met on the way) whose
/// trace differs from the point's by 100 times that error or more: nearer ones are noise,
/// farther ones overstate the slope where the trace only grazes the level. +infinity when none
/// does.
template <typename S>
S levelEnergyError(const PeriodicOrbit<S>& at, const S& traceError, const std::vector<TraceSample<S>>& met) {
  using std::abs;
  S nearest = std::numeric_limits<S>::infinity();
  S slope = 0;
  for (const TraceSample<S>& m : met) {
    const S rise = abs(m.trace - at.trace);
    const S run = abs(m.energy - at.energy);
    if (rise >= S(100) * traceError && run > S(0) && run < nearest) {
      nearest = run;
      slope = rise / run;
    }
  }
  return slope > S(0) ? S(traceError / slope) : std::numeric_limits<S>::infinity();
}

/// The 1IPP family over (0, T2) from its closed form, scanned in T: the admissible orbits at
/// the periods looked at (a grid of `samples` periods T2 i / (samples + 1), refined where the
/// trace bends near +-2 so that two crossings between neighbours cannot go unseen), and its
/// special points located between them by bisection in T to the last bit of S: flips, folds,
/// branch points, the ends of its admissible parts, and its grazing end at T2. Each flip, fold
/// and branch point is checked against its definition (|tr -+ 2| within the rounding) and is
/// given as undecided when it fails.
template <typename S>
struct OnePeriodicScan {
  std::vector<PeriodicOrbit<S>> orbits;            ///< admissible, in increasing T
  std::vector<FamilyBifurcation<S>> points;        ///< in increasing T
  bool complete = false;                           ///< false when stopped
};
template <typename S>
OnePeriodicScan<S> scanOnePeriodicFamily(const TwoMassForm<S>& chain, int samples, std::stop_token stop = {});

/// The special points of scanOnePeriodicFamily alone (nothing after a stop).
template <typename S>
std::vector<FamilyBifurcation<S>> onePeriodicBifurcations(const TwoMassForm<S>& chain, int samples,
                                                          std::stop_token stop = {});

/// The admissible runs of the 1IPP family over (0, T2), sampled at T2 i / (samples + 1): each
/// as the first and last sampled period of the run (to that resolution; for messages).
template <typename S>
std::vector<std::array<S, 2>> onePeriodicParts(const TwoMassForm<S>& chain, int samples);

/// Which side of `level` (-2 or +2) the orbit's trace is on: +1 above, -1 below, 0 on it within
/// the rounding its checks show (parabolic: along an isochronous family the trace stays at 2).
template <typename S>
int sideOfLevel(const PeriodicOrbit<S>& orbit, const S& level);

/// Whether the trace could cross +-2 twice, or once unseen, between neighbours a and b of a
/// family given the orbit halfway: its range over the three, widened by four times its bend
/// (how far the middle is from the chord), holds a level that it does not cross exactly once
/// along a nearly straight line. A trace on the level within rounding asks for nothing.
template <typename S>
bool traceMayCrossUnseen(const PeriodicOrbit<S>& a, const PeriodicOrbit<S>& middle, const PeriodicOrbit<S>& b);

/// How far |tr -+ 2| may be at a located flip, fold or branch point in S: a located point whose
/// trace is farther from the level is not printed as one.
template <typename S>
S traceLevelTolerance();

/// The 2k-impact orbit born at a flip of a k-impact family: Newton on P^2k from the flip orbit
/// (`flip.state`) pushed along the eigenvector of -1, at energies a little below and above the
/// flip's (the new family exists on one side only). The energy offsets stay below
/// `maxRelativeOffset` (a quarter of the way to the family's nearest other special point, so
/// that the orbit found is the one born here), and an orbit is taken only when it is the one
/// born at this flip: its period near twice the flip's and its state near the flip's, as the
/// square root of the offset says.
enum class Side { Below, Above };
std::string_view toString(Side side);  ///< "below", "above"
template <typename S>
struct FlipSwitch {
  OrbitSearch<S> search;
  Side side = Side::Below;
  S energyOffset = 0;  ///< E - E_flip of the orbit found
};
/// The largest relative energy offset for switchAtFlip at `flip`: a quarter of the relative
/// distance to the nearest of the family's other special points and ends (`energies`).
template <typename S>
double birthOffsetBound(const FamilyBifurcation<S>& flip, const std::vector<S>& energies);
template <typename S>
FlipSwitch<S> switchAtFlip(const TwoMassForm<S>& chain, const FamilyBifurcation<S>& flip, int impacts = 1,
                           double maxRelativeOffset = 1e-3, std::stop_token stop = {});

}  // namespace grazelab::core
