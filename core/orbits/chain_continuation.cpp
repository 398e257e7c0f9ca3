// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/chain_continuation.h"

#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/numbers/eigen_quad.h"
#include "core/orbits/chain_return_map.h"

namespace grazelab::core {

std::string_view toString(ChainFamilyEnd end) {
  switch (end) {
    case ChainFamilyEnd::EnergyLimit: return "energy-limit";
    case ChainFamilyEnd::StepLimit: return "step-limit";
    case ChainFamilyEnd::GrazingOrbit: return "grazing-orbit";
    case ChainFamilyEnd::ImpactFades: return "impact-fades";
    case ChainFamilyEnd::InteriorGrazing: return "interior-grazing";
    case ChainFamilyEnd::MeetsDoubling: return "meets-doubling";
    case ChainFamilyEnd::Undecided: return "undecided";
    case ChainFamilyEnd::NotConverging: return "not-converging";
    case ChainFamilyEnd::StartNotAdmissible: return "start-not-admissible";
    case ChainFamilyEnd::Stopped: return "stopped";
  }
  return "unknown";
}

namespace {

using namespace return_map;

// The family's equations at the scaled unknowns w: the path from there and, where it held its
// impact sequence, the residual and Jacobian in scaled units (rows over their coordinate's unit,
// columns times their unknown's) and the tolerance its closing is judged to.
template <typename S>
struct FamilyAt {
  std::optional<BasicChainState<S>> start;
  BasicChainPeriodicOrbit<S> path;
  bool held = false;
  ChainVector<S> residual;
  ChainMatrix<S> jacobian;
  S tolerance = 0;
};

template <typename S>
FamilyAt<S> familyAt(const Unknowns<S>& unknowns, const ChainVector<S>& unit, const ChainVector<S>& w,
                     const BasicChainState<S>& like, int impacts, const S& tolerance) {
  FamilyAt<S> at;
  const ChainVector<S> z = w.cwiseProduct(unit);
  at.start = unknowns.state(z, like);
  if (!at.start) {
    at.path.refusal = OrbitRefusal::BadStart;
    return at;
  }
  at.path = evaluateChainPath(unknowns.chain, *at.start, impacts, tolerance);
  at.held = at.path.refusal == OrbitRefusal::None || at.path.refusal == OrbitRefusal::NotClosed;
  if (!at.held) return at;
  const ReturnMapAt<S> map = returnMapAt(unknowns, z, *at.start, at.path);
  const Eigen::Index rows = map.residual.size();
  at.residual = map.residual.cwiseQuotient(unit.head(rows));
  at.jacobian = map.jacobian;
  for (Eigen::Index i = 0; i < rows; ++i) at.jacobian.row(i) /= unit[i];
  for (Eigen::Index j = 0; j < at.jacobian.cols(); ++j) at.jacobian.col(j) *= unit[j];
  const ChainStateScale<S> scale(unknowns.chain.dynamics);
  at.tolerance = chainCloseTolerance<S>(impacts, S(scale.scaled(map.projected).cwiseAbs().maxCoeff()));
  return at;
}

// The family's unit tangent where its Jacobian (scaled, one column more than rows) is `jacobian`:
// the null vector, the last column of Q in J^T = QR, pointing the way of `along`
template <typename S>
ChainVector<S> tangentOf(const ChainMatrix<S>& jacobian, const ChainVector<S>& along) {
  const Eigen::Index m = jacobian.cols();
  ChainVector<S> t = ChainVector<S>::Unit(m, m - 1);  // (one mass: the energy alone)
  if (jacobian.rows() > 0) {
    const Eigen::HouseholderQR<ChainMatrix<S>> qr(jacobian.transpose());
    t = qr.householderQ() * t;
  }
  if (t.dot(along) < 0) t = -t;
  return t;
}

// the infinity norm of a matrix (by loops: GCC 12 sees Eigen's rowwise sum of long doubles as
// uninitialized)
template <typename S>
S largestRowSum(const ChainMatrix<S>& a) {
  using std::abs;
  S largest = 0;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    S row = 0;
    for (Eigen::Index j = 0; j < a.cols(); ++j) row += abs(a(i, j));
    largest = std::max(largest, row);
  }
  return largest;
}

// The family's orbit on the hyperplane through `predicted` normal to `normal` (scaled unknowns):
// Newton on [F; normal . (y - predicted)] from the predictor, the first iterate that closes within
// its tolerance polished while Newton still halves its residual (a row is then as exact as S
// allows), with how far it may be along the map's softest direction: the tolerance times the
// bordered Jacobian's inverse (next to a period doubling the orbit is known only so far from the
// shorter one run twice). A step longer than `longest` leaves the family: none then.
template <typename S>
struct Corrected {
  std::optional<FamilyAt<S>> accepted;
  ChainVector<S> y;  // its unknowns
  S spread = 0;
  int corrections = 0;
  int toClose = 0;  // the Newton steps before the first iterate that closed (polishing not counted)
  OrbitRefusal refusal = OrbitRefusal::None;  // none accepted: the refusal the path met, if any
};

template <typename S>
Corrected<S> correctOnto(const Unknowns<S>& unknowns, const ChainVector<S>& unit, const ChainVector<S>& predicted,
                         const ChainVector<S>& normal, const S& longest, const BasicChainState<S>& like, int impacts,
                         const S& tolerance) {
  constexpr int kCorrections = 12;
  const Eigen::Index m = predicted.size();
  Corrected<S> out;
  ChainVector<S> y = predicted;
  S acceptedResidual = 0;
  for (; out.corrections < kCorrections; ++out.corrections) {
    FamilyAt<S> at = familyAt(unknowns, unit, y, like, impacts, tolerance);
    if (!at.held) {
      out.refusal = at.path.refusal;
      break;
    }
    const S residual = at.path.periodicityResidual;
    if (out.accepted && !(residual < acceptedResidual / 2)) break;
    ChainMatrix<S> bordered(m, m);
    bordered.topRows(m - 1) = at.jacobian;
    bordered.row(m - 1) = normal.transpose();
    ChainVector<S> g(m);
    g.head(m - 1) = at.residual;
    g[m - 1] = normal.dot(y - predicted);
    const Eigen::FullPivLU<ChainMatrix<S>> lu(bordered);
    const bool invertible = lu.isInvertible();
    if (residual <= at.tolerance) {
      out.spread = invertible ? S(at.tolerance * largestRowSum(ChainMatrix<S>(lu.inverse()))) : S(1);
      if (!out.accepted) out.toClose = out.corrections;
      acceptedResidual = residual;
      out.y = y;
      out.accepted = std::move(at);
      if (residual == 0) break;
    }
    if (!invertible) break;
    const ChainVector<S> dy = lu.solve(g);
    if (!isFinite(S(dy.cwiseAbs().maxCoeff())) || dy.norm() > longest) break;  // (leaving the family)
    y -= dy;
  }
  // (a point farther from the predictor than `longest` is on another family)
  if (out.accepted && (out.y - predicted).norm() > longest) out.accepted.reset();
  if (out.accepted) out.refusal = OrbitRefusal::None;
  return out;
}

// A point of the family: its orbit and its scaled unknowns.
template <typename S>
struct FamilyPoint {
  BasicChainPeriodicOrbit<S> orbit;
  ChainVector<S> w;
};

// The family's point halfway (or, where that has no orbit or an undecided one, 3/8 or 5/8 of the
// way) from a to b: the predictor on the chord corrected onto the family on the hyperplane normal
// to it, no farther from the chord than a quarter of it (farther is another family); none when no
// such point is admissible and decided. Counts each point computed from `budget`.
template <typename S>
std::optional<FamilyPoint<S>> middleOf(const BasicReadyChain<S>& chain, const Unknowns<S>& unknowns,
                                       const ChainVector<S>& unit, const FamilyPoint<S>& a, const FamilyPoint<S>& b,
                                       int impacts, const S& tolerance, int* budget) {
  const ChainVector<S> chord = b.w - a.w;
  const S length = chord.norm();
  for (const S& at : {S(0.5), S(0.375), S(0.625)}) {
    if (budget && (*budget)-- <= 0) return std::nullopt;
    const Corrected<S> corrected = correctOnto<S>(unknowns, unit, ChainVector<S>(a.w + at * chord),
                                                  ChainVector<S>(chord / length), S(length / 4), a.orbit.state,
                                                  impacts, tolerance);
    if (!corrected.accepted) continue;
    BasicChainPeriodicOrbit<S> orbit =
        evaluateChainOrbit(chain, *corrected.accepted->start, impacts, corrected.accepted->tolerance);
    if (!orbit.admissible() || !censusOf(orbit.monodromy).decided) continue;
    return FamilyPoint<S>{std::move(orbit), corrected.y};
  }
  return std::nullopt;
}

// The changes of stability between the family's points a and b (in one unit, their censuses
// decided), in order. Where their numbers on the circle differ, the bracket is halved down to the
// rounding the orbits close to (16 times the tolerance), each half with a census of its own
// searched in turn, so that two changes in one bracket (a middle whose number differs from both
// ends) are both found; the change is named by how the census moved across the last bracket,
// which a middle that cannot be computed leaves wider (its error says so). Where their numbers
// are the same but two changes that undo each other could hide in between (mayHideAPair), the
// halves are searched while `budget` lasts (then it is left below 0: the stretch unsearched).
template <typename S>
void searchBetween(const BasicReadyChain<S>& chain, const Unknowns<S>& unknowns, const ChainVector<S>& unit,
                   const FamilyPoint<S>& a, const FamilyPoint<S>& b, int impacts, const S& tolerance,
                   const std::stop_token& stop, int& budget, ContinuedChainFamily<S>& family) {
  using std::abs;
  const MultiplierCensus below = censusOf(a.orbit.monodromy);
  const MultiplierCensus above = censusOf(b.orbit.monodromy);
  if (!below.decided || !above.decided || stop.stop_requested()) return;
  const bool differ = below.onCircle != above.onCircle;
  const S length = (b.w - a.w).norm();
  const S resolution = std::max<S>(S(16) * tolerance, S(4) * std::numeric_limits<S>::epsilon());
  std::optional<FamilyPoint<S>> middle;
  if (differ && length > resolution) {
    middle = middleOf(chain, unknowns, unit, a, b, impacts, tolerance, static_cast<int*>(nullptr));
  } else if (!differ && length > S(1e-9) && mayHideAPair(a.orbit.monodromy.multipliers, b.orbit.monodromy.multipliers)) {
    if (budget <= 0) {
      budget = -1;
      return;
    }
    middle = middleOf(chain, unknowns, unit, a, b, impacts, tolerance, &budget);
    if (budget < 0) return;
  }
  if (middle) {
    searchBetween(chain, unknowns, unit, a, *middle, impacts, tolerance, stop, budget, family);
    searchBetween(chain, unknowns, unit, *middle, b, impacts, tolerance, stop, budget, family);
    return;
  }
  if (!differ) return;
  ChainFamilyChange<S> change;
  change.kind = changeKind(below, above);
  change.leaves = above.onCircle < below.onCircle;
  change.after = family.orbits.size() - 1;
  change.energy = (a.orbit.energy + b.orbit.energy) / 2;
  change.energyError = abs(b.orbit.energy - a.orbit.energy) / 2;
  change.period = (a.orbit.period + b.orbit.period) / 2;
  change.periodError = abs(b.orbit.period - a.orbit.period) / 2;
  change.state = a.orbit.state;
  family.changes.push_back(std::move(change));
}

// The slowest and the fastest of an orbit's impacts (the stopped mass's speed before each), over
// the scale's speed.
template <typename S>
std::pair<S, S> impactSpeeds(const BasicChainDynamics<S>& dynamics, const BasicChainPeriodicOrbit<S>& orbit) {
  using std::abs;
  const ChainStateScale<S> scale(dynamics);
  S slowest = std::numeric_limits<S>::infinity(), fastest = 0;
  for (const BasicChainEvent<S>& event : orbit.events) {
    const S speed = abs(event.vBefore[dynamics.stop]) / scale.speed;
    slowest = std::min(slowest, speed);
    fastest = std::max(fastest, speed);
  }
  return {slowest, fastest};
}

// An impact slower than this (over the scale's speed) whose family's steps stall is approaching
// the end where it fades.
constexpr double kSlowImpact = 0.05;

// How a family ends after `last`, where no step gave an orbit: its impacts' speeds (over the
// scale's speed) going to 0, all of them or one; else the path from the predictor `beyond` (a few
// smallest steps on) making a contact the last orbit has not (a grazing, a stick, or an impact
// at another time: a flight touched the stop); else what the failed steps' paths showed.
template <typename S>
ChainFamilyEnd endAt(const Unknowns<S>& unknowns, const ChainVector<S>& unit, const ChainVector<S>& beyond,
                     const BasicChainPeriodicOrbit<S>& last, OrbitRefusal refusal, const S& tolerance) {
  using std::abs;
  const auto [slowest, fastest] = impactSpeeds(unknowns.chain.dynamics, last);
  if (fastest < S(kSlowImpact)) return ChainFamilyEnd::GrazingOrbit;
  if (slowest < S(kSlowImpact)) return ChainFamilyEnd::ImpactFades;
  if (refusal == OrbitRefusal::Repeated) return ChainFamilyEnd::MeetsDoubling;
  const std::optional<BasicChainState<S>> start = unknowns.state(beyond.cwiseProduct(unit), last.state);
  if (start) {
    const BasicChainPeriodicOrbit<S> path = evaluateChainPath(unknowns.chain, *start, last.impacts, tolerance);
    if (path.refusal == OrbitRefusal::Undecided) return ChainFamilyEnd::Undecided;
    for (const BasicChainEvent<S>& event : path.events) {
      bool known = event.type == EventType::Impact;
      if (known) {
        known = false;
        for (const BasicChainEvent<S>& impact : last.events) {
          known = known || abs(event.t - impact.t) <= S(1e-6) * last.period;
        }
      }
      if (!known) return ChainFamilyEnd::InteriorGrazing;
    }
  }
  if (refusal == OrbitRefusal::TouchesStop || refusal == OrbitRefusal::NotImpact) {
    return ChainFamilyEnd::InteriorGrazing;
  }
  if (refusal == OrbitRefusal::Undecided) return ChainFamilyEnd::Undecided;
  return ChainFamilyEnd::NotConverging;
}

// the orbits the search for a hidden pair may compute between two consecutive orbits
constexpr int kPairSearchBudget = 256;

// A family whose slowest impact falls below kSlowImpact while its arclength steps stall nears an
// end where that impact fades: the steps shrink with its speed (the impact's saltation grows as
// its inverse), so that they would reach it only after thousands of orbits. It is approached at
// fixed periods instead: each next orbit by Newton at the period halfway from the last one to
// where the secant of the last two orbits' slowest speeds puts 0, while that speed keeps falling
// (to 1e-9 of the scale's speed at most; Newton stops converging before that near a linear orbit,
// whose neighbours of one period form a continuum), the changes of stability between them
// searched as along the family.
template <typename S>
void approachFadingImpact(const BasicReadyChain<S>& chain, const Unknowns<S>& unknowns, const ChainVector<S>& unit,
                          int impacts, const std::stop_token& stop, ContinuedChainFamily<S>& family) {
  const BasicChainDynamics<S>& dynamics = chain.dynamics;
  for (int step = 0; step < 60 && family.orbits.size() >= 2 && !stop.stop_requested(); ++step) {
    const BasicChainPeriodicOrbit<S>& before = family.orbits[family.orbits.size() - 2];
    const BasicChainPeriodicOrbit<S>& last = family.orbits.back();
    const S va = impactSpeeds(dynamics, before).first;
    const S vb = impactSpeeds(dynamics, last).first;
    if (!(vb < va) || vb < S(1e-9)) break;
    const S zero = last.period + (last.period - before.period) * vb / (va - vb);
    const ChainOrbitSearch<S> found = findChainOrbit(chain, last.state, impacts, ChainOrbitConstraint::Period,
                                                     S((last.period + zero) / 2), stop);
    if (!found.orbit || !found.orbit->admissible() ||
        isRepeated(dynamics, *found.orbit, std::max(chainCloseTolerance<S>(impacts, S(1)), found.correction)) ||
        !(impactSpeeds(dynamics, *found.orbit).first < vb)) {
      break;
    }
    const ChainVector<S> wLast = unknowns.of(last.state).cwiseQuotient(unit);
    const ChainVector<S> wFound = unknowns.of(found.orbit->state).cwiseQuotient(unit);
    int budget = kPairSearchBudget;
    searchBetween(chain, unknowns, unit, FamilyPoint<S>{last, wLast}, FamilyPoint<S>{*found.orbit, wFound}, impacts,
                  chainCloseTolerance<S>(impacts, S(1)), stop, budget, family);
    if (budget < 0) ++family.unsearched;
    family.orbits.push_back(*found.orbit);
  }
}

}  // namespace

