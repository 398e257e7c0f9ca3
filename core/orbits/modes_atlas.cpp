// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/modes_atlas.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/orbits/special_orbits.h"
#include "core/numbers/roots.h"

namespace grazelab::core {

std::string_view toString(Birth birth) {
  return birth == Birth::OnePeriodic ? "one-periodic" : "period-doubling";
}

namespace {

// The energy range asked for. A special point computed at its edge (0.7 given,
// 0.70000000000000007 located) belongs to it: points are held within a hair of 1e4 ulps.
template <typename S>
struct EnergyRange {
  S low;
  S high;
  bool holds(const S& energy) const { return energy >= low && energy <= high; }
  bool holdsPoint(const S& energy) const {
    const S hair = S(1e4) * epsilon<S>();
    return energy >= low * (S(1) - hair) && energy <= high * (S(1) + hair);
  }
};

// The 1IPP family's parts inside the range, from its closed-form scan: each admissible part
// (between two of its ends) cut where its energy leaves the range (located by bisection in T),
// each piece a family from its low-energy end, with the special points inside it.
template <typename S>
std::vector<ModeFamily<S>> onePeriodicFamilies(const TwoMassForm<S>& chain, const OnePeriodicScan<S>& scan,
                                               const EnergyRange<S>& range, std::stop_token stop) {
  using std::abs;
  const auto orbitAt = [&](const S& T) { return onePeriodicOrbitStability(chain, T).orbit; };
  const auto isEnd = [](PointKind kind) {
    return kind != PointKind::PeriodDoubling && kind != PointKind::Fold && kind != PointKind::BranchPoint;
  };
  // every orbit the scan has, with the special points' own orbits, in increasing T, with the
  // ends that bound the parts
  struct Row {
    PeriodicOrbit<S> orbit;
    std::optional<FamilyBifurcation<S>> point;
  };
  std::vector<Row> rows;
  for (const PeriodicOrbit<S>& orbit : scan.orbits) rows.push_back({orbit, std::nullopt});
  for (const FamilyBifurcation<S>& point : scan.points) {
    if (point.kind == PointKind::GrazingOrbit) continue;  // the limit at T2 is no orbit of the family
    // the located orbit itself (the closed form at its period need not give it again: near T1
    // the period of a polished orbit is not the one asked for)
    PeriodicOrbit<S> orbit = evaluateOrbit(chain, point.state, 1, std::numeric_limits<S>::infinity());
    if (orbit.admissible) rows.push_back({std::move(orbit), point});
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.orbit.period < b.orbit.period; });

