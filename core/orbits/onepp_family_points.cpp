// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/onepp_family_points.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/orbits/special_orbits.h"
#include "core/numbers/roots.h"

namespace grazelab::core {

std::string_view toString(PointKind kind) {
  switch (kind) {
    case PointKind::PeriodDoubling: return "period-doubling";
    case PointKind::Fold: return "fold";
    case PointKind::BranchPoint: return "branch-point";
    case PointKind::InteriorGrazing: return "interior-grazing";
    case PointKind::ImpactSpeedZero: return "impact-speed-zero";
    case PointKind::EnergyLimit: return "energy-limit";
    case PointKind::GrazingOrbit: return "grazing-orbit";
    case PointKind::Undecided: return "undecided";
    case PointKind::StepLimit: return "step-limit";
    case PointKind::Stopped: return "stopped";
  }
  return "undecided";
}

std::string_view toString(Side side) { return side == Side::Below ? "below" : "above"; }

template <typename S>
S traceLevelTolerance() {
  using std::sqrt;
  // the trace is a smooth function of the period: bisected to the last bit of T, it meets the
  // level to a few ulps times its slope; sqrt(eps) leaves room for steep crossings (1.5e-8 in
  // double) while still telling a located point from a step's neighbour
  return sqrt(epsilon<S>());
}

template <typename S>
int sideOfLevel(const PeriodicOrbit<S>& orbit, const S& level) {
  if (orbit.stability == Stability::Parabolic && (orbit.trace > 0) == (level > 0)) return 0;
  return orbit.trace > level ? 1 : -1;
}

template <typename S>
bool traceMayCrossUnseen(const PeriodicOrbit<S>& a, const PeriodicOrbit<S>& middle, const PeriodicOrbit<S>& b) {
  using std::abs;
  const S ta = a.trace, tm = middle.trace, tb = b.trace;
  const S bend = abs(tm - (ta + tb) / S(2));
  const S low = std::min({ta, tb, tm}) - S(4) * bend;
  const S high = std::max({ta, tb, tm}) + S(4) * bend;
  for (const S& level : {S(-2), S(2)}) {
    if (!(low < level && high > level)) continue;
    const int sa = sideOfLevel(a, level), sm = sideOfLevel(middle, level), sb = sideOfLevel(b, level);
    if (sa == 0 || sm == 0 || sb == 0) continue;  // on the level within rounding: nothing to resolve
    const int crossings = int(sa != sm) + int(sm != sb);
    if (crossings == 1 && bend <= abs(tb - ta) / S(8)) continue;  // one clean crossing
    return true;
  }
  return false;
}

namespace {

// The 1IPP orbit of period T with its trace, if admissible.
template <typename S>
std::optional<PeriodicOrbit<S>> orbitAt(const TwoMassForm<S>& chain, const S& T) {
  OrbitSearch<S> search = onePeriodicOrbitStability(chain, T);
  return std::move(search.orbit);
}

template <typename S>
struct Sample {
  S T;
  std::optional<PeriodicOrbit<S>> orbit;
};

// The levels of the trace where the stability changes: -2 (flip) and +2 (fold, branch point).
template <typename S>
constexpr std::array<S, 2> levels() {
  return {S(-2), S(2)};
}

template <typename S>
class Scanner {
 public:
  Scanner(const TwoMassForm<S>& chain, std::stop_token stop) : m_chain(chain), m_stop(stop) {}

  bool stopped() const { return m_stop.stop_requested(); }

  Sample<S> sample(const S& T) const { return {T, stopped() ? std::nullopt : orbitAt(m_chain, T)}; }

  // The samples strictly inside (a, b) that the trace's shape asks for, in increasing T: the
  // interval is halved while the trace's range over it, widened by four times its bend (how far
  // the middle is from the chord), holds a level that it does not cross exactly once along a
  // nearly straight trace. Two crossings between neighbours (a dip below -2 between two
  // elliptic samples) are so split apart; an interval clear of the levels costs one sample.
  void refine(const Sample<S>& a, const Sample<S>& b, std::vector<Sample<S>>& out) const {
    using std::abs;
    if (!a.orbit || !b.orbit || stopped()) return;
    if (b.T - a.T <= S(64) * epsilon<S>() * b.T) return;
    Sample<S> middle = sample((a.T + b.T) / S(2));
    if (!middle.orbit) {
      // an inadmissible window inside: its edges are located by the caller
      out.push_back(std::move(middle));
      return;
    }
    const bool needed = traceMayCrossUnseen(*a.orbit, *middle.orbit, *b.orbit);
    if (!needed) return;
    refine(a, middle, out);
    out.push_back(middle);
    refine(middle, b, out);
  }

