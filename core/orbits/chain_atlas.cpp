// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/chain_atlas.h"

#include <algorithm>
#include <cmath>

#include "core/orbits/chain_glo.h"
#include "core/orbits/chain_onepp.h"

namespace grazelab::core {

std::string_view toString(ChainBirth birth) {
  switch (birth) {
    case ChainBirth::OnePeriodic:
      return "one-periodic";
    case ChainBirth::PeriodDoubling:
      return "period-doubling";
    case ChainBirth::GivenOrbit:
      return "given-orbit";
  }
  return "unknown";
}

std::string_view toString(ChainBranchOutcome outcome) {
  switch (outcome) {
    case ChainBranchOutcome::Born:
      return "born";
    case ChainBranchOutcome::Reached:
      return "reached";
    case ChainBranchOutcome::NotFound:
      return "not-found";
    case ChainBranchOutcome::BeyondImpacts:
      return "beyond-impacts";
  }
  return "unknown";
}

template <typename S>
AtlasEnergyRange<S> defaultChainAtlasEnergyRange(const BasicReadyChain<S>& chain) {
  // (a range, not a result: its ends in double)
  const MassChain numbers = chainCast<double>(chain.numbers);
  const double tMax = chainOnePeriodicEnd(numbers);
  const ChainGloStart glo = chainGloStart(numbers, onePeriodicGrazingWeights(numbers, tMax));
  double energy = glo.problem == GloStartProblem::None ? chainEnergy(numbers, glo.state) : 0.0;
  if (!(energy > 0) || !std::isfinite(energy))
    energy = chainOnePeriodicOrbit(numbers, tMax / 2).energy;
  if (!(energy > 0) || !std::isfinite(energy)) energy = 1;
  return {S(energy / 100), S(energy * 10000)};
}

namespace {

template <typename S>
ChainAtlasEnd endOf(ChainFamilyEnd kind, OrbitRefusal refusal) {
  return ChainAtlasEnd{kind, refusal, -1, -1};
}

// Whether a family's end is an orbit becoming the shorter one run twice at the doubling `change`
// of a family of half its impacts: its energy and its period (twice the doubling's) the same to
// 1e-5 (the end lies within the smallest step of the doubled orbit, where both move as the square
// of the distance; two doublings 0.6% apart in energy are told apart).
template <typename S>
bool comesBackTo(const ChainAtlasEnd& end, const BasicChainPeriodicOrbit<S>& last,
                 const ChainFamilyChange<S>& change) {
  using std::abs;
  return end.kind == ChainFamilyEnd::MeetsDoubling &&
         abs(last.energy - change.energy) <= S(1e-5) * abs(change.energy) &&
         abs(last.period - 2 * change.period) <= S(2e-5) * change.period;
}

// Whether a family keeps one period all along while its energy moves (ChainAtlasFamily::onePeriod).
template <typename S>
bool onePeriodAllAlong(const ContinuedChainFamily<S>& path) {
  using std::abs;
  if (path.orbits.size() < 3) return false;
  const S T = path.orbits.front().period;
  S low = path.orbits.front().energy, high = low;
  for (const BasicChainPeriodicOrbit<S>& orbit : path.orbits) {
    if (abs(orbit.period - T) > S(1e-9) * T) return false;
    low = std::min(low, orbit.energy);
    high = std::max(high, orbit.energy);
  }
  return high - low > S(1e-3) * high;
}

// T_max: the common period of a commensurate chain, else its slowest mode's period
template <typename S>
S onePeriodicEnd(const BasicChainDynamics<S>& dynamics) {
  if (dynamics.period > 0) return dynamics.period;
  S slowest = 0;
  for (Eigen::Index j = 0; j < dynamics.omega.size(); ++j) {
    if (dynamics.omega[j] > 0 && (slowest == 0 || dynamics.omega[j] < slowest))
      slowest = dynamics.omega[j];
  }
  return twoPi<S>() / slowest;
}

// The 1IPP family's parts in the energy range from its closed form (exact data at every period,
// no continuation needed): the periods `rows` evenly in (0, T_max) and towards T_max looked at;
// each maximal run of admissible rows in the range a part, its two ends located by bisection in T
// (to 1e-13 of T) and approached by rows at distances halving towards them; each row's orbit with
// its exact monodromy; the changes of stability by the closed form's own bisection in T
// (chainOnePeriodicBifurcations); each end named by what lies just beyond it.
template <typename S>
class OnePeriodicParts {
 public:
  OnePeriodicParts(const BasicReadyChain<S>& chain, const ChainAtlasOptions<S>& options,
                   std::stop_token stop)
      : chain_(chain), options_(options), stop_(stop), tMax_(onePeriodicEnd(chain.dynamics)) {}

