// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/periodic_orbit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/orbits.h"
#include "core/simulate.h"

namespace grazelab::core {

namespace {

template <typename S>
Matrix4<S> identity4() {
  Matrix4<S> m{};
  for (int i = 0; i < 4; ++i) m[i][i] = S(1);
  return m;
}

template <typename S>
Matrix4<S> multiply(const Matrix4<S>& a, const Matrix4<S>& b) {
  Matrix4<S> c{};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      S sum = 0;
      for (int k = 0; k < 4; ++k) sum += a[i][k] * b[k][j];
      c[i][j] = sum;
    }
  }
  return c;
}

template <typename S>
std::array<S, 4> times(const Matrix4<S>& a, const std::array<S, 4>& x) {
  std::array<S, 4> y{};
  for (int i = 0; i < 4; ++i) {
    S sum = 0;
    for (int k = 0; k < 4; ++k) sum += a[i][k] * x[k];
    y[i] = sum;
  }
  return y;
}

template <typename S>
std::array<S, 4> asArray(const BasicState<S>& x) {
  return {x.u1, x.u2, x.v1, x.v2};
}

// The physical spring constant k2 the solver uses (the design value when designed).
template <typename S>
S stiffness2(const Chain<S>& chain) {
  return chain.kappa * chain.model.k1;
}

// The vector field of the free flight at x: (v1, v2, a1, a2).
template <typename S>
std::array<S, 4> field(const Chain<S>& chain, const BasicState<S>& x) {
  const BasicModel<S>& m = chain.model;
  const S k2 = stiffness2(chain);
  return {x.v1, x.v2, (-m.k1 * x.u1 + k2 * (x.u2 - x.u1)) / m.m1, k2 * (x.u1 - x.u2) / m.m2};
}

// Q diag(fast, slow) Q^-1 with Q = [[rhoFast, rhoSlow], [1, 1]] (the mode shapes u1/u2)
template <typename S>
std::array<std::array<S, 2>, 2> inModes(const Chain<S>& chain, const S& fast, const S& slow) {
  const S rf = chain.rhoFast;
  const S rs = chain.rhoSlow;
  const S scale = S(1) / (rf - rs);
  return {{{(rf * fast - rs * slow) * scale, rf * rs * (slow - fast) * scale},
           {(fast - slow) * scale, (rf * slow - rs * fast) * scale}}};
}

// Periodicity and symmetry are judged relative to the state's size: the gap for positions and
// w2 times the gap for speeds (the orbit's own size when it is larger).
template <typename S>
std::array<S, 4> stateScales(const Chain<S>& chain, const BasicState<S>& x) {
  using std::abs;
  const S d = chain.model.gap;
  const S position = std::max({d, abs(x.u1), abs(x.u2)});
  const S speed = std::max({d * chain.omegaSlow, abs(x.v1), abs(x.v2)});
  return {position, position, speed, speed};
}

template <typename S>
S relativeDistance(const Chain<S>& chain, const BasicState<S>& a, const BasicState<S>& b) {
  using std::abs;
  const std::array<S, 4> scale = stateScales(chain, a);
  const std::array<S, 4> x = asArray(a);
  const std::array<S, 4> y = asArray(b);
  S largest = 0;
  for (int i = 0; i < 4; ++i) largest = std::max(largest, S(abs(x[i] - y[i]) / scale[i]));
  return largest;
}

// The smallest clearance gap - u2 at an interior maximum of u2 on the flight of duration `tau`
// from `from`, over the gap; +infinity when u2 has no interior maximum. The maxima are where
// v2 turns from + to -: bracketed on 256 samples, then bisected to the precision of S.
template <typename S>
S flightClearance(const Chain<S>& chain, const BasicState<S>& from, const S& tau) {
  constexpr int kSamples = 256;
  const std::array<S, 4> x0 = asArray(from);
  const auto at = [&](const S& t) { return times(flowMatrix(chain, t), x0); };
  S least = std::numeric_limits<S>::infinity();
  std::array<S, 4> previous = x0;
  S tPrevious = 0;
  for (int i = 1; i < kSamples; ++i) {
    const S t = tau * S(i) / S(kSamples);
    const std::array<S, 4> x = at(t);
    if (previous[3] > 0 && x[3] <= 0) {
      S low = tPrevious;
      S high = t;
      for (int step = 0; step < 200 && high - low > epsilon<S>() * tau; ++step) {
        const S middle = (low + high) / S(2);
        if (at(middle)[3] > 0) low = middle;
        else high = middle;
      }
      const S u2 = at((low + high) / S(2))[1];
      least = std::min(least, S((chain.model.gap - u2) / chain.model.gap));
    }
    previous = x;
    tPrevious = t;
  }
  return least;
}