  // The extremum of the trace in [a, b] by golden section (a minimum when `lowest`).
  Sample<S> extremum(S a, S b, bool lowest) const {
    using std::sqrt;
    const S ratio = (sqrt(S(5)) - S(1)) / S(2);
    const auto value = [&](const Sample<S>& s) {
      return !s.orbit ? std::numeric_limits<S>::quiet_NaN() : (lowest ? s.orbit->trace : -s.orbit->trace);
    };
    Sample<S> c = sample(b - ratio * (b - a));
    Sample<S> d = sample(a + ratio * (b - a));
    for (int step = 0; step < 200 && !stopped(); ++step) {
      if (!c.orbit || !d.orbit) break;
      if (b - a <= S(64) * epsilon<S>() * b) break;
      if (value(c) < value(d)) {
        b = d.T;
        d = std::move(c);
        c = sample(b - ratio * (b - a));
      } else {
        a = c.T;
        c = std::move(d);
        d = sample(a + ratio * (b - a));
      }
    }
    return value(c) < value(d) ? c : d;
  }

  // The period where the trace crosses `level` between admissible a and b (one crossing).
  // The orbits met on the way are added to `met`.
  std::optional<PeriodicOrbit<S>> crossing(const Sample<S>& a, const Sample<S>& b, const S& level,
                                           std::vector<TraceSample<S>>& met) const {
    const bool aAbove = a.orbit->trace - level > 0;
    met.push_back({a.orbit->energy, a.orbit->trace});
    met.push_back({b.orbit->energy, b.orbit->trace});
    const S T = bisectBoundary(
        a.T, b.T,
        [&](const S& t) {
          const std::optional<PeriodicOrbit<S>> o = orbitAt(m_chain, t);
          if (o) met.push_back({o->energy, o->trace});
          return o && ((o->trace - level > 0) == aAbove);
        },
        [&] { return stopped(); });
    return orbitAt(m_chain, T);
  }

  // The edge of an admissible part between a (admissible) and b (not), and why it ends there.
  std::optional<FamilyBifurcation<S>> edge(const Sample<S>& a, const Sample<S>& b) const {
    using std::abs;
    const S T = bisectBoundary(a.T, b.T, [&](const S& t) { return orbitAt(m_chain, t).has_value(); },
                               [&] { return stopped(); });
    const std::optional<PeriodicOrbit<S>> last = orbitAt(m_chain, T);
    if (!last) return std::nullopt;
    const S outside = T + (b.T - a.T) * S(1e-9);
    const OnePeriodicOrbit<S> beyond = onePeriodicOrbit(m_chain, outside);
    PointKind kind = PointKind::InteriorGrazing;
    switch (beyond.refusal) {
      case OnePeriodicRefusal::None:  // data admissible beyond, but their orbit does not close in S
      case OnePeriodicRefusal::NotDecided:
      case OnePeriodicRefusal::SearchBudget:
      case OnePeriodicRefusal::MultipleOfPeriod:
      case OnePeriodicRefusal::BadPeriod:
        // where the part really ends is not known in S (a higher precision moves this point)
        kind = PointKind::Undecided;
        break;
      case OnePeriodicRefusal::LeavesIntoStop:
        // V changes sign across the edge through 0 (the impact fades) or through infinity
        // (g2(T) = 0: the energy grows without bound); bisected to full precision, |V| at the
        // edge is far on one side of the family's natural speed w2 d
        kind = abs(last->state.v2) < m_chain.omegaSlow * m_chain.model.gap ? PointKind::ImpactSpeedZero
                                                                           : PointKind::EnergyLimit;
        break;
      case OnePeriodicRefusal::NeverReturns:
      case OnePeriodicRefusal::ReturnsEarly:
        kind = PointKind::InteriorGrazing;
        break;
    }
    return specialPoint(kind, *last);
  }