  std::vector<ChainAtlasFamily<S>> parts() {
    std::vector<S> periods;
    for (int k = 1; k <= options_.onePeriodicRows; ++k)
      periods.push_back(tMax_ * S(k) / S(options_.onePeriodicRows + 1));
    for (int k = 8; k <= 30; ++k) periods.push_back(tMax_ * (1 - S(std::ldexp(1.0, -k))));
    std::sort(periods.begin(), periods.end());
    // which scan periods are in a part; those the closed form cannot decide counted, and the
    // scan given up where its first periods all run out of the contact search's budget (the
    // flights of a chain too stiff to search: as family --onepp, chainOnePeriodicFamily)
    std::vector<char> inside(periods.size(), 0);
    int outOfBudget = 0, trailing = 0;
    bool anyDecided = false;
    for (std::size_t k = 0; k < periods.size() && !stop_.stop_requested(); ++k) {
      const BasicChainOnePeriodicOrbit<S> orbit = data(periods[k]);
      const bool undecided = orbit.refusal == OnePeriodicRefusal::NotDecided ||
                             orbit.refusal == OnePeriodicRefusal::SearchBudget;
      undecidedPeriods_ += undecided ? 1 : 0;
      trailing = undecided ? trailing + 1 : 0;
      outOfBudget += orbit.refusal == OnePeriodicRefusal::SearchBudget ? 1 : 0;
      anyDecided = anyDecided || orbit.admissible() || orbit.refusal == OnePeriodicRefusal::NotDecided;
      if (!anyDecided && outOfBudget >= kFamilySearchBudgetRows) {
        searchBudgetExhausted_ = true;
        return {};
      }
      inside[k] = orbit.admissible() && inRange(orbit.energy);
    }
    // (the undecided run that reaches T_max is the family's approach to its grazing orbit, too
    // near tangent for S as V -> 0: the part before it ends there, named by its V; nothing is
    // missing in it)
    undecidedPeriods_ -= trailing;
    std::vector<ChainAtlasFamily<S>> out;
    std::size_t i = 0;
    while (i < periods.size() && !stop_.stop_requested()) {
      if (!inside[i]) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j + 1 < periods.size() && inside[j + 1]) ++j;
      out.push_back(part(periods, i, j));
      i = j + 1;
    }
    return out;
  }
  int undecidedPeriods() const { return undecidedPeriods_; }
  bool searchBudgetExhausted() const { return searchBudgetExhausted_; }

 private:
  BasicChainOnePeriodicOrbit<S> data(const S& T) const {
    return chainOnePeriodicOrbitIn(chain_.numbers, chain_.dynamics, T);
  }
  bool inRange(const S& energy) const {
    return energy >= options_.energyLow && energy <= options_.energyHigh;
  }
  bool inPart(const S& T) const {
    const BasicChainOnePeriodicOrbit<S> orbit = data(T);
    return orbit.admissible() && inRange(orbit.energy);
  }