// The distance of M's trivial pair of eigenvalues from 1: the characteristic polynomial of M
// (Faddeev-LeVerrier), divided by the nontrivial factor l^2 - t l + 1 (t = tr M - 2); the
// quotient's roots are the trivial pair.
template <typename S>
S trivialPairDistance(const Matrix4<S>& m) {
  using std::abs;
  using std::sqrt;
  // p(l) = l^4 + c1 l^3 + c2 l^2 + c3 l + c4
  S c[5] = {S(1), 0, 0, 0, 0};
  Matrix4<S> accumulated = m;
  for (int k = 1; k <= 4; ++k) {
    S trace = 0;
    for (int i = 0; i < 4; ++i) trace += accumulated[i][i];
    c[k] = -trace / S(k);
    if (k == 4) break;
    Matrix4<S> next = accumulated;
    for (int i = 0; i < 4; ++i) next[i][i] += c[k];
    accumulated = multiply(m, next);
  }
  S traceM = 0;
  for (int i = 0; i < 4; ++i) traceM += m[i][i];
  const S t = traceM - S(2);
  // (l^2 - t l + 1)(l^2 + b l + e) = l^4 + (b - t) l^3 + (e - t b + 1) l^2 + (b - t e) l + e
  const S b = c[1] + t;
  const S e = c[2] + t * b - S(1);
  // the trivial pair: roots of l^2 + b l + e (ideally (l - 1)^2: b = -2, e = 1)
  const S discriminant = b * b / S(4) - e;
  const S centre = -b / S(2);
  if (discriminant >= 0) {
    const S root = sqrt(discriminant);
    return std::max(abs(centre + root - S(1)), abs(centre - root - S(1)));
  }
  const S imaginary = sqrt(-discriminant);
  return sqrt((centre - S(1)) * (centre - S(1)) + imaginary * imaginary);
}

}  // namespace

template <typename S>
Matrix4<S> flowMatrix(const Chain<S>& chain, const S& tau) {
  using std::cos;
  using std::sin;
  const S wSlow = chain.omegaSlow;
  const S wFast = chain.ratio * chain.omegaSlow;
  const S cf = cos(wFast * tau), sf = sin(wFast * tau);
  const S cs = cos(wSlow * tau), ss = sin(wSlow * tau);
  const auto position = inModes(chain, cf, cs);             // u from u, v from v
  const auto byVelocity = inModes(chain, S(sf / wFast), S(ss / wSlow));  // u from v
  const auto byPosition = inModes(chain, S(-wFast * sf), S(-wSlow * ss));  // v from u
  Matrix4<S> phi{};
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      phi[i][j] = position[i][j];
      phi[i][j + 2] = byVelocity[i][j];
      phi[i + 2][j] = byPosition[i][j];
      phi[i + 2][j + 2] = position[i][j];
    }
  }
  return phi;
}

template <typename S>
Matrix4<S> saltationMatrix(const Chain<S>& chain, const BasicState<S>& before) {
  Matrix4<S> s = identity4<S>();
  const S a2 = stiffness2(chain) * (before.u1 - chain.model.gap) / chain.model.m2;
  s[1][1] = S(-1);
  s[3][3] = S(-1);
  s[3][1] = S(2) * a2 / before.v2;
  return s;
}

template <typename S>
std::optional<BasicState<S>> sectionState(const Chain<S>& chain, const S& energy, const S& u1,
                                          const S& v1) {
  using std::sqrt;
  const BasicModel<S>& m = chain.model;
  const S stretch = m.gap - u1;
  const S rest = energy - (m.m1 * v1 * v1 + m.k1 * u1 * u1 + stiffness2(chain) * stretch * stretch) / S(2);
  if (!(rest >= 0) || !isFinite(rest)) return std::nullopt;
  return BasicState<S>{u1, m.gap, v1, S(-sqrt(S(2) * rest / m.m2))};
}

