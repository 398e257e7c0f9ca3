// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/numbers/roots.h"
#include "core/orbits/family_continuation.h"

#include "core/orbits/special_orbits.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <Eigen/Geometry>
#include <Eigen/LU>

namespace grazelab::core {

namespace {

template <typename S>
using Vector3 = Eigen::Matrix<S, 3, 1>;

// The continuation works in units that make a step mean the same in every direction: u1 in
// gaps, v1 in w2 gaps, and the energy by its logarithm, ln(E / E0) (families span decades of
// energy, and the frequency-energy picture is drawn on a log scale).
template <typename S>
struct Units {
  S position;
  S speed;
  S energy;
};

// What the family's equations say at a point y = (u1, v1, E) (scaled): the residual
// P^k(x) - x, its Jacobian [DP^k - I | dP^k/dE], and the orbit through the point.
template <typename S>
struct Evaluation {
  bool usable = false;  ///< the path from y has exactly k impacts (the equations are defined)
  std::array<S, 2> residual{};
  Eigen::Matrix<S, 2, 3> jacobian = Eigen::Matrix<S, 2, 3>::Zero();
  PeriodicOrbit<S> orbit;
};

template <typename S>
Evaluation<S> evaluate(const TwoMassForm<S>& chain, const Units<S>& units, const Vector3<S>& y, int impacts) {
  Evaluation<S> e;
  using std::exp;
  const S energy = units.energy * exp(y[2]);
  const std::optional<BasicState<S>> start =
      sectionState(chain, energy, S(y[0] * units.position), S(y[1] * units.speed));
  if (!start) return e;
  e.orbit = evaluateOrbit(chain, *start, impacts, std::numeric_limits<S>::infinity());
  if (e.orbit.events.size() != std::size_t(impacts)) return e;
  for (const BasicEvent<S>& event : e.orbit.events) {
    if (event.type != EventType::Impact) return e;
  }
  const BasicState<S>& end = e.orbit.events.back().after;
  e.residual = {(end.u1 - start->u1) / units.position, (end.v1 - start->v1) / units.speed};
  const Matrix2<S>& dp = e.orbit.reduced;
  // d/d ln E = E d/dE
  e.jacobian << dp(0, 0) - S(1), dp(0, 1) * units.speed / units.position,
      e.orbit.energyDerivative[0] * energy / units.position,  //
      dp(1, 0) * units.position / units.speed, dp(1, 1) - S(1), e.orbit.energyDerivative[1] * energy / units.speed;
  e.usable = true;
  return e;
}

template <typename S>
S norm(const Vector3<S>& v) {
  using std::sqrt;
  return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// The unit tangent of the family: the null vector of the 2x3 Jacobian (the cross product of
// its rows), turned to agree with `along`.
template <typename S>
Vector3<S> tangent(const Eigen::Matrix<S, 2, 3>& j, const Vector3<S>& along) {
  Vector3<S> t = j.row(0).cross(j.row(1)).transpose();
  t /= norm(t);
  if (t.dot(along) < 0) t = -t;
  return t;
}

// Solves the 3x3 system (the Jacobian's rows over `t`) x = b by LU with full pivoting (the most
// robust of the LUs: next to a fold or branch point the system is nearly singular);
// nothing when a pivot is zero (singular).
template <typename S>
std::optional<Vector3<S>> solve(const Eigen::Matrix<S, 2, 3>& jacobian, const Vector3<S>& t, const Vector3<S>& b) {
  Eigen::Matrix<S, 3, 3> a;
  a << jacobian, t.transpose();
  const Eigen::FullPivLU<Eigen::Matrix<S, 3, 3>> lu(a);
  for (int i = 0; i < 3; ++i) {
    if (!(lu.matrixLU()(i, i) != S(0))) return std::nullopt;
  }
  return Vector3<S>(lu.solve(b));
}

// A point of the family on the hyperplane through `plane` normal to `t`, by Newton on the
// family's equations and the arclength condition from `y`. Nothing when it does not converge,
// or when it converges farther than `reach` from `y`: an orbit that far from the predictor
// belongs to another family.
template <typename S>
std::optional<std::pair<Vector3<S>, Evaluation<S>>> correct(const TwoMassForm<S>& chain, const Units<S>& units,
                                                            Vector3<S> y, const Vector3<S>& plane,
                                                            const Vector3<S>& t, int impacts, const S& reach) {
  using std::abs;
  const S tolerance = S(64) * epsilon<S>() * std::max(S(1), norm(y));
  S previousStep = std::numeric_limits<S>::infinity();  // the smallest so far
  int sinceSmallest = 0;
  const Vector3<S> predicted = y;
  const auto near = [&](const Vector3<S>& x, const S& bound) { return norm<S>(x - predicted) <= bound; };
  const auto converged = [&](Evaluation<S>&& e) -> std::optional<std::pair<Vector3<S>, Evaluation<S>>> {
    if (!near(y, reach)) return std::nullopt;  // an orbit of another family
    return std::pair{y, std::move(e)};
  };
  for (int iteration = 0; iteration < 40; ++iteration) {
    Evaluation<S> e = evaluate(chain, units, y, impacts);
    if (!e.usable) return std::nullopt;
    const S arclength = t.dot(y - plane);
    const S size = std::max({abs(e.residual[0]), abs(e.residual[1]), abs(arclength)});
    if (size <= tolerance) return converged(std::move(e));
    const std::optional<Vector3<S>> step = solve<S>(e.jacobian, t, Vector3<S>(-e.residual[0], -e.residual[1], -arclength));
    if (!step) return std::nullopt;
    // Newton contracts near a regular point and at least halves its steps near a singular one
    const S stepSize = norm(*step);
    // a correction within the rounding of y: the residual is at the noise of the path itself
    if (stepSize <= tolerance) return converged(std::move(e));
    if (stepSize < previousStep) {
      previousStep = stepSize;
      sinceSmallest = 0;
    } else if (++sinceSmallest >= 3) {
      // steps that no longer fall: at the noise of the path when the residual is as small as
      // an orbit of this amplification can close, else not converging
      if (size <= closeTolerance(e.orbit)) return converged(std::move(e));
      return std::nullopt;
    }
    y += *step;
    // a strongly sheared map (a light mass 2: DP's entries in the thousands) sends the first
    // iterates far across the family before they come back; only wandering off is cut short
    if (!near(y, S(100) * reach)) return std::nullopt;
  }
  return std::nullopt;
}

template <typename S>
Vector3<S> along(const Vector3<S>& from, const S& h, const Vector3<S>& t) {
  return from + h * t;
}

template <typename S>
Vector3<S> between(const Vector3<S>& a, const Vector3<S>& b, const S& fraction) {
  return a + fraction * (b - a);
}

// The special point between two neighbours of the family where `test` changes sign, by
// bisection of the hyperplane's distance from `from` along `t` (0 at `from`, `step` at `to`),
// each trial predicted on the chord between the nearest corrected points of either side (its
// error falls like the square of the bracket, so the corrector still converges near a branch
// point, where its basin shrinks like the distance) and corrected onto the family. The
// corrected orbits on either side of the last bracket.
template <typename S, typename Test>
std::pair<std::optional<PeriodicOrbit<S>>, std::optional<PeriodicOrbit<S>>> locate(
    const TwoMassForm<S>& chain, const Units<S>& units, const Vector3<S>& from, const Vector3<S>& to,
    const Vector3<S>& t, S step, int impacts, const Test& test, bool signAtFrom, std::stop_token stop,
    std::vector<TraceSample<S>>* met = nullptr) {
  Vector3<S> yLow = from;
  Vector3<S> yHigh = to;
  std::optional<PeriodicOrbit<S>> lowOrbit;
  std::optional<PeriodicOrbit<S>> highOrbit;
  bool lost = false;  // a trial the corrector could not bring onto the family ends the search
  const auto onFromsSide = [&](const S& middle) {
    const Vector3<S> plane = along(from, middle, t);
    const Vector3<S> predicted = between(yLow, yHigh, S(0.5));
    // near a branch point Newton's first steps are long across the singular direction: the
    // trial may go as far as the whole step, no farther
    const auto corrected = correct(chain, units, predicted, plane, t, impacts, step);
    if (!corrected) {
      lost = true;
      return false;
    }
    if (met) met->push_back({corrected->second.orbit.energy, corrected->second.orbit.trace});
    if (test(corrected->second) == signAtFrom) {
      yLow = corrected->first;
      lowOrbit = corrected->second.orbit;
      return true;
    }
    yHigh = corrected->first;
    highOrbit = corrected->second.orbit;
    return false;
  };
  bisectBoundary(S(0), step, onFromsSide, [&] { return lost || stop.stop_requested(); });
  return {lowOrbit, highOrbit};
}

// An end where impact speeds tend to 0 is a square-root singularity of the family in its
// energy (the speeds go like the root of the distance to the end): the arclength steps stall
// short of it. The energy is bisected instead between `inside` (an orbit of the family) and
// `outside` (no orbit of the family), each trial solved by Newton at fixed energy from the
// nearest orbit found, down to the precision of S or to where S cannot decide the impacts.
template <typename S>
PeriodicOrbit<S> approachInEnergy(const TwoMassForm<S>& chain, const Units<S>& units, PeriodicOrbit<S> inside,
                                  S outside, int impacts, std::stop_token stop) {
  using std::abs;
  const auto onFamily = [&](const S& energy) -> std::optional<PeriodicOrbit<S>> {
    OrbitSearch<S> found = findOrbit(chain, energy, inside.state.u1, inside.state.v1, impacts, stop);
    if (!found.orbit) return std::nullopt;
    // the same family: near in the section and in the period (another family's orbit can sit
    // near the same point of H: a 4-impact orbit of period 5 T1 beside one of 32.6 at E = 3)
    const bool near = abs(found.orbit->state.u1 - inside.state.u1) < S(0.05) * units.position &&
                      abs(found.orbit->state.v1 - inside.state.v1) < S(0.05) * units.speed &&
                      abs(found.orbit->period - inside.period) < S(1e-3) * inside.period;
    return near && determinantChecked(*found.orbit) ? std::move(found.orbit) : std::nullopt;
  };
  if (onFamily(outside)) return inside;  // the family goes on there: nothing to refine
  // the bracket in the energies asked for (an orbit's own energy differs from its target by
  // a rounding, which must not keep the bisection from closing)
  const auto keepsFamily = [&](const S& energy) {
    std::optional<PeriodicOrbit<S>> found = onFamily(energy);
    if (found) inside = std::move(*found);
    return found.has_value();
  };
  bisectBoundary(inside.energy, outside, keepsFamily, [&] { return stop.stop_requested(); });
  return inside;
}

// How far the orbit is, after half its impacts, from where it started (in gaps and w2 gaps): 0
// when a 2k-impact orbit is a k-impact orbit run twice, as at the flip it was born at.
template <typename S>
S halfwayDistance(const Units<S>& units, const PeriodicOrbit<S>& orbit) {
  using std::abs;
  if (orbit.impacts % 2 != 0 || orbit.events.size() != std::size_t(orbit.impacts)) {
    return std::numeric_limits<S>::infinity();
  }
  const BasicState<S>& half = orbit.events[std::size_t(orbit.impacts / 2 - 1)].after;
  return std::max(abs(half.u1 - orbit.state.u1) / units.position, abs(half.v1 - orbit.state.v1) / units.speed);
}

}  // namespace

// A family whose impacts all fade ends on a grazing linear orbit. Two such limits are known
// exactly: a period tending to an odd number of fast periods T1 belongs to GLOM1 alone (every
// free motion repeats after T2 = 2 T1; only the pure fast mode after T1), and the one-impact
// family ends on GLO_lambda* at T2 (Theorem 2.1). The end then is the limit orbit itself.
template <typename S>
void nameGrazingEnd(const TwoMassForm<S>& chain, int impacts, FamilyEnd<S>& end) {
  using std::abs;
  using std::round;
  if (!chain.resonant) return;
  const S T2 = twoPi<S>() / chain.omegaSlow;
  const S T1 = T2 / S(2);
  const S fastPeriods = end.period / T1;
  const S nearest = round(fastPeriods);
  const bool odd = nearest > S(0) && static_cast<long long>(toDouble(nearest)) % 2 == 1;
  if (odd && abs(fastPeriods - nearest) < S(1e-2) && abs(end.gloLambda) < S(1e-2)) {
    end.state = glomData(chain, Mode::Fast);
    end.gloLambda = S(0);
    end.period = nearest * T1;
  } else if (impacts == 1 && abs(end.period / T2 - S(1)) < S(1e-2) &&
             abs(end.gloLambda - lambdaStar(chain)) < S(1e-2)) {
    end.gloLambda = lambdaStar(chain);
    end.state = gloData(chain, end.gloLambda);
    end.period = T2;
  } else {
    return;
  }
  end.energy = physicalEnergy(chain, end.state);
  end.exact = true;
}

template <typename S>
ContinuedFamily<S> continueFamily(const TwoMassForm<S>& chain, const PeriodicOrbit<S>& start,
                                  int direction, const ContinuationOptions<S>& options,
                                  std::stop_token stop) {
  using std::abs;
  ContinuedFamily<S> family;
  family.impacts = start.impacts;
  const int k = start.impacts;
  const Units<S> units{chain.model.gap, S(chain.model.gap * chain.omegaSlow), start.energy};
  Vector3<S> y = {start.state.u1 / units.position, start.state.v1 / units.speed, S(0)};
  Evaluation<S> here = evaluate(chain, units, y, k);
  const auto finish = [&](PointKind kind, const PeriodicOrbit<S>& last) {
    family.end = familyEndAt(kind, last);
    if (kind == PointKind::GrazingOrbit) {
      family.end.gloLambda = (last.state.u1 / chain.model.gap - chain.rhoFast) / (chain.rhoSlow - chain.rhoFast);
      nameGrazingEnd(chain, k, family.end);
    }
    return family;
  };
  if (!here.usable) return finish(PointKind::Undecided, start);
  family.orbits.push_back(summaryOf(start));
  Vector3<S> t = tangent(here.jacobian, Vector3<S>{S(0), S(0), S(direction)});
  S h = S(options.firstStep);
  // the resolution of S in the continuation's units: an end is approached down to it
  const S resolution = S(1024) * epsilon<S>() * std::max(S(1), norm(y));
  PeriodicOrbit<S> last = start;
  // a corrected orbit was evaluated with no closing tolerance: a row must be admissible in
  // every other way, closed as an orbit of its amplification can be, its stability decided
  const auto admissible = [&](const PeriodicOrbit<S>& orbit) {
    return orbit.admissible && orbit.checks.periodicityResidual <= closeTolerance(orbit) && determinantChecked(orbit);
  };
  for (int step = 0; step < options.maxSteps; ++step) {
    if (stop.stop_requested()) return finish(PointKind::Stopped, last);
    const Vector3<S> predicted = along(y, h, t);
    // the corrector moves across the step's hyperplane by about the curvature times h^2: an
    // iterate farther than h/2 from the predictor has jumped
    const auto corrected = correct(chain, units, predicted, predicted, t, k, S(h / S(2)));
    bool accepted = corrected && admissible(corrected->second.orbit);
    if (accepted) {
      // the orbit halfway must lie near the chord, be admissible, and show a trace that does
      // not bend across a level: otherwise the step could hide a jump or two crossings
      const Vector3<S> chord = corrected->first - y;
      const S length = norm(chord);
      const Vector3<S> normal = chord / length;
      const Vector3<S> middle = between(y, corrected->first, S(0.5));
      const auto halfway = correct(chain, units, middle, middle, normal, k, S(length / S(4)));
      accepted = halfway && admissible(halfway->second.orbit) &&
                 !traceMayCrossUnseen(last, halfway->second.orbit, corrected->second.orbit);
    }
    if (!accepted) {
      if (h > resolution) {
        h /= S(2);
        continue;
      }
      // the family ends here: say how, from the orbit it ends on and the path just beyond
      const Evaluation<S> beyond = evaluate(chain, units, along(y, S(4) * h, t), k);
      const bool touches = std::any_of(beyond.orbit.events.begin(), beyond.orbit.events.end(),
                                       [](const BasicEvent<S>& e) { return e.type != EventType::Impact; }) ||
                           (beyond.orbit.events.size() != std::size_t(k) && !beyond.orbit.events.empty()) ||
                           last.minClearance < S(1e-6);
      // how near the last orbit came to losing an impact or touching the stop (the approach
      // to a grazing is singular: the steps shrink before the speeds reach 0)
      const bool slow = last.minImpactSpeed < S(0.05) * units.speed;
      S fastest = 0;
      for (const BasicEvent<S>& event : last.events) fastest = std::max(fastest, event.before.v2);
      const bool allSlow = fastest < S(0.05) * units.speed;
      const bool close = last.minClearance < S(0.05);
      PointKind kind = PointKind::Undecided;
      // every impact fading (and any interior maximum reaching the stop): the orbit becomes a
      // linear orbit that touches the stop, a grazing orbit
      if (allSlow || (slow && close)) kind = PointKind::GrazingOrbit;
      else if (slow) kind = PointKind::ImpactSpeedZero;
      else if (close || touches) kind = PointKind::InteriorGrazing;
      if (slow) {
        // located in the energy, past where the arclength steps stalled
        using std::exp;
        const S outside = last.energy * exp(S(t[2] > 0 ? 1 : -1) * std::max(S(4) * h, S(1e-3)));
        PeriodicOrbit<S> nearer = approachInEnergy(chain, units, last, outside, k, stop);
        if (nearer.energy != last.energy) {
          last = std::move(nearer);
          family.orbits.push_back(summaryOf(last));  // a row of its own only when it got nearer
        }
      }
      if (stop.stop_requested()) return finish(PointKind::Stopped, last);
      return finish(kind, last);
    }
    const Vector3<S> next = corrected->first;
    const Evaluation<S>& there = corrected->second;
    const PeriodicOrbit<S>& orbit = there.orbit;
    if (orbit.energy < options.energyLow || orbit.energy > options.energyHigh) {
      return finish(PointKind::EnergyLimit, last);
    }
    const Vector3<S> nextTangent = tangent(there.jacobian, t);
    const bool turns = (t[2] > 0) != (nextTangent[2] > 0);
    // a 2k-impact family that comes back to a k-impact orbit run twice has reached a flip of
    // that family (its energy turns there: beyond lies the same orbit, begun half a period
    // later): it ends on the flip
    const S nearest = std::min(halfwayDistance(units, last), halfwayDistance(units, orbit));
    // (GLOM1, where the impacts of a family ending on it also merge, has impact speeds near 0;
    // a flip orbit's impacts are real)
    const bool impactsReal = std::min(last.minImpactSpeed, orbit.minImpactSpeed) > S(0.05) * units.speed;
    if (turns && impactsReal && nearest < S(0.02) && nearest < halfwayDistance(units, start) / S(2)) {
      const bool lastNearer = halfwayDistance(units, last) <= halfwayDistance(units, orbit);
      if (!lastNearer) family.orbits.push_back(summaryOf(orbit));
      return finish(PointKind::PeriodDoubling, lastNearer ? last : orbit);
    }
    // special points between the two neighbours
    std::vector<FamilyBifurcation<S>> found;
    const auto crossedLevel = [&](const S& level) { return sideOfLevel(last, level) * sideOfLevel(orbit, level) < 0; };
    for (const S& level : {S(-2), S(2)}) {
      if (!crossedLevel(level)) continue;
      const auto side = [level](const Evaluation<S>& e) { return e.orbit.trace - level > 0; };
      std::vector<TraceSample<S>> met = {{last.energy, last.trace}, {orbit.energy, orbit.trace}};
      const auto [low, high] = locate(chain, units, y, next, t, h, k, side, last.trace - level > 0, stop, &met);
      const auto nearer = [&]() -> std::optional<PeriodicOrbit<S>> {
        if (!low) return high;
        if (!high) return low;
        return abs(low->trace - level) <= abs(high->trace - level) ? low : high;
      }();
      const PeriodicOrbit<S>& at = nearer ? *nearer : orbit;
      FamilyBifurcation<S> point = specialPoint(
          level < 0 ? PointKind::PeriodDoubling : turns ? PointKind::Fold : PointKind::BranchPoint, at);
      // checked against its definition before it is given as one
      point.checked = nearer && abs(at.trace - level) <= traceLevelTolerance<S>();
      point.energyError = levelEnergyError(at, locatedTraceError(chain, at), met) + (low && high ? abs(high->energy - low->energy) : S(0));
      found.push_back(point);
    }
    if (turns && !crossedLevel(S(2))) {
      // the energy turns back without the trace crossing 2 within the step: the turn located
      // where the tangent's energy part changes sign, then checked like any fold
      const auto rising = [&](const Evaluation<S>& e) { return tangent(e.jacobian, t)[2] > 0; };
      const auto [low, high] = locate(chain, units, y, next, t, h, k, rising, t[2] > 0, stop);
      const std::optional<PeriodicOrbit<S>>& nearer = low ? low : high;
      const PeriodicOrbit<S>& at = nearer ? *nearer : orbit;
      FamilyBifurcation<S> point = specialPoint(PointKind::Fold, at);
      point.checked = nearer && abs(at.trace - S(2)) <= traceLevelTolerance<S>();
      // at a turn the energy is stationary along the family: its error is the bracket's
      point.energyError = low && high ? abs(high->energy - low->energy) : std::numeric_limits<S>::infinity();
      found.push_back(point);
    }
    family.bifurcations.insert(family.bifurcations.end(), found.begin(), found.end());
    y = next;
    t = nextTangent;
    last = orbit;
    family.orbits.push_back(summaryOf(orbit));
    // a converged step grows; the failures above shrank it
    h = std::min(S(options.maxStep), S(h * S(1.5)));
  }
  return finish(PointKind::StepLimit, last);
}

#define GRAZELAB_INSTANTIATE(S)                                                             \
  template void nameGrazingEnd<S>(const TwoMassForm<S>&, int, FamilyEnd<S>&);                      \
  template ContinuedFamily<S> continueFamily<S>(const TwoMassForm<S>&, const PeriodicOrbit<S>&, int, \
                                                const ContinuationOptions<S>&, std::stop_token);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