  // the end of the part between `inside` (in it) and `outside` (not, or the scan's edge when
  // empty): located by bisection, named by what lies beyond
  struct End {
    S T;
    ChainAtlasEnd end;
  };
  End endBetween(S inside, std::optional<S> outside) const {
    using std::abs;
    if (!outside) {
      // the scan's edges: T -> 0 (the energy grows without bound) or T -> T_max (the GLO)
      const bool grazing = inside > tMax_ / 2;
      return {inside,
              ChainAtlasEnd{grazing ? ChainFamilyEnd::GrazingOrbit : ChainFamilyEnd::EnergyLimit,
                            OrbitRefusal::None, -1, -1}};
    }
    S out = *outside;
    for (int i = 0; i < 200 && abs(out - inside) > S(1e-13) * inside; ++i) {
      const S middle = (inside + out) / 2;
      (inPart(middle) ? inside : out) = middle;
    }
    // the first row beyond that is decided and not in the part: 1e-13 of T past the end the
    // closed form is often too near tangent to decide (a flight returning to the stop as it
    // grazes it), and next to a grazing end undecided rows and admissible ones in the range
    // alternate at the rounding's scale (in long double at T* - 1e-10 T*, the bisection stopping
    // between two of them). So the distance grows fourfold, up to the scan's neighbour.
    BasicChainOnePeriodicOrbit<S> beyond = data(out);
    const auto unclear = [this](const BasicChainOnePeriodicOrbit<S>& orbit) {
      return orbit.refusal == OnePeriodicRefusal::NotDecided || orbit.refusal == OnePeriodicRefusal::SearchBudget ||
             (orbit.admissible() && inRange(orbit.energy));
    };
    for (S step = out - inside; unclear(beyond) && abs(4 * step) < abs(*outside - inside);) {
      step *= 4;
      beyond = data(inside + step);
    }
    ChainAtlasEnd end;
    const ChainStateScale<S> scale(chain_.dynamics);
    if (beyond.admissible() && !inRange(beyond.energy)) {
      end.kind = ChainFamilyEnd::EnergyLimit;
    } else if (abs(data(inside).V) < S(0.05) * scale.speed) {
      // the impact fades (V through 0, near a common period T* of some modes): the orbit
      // becomes the GLO the closed form tends to there (Theorem 2.1 for N masses), whatever
      // the path just beyond it does
      end.kind = ChainFamilyEnd::GrazingOrbit;
    } else {
      switch (beyond.refusal) {
        case OnePeriodicRefusal::MultipleOfPeriod:
          end.kind = ChainFamilyEnd::GrazingOrbit;
          break;
        case OnePeriodicRefusal::LeavesIntoStop:  // (V through infinity: the energy grows without
                                                  // bound)
          end.kind = ChainFamilyEnd::EnergyLimit;
          break;
        case OnePeriodicRefusal::ReturnsEarly:
          end.kind = ChainFamilyEnd::InteriorGrazing;
          end.refusal = OrbitRefusal::TouchesStop;
          break;
        case OnePeriodicRefusal::NotDecided:
        case OnePeriodicRefusal::SearchBudget:
        case OnePeriodicRefusal::None:  // (admissible in the range up to the scan's neighbour)
          end.kind = ChainFamilyEnd::Undecided;
          end.refusal = OrbitRefusal::Undecided;
          break;
        default:
          end.kind = ChainFamilyEnd::NotConverging;
          break;
      }
    }
    return {inside, end};
  }

  ChainAtlasFamily<S> part(const std::vector<S>& periods, std::size_t first, std::size_t last) {
    const End low =
        endBetween(periods[first], first > 0 ? std::optional<S>(periods[first - 1]) : std::nullopt);
    const End high =
        endBetween(periods[last],
                   last + 1 < periods.size() ? std::optional<S>(periods[last + 1]) : std::nullopt);
    // the rows: the scan's inside the part, and towards each end at distances halving to it
    std::vector<S> rows(periods.begin() + std::ptrdiff_t(first),
                        periods.begin() + std::ptrdiff_t(last) + 1);
    for (int k = 1; k <= 30; ++k) {
      const S step = S(std::ldexp(1.0, -k));
      rows.push_back(low.T + (periods[first] - low.T) * step);
      rows.push_back(high.T - (high.T - periods[last]) * step);
    }
    rows.push_back(low.T);
    rows.push_back(high.T);
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    ChainAtlasFamily<S> family;
    family.birth = ChainBirth::OnePeriodic;
    family.path.impacts = 1;
    std::vector<CensusRow<S>> censuses;
    for (const S& T : rows) {
      if (stop_.stop_requested()) break;
      ChainOnePeriodicStability<S> at = chainOnePeriodicStability(chain_, T);
      if (!at.orbit.admissible() || !inRange(at.orbit.energy)) continue;
      censuses.push_back({T, censusOf(at.orbit.monodromy), at.orbit.monodromy.multipliers});
      family.path.orbits.push_back(std::move(at.orbit));
    }
    const ChainBifurcations<S> changes = chainOnePeriodicBifurcations(chain_, censuses, stop_);
    for (const ChainBifurcation<S>& b : changes.changes) {
      ChainFamilyChange<S> change;
      change.kind = b.kind;
      change.leaves = b.leaves;  // (the rows go the way T grows)
      std::size_t after = 0;
      while (after + 2 < family.path.orbits.size() && family.path.orbits[after + 1].period <= b.T)
        ++after;
      change.after = after;
      change.energy = b.energy;
      change.energyError = b.energyError;
      change.period = b.T;
      change.periodError = b.periodError;
      change.state = data(S(b.T - b.periodError)).postImpact;
      family.path.changes.push_back(std::move(change));
    }
    family.path.unsearched = int(changes.unsearched.size());
    family.path.end = high.end.kind;
    family.path.refusal = high.end.refusal;
    family.firstEnd = low.end;
    family.lastEnd = high.end;
    return family;
  }

