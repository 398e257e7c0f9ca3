// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <functional>
#include <stop_token>
#include <string>
#include <vector>

#include "core/periodic_continuation.h"

/// The atlas of the chain's nonlinear normal modes up to K impacts per period (docs/model.md
/// section 10): every admissible part of the 1IPP family that reaches into the energy range,
/// continued in energy both ways from an orbit of it in the range, and every family born from
/// one of them at a flip inside the range (recursively, while 2k <= K), each continued to its
/// end or the range's.
namespace grazelab::core {

template <typename S>
struct ModeFamily {
  int id = 0;
  int impacts = 0;
  std::string symmetry;  ///< "A", "B" or empty, of the orbit the family was started from
  /// how it was found: kind "one-periodic" (a part of the 1IPP family, started from its
  /// closed-form orbit of energy bornEnergy and period bornPeriod, family -1) or
  /// "period-doubling" (born at a flip of family `parent`, at bornEnergy and bornPeriod)
  std::string bornKind;
  int parent = -1;
  S bornEnergy = 0;
  S bornPeriod = 0;
  std::string side;  ///< born at a flip: "below" or "above" its energy
  /// the orbits in increasing arclength from one end to the other (a 1IPP part: from its low
  /// energy end; a family born at a flip: from the flip)
  std::vector<FamilyOrbit<S>> orbits;
  std::vector<FamilyBifurcation<S>> bifurcations;
  FamilyEnd<S> end;       ///< where it ends (the far end from its birth)
  FamilyEnd<S> startEnd;  ///< a 1IPP part's other end (its low-energy side)
};

template <typename S>
struct ModesAtlas {
  std::vector<ModeFamily<S>> families;
  bool complete = false;  ///< false when stopped
};

/// Computes the atlas; `familyDone` is called with each family as it is finished (for a
/// display that shows them as they come).
template <typename S>
ModesAtlas<S> computeModesAtlas(const Chain<S>& chain, int maxImpacts, const S& energyLow,
                                const S& energyHigh, std::stop_token stop = {},
                                const std::function<void(const ModeFamily<S>&)>& familyDone = {});

}  // namespace grazelab::core
