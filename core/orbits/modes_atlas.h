// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "core/orbits/atlas_energy_range.h"
#include "core/orbits/family_continuation.h"

/// The atlas of the chain's nonlinear normal modes up to K impacts per period (docs/model.md
/// section 10): every admissible part of the 1IPP family inside the energy range, from its
/// closed form (scanOnePeriodicFamily: the same orbits, flips, folds and ends as `family
/// --onepp`), and every family born at a flip inside the range (recursively, while 2k <= K),
/// continued to its end or the range's; a family that comes back to a flip ends there, and
/// that flip is not switched at again.
namespace grazelab::core {

/// How a family of the atlas was found.
enum class Birth {
  OnePeriodic,     ///< a part of the 1IPP family, from its closed form
  PeriodDoubling,  ///< born at a flip of family `parent`
};
/// "one-periodic", "period-doubling".
std::string_view toString(Birth birth);

template <typename S>
struct ModeFamily {
  int id = 0;
  int impacts = 0;
  std::string symmetry;  ///< "A", "B" or empty, of the orbit the family was started from
  /// a 1IPP part: bornEnergy and bornPeriod are those of its orbit nearest the middle of the
  /// range; a family born at a flip of family `parent`: the flip's energy and period
  Birth birth = Birth::OnePeriodic;
  int parent = -1;
  S bornEnergy = 0;
  S bornPeriod = 0;
  Side side = Side::Below;  ///< born at a flip: below or above its energy
  /// the orbits in increasing arclength from one end to the other (a 1IPP part: from its low
  /// energy end, the closed form's orbits at the periods its scan looked at and at its special
  /// points; a family born at a flip: from the flip)
  std::vector<FamilyOrbit<S>> orbits;
  /// flips, folds, branch points in the order of `orbits`; a flip in the range says which
  /// family was born there, or why none was found
  std::vector<FamilyBifurcation<S>> bifurcations;
  FamilyEnd<S> end;       ///< where it ends (the far end from its birth)
  FamilyEnd<S> startEnd;  ///< a 1IPP part's other end (its low-energy side); a flip's family: the flip
};

template <typename S>
struct ModesAtlas {
  std::vector<ModeFamily<S>> families;
  bool complete = false;  ///< false when stopped
};

/// The energies over which the atlas follows families unless told otherwise, for the command
/// line and the explorer alike: 1/100 to 10000 times the energy of the 1IPP family's grazing end
/// (GLO_lambda*), where the families are born and end.
template <typename S>
AtlasEnergyRange<S> defaultAtlasEnergyRange(const TwoMassForm<S>& chain);

/// The most impacts per period the atlas follows unless told otherwise.
inline constexpr int kDefaultAtlasMaxImpacts = 4;

/// The impacts per period of the atlas's orbit whose state just after an impact is `state`,
/// bit for bit (a click on the atlas's picture, or a session that saved it, gives one); empty
/// when no orbit of the atlas has it.
template <typename S>
std::optional<int> impactsOfAtlasOrbit(const ModesAtlas<S>& atlas, const BasicState<S>& state);

/// Computes the atlas; `familyDone` is called with each family as it is finished (for a
/// display that shows them as they come).
template <typename S>
ModesAtlas<S> computeModesAtlas(const TwoMassForm<S>& chain, int maxImpacts, const S& energyLow,
                                const S& energyHigh, std::stop_token stop = {},
                                const std::function<void(const ModeFamily<S>&)>& familyDone = {});

}  // namespace grazelab::core