  // A located flip, fold or branch point, checked against its definition.
  FamilyBifurcation<S> levelPoint(const PeriodicOrbit<S>& at, const S& level, const Sample<S>& a,
                                  const Sample<S>& b, const std::vector<TraceSample<S>>& met) const {
    using std::abs;
    PointKind kind = PointKind::PeriodDoubling;
    if (level > 0) {
      // tr = +2 where the energy turns back along the family is a fold
      const bool turns = (at.energy - a.orbit->energy > 0) != (b.orbit->energy - at.energy > 0);
      kind = turns ? PointKind::Fold : PointKind::BranchPoint;
    }
    FamilyBifurcation<S> point = specialPoint(kind, at);
    point.checked = abs(at.trace - level) <= traceLevelTolerance<S>();
    point.energyError = levelEnergyError(at, locatedTraceError(m_chain, at), met);
    return point;
  }

 private:
  const TwoMassForm<S>& m_chain;
  std::stop_token m_stop;
};

}  // namespace

template <typename S>
OnePeriodicScan<S> scanOnePeriodicFamily(const TwoMassForm<S>& chain, int samples, std::stop_token stop) {
  using std::pow;
  OnePeriodicScan<S> scan;
  const Scanner<S> scanner(chain, stop);
  const S T2 = twoPi<S>() / chain.omegaSlow;
  // the grid, and periods approaching T2 geometrically where the family ends on its grazing orbit
  std::vector<S> periods;
  for (int i = 1; i <= samples; ++i) periods.push_back(T2 * S(i) / S(samples + 1));
  const int firstHalving = int(std::ceil(std::log2(double(samples + 1)))) + 1;
  for (int k = firstHalving; k <= firstHalving + 10; ++k) periods.push_back(T2 * (S(1) - pow(S(2), S(-k))));
  std::sort(periods.begin(), periods.end());
  std::vector<Sample<S>> grid;
  for (const S& T : periods) {
    if (scanner.stopped()) return scan;
    grid.push_back(scanner.sample(T));
  }
  // refined where two crossings of a level could hide between neighbours
  std::vector<Sample<S>> all;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (i > 0) scanner.refine(grid[i - 1], grid[i], all);
    all.push_back(grid[i]);
  }
  if (scanner.stopped()) return scan;
  // a dip that stays between samples: at each discrete extremum of the trace near a level that
  // no neighbour crosses, the extremum itself, by golden section
  std::vector<Sample<S>> extrema;
  for (std::size_t i = 1; i + 1 < all.size(); ++i) {
    if (!all[i - 1].orbit || !all[i].orbit || !all[i + 1].orbit) continue;
    const S before = all[i - 1].orbit->trace, here = all[i].orbit->trace, after = all[i + 1].orbit->trace;
    for (const S& level : levels<S>()) {
      const bool minimum = here < before && here < after && here > level && here - level < S(0.25);
      const bool maximum = here > before && here > after && here < level && level - here < S(0.25);
      if (!minimum && !maximum) continue;
      Sample<S> e = scanner.extremum(all[i - 1].T, all[i + 1].T, minimum);
      if (e.orbit && ((e.orbit->trace > level) != (here > level))) extrema.push_back(std::move(e));
    }
  }
  all.insert(all.end(), std::make_move_iterator(extrema.begin()), std::make_move_iterator(extrema.end()));
  std::sort(all.begin(), all.end(), [](const Sample<S>& a, const Sample<S>& b) { return a.T < b.T; });
  if (scanner.stopped()) return scan;

