// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/periodic_family.h"

#include <cmath>
#include <optional>

#include "core/orbits.h"

namespace grazelab::core {

namespace {

// The 1IPP orbit of period T with its trace, if admissible.
template <typename S>
std::optional<PeriodicOrbit<S>> orbitAt(const Chain<S>& chain, const S& T) {
  OrbitSearch<S> search = onePeriodicOrbitStability(chain, T);
  return std::move(search.orbit);
}

// Bisects [low, high] (low inside, high outside of `inside`) down to the precision of S.
template <typename S, typename Inside>
S bisect(S low, S high, const Inside& inside) {
  using std::abs;
  for (int step = 0; step < 400; ++step) {
    const S middle = (low + high) / S(2);
    if (middle == low || middle == high) break;
    if (inside(middle)) low = middle;
    else high = middle;
  }
  return low;
}

template <typename S>
FamilyBifurcation<S> pointAt(const std::string& kind, const PeriodicOrbit<S>& orbit) {
  return {kind, orbit.period, orbit.energy, orbit.trace, orbit.state};
}

}  // namespace

template <typename S>
std::vector<FamilyBifurcation<S>> onePeriodicBifurcations(const Chain<S>& chain, int samples,
                                                          std::stop_token stop) {
  std::vector<FamilyBifurcation<S>> found;
  const S T2 = twoPi<S>() / chain.omegaSlow;
  std::optional<PeriodicOrbit<S>> previous;
  S previousT = 0;
  for (int i = 1; i <= samples; ++i) {
    if (stop.stop_requested()) return {};
    const S T = T2 * S(i) / S(samples + 1);
    std::optional<PeriodicOrbit<S>> orbit = orbitAt(chain, T);
    if (previous.has_value() != orbit.has_value() && i > 1) {
      // an admissible part begins or ends between the two: why, from its outer side
      const bool ends = previous.has_value();
      const S edge = ends ? bisect(previousT, T, [&](const S& t) { return orbitAt(chain, t).has_value(); })
                          : bisect(T, previousT, [&](const S& t) { return orbitAt(chain, t).has_value(); });
      const S outside = ends ? S(edge + (T - previousT) * S(1e-9)) : S(edge - (T - previousT) * S(1e-9));
      const OnePeriodicOrbit<S> beyond = onePeriodicOrbit(chain, outside);
      if (const std::optional<PeriodicOrbit<S>> last = orbitAt(chain, edge)) {
        // V changes sign across the edge through 0 (the impact fades) or through infinity
        // (g2(T) = 0: the energy grows without bound); bisected to full precision, |V| at
        // the edge is far on one side of the family's natural speed w2 d
        std::string kind = "interior-grazing";
        if (beyond.reason.find("not decided") != std::string::npos || beyond.admissible) {
          // the closed form's data are admissible beyond, but their orbit could not be made to
          // close in S (they lose digits near a multiple of T1), or its contact cannot be
          // decided: where the part really ends is not known in S (a higher precision moves
          // this point)
          kind = "undecided";
        } else if (!(beyond.V < 0)) {
          using std::abs;
          kind = abs(last->state.v2) < chain.omegaSlow * chain.model.gap ? "impact-speed-zero"
                                                                          : "energy-limit";
        }
        found.push_back(pointAt(kind, *last));
      }
    } else if (previous && orbit) {
      const auto crossed = [&](const S& level) {
        return (previous->trace - level > 0) != (orbit->trace - level > 0);
      };
      for (const S& level : {S(-2), S(2)}) {
        if (!crossed(level)) continue;
        const bool startsAbove = previous->trace - level > 0;
        const S t = bisect(previousT, T, [&](const S& at) {
          const std::optional<PeriodicOrbit<S>> o = orbitAt(chain, at);
          return o && ((o->trace - level > 0) == startsAbove);
        });
        const std::optional<PeriodicOrbit<S>> at = orbitAt(chain, t);
        if (!at) continue;
        std::string kind = "period-doubling";
        if (level > 0) {
          // tr = +2 where the energy turns back along the family is a fold
          const std::optional<PeriodicOrbit<S>> before = orbitAt(chain, S(t - (T - previousT) / S(8)));
          const std::optional<PeriodicOrbit<S>> after = orbitAt(chain, S(t + (T - previousT) / S(8)));
          const bool turns = before && after &&
                             ((at->energy - before->energy > 0) != (after->energy - at->energy > 0));
          kind = turns ? "fold" : "branch-point";
        }
        found.push_back(pointAt(kind, *at));
      }
    }
    previous = std::move(orbit);
    previousT = T;
  }
  // the grazing end at T2 (Theorem 2.1): the data of GLO_lambda*, energy and trace in the limit
  if (previous) {
    FamilyBifurcation<S> end;
    end.kind = "grazing-orbit";
    end.T = T2;
    end.state = gloData(chain, lambdaStar(chain));
    end.energy = physicalEnergy(chain, end.state);
    end.trace = S(2);
    found.push_back(end);
  }
  return found;
}

template <typename S>
std::vector<std::array<S, 2>> onePeriodicParts(const Chain<S>& chain, int samples) {
  const S T2 = twoPi<S>() / chain.omegaSlow;
  std::vector<std::array<S, 2>> parts;
  std::optional<S> first;
  S last = 0;
  for (int i = 1; i <= samples + 1; ++i) {
    const S T = T2 * S(i) / S(samples + 1);
    const bool admissible = i <= samples && orbitAt(chain, T).has_value();
    if (admissible) {
      if (!first) first = T;
      last = T;
    } else if (first) {
      parts.push_back({*first, last});
      first.reset();
    }
  }
  return parts;
}

template <typename S>
FlipSwitch<S> switchAtFlip(const Chain<S>& chain, const FamilyBifurcation<S>& flip,
                           int impacts, std::stop_token stop) {
  using std::abs;
  using std::sqrt;
  FlipSwitch<S> result;
  // the flip's orbit again, with its Jacobian (a located point closes to the last bits)
  const PeriodicOrbit<S> evaluated = evaluateOrbit(chain, flip.state, impacts, S(1e6) * defaultCloseTolerance<S>());
  const std::optional<PeriodicOrbit<S>> orbit =
      evaluated.admissible ? std::optional<PeriodicOrbit<S>>(evaluated) : std::nullopt;
  if (!orbit) {
    result.search.problem = "the orbit at the flip is not admissible: " + evaluated.reason;
    return result;
  }
  // the eigenvector of DP for -1: (DP + I) e = 0, from the row with the larger entries
  const Matrix2<S>& dp = orbit->reduced;
  S eu = -dp[0][1];
  S ev = dp[0][0] + S(1);
  if (abs(dp[1][0]) + abs(dp[1][1] + S(1)) > abs(eu) + abs(ev)) {
    eu = dp[1][1] + S(1);
    ev = -dp[1][0];
  }
  // in units of the gap and of w2 times the gap
  const S d = chain.model.gap;
  const S w = chain.omegaSlow;
  const S size = sqrt(eu * eu / (d * d) + ev * ev / (d * d * w * w));
  eu /= size;
  ev /= size;
  for (const double offset : {1e-3, 1e-4, 1e-5}) {
    for (const int sign : {-1, 1}) {
      for (const double reach : {0.3, 1.0, 3.0}) {
        for (const int direction : {1, -1}) {
          if (stop.stop_requested()) {
            result.search.problem = "stopped";
            return result;
          }
          const S energy = flip.energy * (S(1) + S(sign * offset));
          // the new orbit's distance grows like the square root of the energy offset
          const S push = S(direction * reach * std::sqrt(offset));
          OrbitSearch<S> search = findOrbit(chain, energy, S(orbit->state.u1 + push * eu),
                                            S(orbit->state.v1 + push * ev), 2 * impacts, stop);
          if (!search.orbit) {
            result.search.problem = search.problem;
            continue;
          }
          result.search = std::move(search);
          result.side = sign < 0 ? "below" : "above";
          result.energyOffset = energy - flip.energy;
          return result;
        }
      }
    }
  }
  result.search.problem = "no " + std::to_string(2 * impacts) + "-impact orbit found near the flip at T = " + formatScalar(flip.T) +
                          " (last: " + result.search.problem + ")";
  return result;
}

#define GRAZELAB_INSTANTIATE(S)                                                                   \
  template std::vector<FamilyBifurcation<S>> onePeriodicBifurcations<S>(const Chain<S>&, int,     \
                                                                        std::stop_token);         \
  template std::vector<std::array<S, 2>> onePeriodicParts<S>(const Chain<S>&, int);             \
  template FlipSwitch<S> switchAtFlip<S>(const Chain<S>&, const FamilyBifurcation<S>&, int,       \
                                         std::stop_token);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
