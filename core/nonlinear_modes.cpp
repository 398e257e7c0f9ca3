// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/nonlinear_modes.h"

#include <algorithm>
#include <optional>

namespace grazelab::core {

namespace {

// For each admissible run of the 1IPP closed form over (0, T2) (sampled at T2 i / (samples +
// 1)) that reaches into [energyLow, energyHigh]: an orbit of it inside that range, the one
// nearest the run's middle, to start the family's continuation from. A run whose samples all
// lie outside the range but straddle it gives the orbit where its energy crosses the range's
// geometric middle (by bisection in T).
template <typename S>
std::vector<PeriodicOrbit<S>> onePeriodicStarts(const Chain<S>& chain, int samples, const S& energyLow,
                                                const S& energyHigh, std::stop_token stop) {
  using std::abs;
  using std::sqrt;
  const S T2 = twoPi<S>() / chain.omegaSlow;
  std::vector<PeriodicOrbit<S>> starts;
  std::vector<PeriodicOrbit<S>> run;
  const auto inRange = [&](const PeriodicOrbit<S>& o) { return o.energy >= energyLow && o.energy <= energyHigh; };
  const auto closeRun = [&] {
    if (run.empty()) return;
    const std::size_t middle = run.size() / 2;
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < run.size(); ++i) {
      if (!inRange(run[i])) continue;
      const auto distance = [&](std::size_t j) { return j > middle ? j - middle : middle - j; };
      if (!best || distance(i) < distance(*best)) best = i;
    }
    if (best) {
      starts.push_back(run[*best]);
    } else {
      const S target = sqrt(energyLow * energyHigh);
      for (std::size_t i = 0; i + 1 < run.size(); ++i) {
        if ((run[i].energy < target) == (run[i + 1].energy < target)) continue;
        S low = run[i].period, high = run[i + 1].period;
        const bool lowBelow = run[i].energy < target;
        for (int step = 0; step < 200; ++step) {
          const S mid = (low + high) / S(2);
          if (mid == low || mid == high) break;
          const OrbitSearch<S> o = onePeriodicOrbitStability(chain, mid);
          if (!o.orbit) break;
          if ((o.orbit->energy < target) == lowBelow) low = mid;
          else high = mid;
        }
        const OrbitSearch<S> o = onePeriodicOrbitStability(chain, low);
        if (o.orbit && inRange(*o.orbit)) starts.push_back(*o.orbit);
        break;
      }
    }
    run.clear();
  };
  for (int i = 1; i <= samples; ++i) {
    if (stop.stop_requested()) return {};
    OrbitSearch<S> found = onePeriodicOrbitStability(chain, S(T2 * S(i) / S(samples + 1)));
    if (found.orbit) run.push_back(std::move(*found.orbit));
    else closeRun();
  }
  closeRun();
  return starts;
}

}  // namespace

template <typename S>
ModesAtlas<S> computeModesAtlas(const Chain<S>& chain, int maxImpacts, const S& energyLow,
                                const S& energyHigh, std::stop_token stop,
                                const std::function<void(const ModeFamily<S>&)>& familyDone) {
  ModesAtlas<S> atlas;
  ContinuationOptions<S> options;
  options.energyLow = energyLow;
  options.energyHigh = energyHigh;
  const auto finished = [&](ModeFamily<S> family) {
    family.id = int(atlas.families.size());
    atlas.families.push_back(std::move(family));
    if (familyDone) familyDone(atlas.families.back());
  };
  // every admissible part of the 1IPP family that reaches into the energy range, from an orbit
  // of it in the range both ways in energy
  for (const PeriodicOrbit<S>& middle : onePeriodicStarts(chain, 400, energyLow, energyHigh, stop)) {
    const ContinuedFamily<S> down = continueFamily(chain, middle, -1, options, stop);
    const ContinuedFamily<S> up = continueFamily(chain, middle, +1, options, stop);
    if (stop.stop_requested()) return atlas;
    ModeFamily<S> family;
    family.impacts = 1;
    family.symmetry = orbitSymmetry(middle, S(1e-9));
    family.bornKind = "one-periodic";
    family.bornEnergy = middle.energy;
    family.bornPeriod = middle.period;
    // one curve from the low end to the high end (the middle once)
    family.orbits.assign(down.orbits.rbegin(), down.orbits.rend());
    family.orbits.insert(family.orbits.end(), up.orbits.begin() + 1, up.orbits.end());
    family.bifurcations.assign(down.bifurcations.rbegin(), down.bifurcations.rend());
    family.bifurcations.insert(family.bifurcations.end(), up.bifurcations.begin(), up.bifurcations.end());
    family.startEnd = down.end;
    family.end = up.end;
    finished(std::move(family));
  }
  // the families born at flips, breadth first, while their impacts stay within the bound
  for (std::size_t next = 0; next < atlas.families.size(); ++next) {
    if (stop.stop_requested()) return atlas;
    const int impacts = atlas.families[next].impacts;
    if (2 * impacts > maxImpacts) continue;
    const std::vector<FamilyBifurcation<S>> flips = atlas.families[next].bifurcations;
    for (const FamilyBifurcation<S>& flip : flips) {
      if (flip.kind != "period-doubling") continue;
      if (!(flip.energy >= energyLow && flip.energy <= energyHigh)) continue;  // born outside the range
      const FlipSwitch<S> born = switchAtFlip(chain, flip, impacts, stop);
      if (stop.stop_requested()) return atlas;
      if (!born.search.orbit) continue;
      const ContinuedFamily<S> continued =
          continueFamily(chain, *born.search.orbit, born.side == "below" ? -1 : +1, options, stop);
      if (stop.stop_requested()) return atlas;
      ModeFamily<S> family;
      family.impacts = 2 * impacts;
      family.symmetry = orbitSymmetry(*born.search.orbit, S(1e-9));
      family.bornKind = "period-doubling";
      family.parent = int(next);
      family.bornEnergy = flip.energy;
      family.bornPeriod = flip.T;
      family.side = born.side;
      family.orbits = continued.orbits;
      family.bifurcations = continued.bifurcations;
      family.end = continued.end;
      family.startEnd = {"period-doubling", flip.energy, S(2) * flip.T, flip.state};
      finished(std::move(family));
    }
  }
  atlas.complete = true;
  return atlas;
}

#define GRAZELAB_INSTANTIATE(S)                                                                  \
  template ModesAtlas<S> computeModesAtlas<S>(const Chain<S>&, int, const S&, const S&,          \
                                              std::stop_token,                                   \
                                              const std::function<void(const ModeFamily<S>&)>&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
