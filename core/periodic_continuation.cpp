// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/periodic_continuation.h"

#include "core/orbits.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace grazelab::core {

namespace {

template <typename S>
using Vector3 = std::array<S, 3>;

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
  std::array<Vector3<S>, 2> jacobian{};
  PeriodicOrbit<S> orbit;
};

template <typename S>
Evaluation<S> evaluate(const Chain<S>& chain, const Units<S>& units, const Vector3<S>& y, int impacts) {
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
  e.jacobian[0] = {dp[0][0] - S(1), dp[0][1] * units.speed / units.position,
                   e.orbit.energyDerivative[0] * energy / units.position};
  e.jacobian[1] = {dp[1][0] * units.position / units.speed, dp[1][1] - S(1),
                   e.orbit.energyDerivative[1] * energy / units.speed};
  e.usable = true;
  return e;
}

template <typename S>
S norm(const Vector3<S>& v) {
  using std::sqrt;
  return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// The unit tangent of the family: the null vector of the 2x3 Jacobian, turned to agree with
// `along`.
template <typename S>
Vector3<S> tangent(const std::array<Vector3<S>, 2>& j, const Vector3<S>& along) {
  Vector3<S> t = {j[0][1] * j[1][2] - j[0][2] * j[1][1], j[0][2] * j[1][0] - j[0][0] * j[1][2],
                  j[0][0] * j[1][1] - j[0][1] * j[1][0]};
  const S size = norm(t);
  for (S& c : t) c /= size;
  if (t[0] * along[0] + t[1] * along[1] + t[2] * along[2] < 0) {
    for (S& c : t) c = -c;
  }
  return t;
}

// Solves the 3x3 system a x = b by elimination with partial pivoting; nothing when singular.
template <typename S>
std::optional<Vector3<S>> solve(std::array<Vector3<S>, 3> a, Vector3<S> b) {
  using std::abs;
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int row = col + 1; row < 3; ++row) {
      if (abs(a[std::size_t(row)][std::size_t(col)]) > abs(a[std::size_t(pivot)][std::size_t(col)])) pivot = row;
    }
    if (!(abs(a[std::size_t(pivot)][std::size_t(col)]) > S(0))) return std::nullopt;
    std::swap(a[std::size_t(col)], a[std::size_t(pivot)]);
    std::swap(b[std::size_t(col)], b[std::size_t(pivot)]);
    for (int row = col + 1; row < 3; ++row) {
      const S factor = a[std::size_t(row)][std::size_t(col)] / a[std::size_t(col)][std::size_t(col)];
      for (int k = col; k < 3; ++k) a[std::size_t(row)][std::size_t(k)] -= factor * a[std::size_t(col)][std::size_t(k)];
      b[std::size_t(row)] -= factor * b[std::size_t(col)];
    }
  }
  Vector3<S> x{};
  for (int row = 2; row >= 0; --row) {
    S sum = b[std::size_t(row)];
    for (int k = row + 1; k < 3; ++k) sum -= a[std::size_t(row)][std::size_t(k)] * x[std::size_t(k)];
    x[std::size_t(row)] = sum / a[std::size_t(row)][std::size_t(row)];
  }
  return x;
}

// A point of the family on the hyperplane through `predicted` normal to `t`: Newton on the
// family's equations and the arclength condition. Nothing when it does not converge.
template <typename S>
std::optional<std::pair<Vector3<S>, Evaluation<S>>> correct(const Chain<S>& chain, const Units<S>& units,
                                                            Vector3<S> y, const Vector3<S>& predicted,
                                                            const Vector3<S>& t, int impacts) {
  using std::abs;
  const S tolerance = S(64) * epsilon<S>() * std::max(S(1), norm(y));
  for (int iteration = 0; iteration < 12; ++iteration) {
    Evaluation<S> e = evaluate(chain, units, y, impacts);
    if (!e.usable) return std::nullopt;
    const S arclength = t[0] * (y[0] - predicted[0]) + t[1] * (y[1] - predicted[1]) + t[2] * (y[2] - predicted[2]);
    const S size = std::max({abs(e.residual[0]), abs(e.residual[1]), abs(arclength)});
    if (size <= tolerance) return std::pair{y, std::move(e)};
    const std::optional<Vector3<S>> step =
        solve<S>({e.jacobian[0], e.jacobian[1], t}, {-e.residual[0], -e.residual[1], -arclength});
    if (!step) return std::nullopt;
    for (int i = 0; i < 3; ++i) y[std::size_t(i)] += (*step)[std::size_t(i)];
  }
  return std::nullopt;
}