template <typename S>
ContinuedChainFamily<S> continueChainFamily(const BasicReadyChain<S>& chain, const BasicChainPeriodicOrbit<S>& start,
                                            int direction, const ChainContinuationOptions<S>& options,
                                            std::stop_token stop) {
  using std::abs;
  ContinuedChainFamily<S> family;
  family.impacts = start.impacts;
  const int k = start.impacts;
  const BasicChainDynamics<S>& dynamics = chain.dynamics;
  const Unknowns<S> unknowns{chain, sectionIndices(dynamics.mass.size(), dynamics.stop), ChainOrbitConstraint::Period,
                             start.period};
  const Eigen::Index m = unknowns.size();
  // units: the gap, the scale's speed, and the energy of the last orbit taken (so that a step
  // in energy is relative: families span decades of it)
  ChainVector<S> unit = unknowns.units(unknowns.of(start.state));
  ChainVector<S> w = unknowns.of(start.state).cwiseQuotient(unit);
  FamilyAt<S> here = familyAt(unknowns, unit, w, start.state, k, chainCloseTolerance<S>(k, S(1)));
  if (!start.admissible() || !here.held) {
    family.end = ChainFamilyEnd::StartNotAdmissible;
    family.refusal = start.admissible() ? here.path.refusal : start.refusal;
    return family;
  }
  family.orbits.push_back(start);
  ChainVector<S> way = ChainVector<S>::Zero(m);
  way[m - 1] = direction >= 0 ? 1 : -1;
  ChainVector<S> t = tangentOf(here.jacobian, way);
  S tolerance = here.tolerance;
  double h = options.firstStep;
  OrbitRefusal refusal = OrbitRefusal::None;  // the last refusal a failed step met
  while (int(family.orbits.size()) < options.maxOrbits) {
    if (stop.stop_requested()) {
      family.end = ChainFamilyEnd::Stopped;
      return family;
    }
    // the predictor along the tangent, then Newton on the family and the arclength's hyperplane
    const Corrected<S> corrected = correctOnto<S>(unknowns, unit, ChainVector<S>(w + S(h) * t), t, S(2 * h),
                                                  family.orbits.back().state, k, tolerance);
    if (!corrected.accepted) refusal = corrected.refusal;
    const std::optional<FamilyAt<S>>& accepted = corrected.accepted;
    const ChainVector<S>& acceptedY = corrected.y;
    const S spread = corrected.spread;
    const int toClose = corrected.toClose;
    // the orbit there: admissible, no shorter one run twice, and the family's tangent turned by
    // less than a quarter of a right angle (a larger turn is a jump onto another family)
    std::optional<BasicChainPeriodicOrbit<S>> orbit;
    std::optional<ChainVector<S>> turned;
    if (accepted) {
      BasicChainPeriodicOrbit<S> found = evaluateChainOrbit(chain, *accepted->start, k, accepted->tolerance);
      if (found.admissible() && isRepeated(dynamics, found, std::max(accepted->tolerance, spread))) {
        found.refusal = OrbitRefusal::Repeated;
      }
      // (a step across the doubled orbit of a period doubling, onto the family's other half)
      const ChainVector<S> shift = halfPeriodShift(dynamics, found);
      if (found.admissible() && shift.size() > 0 && shift.dot(halfPeriodShift(dynamics, family.orbits.back())) < 0) {
        found.refusal = OrbitRefusal::Repeated;
      }
      if (found.admissible()) {
        const ChainVector<S> next = tangentOf(accepted->jacobian, t);
        if (next.dot(t) >= S(0.92)) {
          orbit = std::move(found);
          turned = next;
        } else {
          refusal = OrbitRefusal::None;  // (turned too far: no path refused, a branch point or another family)
        }
      } else {
        refusal = found.refusal;
      }
    }
    if (!orbit) {
      h /= 2;
      if (h < options.minStep) {
        family.end = endAt(unknowns, unit, ChainVector<S>(w + S(4 * h) * t), family.orbits.back(), refusal, tolerance);
        family.refusal = refusal;
        return family;
      }
      continue;
    }
    if (!(orbit->energy >= options.energyLow && orbit->energy <= options.energyHigh)) {
      family.end = ChainFamilyEnd::EnergyLimit;
      return family;
    }
    // the changes of stability since the last orbit, located (in the units both are in)
    int budget = kPairSearchBudget;
    searchBetween(chain, unknowns, unit, FamilyPoint<S>{family.orbits.back(), w}, FamilyPoint<S>{*orbit, acceptedY}, k,
                  accepted->tolerance, stop, budget, family);
    if (budget < 0) ++family.unsearched;
    // the energy's unit moves to the new orbit's energy: w, the tangent (renormalised) with it
    const S ratio = abs(orbit->energy) / unit[m - 1];
    w = acceptedY;
    w[m - 1] /= ratio;
    t = *turned;
    t[m - 1] /= ratio;
    t.normalize();
    unit[m - 1] = abs(orbit->energy);
    tolerance = accepted->tolerance;
    family.orbits.push_back(std::move(*orbit));
    refusal = OrbitRefusal::None;
    // an impact fading where the steps stall: approached at fixed periods, and the family ends
    // there (its last orbit says how near: the speed it was approached to)
    if (impactSpeeds(dynamics, family.orbits.back()).first < S(kSlowImpact) && h < options.firstStep) {
      approachFadingImpact(chain, unknowns, unit, k, stop, family);
      const bool allSlow = impactSpeeds(dynamics, family.orbits.back()).second < S(kSlowImpact);
      family.end = allSlow ? ChainFamilyEnd::GrazingOrbit : ChainFamilyEnd::ImpactFades;
      return family;
    }
    // (a step that closes within two Newton steps is short for the family's curvature)
    h = toClose <= 2 ? std::min(2 * h, options.maxStep) : toClose >= 5 ? h / 2 : h;
  }
  family.end = ChainFamilyEnd::StepLimit;
  return family;
}