std::string_view toString(Stability stability) {
  switch (stability) {
    case Stability::Elliptic: return "elliptic";
    case Stability::Hyperbolic: return "hyperbolic";
    case Stability::FlipHyperbolic: return "flip-hyperbolic";
    case Stability::Parabolic: return "parabolic";
  }
  return "elliptic";
}

template <typename S>
S defaultCloseTolerance() {
  return S(512) * epsilon<S>();
}

template <typename S>
S closeTolerance(const PeriodicOrbit<S>& orbit) {
  using std::abs;
  // at most a million times the default: next to a grazing the saltation's 1 / v2 makes the
  // amplification grow without bound, while a path that far from closing is no orbit
  const S amplified = defaultCloseTolerance<S>() * S(8 * std::max(1, orbit.impacts)) *
                      std::max({S(1), abs(orbit.trace), orbit.amplification});
  return std::min(amplified, S(1e6) * defaultCloseTolerance<S>());
}

template <typename S>
bool stabilityDecided(const PeriodicOrbit<S>& orbit) {
  using std::abs;
  return abs(orbit.checks.detMinus1) <= S(1e3) * defaultCloseTolerance<S>();
}

template <typename S>
PeriodicOrbit<S> evaluateOrbit(const Chain<S>& chain, const BasicState<S>& start, int impacts,
                               const S& closeTolerance) {
  using std::abs;
  using std::sqrt;
  PeriodicOrbit<S> orbit;
  orbit.state = start;
  orbit.impacts = impacts;
  orbit.energy = physicalEnergy(chain, start);
  const auto refuse = [&orbit](OrbitRefusal refusal, std::string reason) {
    orbit.admissible = false;
    orbit.refusal = refusal;
    orbit.reason = std::move(reason);
    return orbit;
  };
  if (impacts < 1) return refuse(OrbitRefusal::BadStart, "an orbit needs at least one impact per period");
  if (!(start.u2 == chain.model.gap) || !(start.v2 <= 0)) {
    return refuse(OrbitRefusal::BadStart, "the start is not just after an impact (u2 = gap, v2 <= 0)");
  }
  BasicRequest<S> request;
  request.initial = start;
  request.maxContacts = impacts;
  request.needs.events = true;
  request.stopAtUndecided = true;
  const BasicResult<S> run = simulate(chain.model, request);
  orbit.events = run.events;
  if (run.stop == StopReason::Undecided) {
    return refuse(OrbitRefusal::Undecided, "a contact of the path is too near tangent for this precision to decide "
                  "(try a higher precision)");
  }
  if (std::int64_t(run.events.size()) != impacts) {
    return refuse(OrbitRefusal::ContactCount, "the path made " + std::to_string(run.events.size()) + " contacts, not " +
                  std::to_string(impacts));
  }
  // the monodromy, flight by flight, with the clearance of every flight
  Matrix4<S> monodromy = identity4<S>();
  S previousTime = 0;
  BasicState<S> leaving = start;
  orbit.minImpactSpeed = std::numeric_limits<S>::infinity();
  orbit.minClearance = std::numeric_limits<S>::infinity();
  for (const BasicEvent<S>& event : run.events) {
    if (event.type != EventType::Impact) {
      return refuse(OrbitRefusal::NotImpact, "the path has a " + std::string(toString(event.type)) + " at t = " +
                    formatScalar(event.t) + ", not only impacts");
    }
    const S tau = event.t - previousTime;
    monodromy = multiply(saltationMatrix(chain, event.before), multiply(flowMatrix(chain, tau), monodromy));
    orbit.minImpactSpeed = std::min(orbit.minImpactSpeed, event.before.v2);
    orbit.minClearance = std::min(orbit.minClearance, flightClearance(chain, leaving, tau));
    previousTime = event.t;
    leaving = event.after;
  }
  orbit.period = previousTime;
  orbit.monodromy = monodromy;
  const BasicState<S>& end = run.events.back().after;
  orbit.checks.periodicityResidual = relativeDistance(chain, start, end);
  // the reduced Jacobian at fixed energy: lift (du1, dv1) onto the energy level at the start,
  // carry it by M, project along the flow onto H at the end
  const BasicModel<S>& m = chain.model;
  const S dEdu1 = m.k1 * start.u1 + stiffness2(chain) * (start.u1 - start.u2);
  const S dEdv1 = m.m1 * start.v1;
  const S dEdv2 = m.m2 * start.v2;
  const std::array<std::array<S, 4>, 3> lifts = {{
      {S(1), S(0), S(0), S(-dEdu1 / dEdv2)},  // du1
      {S(0), S(0), S(1), S(-dEdv1 / dEdv2)},  // dv1
      {S(0), S(0), S(0), S(S(1) / dEdv2)},    // dE
  }};
  const std::array<S, 4> flow = field(chain, end);
  std::array<std::array<S, 4>, 3> carried{};
  for (int c = 0; c < 3; ++c) {
    std::array<S, 4> y = times(monodromy, lifts[std::size_t(c)]);
    const S along = y[1] / flow[1];  // the time shift that brings u2 back onto H
    for (int i = 0; i < 4; ++i) y[i] -= along * flow[i];
    carried[std::size_t(c)] = y;
  }
  orbit.reduced = {{{carried[0][0], carried[1][0]}, {carried[0][2], carried[1][2]}}};
  orbit.energyDerivative = {carried[2][0], carried[2][2]};
  {
    const S w = chain.omegaSlow;  // (u1 / d, v1 / (w d)): DP's entries as the continuation sees them
    orbit.amplification = std::max({S(1), abs(orbit.reduced[0][0]), abs(orbit.reduced[1][1]),
                                    abs(orbit.reduced[0][1] * w), abs(orbit.reduced[1][0] / w)});
  }
  const S trace = orbit.reduced[0][0] + orbit.reduced[1][1];
  const S det = orbit.reduced[0][0] * orbit.reduced[1][1] - orbit.reduced[0][1] * orbit.reduced[1][0];
  orbit.trace = trace;
  orbit.checks.detMinus1 = det - S(1);
  orbit.checks.trivialPair = trivialPairDistance(monodromy);
  const S discriminant = trace * trace / S(4) - det;
  if (discriminant >= 0) {
    const S root = sqrt(discriminant);
    orbit.multipliers = {{{trace / S(2) + root, S(0)}, {trace / S(2) - root, S(0)}}};
  } else {
    const S root = sqrt(-discriminant);
    orbit.multipliers = {{{trace / S(2), root}, {trace / S(2), -root}}};
  }
  // |tr| = 2 within what the checks say the rounding is (at least 64 ulps)
  const S rounding = std::max({S(64) * epsilon<S>(), S(4) * abs(orbit.checks.detMinus1),
                               S(4) * orbit.checks.trivialPair * orbit.checks.trivialPair});
  if (abs(abs(trace) - S(2)) <= rounding * std::max(S(1), abs(trace))) orbit.stability = Stability::Parabolic;
  else if (trace > S(2)) orbit.stability = Stability::Hyperbolic;
  else if (trace < S(-2)) orbit.stability = Stability::FlipHyperbolic;
  else orbit.stability = Stability::Elliptic;
  if (!(orbit.checks.periodicityResidual <= closeTolerance)) {
    return refuse(OrbitRefusal::NotClosed, "the path does not close: it is " + formatScalar(orbit.checks.periodicityResidual) +
                  " (relative) from its start after " + std::to_string(impacts) + " impacts");
  }
  // minimal: not a shorter orbit repeated (its state after j impacts, j dividing k, elsewhere)
  for (int j = 1; j < impacts; ++j) {
    if (impacts % j != 0) continue;
    // within what a computed orbit's closing allows in S (2e-9 in double, 2e-27 in binary128)
    if (relativeDistance(chain, start, run.events[std::size_t(j - 1)].after) <= S(1e7) * epsilon<S>()) {
      return refuse(OrbitRefusal::Repeated, "the orbit is a " + std::to_string(j) + "-impact orbit repeated");
    }
  }
  if (!(orbit.minClearance > 0)) return refuse(OrbitRefusal::TouchesStop, "a flight touches or crosses the stop between impacts");
  orbit.admissible = true;
  return orbit;
}