  for (std::size_t i = 0; i < all.size(); ++i) {
    if (scanner.stopped()) return scan;
    const Sample<S>& b = all[i];
    if (b.orbit) scan.orbits.push_back(*b.orbit);
    if (i == 0) continue;
    const Sample<S>& a = all[i - 1];
    if (a.orbit.has_value() != b.orbit.has_value()) {
      // an admissible part begins or ends between the two: why, from its outer side
      const std::optional<FamilyBifurcation<S>> point = a.orbit ? scanner.edge(a, b) : scanner.edge(b, a);
      if (point) scan.points.push_back(*point);
      continue;
    }
    if (!a.orbit) continue;
    std::vector<FamilyBifurcation<S>> between;
    for (const S& level : levels<S>()) {
      const int sa = sideOfLevel(*a.orbit, level);
      const int sb = sideOfLevel(*b.orbit, level);
      if (sa * sb < 0) {
        std::vector<TraceSample<S>> met;
        if (const std::optional<PeriodicOrbit<S>> at = scanner.crossing(a, b, level, met)) {
          between.push_back(scanner.levelPoint(*at, level, a, b, met));
        }
      } else if (sa != 0 && sb == 0 && i + 1 < all.size() && all[i + 1].orbit &&
                 sideOfLevel(*all[i + 1].orbit, level) == -sa) {
        // a sample right on the level (T = 2 T2 / 3 on a grid of 2001 intervals) that the
        // trace crosses: the point itself, to rounding already
        const std::vector<TraceSample<S>> met = {{a.orbit->energy, a.orbit->trace},
                                                 {all[i + 1].orbit->energy, all[i + 1].orbit->trace}};
        between.push_back(scanner.levelPoint(*b.orbit, level, a, all[i + 1], met));
      }
    }
    std::sort(between.begin(), between.end(), [](const auto& x, const auto& y) { return x.T < y.T; });
    scan.points.insert(scan.points.end(), between.begin(), between.end());
  }
  if (scanner.stopped()) return scan;
  // the points of a part's start were found from its inner side: all in increasing T
  std::stable_sort(scan.points.begin(), scan.points.end(), [](const auto& x, const auto& y) { return x.T < y.T; });
  // the grazing end at T2 (Theorem 2.1): the data of GLO_lambda*, energy and trace in the limit
  if (!all.empty() && all.back().orbit) {
    FamilyBifurcation<S> end;
    end.kind = PointKind::GrazingOrbit;
    end.T = T2;
    end.state = gloData(chain, lambdaStar(chain));
    end.energy = physicalEnergy(chain, end.state);
    end.trace = S(2);
    scan.points.push_back(end);
  }
  scan.complete = true;
  return scan;
}

template <typename S>
std::vector<FamilyBifurcation<S>> onePeriodicBifurcations(const TwoMassForm<S>& chain, int samples,
                                                          std::stop_token stop) {
  OnePeriodicScan<S> scan = scanOnePeriodicFamily(chain, samples, stop);
  if (!scan.complete) return {};
  return std::move(scan.points);
}