namespace {

// The largest difference of two states in the scaled units
template <typename S>
S scaledDistance(const ChainStateScale<S>& scale, const BasicChainState<S>& a, const BasicChainState<S>& b) {
  const Eigen::Index n = a.u.size();
  ChainVector<S> x(2 * n);
  x << a.u - b.u, a.v - b.v;
  return scale.scaled(x).cwiseAbs().maxCoeff();
}

}  // namespace

template <typename S>
ChainOrbitSearch<S> branchAtDoubling(const BasicReadyChain<S>& chain, const ChainFamilyChange<S>& doubling,
                                     int parentImpacts, std::stop_token stop,
                                     const std::function<bool(const BasicChainPeriodicOrbit<S>&)>& accept) {
  using std::abs;
  using std::sqrt;
  const BasicChainDynamics<S>& dynamics = chain.dynamics;
  const Eigen::Index n = dynamics.mass.size();
  const ChainStateScale<S> scale(dynamics);
  ChainOrbitSearch<S> none;
  none.problem = ChainOrbitProblem::NotConverging;
  // Two ways of pushing, the second tried where the first found nothing: along the eigenvector
  // of the multiplier nearest -1 by inverse iteration on M + I, by fixed amounts; and along the
  // right singular vector of M + I's smallest singular value by c sqrt(offset), c from 0.3 to 30
  // (where the branch lies, c not known). At a doubling the pair at -1 is one Jordan block, split
  // to -1 -+ e a little off it: inverse iteration, both equally near, mixes in the block's
  // generalized vector, and on random chains of three and four masses one doubling in seven found
  // no branch that way; the singular vector is the block's eigenvector, yet misses branches the
  // first way finds.
  for (const bool singular : {false, true}) {
    for (const S& offset : {S(1e-5), S(1e-4), S(1e-3), S(1e-6)}) {
      for (const int side : {-1, 1}) {
        if (stop.stop_requested()) {
          none.problem = ChainOrbitProblem::Stopped;
          return none;
        }
        const S energy = doubling.energy * (1 + side * offset);
        const ChainOrbitSearch<S> parent =
            findChainOrbit(chain, doubling.state, parentImpacts, ChainOrbitConstraint::Energy, energy, stop);
        if (!parent.orbit) continue;
        // in the scaled units
        const ChainMatrix<S> shifted =
            scale.scaled(parent.orbit->monodromy.matrix) + ChainMatrix<S>::Identity(2 * n, 2 * n);
        ChainVector<S> v = ChainVector<S>::Ones(2 * n);
        if (singular) {
          v = Eigen::JacobiSVD<ChainMatrix<S>>(shifted, Eigen::ComputeFullV).matrixV().col(2 * n - 1);
        } else {
          const Eigen::FullPivLU<ChainMatrix<S>> lu(shifted);
          for (int iteration = 0; iteration < 6; ++iteration) {
            v = lu.solve(v);
            const S size = v.norm();
            if (!(size > 0) || !isFinite(size)) break;
            v /= size;
          }
        }
        if (!isFinite(S(v.cwiseAbs().maxCoeff()))) continue;
        std::vector<S> pushes;
        if (singular) {
          // (no farther than the first way's farthest: beyond it only `accept` would keep the
          // orbit found near this doubling, and each of its checks follows 40 orbits)
          for (const double c : {1.0, 0.3, 3.0, 10.0, 30.0, 2.0, 5.0, 20.0}) {
            if (S(c) * sqrt(offset) <= S(0.1)) pushes.push_back(S(c) * sqrt(offset));
          }
        } else {
          pushes = {S(1e-3), S(3e-3), S(1e-2), S(3e-2), S(1e-1)};
        }
        for (const S& push : pushes) {
          for (const int way : {1, -1}) {
            BasicChainState<S> guess = parent.orbit->state;
            guess.u += (way * push * scale.length) * v.head(n);
            guess.v += (way * push * scale.speed) * v.tail(n);
            guess.u[dynamics.stop] = dynamics.gap;
            ChainOrbitSearch<S> found =
                findChainOrbit(chain, guess, 2 * parentImpacts, ChainOrbitConstraint::Energy, energy, stop);
            // (the branch's orbit, near the parent: not another orbit of twice the impacts)
            if (found.orbit &&
                abs(found.orbit->period - 2 * parent.orbit->period) <= S(0.01) * parent.orbit->period &&
                scaledDistance(scale, found.orbit->state, parent.orbit->state) <= 3 * push &&
                (!accept || accept(*found.orbit))) {
              return found;
            }
          }
        }
      }
    }
  }
  return none;
}

#define GRAZELAB_INSTANTIATE(S)                                                                        \
  template ContinuedChainFamily<S> continueChainFamily<S>(const BasicReadyChain<S>&,                   \
                                                          const BasicChainPeriodicOrbit<S>&, int,      \
                                                          const ChainContinuationOptions<S>&, std::stop_token); \
  template ChainOrbitSearch<S> branchAtDoubling<S>(const BasicReadyChain<S>&, const ChainFamilyChange<S>&, int,     \
                                                   std::stop_token,                                              \
                                                   const std::function<bool(const BasicChainPeriodicOrbit<S>&)>&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)

}  // namespace grazelab::core
