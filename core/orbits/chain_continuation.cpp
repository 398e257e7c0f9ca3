// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/chain_continuation.h"

#include <Eigen/LU>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/numbers/eigen_quad.h"
#include "core/orbits/chain_return_map.h"

namespace grazelab::core {

std::string_view toString(ChainFamilyEnd end) {
  switch (end) {
    case ChainFamilyEnd::EnergyLimit: return "energy-limit";
    case ChainFamilyEnd::StepLimit: return "step-limit";
    case ChainFamilyEnd::Inadmissible: return "inadmissible";
    case ChainFamilyEnd::NotConverging: return "not-converging";
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

}  // namespace

template <typename S>
ContinuedChainFamily<S> continueChainFamily(const BasicReadyChain<S>& chain, const BasicChainPeriodicOrbit<S>& start,
                                            int direction, const ChainContinuationOptions<S>& options,
                                            std::stop_token stop) {
  using std::abs;
  using std::sqrt;
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
  family.orbits.push_back(start);
  FamilyAt<S> here = familyAt(unknowns, unit, w, start.state, k, chainCloseTolerance<S>(k, S(1)));
  if (!start.admissible() || !here.held) {
    family.end = ChainFamilyEnd::Inadmissible;
    family.refusal = start.admissible() ? here.path.refusal : start.refusal;
    return family;
  }
  ChainVector<S> way = ChainVector<S>::Zero(m);
  way[m - 1] = direction >= 0 ? 1 : -1;
  ChainVector<S> t = tangentOf(here.jacobian, way);
  S tolerance = here.tolerance;
  double h = options.firstStep;
  OrbitRefusal refusal = OrbitRefusal::None;  // the last refusal a failed step met
  constexpr int kCorrections = 12;
  while (int(family.orbits.size()) < options.maxOrbits) {
    if (stop.stop_requested()) {
      family.end = ChainFamilyEnd::Stopped;
      return family;
    }
    // the predictor along the tangent, then Newton on the family and the arclength's hyperplane
    const ChainVector<S> predicted = w + S(h) * t;
    ChainVector<S> y = predicted;
    // the first iterate that closes within its tolerance, polished while Newton still halves its
    // residual (a row is then as exact as S allows), and how far it may be along the map's softest
    // direction: the tolerance times the bordered Jacobian's inverse (next to a period doubling
    // the orbit is known only so far from the shorter one run twice)
    std::optional<FamilyAt<S>> accepted;
    ChainVector<S> acceptedY;
    S acceptedResidual = 0;
    S spread = 0;
    int corrections = 0;
    for (; corrections < kCorrections; ++corrections) {
      FamilyAt<S> at = familyAt(unknowns, unit, y, family.orbits.back().state, k, tolerance);
      if (!at.held) {
        refusal = at.path.refusal;
        break;
      }
      const S residual = at.path.periodicityResidual;
      if (accepted && !(residual < acceptedResidual / 2)) break;
      ChainMatrix<S> bordered(m, m);
      bordered.topRows(m - 1) = at.jacobian;
      bordered.row(m - 1) = t.transpose();
      ChainVector<S> g(m);
      g.head(m - 1) = at.residual;
      g[m - 1] = t.dot(y - predicted);
      const Eigen::FullPivLU<ChainMatrix<S>> lu(bordered);
      const bool invertible = lu.isInvertible();
      if (residual <= at.tolerance) {
        spread = invertible ? S(at.tolerance * largestRowSum(ChainMatrix<S>(lu.inverse()))) : S(1);
        acceptedResidual = residual;
        acceptedY = y;
        accepted = std::move(at);
        if (residual == 0) break;
      }
      if (!invertible) break;
      const ChainVector<S> dy = lu.solve(g);
      if (!isFinite(S(dy.cwiseAbs().maxCoeff())) || dy.norm() > S(2 * h)) break;  // (leaving the family)
      y -= dy;
    }
    // the orbit there: admissible, no shorter one run twice, and the family's tangent turned by
    // less than a quarter of a right angle (a larger turn is a jump onto another family)
    std::optional<BasicChainPeriodicOrbit<S>> orbit;
    std::optional<ChainVector<S>> turned;
    if (accepted) {
      BasicChainPeriodicOrbit<S> found = evaluateChainOrbit(chain, *accepted->start, k, accepted->tolerance);
      if (found.admissible() && isRepeated(dynamics, found, std::max(accepted->tolerance, spread))) {
        found.refusal = OrbitRefusal::Repeated;
      }
      if (found.admissible()) {
        const ChainVector<S> next = tangentOf(accepted->jacobian, t);
        if (next.dot(t) >= S(0.92)) {
          orbit = std::move(found);
          turned = next;
        }
      } else {
        refusal = found.refusal;
      }
    }
    if (!orbit) {
      h /= 2;
      if (h < options.minStep) {
        const bool said = refusal != OrbitRefusal::None && refusal != OrbitRefusal::NotClosed;
        family.end = said ? ChainFamilyEnd::Inadmissible : ChainFamilyEnd::NotConverging;
        family.refusal = said ? refusal : OrbitRefusal::None;
        return family;
      }
      continue;
    }
    if (!(orbit->energy >= options.energyLow && orbit->energy <= options.energyHigh)) {
      family.end = ChainFamilyEnd::EnergyLimit;
      return family;
    }
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
    h = corrections <= 3 ? std::min(2 * h, options.maxStep) : corrections >= 7 ? h / 2 : h;
  }
  family.end = ChainFamilyEnd::StepLimit;
  return family;
}

#define GRAZELAB_INSTANTIATE(S)                                                                        \
  template ContinuedChainFamily<S> continueChainFamily<S>(const BasicReadyChain<S>&,                   \
                                                          const BasicChainPeriodicOrbit<S>&, int,      \
                                                          const ChainContinuationOptions<S>&, std::stop_token);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)

}  // namespace grazelab::core