template <typename S>
OrbitSearch<S> findOrbit(const Chain<S>& chain, const S& energy, const S& u1, const S& v1,
                         int impacts, std::stop_token stop) {
  using std::abs;
  OrbitSearch<S> search;
  S x = u1;
  S y = v1;
  constexpr int kIterations = 60;
  // Newton converges in a few steps from a guess near an orbit; a residual that has not
  // improved on its best for this many iterations is wandering, not converging
  constexpr int kPatience = 8;
  S bestResidual = std::numeric_limits<S>::infinity();
  int bestIteration = 0;
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    search.iterations = iteration + 1;
    if (stop.stop_requested()) {
      search.problem = "stopped";
      return search;
    }
    const std::optional<BasicState<S>> start = sectionState(chain, energy, x, y);
    if (!start && iteration == 0) {
      search.problem = "no state of energy " + formatScalar(energy) + " at the guess u1 = " +
                       formatScalar(x) + ", v1 = " + formatScalar(y) +
                       " on H: mass 1 and the springs alone hold more there; give a guess nearer "
                       "u1 = k2 d / (k1 + k2), v1 = 0";
      return search;
    }
    if (!start) {
      search.problem = "Newton left the energy level at iteration " + std::to_string(iteration + 1) +
                       " (u1 = " + formatScalar(x) + ", v1 = " + formatScalar(y) +
                       "): give a guess nearer the orbit";
      return search;
    }
    PeriodicOrbit<S> orbit = evaluateOrbit(chain, *start, impacts, std::numeric_limits<S>::infinity());
    if (orbit.events.size() != std::size_t(impacts) ||
        std::any_of(orbit.events.begin(), orbit.events.end(),
                    [](const BasicEvent<S>& e) { return e.type != EventType::Impact; })) {
      search.refusal = orbit.refusal;
      search.problem = "Newton left the " + std::to_string(impacts) + "-impact orbits at iteration " +
                       std::to_string(iteration + 1) + " (" + orbit.reason + ")";
      return search;
    }
    if (orbit.checks.periodicityResidual <= closeTolerance(orbit)) {
      if (!orbit.admissible) {
        search.refusal = orbit.refusal;
        search.problem = "the orbit found is not admissible: " + orbit.reason;
        return search;
      }
      search.orbit = std::move(orbit);
      return search;
    }
    if (orbit.checks.periodicityResidual < bestResidual) {
      bestResidual = orbit.checks.periodicityResidual;
      bestIteration = iteration;
    } else if (iteration - bestIteration >= kPatience) {
      search.problem = "Newton does not converge from this guess (its residual stopped falling at " +
                       formatScalar(bestResidual) + ")";
      return search;
    }
    // Newton on P^k(x) - x = 0 with the exact Jacobian DP^k - I
    const BasicState<S>& end = orbit.events.back().after;
    const S f0 = end.u1 - x;
    const S f1 = end.v1 - y;
    const S a = orbit.reduced[0][0] - S(1), b = orbit.reduced[0][1];
    const S c = orbit.reduced[1][0], d = orbit.reduced[1][1] - S(1);
    const S det = a * d - b * c;
    if (!(abs(det) > S(0)) || !isFinite(det)) {
      search.problem = "the Jacobian DP^k - I is singular (a fold or branch point: tr DP^k = 2)";
      return search;
    }
    x -= (d * f0 - b * f1) / det;
    y -= (-c * f0 + a * f1) / det;
  }
  search.problem = "Newton did not converge in " + std::to_string(kIterations) + " iterations";
  return search;
}

