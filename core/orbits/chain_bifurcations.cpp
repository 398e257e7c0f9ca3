// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/chain_bifurcations.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/numbers/eigen_quad.h"
#include "core/orbits/chain_onepp.h"

namespace grazelab::core {

namespace {

// the census of the orbit of period T when admissible (the family goes on there)
template <typename S>
std::optional<MultiplierCensus> censusAt(const BasicReadyChain<S>& chain, const S& T, S* energy = nullptr) {
  const ChainOnePeriodicStability<S> found = chainOnePeriodicStability(chain, T);
  if (found.onePeriodic != OnePeriodicRefusal::None || !found.orbit.admissible()) return std::nullopt;
  if (energy) *energy = found.orbit.energy;
  return censusOf(found.orbit.monodromy);
}

// the same from the closed form alone (V < 0; the flight is not searched, the path not run): what
// a bisection between two admissible orbits asks at each step. The point found is checked in
// full; a change inside a stretch where the flight meets the stop early is dropped with it.
template <typename S>
std::optional<MultiplierCensus> closedFormCensusAt(const BasicReadyChain<S>& chain, const S& T) {
  const BasicChainOnePeriodicOrbit<S> data = chainOnePeriodicOrbitIn<S>(chain.numbers, chain.dynamics, T, false);
  if (!data.admissible()) return std::nullopt;
  return censusOf(chainOnePeriodicMonodromy(chain, data.postImpact, T));
}

template <typename S>
ChainBifurcation<S> named(const MultiplierCensus& below, const MultiplierCensus& above) {
  const int negative = above.negative - below.negative;
  const int positive = above.positive - below.positive;
  const int complex = above.complex - below.complex;
  ChainBifurcation<S> point;
  const int moved = (negative != 0) + (positive != 0) + (complex != 0);
  if (moved == 1) {
    point.kind = negative != 0 ? ChainBifurcationKind::PeriodDoubling
                 : positive != 0 ? ChainBifurcationKind::Fold
                                 : ChainBifurcationKind::KreinCollision;
  }
  point.leaves = above.onCircle < below.onCircle;
  return point;
}

// The changes between a (census ca) and b (census cb != ca), both admissible and decided.
template <typename S>
void locate(const BasicReadyChain<S>& chain, S a, MultiplierCensus ca, S b, MultiplierCensus cb,
            std::vector<ChainBifurcation<S>>& out, const std::stop_token& stop, int depth = 0) {
  using std::abs;
  // to 1e-12 of T (the 1e-9 with room; 8 ulps of double are below it)
  const S resolution = std::max<S>(8 * std::numeric_limits<S>::epsilon(), S(1e-12));
  S energy = 0;
  while (b - a > resolution * abs(b) && !stop.stop_requested()) {
    const S middle = (a + b) / 2;
    const std::optional<MultiplierCensus> cm = closedFormCensusAt(chain, middle);
    if (!cm) return;  // the family's part ends in between
    if (!cm->decided) break;
    // (an end moved takes the middle's census: the change is named from the last bracket)
    if (cm->onCircle == ca.onCircle) {
      a = middle;
      ca = *cm;
    } else if (cm->onCircle == cb.onCircle) {
      b = middle;
      cb = *cm;
    } else {
      // a third census: two changes in between, each on its side
      if (depth < 16) {
        locate(chain, a, ca, middle, *cm, out, stop, depth + 1);
        locate(chain, middle, *cm, b, cb, out, stop, depth + 1);
      }
      return;
    }
  }
  ChainBifurcation<S> point = named<S>(ca, cb);
  point.T = (a + b) / 2;
  point.periodError = (b - a) / 2;
  if (!censusAt(chain, point.T, &energy)) return;
  point.energy = energy;
  out.push_back(point);
}

}  // namespace

template <typename S>
MultiplierCensus censusOf(const ChainMonodromy<S>& monodromy) {
  using std::abs;
  MultiplierCensus census;
  census.decided = monodromy.stability != ChainStability::Undecided;
  for (const ChainMultiplier<S>& m : monodromy.multipliers) {
    if (m.onCircle) {
      ++census.onCircle;
    } else if (abs(m.im) > m.error) {
      ++census.complex;
    } else if (m.re > 0) {
      ++census.positive;
    } else {
      ++census.negative;
    }
  }
  return census;
}

std::string_view toString(ChainBifurcationKind kind) {
  switch (kind) {
    case ChainBifurcationKind::PeriodDoubling: return "period-doubling";
    case ChainBifurcationKind::Fold: return "fold";
    case ChainBifurcationKind::KreinCollision: return "krein-collision";
    case ChainBifurcationKind::Other: return "other";
  }
  return "other";
}

template <typename S>
std::vector<ChainBifurcation<S>> chainOnePeriodicBifurcations(const BasicReadyChain<S>& chain,
                                                              const std::vector<CensusRow<S>>& rows,
                                                              std::stop_token stop) {
  std::vector<ChainBifurcation<S>> out;
  const CensusRow<S>* before = nullptr;
  for (const CensusRow<S>& row : rows) {
    if (stop.stop_requested()) break;
    const std::optional<MultiplierCensus>& here = row.census;
    // (multipliers that move off the circle among themselves, a quadruplet meeting the real
    // axis as two real pairs, change no stability: only the count on the circle is followed)
    if (before && here && here->decided && before->census->onCircle != here->onCircle) {
      locate(chain, before->T, *before->census, row.T, *here, out, stop);
    }
    // an undecided or inadmissible orbit breaks the chain of neighbours
    before = here && here->decided ? &row : nullptr;
  }
  return out;
}

template <typename S>
std::vector<ChainBifurcation<S>> chainOnePeriodicBifurcations(const BasicReadyChain<S>& chain,
                                                              const std::vector<S>& periods, std::stop_token stop) {
  std::vector<CensusRow<S>> rows;
  for (const S& T : periods) {
    if (stop.stop_requested()) break;
    rows.push_back({T, censusAt(chain, T)});
  }
  return chainOnePeriodicBifurcations(chain, rows, stop);
}

#define GRAZELAB_CHAIN_BIFURCATIONS(S)                                                             \
  template MultiplierCensus censusOf<S>(const ChainMonodromy<S>&);                                 \
  template std::vector<ChainBifurcation<S>> chainOnePeriodicBifurcations<S>(const BasicReadyChain<S>&, \
                                                                            const std::vector<S>&, std::stop_token); \
  template std::vector<ChainBifurcation<S>> chainOnePeriodicBifurcations<S>(                       \
      const BasicReadyChain<S>&, const std::vector<CensusRow<S>>&, std::stop_token);
GRAZELAB_CHAIN_BIFURCATIONS(double)
GRAZELAB_CHAIN_BIFURCATIONS(long double)
GRAZELAB_CHAIN_BIFURCATIONS(Quad)
#undef GRAZELAB_CHAIN_BIFURCATIONS

}  // namespace grazelab::core
