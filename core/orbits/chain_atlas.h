// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <functional>
#include <optional>
#include <stop_token>
#include <string_view>
#include <vector>

#include "core/orbits/atlas_energy_range.h"
#include "core/orbits/chain_continuation.h"

/// The atlas of a chain's nonsmooth modes up to K impacts per period, for any chain
/// (docs/model.md section 12): every admissible part of the 1IPP family inside the energy range,
/// from its closed form (its rows, its stability changes by bisection in T, its ends located and
/// named), and every family born at a period doubling inside the range (branch switching, then
/// continuation on the exact return map away from the doubling), recursively while 2k <= K. A
/// family that comes back to another period doubling (its orbit becoming the shorter one run
/// twice) ends there, and that doubling is said to be reached by it, not switched at again.
namespace grazelab::core {

/// How a family of a chain's atlas was found.
enum class ChainBirth {
  OnePeriodic,     ///< a part of the 1IPP family, seeded by its closed form
  PeriodDoubling,  ///< born at a period doubling of family `parent`
  GivenOrbit,      ///< followed both ways from an orbit given (followChainFamily)
};
/// "one-periodic", "period-doubling", "given-orbit".
std::string_view toString(ChainBirth birth);

/// One end of a family of the atlas, as its continuation met it.
struct ChainAtlasEnd {
  ChainFamilyEnd kind = ChainFamilyEnd::NotConverging;
  OrbitRefusal refusal = OrbitRefusal::None;  ///< an Inadmissible end: what the path showed
  /// an end where the orbit became a shorter one run twice: the family and the index of its
  /// period doubling it came back to, if the atlas has it
  int family = -1;
  int change = -1;
};

/// What the atlas did at a period doubling of a family.
enum class ChainBranchOutcome {
  Born,           ///< the family `family` was born there and followed away from it
  Reached,        ///< the family `family`, followed from elsewhere, came back to it
  NotFound,       ///< branch switching found no orbit (`problem` says why)
  BeyondImpacts,  ///< its family would have more impacts than the atlas follows
};
/// "born", "reached", "not-found", "beyond-impacts".
std::string_view toString(ChainBranchOutcome outcome);

struct ChainAtlasBranch {
  std::size_t change = 0;  ///< the doubling: the index in the family's `path.changes`
  ChainBranchOutcome outcome = ChainBranchOutcome::NotFound;
  int family = -1;
  ChainOrbitProblem problem = ChainOrbitProblem::None;
};

template <typename S>
struct ChainAtlasFamily {
  int id = 0;
  ChainBirth birth = ChainBirth::OnePeriodic;
  int parent = -1;        ///< born at a doubling: the parent family and the doubling's index
  int parentChange = -1;  ///< in its `path.changes`
  /// the orbits from one end to the other, with the changes between them and the far end
  /// (`path.end`, `path.refusal`): a 1IPP part in increasing period, from its end of shorter
  /// period; a family born at a doubling from the doubling
  ContinuedChainFamily<S> path;
  /// the end at `path.orbits.front()` (a family born at a doubling: none, it starts there)
  std::optional<ChainAtlasEnd> firstEnd;
  ChainAtlasEnd lastEnd;
  std::vector<ChainAtlasBranch> branches;  ///< one per period doubling in `path.changes`
  /// every orbit has the period of the first to 1e-9 while the energy moves by more than 1e-3:
  /// an isochronous family (at that period its orbits are not isolated; it may lie in a wider
  /// sheet of them, which the atlas does not say)
  bool onePeriod = false;
};

template <typename S>
struct ChainAtlas {
  std::vector<ChainAtlasFamily<S>> families;
  bool complete = false;  ///< false when stopped
  /// the 1IPP scan's periods whose closed form this precision could not decide (a contact too
  /// near tangent, or the contact search's budget run out): parts of the family may be missing
  /// or cut short there. Not counted: the undecided periods that run on to T_max, where the
  /// family tends to its grazing orbit (V -> 0) and the last part ends on it
  int undecidedPeriods = 0;
  /// the scan was given up: kFamilySearchBudgetRows of its periods ran out of the contact search's
  /// budget before any was decided (flights too stiff to search); no family
  bool searchBudgetExhausted = false;
};

template <typename S>
struct ChainAtlasOptions {
  int maxImpacts = 2;
  S energyLow = 0;
  S energyHigh = 0;
  int maxOrbitsPerFamily = 2000;
  /// the 1IPP family's closed form is looked at on so many periods evenly spread in (0, T_max),
  /// and 23 more towards T_max, for its admissible parts
  int onePeriodicRows = 400;
};

/// The energies the atlas follows unless told otherwise: 1/100 to 10000 times the energy of the
/// GLO the 1IPP family tends to at its grazing end (T -> T_max), as for the two-mass atlas; the
/// closed form's energy at T_max / 2 where that GLO cannot be made.
template <typename S>
AtlasEnergyRange<S> defaultChainAtlasEnergyRange(const BasicReadyChain<S>& chain);

/// Computes the atlas; `familyDone` hears each family as soon as its path and ends are found, in
/// the order of their ids (what happened at its own doublings, and the ends of later families
/// that come back to them, only the atlas returned has).
template <typename S>
ChainAtlas<S> computeChainAtlas(
    const BasicReadyChain<S>& chain, const ChainAtlasOptions<S>& options, std::stop_token stop = {},
    const std::function<void(const ChainAtlasFamily<S>&)>& familyDone = {});

/// The family of the admissible orbit `start` followed both ways in energy until it ends: `path`
/// from the end met going down in energy (`firstEnd`), through `start`, to the end met going up
/// (`lastEnd`), its changes in that order (a change met going down is reversed: `leaves` the way
/// the path runs). No branch is switched at (the atlas does that).
template <typename S>
ChainAtlasFamily<S> followChainFamily(const BasicReadyChain<S>& chain, const BasicChainPeriodicOrbit<S>& start,
                                      const ChainContinuationOptions<S>& options, std::stop_token stop = {});

}  // namespace grazelab::core