template <typename S>
OrbitSearch<S> onePeriodicOrbitStability(const Chain<S>& chain, const S& T) {
  OrbitSearch<S> search;
  const OnePeriodicOrbit<S> data = onePeriodicOrbit(chain, T);
  if (!data.admissible) {
    if (data.refusal == OnePeriodicRefusal::NotDecided) search.refusal = OrbitRefusal::Undecided;
    search.problem = "no admissible 1IPP orbit of period " + formatScalar(T) + ": " + data.reason;
    return search;
  }
  PeriodicOrbit<S> orbit = evaluateOrbit(chain, data.postImpact, 1, defaultCloseTolerance<S>());
  if (!orbit.admissible && orbit.refusal == OrbitRefusal::NotClosed) {
    // near a multiple of T1 the closed form loses digits like 1 / (T1 - T): its data are
    // polished by Newton at their energy (the orbit itself is well conditioned there)
    OrbitSearch<S> polished = findOrbit(chain, orbit.energy, data.postImpact.u1, data.postImpact.v1, 1);
    using std::abs;
    if (polished.orbit && abs(polished.orbit->period - T) <= S(1e-6) * T && stabilityDecided(*polished.orbit)) {
      orbit = std::move(*polished.orbit);
    }
  }
  if (!orbit.admissible) {
    search.refusal = orbit.refusal;
    search.problem = "the 1IPP orbit of period " + formatScalar(T) + " is not admissible: " + orbit.reason;
    return search;
  }
  if (orbit.state.u1 == data.postImpact.u1 && orbit.state.v2 == data.postImpact.v2) {
    // the closed form's own data: cot(w_j T / 2) loses digits like (w_j T / 2) / sin(w_j T / 2)
    // near a multiple of T_j (near T2 the impact speed, a 1e-11 fraction of w2 d just below T2,
    // is off by 1e-5 of itself in double)
    using std::abs;
    using std::sin;
    S conditioning = 1;
    for (const S& w : {S(chain.ratio * chain.omegaSlow), chain.omegaSlow}) {
      const S half = w * T / S(2);
      conditioning = std::max(conditioning, S(abs(half / sin(half))));
    }
    search.dataError = S(8) * epsilon<S>() * conditioning;
  } else {
    search.dataError = closeTolerance(orbit);  // polished: an orbit of its own period to its closing
  }
  search.orbit = std::move(orbit);
  return search;
}