  std::vector<ModeFamily<S>> families;
  std::optional<ModeFamily<S>> open;  // the piece being built, in increasing T
  const auto close = [&](FamilyEnd<S> end) {
    if (!open) return;
    open->end = std::move(end);
    if (open->orbits.size() >= 2) {
      // from the low-energy end
      if (open->orbits.front().energy > open->orbits.back().energy) {
        std::reverse(open->orbits.begin(), open->orbits.end());
        std::reverse(open->bifurcations.begin(), open->bifurcations.end());
        std::swap(open->startEnd, open->end);
      }
      // the orbit nearest the piece's middle names it
      const FamilyOrbit<S>& middle = open->orbits[open->orbits.size() / 2];
      open->bornEnergy = middle.energy;
      open->bornPeriod = middle.period;
      families.push_back(std::move(*open));
    }
    open.reset();
  };
  const auto begin = [&](FamilyEnd<S> start) {
    open.emplace();
    open->impacts = 1;
    open->birth = Birth::OnePeriodic;
    open->startEnd = std::move(start);
  };
  // the orbit where the energy crosses `level` between two rows (one in the range, one not)
  const auto crossingAt = [&](const PeriodicOrbit<S>& inside, const PeriodicOrbit<S>& outside, const S& level) {
    const bool insideBelow = inside.energy < level;
    const S T = bisectBoundary(
        inside.period, outside.period,
        [&](const S& t) {
          const std::optional<PeriodicOrbit<S>> o = orbitAt(t);
          return o && (o->energy < level) == insideBelow;
        },
        [&] { return stop.stop_requested(); });
    return orbitAt(T);
  };
  const PeriodicOrbit<S>* previous = nullptr;
  bool previousEnded = true;  // a part's end lies between the previous row and this one
  bool previousIn = false;
  bool previousOnEdge = false;
  for (const Row& row : rows) {
    if (stop.stop_requested()) return {};
    const PeriodicOrbit<S>& orbit = row.orbit;
    const bool partStarts = previousEnded;
    // a special point a hair outside the range lies on its edge: the piece ends or begins there
    const bool onEdge = row.point && !range.holds(orbit.energy) && range.holdsPoint(orbit.energy);
    const bool in = range.holds(orbit.energy) || onEdge;
    if (!partStarts && previousIn != in && !onEdge && !previousOnEdge) {
      // the energy leaves or enters the range between the two rows
      const S level = (previousIn ? orbit.energy : previous->energy) > range.high ? range.high : range.low;
      const std::optional<PeriodicOrbit<S>> edge =
          previousIn ? crossingAt(*previous, orbit, level) : crossingAt(orbit, *previous, level);
      if (edge && previousIn) {
        if (open && edge->period != previous->period) open->orbits.push_back(summaryOf(*edge));
        close(familyEndAt(PointKind::EnergyLimit, *edge));
      } else if (edge) {
        begin(familyEndAt(PointKind::EnergyLimit, *edge));
        if (edge->period != orbit.period) open->orbits.push_back(summaryOf(*edge));
      }
    } else if (!partStarts && previousIn != in && !onEdge && open) {
      close(familyEndAt(PointKind::EnergyLimit, *previous));  // left the range at a point on its edge
    }
    if (in) {
      if (!open) {
        // a part that starts here: at one of its ends, on the range's edge, or (its first
        // sample) where the scan began
        const bool atEnd = row.point && isEnd(row.point->kind);
        begin(familyEndAt(atEnd ? row.point->kind : PointKind::EnergyLimit, orbit));
      }
      open->orbits.push_back(summaryOf(orbit));
      if (row.point && !isEnd(row.point->kind)) open->bifurcations.push_back(*row.point);
    }
    // an end point closes its part when the part started before it
    previousEnded = false;
    if (row.point && isEnd(row.point->kind) && !partStarts) {
      if (open) close(familyEndAt(row.point->kind, orbit));
      previousEnded = true;
    }
    previous = &orbit;
    previousIn = in;
    previousOnEdge = onEdge;
  }
  // the last part ends on its grazing orbit at T2 (the scan's last point) when it reaches there
  if (open) {
    FamilyEnd<S> end = familyEndAt(PointKind::EnergyLimit, *previous);
    if (!scan.points.empty() && scan.points.back().kind == PointKind::GrazingOrbit && range.holdsPoint(scan.points.back().energy)) {
      const FamilyBifurcation<S>& limit = scan.points.back();
      end.kind = PointKind::GrazingOrbit;
      end.energy = limit.energy;
      end.period = limit.T;
      end.state = limit.state;
      end.gloLambda = lambdaStar(chain);
      end.exact = true;
    }
    close(std::move(end));
  }
  for (ModeFamily<S>& family : families) {
    // a part whose period tends to T1 while S cannot decide its last orbits: its data tend to
    // GLOM1 (cot(w1 T / 2) grows without bound: u1 -> d rho_fast, V -> 0), its limit is known
    for (FamilyEnd<S>* end : {&family.end, &family.startEnd}) {
      if (end->kind != PointKind::Undecided) continue;
      FamilyEnd<S> named = *end;
      named.gloLambda = (end->state.u1 / chain.model.gap - chain.rhoFast) / (chain.rhoSlow - chain.rhoFast);
      nameGrazingEnd(chain, 1, named);
      if (named.exact) {
        named.kind = PointKind::GrazingOrbit;
        *end = named;
      }
    }
    family.symmetry = orbitSymmetry(evaluateOrbit(chain, family.orbits[family.orbits.size() / 2].state, 1,
                                                  std::numeric_limits<S>::infinity()),
                                    symmetryTolerance<S>());
  }
  return families;
}

// How far the energy may move off a flip when looking for the family born there (the family's
// other special points and its ends bound it).
template <typename S>
double birthOffsetBound(const ModeFamily<S>& family, const FamilyBifurcation<S>& flip, const EnergyRange<S>& range) {
  using std::abs;
  std::vector<S> energies;
  // the range's edges are no special points, but the family born is looked for inside it
  for (const FamilyEnd<S>* end : {&family.end, &family.startEnd}) {
    if (end->kind != PointKind::EnergyLimit) energies.push_back(end->energy);
  }
  for (const FamilyBifurcation<S>& other : family.bifurcations) energies.push_back(other.energy);
  double bound = birthOffsetBound(flip, energies);
  for (const S& edge : {range.low, range.high}) {
    const double distance = toDouble(S(abs(edge - flip.energy) / flip.energy));
    // a flip at the range's very edge: its family is still looked for a little way off it
    if (distance > 1e-7) bound = std::min(bound, distance);
  }
  return bound;
}

// The flip of a k-impact family that a 2k-impact family's PeriodDoubling end meets: the flip
// whose orbit is nearest the end's state (within 5 % of the gap and of w2 times the gap).
template <typename S>
std::optional<std::pair<int, std::size_t>> flipMet(const TwoMassForm<S>& chain, const std::vector<ModeFamily<S>>& families,
                                                   const FamilyEnd<S>& end, int impacts) {
  using std::abs;
  const S d = chain.model.gap;
  const S speed = d * chain.omegaSlow;
  std::optional<std::pair<int, std::size_t>> best;
  S bestDistance = S(0.05);
  for (const ModeFamily<S>& family : families) {
    if (2 * family.impacts != impacts) continue;
    for (std::size_t i = 0; i < family.bifurcations.size(); ++i) {
      const FamilyBifurcation<S>& flip = family.bifurcations[i];
      if (flip.kind != PointKind::PeriodDoubling) continue;
      const S distance = std::max(abs(flip.state.u1 - end.state.u1) / d, abs(flip.state.v1 - end.state.v1) / speed);
      // the end may be at the flip's orbit or at its image half a period later: compare both
      if (distance < bestDistance) {
        bestDistance = distance;
        best = {family.id, i};
      }
    }
  }
  return best;
}

}  // namespace