template <typename S>
FamilyOrbit<S> summary(const PeriodicOrbit<S>& orbit) {
  return {orbit.energy, orbit.period, orbit.trace, orbit.stability, orbit.state, orbit.minImpactSpeed,
          orbit.minClearance};
}

// The special point between two neighbours of the family where `test` changes sign, by
// bisection of the step from `from` along `t` (each trial corrected onto the family).
template <typename S, typename Test>
std::optional<PeriodicOrbit<S>> locate(const Chain<S>& chain, const Units<S>& units, const Vector3<S>& from,
                                       const Vector3<S>& t, S step, int impacts, const Test& test,
                                       bool signAtFrom) {
  S low = 0;
  S high = step;
  std::optional<PeriodicOrbit<S>> best;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const S middle = (low + high) / S(2);
    if (middle == low || middle == high) break;
    const Vector3<S> predicted = {from[0] + middle * t[0], from[1] + middle * t[1], from[2] + middle * t[2]};
    const auto corrected = correct(chain, units, predicted, predicted, t, impacts);
    if (!corrected) break;
    best = corrected->second.orbit;
    if (test(corrected->second.orbit) == signAtFrom) low = middle;
    else high = middle;
  }
  return best;
}

// An end where impact speeds tend to 0 is a square-root singularity of the family in its
// energy (the speeds go like the root of the distance to the end): the arclength steps stall
// short of it. The energy is bisected instead between `inside` (an orbit of the family) and
// `outside` (no orbit of the family), each trial solved by Newton at fixed energy from the
// nearest orbit found, down to the precision of S or to where S cannot decide the impacts.
template <typename S>
PeriodicOrbit<S> approachInEnergy(const Chain<S>& chain, const Units<S>& units, PeriodicOrbit<S> inside,
                                  S outside, int impacts) {
  using std::abs;
  const auto onFamily = [&](const S& energy) -> std::optional<PeriodicOrbit<S>> {
    OrbitSearch<S> found = findOrbit(chain, energy, inside.state.u1, inside.state.v1, impacts);
    if (!found.orbit) return std::nullopt;
    const bool near = abs(found.orbit->state.u1 - inside.state.u1) < S(0.05) * units.position &&
                      abs(found.orbit->state.v1 - inside.state.v1) < S(0.05) * units.speed;
    return near ? std::move(found.orbit) : std::nullopt;
  };
  if (onFamily(outside)) return inside;  // the family goes on there: nothing to refine
  for (int step = 0; step < 200; ++step) {
    const S middle = (inside.energy + outside) / S(2);
    if (middle == inside.energy || middle == outside) break;
    if (std::optional<PeriodicOrbit<S>> found = onFamily(middle)) inside = std::move(*found);
    else outside = middle;
  }
  return inside;
}

// A family whose impacts all fade ends on a grazing linear orbit. Two such limits are known
// exactly: a period tending to an odd number of fast periods T1 belongs to GLOM1 alone (every
// free motion repeats after T2 = 2 T1; only the pure fast mode after T1), and the one-impact
// family ends on GLO_lambda* at T2 (Theorem 2.1). The end then is the limit orbit itself.
template <typename S>
void endOnGrazingOrbit(const Chain<S>& chain, int impacts, FamilyEnd<S>& end) {
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

}  // namespace