template <typename S>
std::string orbitSymmetry(const PeriodicOrbit<S>& orbit, const S& tolerance) {
  using std::abs;
  if (orbit.events.empty()) return {};
  S speedScale = 0;
  S positionScale = 0;
  for (const BasicEvent<S>& event : orbit.events) {
    speedScale = std::max({speedScale, abs(event.after.v1), abs(event.after.v2)});
    positionScale = std::max({positionScale, abs(event.after.u1), abs(event.after.u2)});
  }
  const auto near = [&](const S& a, const S& b, const S& size) { return abs(a - b) <= tolerance * size; };
  bool typeA = true;
  for (const BasicEvent<S>& event : orbit.events) typeA = typeA && near(event.after.v1, S(0), speedScale);
  if (typeA) return "A";
  // B: the impact points, reflected (u1, -v1), are the same set
  for (const BasicEvent<S>& event : orbit.events) {
    const bool mirrored = std::any_of(orbit.events.begin(), orbit.events.end(), [&](const BasicEvent<S>& other) {
      return near(other.after.u1, event.after.u1, positionScale) &&
             near(other.after.v1, S(-event.after.v1), speedScale);
    });
    if (!mirrored) return {};
  }
  return "B";
}

#define GRAZELAB_INSTANTIATE(S)                                                                    \
  template Matrix4<S> flowMatrix<S>(const Chain<S>&, const S&);                                    \
  template Matrix4<S> saltationMatrix<S>(const Chain<S>&, const BasicState<S>&);                   \
  template std::optional<BasicState<S>> sectionState<S>(const Chain<S>&, const S&, const S&,       \
                                                        const S&);                                 \
  template S defaultCloseTolerance<S>();                                                           \
  template S closeTolerance<S>(const PeriodicOrbit<S>&);                                          \
  template bool stabilityDecided<S>(const PeriodicOrbit<S>&);                                     \
  template PeriodicOrbit<S> evaluateOrbit<S>(const Chain<S>&, const BasicState<S>&, int,           \
                                             const S&);                                            \
  template OrbitSearch<S> findOrbit<S>(const Chain<S>&, const S&, const S&, const S&, int,         \
                                       std::stop_token);                                           \
  template OrbitSearch<S> onePeriodicOrbitStability<S>(const Chain<S>&, const S&);                 \
  template std::string orbitSymmetry<S>(const PeriodicOrbit<S>&, const S&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