template <typename S>
ModesAtlas<S> computeModesAtlas(const TwoMassForm<S>& chain, int maxImpacts, const S& energyLow,
                                const S& energyHigh, std::stop_token stop,
                                const std::function<void(const ModeFamily<S>&)>& familyDone) {
  ModesAtlas<S> atlas;
  const EnergyRange<S> range{energyLow, energyHigh};
  ContinuationOptions<S> options;
  options.energyLow = range.low;
  options.energyHigh = range.high;
  const auto finished = [&](ModeFamily<S> family) {
    family.id = int(atlas.families.size());
    atlas.families.push_back(std::move(family));
    if (familyDone) familyDone(atlas.families.back());
  };
  // the 1IPP family from its closed form
  const OnePeriodicScan<S> scan = scanOnePeriodicFamily(chain, 400, stop);
  if (!scan.complete) return atlas;
  for (ModeFamily<S>& family : onePeriodicFamilies(chain, scan, range, stop)) finished(std::move(family));
  if (stop.stop_requested()) return atlas;
  // the families born at flips, breadth first, while their impacts stay within the bound
  for (std::size_t next = 0; next < atlas.families.size(); ++next) {
    if (stop.stop_requested()) return atlas;
    const int impacts = atlas.families[next].impacts;
    if (2 * impacts > maxImpacts) continue;
    for (std::size_t i = 0; i < atlas.families[next].bifurcations.size(); ++i) {
      if (stop.stop_requested()) return atlas;
      const FamilyBifurcation<S> flip = atlas.families[next].bifurcations[i];
      if (flip.kind != PointKind::PeriodDoubling || !range.holdsPoint(flip.energy)) continue;
      if (flip.born >= 0) continue;  // a family already found comes back here
      const FlipSwitch<S> born =
          switchAtFlip(chain, flip, impacts, birthOffsetBound(atlas.families[next], flip, range), stop);
      if (stop.stop_requested()) return atlas;
      if (!born.search.orbit) {
        atlas.families[next].bifurcations[i].birthProblem = born.search.problem;
        continue;
      }
      const ContinuedFamily<S> continued =
          continueFamily(chain, *born.search.orbit, born.side == Side::Below ? -1 : +1, options, stop);
      if (stop.stop_requested()) return atlas;
      ModeFamily<S> family;
      family.id = int(atlas.families.size());
      family.impacts = 2 * impacts;
      family.symmetry = orbitSymmetry(*born.search.orbit, symmetryTolerance<S>());
      family.birth = Birth::PeriodDoubling;
      family.parent = int(next);
      family.bornEnergy = flip.energy;
      family.bornPeriod = flip.T;
      family.side = born.side;
      family.orbits = continued.orbits;
      family.bifurcations = continued.bifurcations;
      family.end = continued.end;
      family.startEnd.kind = PointKind::PeriodDoubling;
      family.startEnd.energy = flip.energy;
      family.startEnd.period = S(2) * flip.T;
      family.startEnd.state = flip.state;
      family.startEnd.lastEnergy = flip.energy;
      family.startEnd.exact = true;
      family.startEnd.family = int(next);
      atlas.families[next].bifurcations[i].born = family.id;
      if (family.end.kind == PointKind::PeriodDoubling) {
        // it comes back to a flip: that flip's own family is this one, and the end is the
        // flip's orbit run twice
        if (const auto met = flipMet(chain, atlas.families, family.end, family.impacts)) {
          FamilyBifurcation<S>& other = atlas.families[std::size_t(met->first)].bifurcations[met->second];
          if (other.born < 0) other.born = family.id;
          family.end.energy = other.energy;
          family.end.period = S(2) * other.T;
          family.end.state = other.state;
          family.end.exact = true;
          family.end.family = met->first;
        }
      }
      finished(std::move(family));
    }
  }
  atlas.complete = true;
  return atlas;
}

