// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <functional>
#include <stop_token>
#include <string_view>
#include <vector>

#include "core/orbits/chain_bifurcations.h"
#include "core/orbits/chain_kipp.h"

/// A family of kIPP orbits of any chain followed in energy by pseudo-arclength continuation on the
/// exact return map (docs/model.md section 12): the unknowns are the section's 2N - 2 coordinates
/// and the energy, in scaled units (lengths over the gap, speeds over the scale's speed, the
/// energy over the first orbit's), the family is F = P^k(x) - x = 0 with the exact Jacobian
/// [DP^k g - I | dP^k/dE]; a predictor along the tangent (the Jacobian's null vector), a Newton
/// corrector on the family and the arclength, a step that grows while the corrector converges
/// fast and halves when it fails. A fold in energy is passed like any other point.
namespace grazelab::core {

/// Why a continued family ends. Where no step down to the smallest one gives an orbit, the end
/// is named from the last orbit and the path just beyond it (the predictor a few smallest steps
/// on): the speeds of its impacts against the scale's speed, and the contacts beyond. Where an
/// impact slows below 5% of the scale's speed while the steps shrink (its saltation grows as the
/// inverse of its speed), the family is approached at fixed periods towards the period where the
/// speed's secant puts 0, as far as Newton converges, and ends there: its last orbit's slowest
/// impact speed says how near the end it is.
enum class ChainFamilyEnd {
  EnergyLimit,      ///< the energy left the range asked for
  StepLimit,        ///< the most orbits asked for were taken
  /// every impact's speed tends to 0 (each below 5% of the scale's speed at the last orbit): the
  /// family tends to a linear orbit that grazes the stop (a 1IPP family at T_max: its GLO)
  GrazingOrbit,
  ImpactFades,      ///< one impact's speed tends to 0, not all
  InteriorGrazing,  ///< a flight touches the stop between impacts: the path beyond makes a new contact
  /// the orbit becomes one of half the impacts run twice: the family meets a period doubling of
  /// that family
  MeetsDoubling,
  Undecided,        ///< a contact of the path beyond cannot be decided in this precision
  /// the corrector fails at the smallest step with none of the above in sight, or the tangent
  /// turns by more than 23 degrees at every step down to it (a branch point, or a jump onto
  /// another family)
  NotConverging,
  StartNotAdmissible,  ///< the orbit given to start from is not an admissible one (`refusal` says why)
  Stopped,             ///< a stop was requested
};
/// "energy-limit", "step-limit", "grazing-orbit", "impact-fades", "interior-grazing",
/// "meets-doubling", "undecided", "not-converging", "start-not-admissible", "stopped".
std::string_view toString(ChainFamilyEnd end);

template <typename S>
struct ChainContinuationOptions {
  S energyLow = 0;   ///< the family is followed while its energy stays in
  S energyHigh = 0;  ///< [energyLow, energyHigh]
  int maxOrbits = 2000;
  /// steps along the arclength in scaled units: the first, the largest, and the smallest tried
  /// before the family is said to end
  double firstStep = 1e-3;
  double maxStep = 0.05;
  double minStep = 1e-9;
};

/// Where a continued family changes stability: between two of its orbits whose multipliers sit
/// differently on the unit circle (both decided), located by bisection along the chord between
/// them (each point corrected onto the family) to the resolution of S, and named by how the rest
/// of the census moved across the last bracket (two changes in one bracket are both found).
/// Between two orbits of one census the halves are searched where two changes that undo each other
/// could hide (mayHideAPair), as along the 1IPP family (its refinement near the poles of sigma, a
/// closed-form quantity of 1IPP orbits, has no counterpart here).
template <typename S>
struct ChainFamilyChange {
  ChainBifurcationKind kind = ChainBifurcationKind::Other;
  bool leaves = true;      ///< multipliers leave the circle the way the family is followed
  std::size_t after = 0;   ///< between orbits[after] and orbits[after + 1]
  S energy = 0;            ///< the middle of the last bracket, and half its spread
  S energyError = 0;
  S period = 0;
  S periodError = 0;
  BasicChainState<S> state;  ///< the bracket's orbit on the side the family comes from
};

template <typename S>
struct ContinuedChainFamily {
  int impacts = 0;
  /// the orbits in the order followed, the first the one started from; each admissible, with its
  /// monodromy, multipliers and class
  std::vector<BasicChainPeriodicOrbit<S>> orbits;
  std::vector<ChainFamilyChange<S>> changes;  ///< in the order followed
  /// the pairs of consecutive orbits between which the search for two changes that undo each other
  /// ran out of its budget (256 orbits, beside the bisections of the changes found) before it could
  /// rule them out
  int unsearched = 0;
  ChainFamilyEnd end = ChainFamilyEnd::NotConverging;
  /// what the path showed at the last step that failed (None: the corrector failed or turned)
  OrbitRefusal refusal = OrbitRefusal::None;
};

/// The orbit of twice as many impacts born at the period doubling `doubling` of a family of
/// `parentImpacts`-impact orbits: the parent orbit at energies a little to either side of the
/// doubling (relative offsets 1e-6 to 1e-3, by Newton from the doubling's state) pushed along the
/// eigenvector of its multiplier nearest -1 (by inverse iteration on M + I) by 1e-3 to 1e-1 either
/// way, and where none of these gives the branch along the singular vector of M + I's smallest
/// singular value by c sqrt(offset), c from 0.3 to 30 (at most 0.1); then Newton at that energy;
/// the first orbit found whose period is within 1% of twice the parent's, within three pushes of
/// the parent (scaled), not the parent run twice, and accepted by `accept` when given (the atlas
/// follows it back to see it meet this doubling: next to two close doublings the
/// other's branch passes near the parent too). Its problem when none is found (the branch's side
/// may be too narrow).
template <typename S>
ChainOrbitSearch<S> branchAtDoubling(
    const BasicReadyChain<S>& chain, const ChainFamilyChange<S>& doubling, int parentImpacts, std::stop_token stop = {},
    const std::function<bool(const BasicChainPeriodicOrbit<S>&)>& accept = {});

/// Follows the family of the admissible orbit `start` with its energy first moving the way of
/// `direction` (+1 up, -1 down), until it ends.
template <typename S>
ContinuedChainFamily<S> continueChainFamily(const BasicReadyChain<S>& chain, const BasicChainPeriodicOrbit<S>& start,
                                            int direction, const ChainContinuationOptions<S>& options,
                                            std::stop_token stop = {});

}  // namespace grazelab::core