  const BasicReadyChain<S>& chain_;
  const ChainAtlasOptions<S>& options_;
  std::stop_token stop_;
  S tMax_;
  int undecidedPeriods_ = 0;
  bool searchBudgetExhausted_ = false;
};

}  // namespace

template <typename S>
ChainAtlas<S> computeChainAtlas(const BasicReadyChain<S>& chain,
                                const ChainAtlasOptions<S>& options, std::stop_token stop,
                                const std::function<void(const ChainAtlasFamily<S>&)>& familyDone) {
  ChainAtlas<S> atlas;
  ChainContinuationOptions<S> continuation;
  continuation.energyLow = options.energyLow;
  continuation.energyHigh = options.energyHigh;
  continuation.maxOrbits = options.maxOrbitsPerFamily;
  const auto finish = [&](ChainAtlasFamily<S>&& family) {
    family.id = int(atlas.families.size());
    family.onePeriod = onePeriodAllAlong(family.path);
    atlas.families.push_back(std::move(family));
    if (familyDone) familyDone(atlas.families.back());
  };

  // the 1IPP family's parts in the range, from its closed form
  if (options.maxImpacts >= 1) {
    OnePeriodicParts<S> scan(chain, options, stop);
    for (ChainAtlasFamily<S>& part : scan.parts()) {
      if (stop.stop_requested()) return atlas;
      if (part.path.orbits.size() >= 2) finish(std::move(part));
    }
    atlas.undecidedPeriods = scan.undecidedPeriods();
    if (scan.searchBudgetExhausted()) {
      atlas.searchBudgetExhausted = true;
      atlas.complete = true;
      return atlas;
    }
    if (stop.stop_requested()) return atlas;
  }

  // every period doubling, in the order the families were found: switched at, or reached
  for (std::size_t f = 0; f < atlas.families.size(); ++f) {
    const int k = atlas.families[f].path.impacts;
    for (std::size_t c = 0; c < atlas.families[f].path.changes.size(); ++c) {
      if (stop.stop_requested()) return atlas;
      const ChainFamilyChange<S> doubling = atlas.families[f].path.changes[c];
      if (doubling.kind != ChainBifurcationKind::PeriodDoubling) continue;
      ChainAtlasBranch branch;
      branch.change = c;
      if (2 * k > options.maxImpacts) {
        branch.outcome = ChainBranchOutcome::BeyondImpacts;
        atlas.families[f].branches.push_back(branch);
        continue;
      }
      // a family of twice the impacts that came back to this doubling
      for (ChainAtlasFamily<S>& other : atlas.families) {
        if (other.path.impacts != 2 * k || other.path.orbits.empty()) continue;
        if (other.lastEnd.family < 0 &&
            comesBackTo(other.lastEnd, other.path.orbits.back(), doubling)) {
          other.lastEnd.family = int(f);
          other.lastEnd.change = int(c);
        } else if (other.firstEnd &&
                   comesBackTo(*other.firstEnd, other.path.orbits.front(), doubling)) {
          other.firstEnd->family = int(f);
          other.firstEnd->change = int(c);
        } else {
          continue;
        }
        branch.outcome = ChainBranchOutcome::Reached;
        branch.family = other.id;
        break;
      }
      if (branch.outcome == ChainBranchOutcome::Reached) {
        atlas.families[f].branches.push_back(branch);
        continue;
      }
      // (the branch's orbit, followed back towards the doubling, meets it within a few orbits)
      using Accept = std::function<bool(const BasicChainPeriodicOrbit<S>&)>;
      const Accept meetsThisDoubling = [&](const BasicChainPeriodicOrbit<S>& orbit) {
        ChainContinuationOptions<S> back = continuation;
        back.maxOrbits = 40;
        const int toward = orbit.energy >= doubling.energy ? -1 : 1;
        const ContinuedChainFamily<S> path = continueChainFamily(chain, orbit, toward, back, stop);
        return path.end == ChainFamilyEnd::MeetsDoubling &&
               comesBackTo(ChainAtlasEnd{path.end, path.refusal, -1, -1}, path.orbits.back(),
                           doubling);
      };
      const ChainOrbitSearch<S> born =
          branchAtDoubling(chain, doubling, k, stop, meetsThisDoubling);
      if (stop.stop_requested()) return atlas;
      if (!born.orbit) {
        branch.problem = born.problem;
        atlas.families[f].branches.push_back(branch);
        continue;
      }
      ChainAtlasFamily<S> child;
      child.birth = ChainBirth::PeriodDoubling;
      child.parent = int(f);
      child.parentChange = int(c);
      const int away = born.orbit->energy >= doubling.energy ? 1 : -1;
      child.path = continueChainFamily(chain, *born.orbit, away, continuation, stop);
      if (stop.stop_requested()) return atlas;
      child.lastEnd = endOf<S>(child.path.end, child.path.refusal);
      branch.outcome = ChainBranchOutcome::Born;
      branch.family = int(atlas.families.size());
      atlas.families[f].branches.push_back(branch);
      finish(std::move(child));
    }
  }
  atlas.complete = true;
  return atlas;
}