template <typename S>
AtlasEnergyRange<S> defaultAtlasEnergyRange(const TwoMassForm<S>& chain) {
  const S grazing = physicalEnergy(chain, gloData(chain, lambdaStar(chain)));
  return {grazing / S(100), grazing * S(10000)};
}

template <typename S>
std::optional<int> impactsOfAtlasOrbit(const ModesAtlas<S>& atlas, const BasicState<S>& state) {
  for (const ModeFamily<S>& family : atlas.families) {
    for (const FamilyOrbit<S>& orbit : family.orbits) {
      const BasicState<S>& x = orbit.state;
      if (x.u1 == state.u1 && x.u2 == state.u2 && x.v1 == state.v1 && x.v2 == state.v2) return family.impacts;
    }
  }
  return std::nullopt;
}

#define GRAZELAB_INSTANTIATE(S)                                                                  \
  template AtlasEnergyRange<S> defaultAtlasEnergyRange<S>(const TwoMassForm<S>&);                       \
  template std::optional<int> impactsOfAtlasOrbit<S>(const ModesAtlas<S>&, const BasicState<S>&); \
  template ModesAtlas<S> computeModesAtlas<S>(const TwoMassForm<S>&, int, const S&, const S&,          \
                                              std::stop_token,                                   \
                                              const std::function<void(const ModeFamily<S>&)>&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