template <typename S>
ContinuedFamily<S> continueFamily(const Chain<S>& chain, const PeriodicOrbit<S>& start,
                                  int direction, const ContinuationOptions<S>& options,
                                  std::stop_token stop) {
  using std::abs;
  ContinuedFamily<S> family;
  family.impacts = start.impacts;
  const int k = start.impacts;
  const Units<S> units{chain.model.gap, S(chain.model.gap * chain.omegaSlow), start.energy};
  Vector3<S> y = {start.state.u1 / units.position, start.state.v1 / units.speed, S(0)};
  Evaluation<S> here = evaluate(chain, units, y, k);
  const auto finish = [&](const std::string& kind, const PeriodicOrbit<S>& last) {
    family.end = {kind, last.energy, last.period, last.state};
    family.end.lastEnergy = last.energy;
    if (kind == "grazing-orbit") {
      family.end.gloLambda = (last.state.u1 / chain.model.gap - chain.rhoFast) / (chain.rhoSlow - chain.rhoFast);
      endOnGrazingOrbit(chain, k, family.end);
    }
    return family;
  };
  if (!here.usable) return finish("undecided", start);
  family.orbits.push_back(summary(start));
  Vector3<S> t = tangent(here.jacobian, Vector3<S>{S(0), S(0), S(direction)});
  S h = S(options.firstStep);
  PeriodicOrbit<S> last = start;
  for (int step = 0; step < options.maxSteps; ++step) {
    if (stop.stop_requested()) return finish("stopped", last);
    const Vector3<S> predicted = {y[0] + h * t[0], y[1] + h * t[1], y[2] + h * t[2]};
    const auto corrected = correct(chain, units, predicted, predicted, t, k);
    const bool admissible = corrected && evaluateOrbit(chain, corrected->second.orbit.state, k,
                                                       defaultCloseTolerance<S>()).admissible;
    if (!admissible) {
      if (h > S(options.minStep)) {
        h /= S(2);
        continue;
      }
      // the family ends here: say how, from the orbit it ends on and the path just beyond
      const Evaluation<S> beyond = evaluate(chain, units,
                                            Vector3<S>{y[0] + S(4) * h * t[0], y[1] + S(4) * h * t[1],
                                                       y[2] + S(4) * h * t[2]}, k);
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
      std::string kind = "undecided";
      // every impact fading (and any interior maximum reaching the stop): the orbit becomes a
      // linear orbit that touches the stop, a grazing orbit
      if (allSlow || (slow && close)) kind = "grazing-orbit";
      else if (slow) kind = "impact-speed-zero";
      else if (close || touches) kind = "interior-grazing";
      if (slow) {
        // located in the energy, past where the arclength steps stalled
        using std::exp;
        const S beyond = last.energy * exp(S(t[2] > 0 ? 1 : -1) * std::max(S(4) * h, S(1e-3)));
        PeriodicOrbit<S> nearer = approachInEnergy(chain, units, last, beyond, k);
        if (nearer.energy != last.energy) {
          last = std::move(nearer);
          family.orbits.push_back(summary(last));  // a row of its own only when it got nearer
        }
      }
      return finish(kind, last);
    }
    const Vector3<S> next = corrected->first;
    const Evaluation<S>& there = corrected->second;
    const PeriodicOrbit<S>& orbit = there.orbit;
    if (orbit.energy < options.energyLow || orbit.energy > options.energyHigh) {
      return finish("energy-limit", last);
    }
    const Vector3<S> nextTangent = tangent(there.jacobian, t);
    // special points between the two neighbours
    const auto crossedLevel = [&](const S& level) { return (last.trace - level > 0) != (orbit.trace - level > 0); };
    if (crossedLevel(S(-2))) {
      const auto at = locate(chain, units, y, t, h, k, [](const PeriodicOrbit<S>& o) { return o.trace + S(2) > 0; },
                             last.trace + S(2) > 0);
      if (at) family.bifurcations.push_back({"period-doubling", at->period, at->energy, at->trace, at->state});
    }
    const bool turns = (t[2] > 0) != (nextTangent[2] > 0);
    if (crossedLevel(S(2))) {
      const auto at = locate(chain, units, y, t, h, k, [](const PeriodicOrbit<S>& o) { return o.trace - S(2) > 0; },
                             last.trace - S(2) > 0);
      if (at) family.bifurcations.push_back({turns ? "fold" : "branch-point", at->period, at->energy, at->trace, at->state});
    } else if (turns) {
      // the energy turns back without the trace crossing 2 within the step: a fold, placed to
      // the step's resolution only
      family.bifurcations.push_back({"fold", orbit.period, orbit.energy, orbit.trace, orbit.state});
    }
    y = next;
    t = nextTangent;
    last = orbit;
    family.orbits.push_back(summary(orbit));
    // a converged step that cost little grows; the corrector's failures shrank it above
    h = std::min(S(options.maxStep), S(h * S(1.5)));
  }
  return finish("step-limit", last);
}

#define GRAZELAB_INSTANTIATE(S)                                                             \
  template ContinuedFamily<S> continueFamily<S>(const Chain<S>&, const PeriodicOrbit<S>&, int, \
                                                const ContinuationOptions<S>&, std::stop_token);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