template <typename S>
ChainAtlasFamily<S> followChainFamily(const BasicReadyChain<S>& chain, const BasicChainPeriodicOrbit<S>& start,
                                      const ChainContinuationOptions<S>& options, std::stop_token stop) {
  ChainAtlasFamily<S> family;
  family.birth = ChainBirth::GivenOrbit;
  const ContinuedChainFamily<S> down = continueChainFamily(chain, start, -1, options, stop);
  if (stop.stop_requested()) return family;
  ContinuedChainFamily<S> up = continueChainFamily(chain, start, 1, options, stop);
  // down reversed (its first orbit is `start`, which `up` begins with too), then up
  ContinuedChainFamily<S>& path = family.path;
  path.impacts = start.impacts;
  path.orbits.assign(down.orbits.rbegin(), down.orbits.rend());
  const std::size_t shift = path.orbits.empty() ? 0 : path.orbits.size() - 1;
  if (!path.orbits.empty() && !up.orbits.empty()) path.orbits.pop_back();
  for (auto change = down.changes.rbegin(); change != down.changes.rend(); ++change) {
    ChainFamilyChange<S> reversed = *change;
    reversed.after = shift - 1 - change->after;  // (between down[after] and down[after + 1])
    reversed.leaves = !change->leaves;
    path.changes.push_back(reversed);
  }
  for (BasicChainPeriodicOrbit<S>& orbit : up.orbits) path.orbits.push_back(std::move(orbit));
  for (ChainFamilyChange<S> change : up.changes) {
    change.after += shift;
    path.changes.push_back(change);
  }
  path.unsearched = down.unsearched + up.unsearched;
  path.end = up.end;
  path.refusal = up.refusal;
  family.firstEnd = endOf<S>(down.end, down.refusal);
  family.lastEnd = endOf<S>(up.end, up.refusal);
  family.onePeriod = onePeriodAllAlong(family.path);
  return family;
}

#define GRAZELAB_INSTANTIATE(S)                                                                 \
  template ChainAtlasFamily<S> followChainFamily<S>(const BasicReadyChain<S>&, const BasicChainPeriodicOrbit<S>&, \
                                                    const ChainContinuationOptions<S>&, std::stop_token); \
  template AtlasEnergyRange<S> defaultChainAtlasEnergyRange<S>(const BasicReadyChain<S>&); \
  template ChainAtlas<S> computeChainAtlas<S>(                                                  \
      const BasicReadyChain<S>&, const ChainAtlasOptions<S>&, std::stop_token,                  \
      const std::function<void(const ChainAtlasFamily<S>&)>&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)

}  // namespace grazelab::core
