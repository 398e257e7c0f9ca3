// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/chain_bifurcations.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>

#include "core/numbers/eigen_quad.h"
#include "core/orbits/chain_onepp.h"

namespace grazelab::core {

namespace {

// the row of the orbit of period T: its census and multipliers when admissible (the family goes
// on there)
template <typename S>
CensusRow<S> rowAt(const BasicReadyChain<S>& chain, const S& T, S* energy = nullptr) {
  const ChainOnePeriodicStability<S> found = chainOnePeriodicStability(chain, T);
  if (found.onePeriodic != OnePeriodicRefusal::None || !found.orbit.admissible()) return {T, std::nullopt, {}};
  if (energy) *energy = found.orbit.energy;
  return {T, censusOf(found.orbit.monodromy), found.orbit.monodromy.multipliers};
}

template <typename S>
std::optional<MultiplierCensus> censusAt(const BasicReadyChain<S>& chain, const S& T, S* energy = nullptr) {
  return rowAt(chain, T, energy).census;
}

// Whether a multiplier of `at` is nearer a change of the census than four times what it and the
// one it would meet moved between the rows (`moved`, by multiplier): on the circle, to its
// conjugate (a collision at +-1) and to one of the other Krein signature; off it, complex, to the
// circle; real, to +-1.
template <typename S>
bool nearAChange(const std::vector<ChainMultiplier<S>>& at, const std::vector<S>& moved) {
  using std::abs;
  for (std::size_t i = 0; i < at.size(); ++i) {
    const ChainMultiplier<S>& x = at[i];
    const std::complex<S> lx(x.re, x.im);
    if (!x.onCircle) {
      const S margin = abs(x.im) > x.error ? S(abs(abs(lx) - 1)) : S(std::min(abs(x.re - 1), abs(x.re + 1)));
      if (margin <= 4 * moved[i]) return true;
      continue;
    }
    // (its conjugate moves as it does)
    if (2 * abs(x.im) <= 8 * moved[i]) return true;
    for (std::size_t j = i + 1; j < at.size(); ++j) {
      const ChainMultiplier<S>& y = at[j];
      if (!y.onCircle || (x.krein != 0 && x.krein == y.krein)) continue;
      if (abs(lx - std::complex<S>(y.re, y.im)) <= 4 * (moved[i] + moved[j])) return true;
    }
  }
  return false;
}

// Whether two changes that undo each other could hide between rows a and b of one census: a
// multiplier at either end nearer a change than four times what moved in between (matched by their
// order, by angle: a reordering only overstates the motion). The margin is each multiplier's own:
// a fast one far from any change does not refine where a slow one sits near -1.
template <typename S>
bool mayHideAPair(const CensusRow<S>& a, const CensusRow<S>& b) {
  return core::mayHideAPair(a.multipliers, b.multipliers);
}

// the same from the closed form alone (V < 0; the flight is not searched, the path not run): what
// a bisection between two admissible orbits asks at each step. The point found is checked in
// full; a change inside a stretch where the flight meets the stop early is dropped with it.
template <typename S>
CensusRow<S> closedFormRowAt(const BasicReadyChain<S>& chain, const S& T) {
  const BasicChainOnePeriodicOrbit<S> data = chainOnePeriodicOrbitIn<S>(chain.numbers, chain.dynamics, T, false);
  if (!data.admissible()) return {T, std::nullopt, {}};
  const ChainMonodromy<S> monodromy = chainOnePeriodicMonodromy(chain, data.postImpact, T);
  return {T, censusOf(monodromy), monodromy.multipliers};
}

template <typename S>
ChainBifurcation<S> named(const MultiplierCensus& below, const MultiplierCensus& above) {
  ChainBifurcation<S> point;
  point.kind = changeKind(below, above);
  point.leaves = above.onCircle < below.onCircle;
  return point;
}

// Whether (a, b) holds a multiple of the period of a mode that moves the stopped mass: a pole of
// sigma = 2 m_s sum_j w_j P[s][j]^2 cot(w_j T / 2). Between its poles sigma falls monotonically and
// the flight's matrix moves by w_max dT, so the multipliers move with the rows; next to one they
// sweep across the plane faster than any rows follow.
template <typename S>
bool holdsAPole(const BasicChainDynamics<S>& dynamics, const S& a, const S& b) {
  using std::ceil;
  for (Eigen::Index j = 0; j < dynamics.omega.size(); ++j) {
    if (!(dynamics.omega[j] > 0) || dynamics.nodeAtStop[std::size_t(j)]) continue;
    const S period = twoPi<S>() / dynamics.omega[j];
    if (ceil(a / period) * period < b) return true;
  }
  return false;
}

template <typename S>
void between(const BasicReadyChain<S>& chain, const CensusRow<S>& a, const CensusRow<S>& b,
             ChainBifurcations<S>& out, const std::stop_token& stop, int& budget);

// The changes between rows a and b, both admissible and decided, whose counts on the circle
// differ: bisection on the count; each half it leaves behind (of one count with its end) is
// looked at for a pair hidden in it (`between`).
template <typename S>
void locate(const BasicReadyChain<S>& chain, CensusRow<S> a, CensusRow<S> b, ChainBifurcations<S>& out,
            const std::stop_token& stop, int& budget) {
  using std::abs;
  // to 8 ulps of T, or where the middle is undecided (the census then cannot say more)
  const S resolution = 8 * std::numeric_limits<S>::epsilon();
  S energy = 0;
  while (b.T - a.T > resolution * abs(b.T) && !stop.stop_requested()) {
    const CensusRow<S> middle = closedFormRowAt(chain, S((a.T + b.T) / 2));
    if (!middle.census) return;  // the family's part ends in between
    if (!middle.census->decided) break;
    // (an end moved takes the middle's census: the change is named from the last bracket)
    // (the halves within 1e-6 of T of the change are left: there the change's own pair, ever
    // nearer it, would keep them halving to the end of the budget)
    const bool wide = b.T - a.T > S(2e-6) * abs(b.T);
    if (middle.census->onCircle == a.census->onCircle) {
      if (wide) between(chain, a, middle, out, stop, budget);
      a = middle;
    } else if (middle.census->onCircle == b.census->onCircle) {
      if (wide) between(chain, middle, b, out, stop, budget);
      b = middle;
    } else {
      // a third census: changes on both sides
      locate(chain, a, middle, out, stop, budget);
      locate(chain, middle, b, out, stop, budget);
      return;
    }
  }
  ChainBifurcation<S> point = named<S>(*a.census, *b.census);
  point.T = (a.T + b.T) / 2;
  point.periodError = (b.T - a.T) / 2;
  if (!censusAt(chain, point.T, &energy)) return;
  point.energy = energy;
  // the energy over the bracket (the closed form's, at its ends) and its rounding
  const auto energyAt = [&chain](const S& T) {
    return chainOnePeriodicOrbitIn<S>(chain.numbers, chain.dynamics, T, false).energy;
  };
  // (the data's cotangents lose digits like x / sin x near a multiple of a mode's period)
  S conditioning = 1;
  for (Eigen::Index j = 0; j < chain.dynamics.omega.size(); ++j) {
    using std::sin;
    if (!(chain.dynamics.omega[j] > 0) || chain.dynamics.nodeAtStop[std::size_t(j)]) continue;
    const S x = chain.dynamics.omega[j] * point.T / 2;
    conditioning = std::max<S>(conditioning, abs(x / sin(x)));
  }
  point.energyError = abs(energyAt(b.T) - energyAt(a.T)) / 2 +
                      8 * std::numeric_limits<S>::epsilon() * conditioning * abs(energy);
  out.changes.push_back(point);
}

// The changes between rows a and b (both admissible and decided): located where their counts on
// the circle differ, else looked for in halves while a pair of changes could hide in between.
// (`budget`: the orbits the halving may still compute between two neighbouring rows; a multiplier
// that stays within rounding of a change over a long stretch would otherwise halve it to the end)
template <typename S>
void between(const BasicReadyChain<S>& chain, const CensusRow<S>& a, const CensusRow<S>& b,
             ChainBifurcations<S>& out, const std::stop_token& stop, int& budget) {
  using std::abs;
  if (a.census->onCircle != b.census->onCircle) {
    locate(chain, a, b, out, stop, budget);
    return;
  }
  if (stop.stop_requested() || b.T - a.T <= S(1e-9) * abs(b.T)) return;
  if (!mayHideAPair(a, b) && !holdsAPole(chain.dynamics, a.T, b.T)) return;
  if (budget <= 0) {
    out.unsearched.push_back({a.T, b.T});
    return;
  }
  // the middle, or where it is undecided (a collision within its bars) or has no orbit (next to a
  // pole of sigma the data may leave into the stop for a stretch) a point aside
  CensusRow<S> middle;
  for (const S& at : {S(0.5), S(0.375), S(0.625), S(0.25), S(0.75)}) {
    if (budget-- <= 0) {
      out.unsearched.push_back({a.T, b.T});
      return;
    }
    middle = closedFormRowAt(chain, S(a.T + at * (b.T - a.T)));
    if (middle.census && middle.census->decided) break;
  }
  if (!middle.census || !middle.census->decided) return;
  between(chain, a, middle, out, stop, budget);
  between(chain, middle, b, out, stop, budget);
}

// the orbits the search for a hidden pair may compute between two neighbouring rows
constexpr int kRefinementBudget = 256;

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

template <typename S>
bool mayHideAPair(const std::vector<ChainMultiplier<S>>& a, const std::vector<ChainMultiplier<S>>& b) {
  using std::abs;
  if (a.empty() || a.size() != b.size()) return false;
  std::vector<S> moved;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const ChainMultiplier<S>& x = a[i];
    const ChainMultiplier<S>& y = b[i];
    // two of opposite signatures that swapped places: they met in between (and may have left)
    if (x.krein != 0 && y.krein != 0 && x.krein != y.krein) return true;
    moved.push_back(abs(std::complex<S>(x.re - y.re, x.im - y.im)));
  }
  return nearAChange(a, moved) || nearAChange(b, moved);
}

ChainBifurcationKind changeKind(const MultiplierCensus& before, const MultiplierCensus& after) {
  const int negative = after.negative - before.negative;
  const int positive = after.positive - before.positive;
  const int complex = after.complex - before.complex;
  if ((negative != 0) + (positive != 0) + (complex != 0) != 1) return ChainBifurcationKind::Other;
  return negative != 0 ? ChainBifurcationKind::PeriodDoubling
         : positive != 0 ? ChainBifurcationKind::Fold
                         : ChainBifurcationKind::KreinCollision;
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
ChainBifurcations<S> chainOnePeriodicBifurcations(const BasicReadyChain<S>& chain, const std::vector<CensusRow<S>>& rows,
                                                  std::stop_token stop) {
  ChainBifurcations<S> out;
  const CensusRow<S>* before = nullptr;
  for (const CensusRow<S>& row : rows) {
    if (stop.stop_requested()) break;
    const std::optional<MultiplierCensus>& here = row.census;
    // (multipliers that move off the circle among themselves, a quadruplet meeting the real
    // axis as two real pairs, change no stability: only the count on the circle is followed)
    if (before && here && here->decided) {
      int budget = kRefinementBudget;
      between(chain, *before, row, out, stop, budget);
    }
    // an undecided or inadmissible orbit breaks the chain of neighbours
    before = here && here->decided ? &row : nullptr;
  }
  // (a change found in a half the bisection left behind comes after the one it went on to)
  std::sort(out.changes.begin(), out.changes.end(),
            [](const ChainBifurcation<S>& x, const ChainBifurcation<S>& y) { return x.T < y.T; });
  return out;
}

template <typename S>
ChainBifurcations<S> chainOnePeriodicBifurcations(const BasicReadyChain<S>& chain, const std::vector<S>& periods,
                                                  std::stop_token stop) {
  std::vector<CensusRow<S>> rows;
  for (const S& T : periods) {
    if (stop.stop_requested()) break;
    rows.push_back(rowAt(chain, T));
  }
  return chainOnePeriodicBifurcations(chain, rows, stop);
}

#define GRAZELAB_CHAIN_BIFURCATIONS(S)                                                                          \
  template MultiplierCensus censusOf<S>(const ChainMonodromy<S>&);                                              \
  template bool mayHideAPair<S>(const std::vector<ChainMultiplier<S>>&, const std::vector<ChainMultiplier<S>>&); \
  template ChainBifurcations<S> chainOnePeriodicBifurcations<S>(const BasicReadyChain<S>&, const std::vector<S>&, \
                                                                std::stop_token);                               \
  template ChainBifurcations<S> chainOnePeriodicBifurcations<S>(const BasicReadyChain<S>&,                      \
                                                                const std::vector<CensusRow<S>>&, std::stop_token);
GRAZELAB_CHAIN_BIFURCATIONS(double)
GRAZELAB_CHAIN_BIFURCATIONS(long double)
GRAZELAB_CHAIN_BIFURCATIONS(Quad)
#undef GRAZELAB_CHAIN_BIFURCATIONS

}  // namespace grazelab::core
