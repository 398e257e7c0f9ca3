// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/nonlinear_modes.h"

#include <algorithm>
#include <deque>

namespace grazelab::core {

namespace {

// The periods at the middle of each admissible run of the 1IPP closed form over (0, T2),
// sampled at T2 i / (samples + 1).
template <typename S>
std::vector<S> onePeriodicPartMiddles(const Chain<S>& chain, int samples, std::stop_token stop) {
  const S T2 = twoPi<S>() / chain.omegaSlow;
  std::vector<S> middles;
  int first = -1;
  for (int i = 1; i <= samples + 1; ++i) {
    if (stop.stop_requested()) return {};
    const bool admissible = i <= samples && onePeriodicOrbitStability(chain, S(T2 * S(i) / S(samples + 1))).orbit;
    if (admissible && first < 0) first = i;
    if (!admissible && first >= 0) {
      middles.push_back(T2 * S(first + i - 1) / S(2 * (samples + 1)));
      first = -1;
    }
  }
  return middles;
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
  // every admissible part of the 1IPP family, from its middle both ways in energy
  for (const S& T : onePeriodicPartMiddles(chain, 400, stop)) {
    const OrbitSearch<S> middle = onePeriodicOrbitStability(chain, T);
    if (!middle.orbit) continue;
    if (!(middle.orbit->energy >= energyLow && middle.orbit->energy <= energyHigh)) continue;
    const ContinuedFamily<S> down = continueFamily(chain, *middle.orbit, -1, options, stop);
    const ContinuedFamily<S> up = continueFamily(chain, *middle.orbit, +1, options, stop);
    if (stop.stop_requested()) return atlas;
    ModeFamily<S> family;
    family.impacts = 1;
    family.symmetry = orbitSymmetry(*middle.orbit, S(1e-9));
    family.bornKind = "one-periodic";
    family.bornEnergy = middle.orbit->energy;
    family.bornPeriod = T;
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