template <typename S>
std::vector<std::array<S, 2>> onePeriodicParts(const TwoMassForm<S>& chain, int samples) {
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
double birthOffsetBound(const FamilyBifurcation<S>& flip, const std::vector<S>& energies) {
  using std::abs;
  double nearest = 1;
  for (const S& energy : energies) {
    const double distance = toDouble(S(abs(energy - flip.energy) / flip.energy));
    if (distance > 0) nearest = std::min(nearest, distance);
  }
  return nearest / 4;
}

template <typename S>
FlipSwitch<S> switchAtFlip(const TwoMassForm<S>& chain, const FamilyBifurcation<S>& flip, int impacts,
                           double maxRelativeOffset, std::stop_token stop) {
  using std::abs;
  using std::sqrt;
  FlipSwitch<S> result;
  // the flip's orbit again, with its Jacobian (a located point closes to the last bits)
  const PeriodicOrbit<S> orbit = evaluateOrbit(chain, flip.state, impacts, S(1e6) * defaultCloseTolerance<S>());
  if (!orbit.admissible) {
    result.search.problem = "the orbit at the flip is not admissible: " + orbit.reason;
    return result;
  }
  // the eigenvector of DP for -1: (DP + I) e = 0, from the row with the larger entries
  const Matrix2<S>& dp = orbit.reduced;
  S eu = -dp(0, 1);
  S ev = dp(0, 0) + S(1);
  if (abs(dp(1, 0)) + abs(dp(1, 1) + S(1)) > abs(eu) + abs(ev)) {
    eu = dp(1, 1) + S(1);
    ev = -dp(1, 0);
  }
  // in units of the gap and of w2 times the gap: e has length 1 there
  const S d = chain.model.gap;
  const S w = chain.omegaSlow;
  const S size = sqrt(eu * eu / (d * d) + ev * ev / (d * d * w * w));
  eu /= size;
  ev /= size;
  // the orbit born here is, at an energy offset o, the flip's state moved along e by about
  // c sqrt(o) on one side of the flip only, its k-th impact the mirror image -c sqrt(o): an
  // orbit elsewhere (born at another flip, or of another family, or farther than 100 sqrt(o))
  // is refused
  const auto bornHere = [&](const OrbitSearch<S>& search, double offset) {
    const PeriodicOrbit<S>& found = *search.orbit;
    const S du = (found.state.u1 - orbit.state.u1) / d;
    const S dv = (found.state.v1 - orbit.state.v1) / (d * w);
    const S distance = sqrt(du * du + dv * dv);
    const S along = abs(du * eu / d + dv * ev / (d * w));
    // after k impacts the orbit born here is at the mirror image, about twice as far from its
    // start: the flip's own orbit run twice (which P^2k - x = 0 also solves) is not
    const BasicState<S>& half = found.events[std::size_t(impacts - 1)].after;
    const S hu = (half.u1 - found.state.u1) / d;
    const S hv = (half.v1 - found.state.v1) / (d * w);
    const S halfway = sqrt(hu * hu + hv * hv);
    // near the flip P^2k is close to the identity along e: Newton can stall on a plateau that
    // closes within the tolerance (amplified for rounding) but is no orbit; a born orbit is
    // converged, its Newton step a small part of its distance from the flip
    return distance <= S(100.0 * std::sqrt(offset)) && along >= S(0.5) * distance &&
           halfway >= distance && halfway > S(1e3) * closeTolerance(found) &&
           search.correction <= S(1e-3) * distance;
  };
  const double largest = std::min(1e-3, maxRelativeOffset);
  std::string problem;
  for (const double offset : {largest, largest / 10, largest / 100, largest / 1000}) {
    for (const Side side : {Side::Below, Side::Above}) {
      // the family's own c is not known: from a third to thirty (on m2/m1 = 0.52, upper
      // design, the family born at T/T2 = 0.6776 sits at 6 sqrt(o))
      for (const double reach : {1.0, 0.3, 3.0, 10.0, 30.0, 2.0, 5.0, 20.0}) {
        for (const int direction : {1, -1}) {
          if (stop.stop_requested()) {
            result.search.problem = "stopped";
            return result;
          }
          const S energy = flip.energy * (S(1) + S(side == Side::Below ? -offset : offset));
          const S push = S(direction * reach * std::sqrt(offset));
          OrbitSearch<S> search = findOrbit(chain, energy, S(orbit.state.u1 + push * eu),
                                            S(orbit.state.v1 + push * ev), 2 * impacts, stop);
          if (!search.orbit) {
            problem = search.problem;
            continue;
          }
          if (!bornHere(search, offset)) {
            problem = "the orbit found near the flip belongs elsewhere";
            continue;
          }
          result.search = std::move(search);
          result.side = side;
          result.energyOffset = energy - flip.energy;
          return result;
        }
      }
    }
  }
  result.search.problem = "no " + std::to_string(2 * impacts) + "-impact orbit born at the flip at T = " +
                          formatScalar(flip.T) + " was found (last: " + problem + ")";
  return result;
}

#define GRAZELAB_INSTANTIATE(S)                                                                   \
  template S traceLevelTolerance<S>();                                                            \
  template int sideOfLevel<S>(const PeriodicOrbit<S>&, const S&);                                 \
  template bool traceMayCrossUnseen<S>(const PeriodicOrbit<S>&, const PeriodicOrbit<S>&,          \
                                       const PeriodicOrbit<S>&);                                  \
  template OnePeriodicScan<S> scanOnePeriodicFamily<S>(const TwoMassForm<S>&, int, std::stop_token);    \
  template std::vector<FamilyBifurcation<S>> onePeriodicBifurcations<S>(const TwoMassForm<S>&, int,     \
                                                                        std::stop_token);         \
  template std::vector<std::array<S, 2>> onePeriodicParts<S>(const TwoMassForm<S>&, int);             \
  template double birthOffsetBound<S>(const FamilyBifurcation<S>&, const std::vector<S>&);          \
  template FlipSwitch<S> switchAtFlip<S>(const TwoMassForm<S>&, const FamilyBifurcation<S>&, int,       \
                                         double, std::stop_token);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
