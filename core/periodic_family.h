// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <array>
#include <stop_token>
#include <string>
#include <vector>

#include "core/periodic_orbit.h"

/// Along the 1IPP family: where its stability changes and where its admissible parts end, each
/// located to the precision of S by bisection in the period (docs/model.md section 10); and the
/// switch at a flip onto the 2-impact family born there.
namespace grazelab::core {

/// A special point of a family.
template <typename S>
struct FamilyBifurcation {
  /// "period-doubling" (tr DP = -2), "fold" (tr DP = +2 where the energy turns back),
  /// "branch-point" (tr DP = +2 otherwise), "interior-grazing" (a flight touches the stop:
  /// the admissible part ends), "impact-speed-zero" (V -> 0 inside (0, T2): the part ends),
  /// "energy-limit" (V and the energy grow without bound as g2(T) -> 0: the part ends),
  /// "undecided" (beyond this point the precision cannot decide whether a flight touches the
  /// stop: not a bifurcation, the limit of what S can tell; a higher precision moves it),
  /// "grazing-orbit" (T -> T2: impact speed and clearance tend to 0, the orbit becomes
  /// GLO_lambda*, Theorem 2.1)
  std::string kind;
  S T = 0;
  S energy = 0;
  S trace = 0;
  BasicState<S> state;  ///< the orbit's state just after its impact (the admissible side's)
};

/// The bifurcations of the 1IPP family over (0, T2), scanned at `samples` periods T2 i /
/// (samples + 1) and located between neighbours, in increasing T, ending with its grazing end
/// at T2. Nothing after a stop.
template <typename S>
std::vector<FamilyBifurcation<S>> onePeriodicBifurcations(const Chain<S>& chain, int samples,
                                                          std::stop_token stop = {});

/// The admissible runs of the 1IPP family over (0, T2), sampled at T2 i / (samples + 1): each
/// as the first and last sampled period of the run (to that resolution).
template <typename S>
std::vector<std::array<S, 2>> onePeriodicParts(const Chain<S>& chain, int samples);

/// The 2k-impact orbit born at a flip of a k-impact family: Newton on P^2k from the flip orbit
/// (`flip.state`) pushed along the eigenvector of -1, at energies a little below and above the
/// flip's (the new family exists on one side only). `side` says which ("below" or "above").
template <typename S>
struct FlipSwitch {
  OrbitSearch<S> search;
  std::string side;
  S energyOffset = 0;  ///< E - E_flip of the orbit found
};
template <typename S>
FlipSwitch<S> switchAtFlip(const Chain<S>& chain, const FamilyBifurcation<S>& flip,
                           int impacts = 1, std::stop_token stop = {});

}  // namespace grazelab::core
