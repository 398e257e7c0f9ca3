// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/periodic_orbit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/numbers/roots.h"
#include "core/orbits/special_orbits.h"
#include "core/solver/two_mass_run.h"

namespace grazelab::core {

namespace {

template <typename S>
Vector4<S> asVector(const BasicState<S>& x) {
  return {x.u1, x.u2, x.v1, x.v2};
}

// The physical spring constant k2 the solver uses (the design value when designed).
template <typename S>
S stiffness2(const TwoMassForm<S>& chain) {
  return chain.kappa * chain.model.k1;
}

// The vector field of the free flight at x: (v1, v2, a1, a2).
template <typename S>
std::array<S, 4> field(const TwoMassForm<S>& chain, const BasicState<S>& x) {
  const BasicModel<S>& m = chain.model;
  const S k2 = stiffness2(chain);
  return {x.v1, x.v2, (-m.k1 * x.u1 + k2 * (x.u2 - x.u1)) / m.m1, k2 * (x.u1 - x.u2) / m.m2};
}

// Q diag(fast, slow) Q^-1 with Q = [[rhoFast, rhoSlow], [1, 1]] (the mode shapes u1/u2)
template <typename S>
std::array<std::array<S, 2>, 2> inModes(const TwoMassForm<S>& chain, const S& fast, const S& slow) {
  const S rf = chain.rhoFast;
  const S rs = chain.rhoSlow;
  const S scale = S(1) / (rf - rs);
  return {{{(rf * fast - rs * slow) * scale, rf * rs * (slow - fast) * scale},
           {(fast - slow) * scale, (rf * slow - rs * fast) * scale}}};
}

// Periodicity and symmetry are judged relative to the state's size: the gap for positions and
// w2 times the gap for speeds (the orbit's own size when it is larger).
template <typename S>
std::array<S, 4> stateScales(const TwoMassForm<S>& chain, const BasicState<S>& x) {
  using std::abs;
  const S d = chain.model.gap;
  const S position = std::max({d, abs(x.u1), abs(x.u2)});
  const S speed = std::max({d * chain.omegaSlow, abs(x.v1), abs(x.v2)});
  return {position, position, speed, speed};
}

template <typename S>
S relativeDistance(const TwoMassForm<S>& chain, const BasicState<S>& a, const BasicState<S>& b) {
  using std::abs;
  const std::array<S, 4> scale = stateScales(chain, a);
  const Vector4<S> x = asVector(a);
  const Vector4<S> y = asVector(b);
  S largest = 0;
  for (int i = 0; i < 4; ++i) largest = std::max(largest, S(abs(x[i] - y[i]) / scale[i]));
  return largest;
}

// The second mass's free motion in modal form. The mode shapes have unit u2 component, so
//   u2(t) = sum_j q_j cos(w_j t) + r_j sin(w_j t),   j = fast, slow,
// with q the modal parts of (u1, u2) and r those of (v1, v2) over w_j.
template <typename S>
struct SecondMassMotion {
  std::array<S, 2> w{}, q{}, r{};

  SecondMassMotion(const TwoMassForm<S>& chain, const BasicState<S>& x) {
    const S rf = chain.rhoFast;
    const S rs = chain.rhoSlow;
    const S scale = S(1) / (rf - rs);  // Q = [[rf, rs], [1, 1]], Q^-1 = [[1, -rs], [-1, rf]] / (rf - rs)
    w = {chain.ratio * chain.omegaSlow, chain.omegaSlow};
    q = {(x.u1 - rs * x.u2) * scale, (rf * x.u2 - x.u1) * scale};
    r = {(x.v1 - rs * x.v2) * scale / w[0], (rf * x.v2 - x.v1) * scale / w[1]};
  }
  // (u2, v2, a2) at t
  std::array<S, 3> at(const S& t) const {
    using std::cos;
    using std::sin;
    std::array<S, 3> y{};
    for (int j = 0; j < 2; ++j) {
      const S c = cos(w[j] * t), s = sin(w[j] * t);
      const S position = q[j] * c + r[j] * s;
      y[0] += position;
      y[1] += w[j] * (r[j] * c - q[j] * s);
      y[2] -= w[j] * w[j] * position;
    }
    return y;
  }
};

// The infinity norm of m in units of the gap and of w2 times the gap.
template <typename S>
S scaledNorm(const TwoMassForm<S>& chain, const Matrix4<S>& m) {
  using std::abs;
  const std::array<S, 4> unit = {S(1), S(1), chain.omegaSlow, chain.omegaSlow};
  S largest = 0;
  for (int i = 0; i < 4; ++i) {
    S row = 0;
    for (int j = 0; j < 4; ++j) row += abs(m(i, j)) * unit[j] / unit[i];
    largest = std::max(largest, row);
  }
  return largest;
}

// The smallest clearance gap - u2 at an interior maximum of u2 on the flight of duration `tau`
// from `from`, over the gap; +infinity when u2 has no interior maximum. The maxima are where
// v2 turns from + to -: bracketed on 256 samples, then solved by the core's safeguarded Newton
// (solveBracketed). The samples rotate each mode's phase by a fixed step (one complex product, not a
// sine and cosine each): the rounding they gather over 256 steps only moves a sign change
// within a few ulps of a zero of v2, and the root itself is solved from exact evaluations.
template <typename S>
S flightClearance(const TwoMassForm<S>& chain, const BasicState<S>& from, const S& tau) {
  using std::abs;
  using std::cos;
  using std::sin;
  constexpr int kSamples = 256;
  const SecondMassMotion<S> motion(chain, from);
  const S h = tau / S(kSamples);
  std::array<S, 2> stepCos{}, stepSin{}, c{S(1), S(1)}, s{S(0), S(0)};
  for (int j = 0; j < 2; ++j) {
    stepCos[j] = cos(motion.w[j] * h);
    stepSin[j] = sin(motion.w[j] * h);
  }
  const auto speed = [&] {
    S v = 0;
    for (int j = 0; j < 2; ++j) v += motion.w[j] * (motion.r[j] * c[j] - motion.q[j] * s[j]);
    return v;
  };
  S least = std::numeric_limits<S>::infinity();
  S previous = from.v2;
  for (int i = 1; i < kSamples; ++i) {
    for (int j = 0; j < 2; ++j) {
      const S rotated = c[j] * stepCos[j] - s[j] * stepSin[j];
      s[j] = s[j] * stepCos[j] + c[j] * stepSin[j];
      c[j] = rotated;
    }
    const S v = speed();
    if (previous > 0 && v <= 0) {
      // v2 and its derivative a2 from the exact motion: the core's safeguarded Newton
      const auto speedAndSlope = [&](const S& t) {
        const std::array<S, 3> y = motion.at(t);
        return std::pair<S, S>{y[1], y[2]};
      };
      const S low = h * S(i - 1);
      const S high = h * S(i);
      const S t = solveBracketed(speedAndSlope, low, high, previous, v, S((low + high) / S(2))).first;
      least = std::min(least, S((chain.model.gap - motion.at(t)[0]) / chain.model.gap));
    }
    previous = v;
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
    c[k] = -accumulated.trace() / S(k);
    if (k == 4) break;
    accumulated = m * (accumulated + c[k] * Matrix4<S>::Identity());
  }
  const S t = m.trace() - S(2);
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
Matrix4<S> flowMatrix(const TwoMassForm<S>& chain, const S& tau) {
  using std::cos;
  using std::sin;
  const S wSlow = chain.omegaSlow;
  const S wFast = chain.ratio * chain.omegaSlow;
  const S cf = cos(wFast * tau), sf = sin(wFast * tau);
  const S cs = cos(wSlow * tau), ss = sin(wSlow * tau);
  const auto position = inModes(chain, cf, cs);             // u from u, v from v
  const auto byVelocity = inModes(chain, S(sf / wFast), S(ss / wSlow));  // u from v
  const auto byPosition = inModes(chain, S(-wFast * sf), S(-wSlow * ss));  // v from u
  Matrix4<S> phi;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      phi(i, j) = position[i][j];
      phi(i, j + 2) = byVelocity[i][j];
      phi(i + 2, j) = byPosition[i][j];
      phi(i + 2, j + 2) = position[i][j];
    }
  }
  return phi;
}

template <typename S>
Matrix4<S> saltationMatrix(const TwoMassForm<S>& chain, const BasicState<S>& before) {
  Matrix4<S> s = Matrix4<S>::Identity();
  const S a2 = stiffness2(chain) * (before.u1 - chain.model.gap) / chain.model.m2;
  s(1, 1) = S(-1);
  s(3, 3) = S(-1);
  s(3, 1) = S(2) * a2 / before.v2;
  return s;
}

template <typename S>
std::optional<BasicState<S>> sectionState(const TwoMassForm<S>& chain, const S& energy, const S& u1,
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
    case Stability::Undecided: return "undecided";
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
bool determinantChecked(const PeriodicOrbit<S>& orbit) {
  using std::abs;
  return abs(orbit.checks.detMinus1) <= S(1e3) * defaultCloseTolerance<S>();
}

template <typename S>
Stability decidedStability(const PeriodicOrbit<S>& orbit) {
  using std::abs;
  if (orbit.stability == Stability::Parabolic) return Stability::Parabolic;
  const S error = std::max(orbit.traceError, S(abs(orbit.checks.detMinus1)));
  return abs(abs(orbit.trace) - S(2)) > error ? orbit.stability : Stability::Undecided;
}

namespace {

// evaluateOrbit on the chain made ready once (a Newton search evaluates one orbit per step)
template <typename S>
PeriodicOrbit<S> evaluateOn(const BasicReadyChain<S>& ready, const BasicState<S>& start, int impacts,
                            const S& closeTolerance) {
  const TwoMassForm<S>& chain = *ready.notes;
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
  if (!isFinite(start.u1) || !isFinite(start.v1) || !isFinite(start.v2)) {
    return refuse(OrbitRefusal::BadStart, "the start is not finite");
  }
  if (!(start.u2 == chain.model.gap) || !(start.v2 <= 0)) {
    return refuse(OrbitRefusal::BadStart, "the start is not just after an impact (u2 = gap, v2 <= 0)");
  }
  // the one run of the chain, made ready from its form (no eigensolve per Newton step), its
  // events streamed (no vectors kept per event)
  orbit.events.reserve(std::size_t(std::min(impacts, 1 << 16)));
  const BasicChainRun<S> run =
      runChain(ready, BasicChainStart<S>(chainStateOf(start)), impacts, S(0), {},
               [&orbit](const BasicChainEvent<S>& event) { orbit.events.push_back(twoMassEventOf(event)); });
  if (run.stop == StopReason::Undecided) {
    return refuse(OrbitRefusal::Undecided, "a contact of the path is too near tangent for this precision to decide "
                  "(try a higher precision)");
  }
  if (std::int64_t(orbit.events.size()) != impacts) {
    return refuse(OrbitRefusal::ContactCount, "the path made " + std::to_string(orbit.events.size()) + " contacts, not " +
                  std::to_string(impacts));
  }
  // the monodromy, flight by flight, with the clearance of every flight
  Matrix4<S> monodromy = Matrix4<S>::Identity();
  S normProduct = 1;
  S previousTime = 0;
  BasicState<S> leaving = start;
  orbit.minImpactSpeed = std::numeric_limits<S>::infinity();
  orbit.minClearance = std::numeric_limits<S>::infinity();
  for (const BasicEvent<S>& event : orbit.events) {
    if (event.type != EventType::Impact) {
      return refuse(OrbitRefusal::NotImpact, "the path has a " + std::string(toString(event.type)) + " at t = " +
                    formatScalar(event.t) + ", not only impacts");
    }
    const S tau = event.t - previousTime;
    const Matrix4<S> flow = flowMatrix(chain, tau);
    const Matrix4<S> saltation = saltationMatrix(chain, event.before);
    monodromy = saltation * (flow * monodromy);
    normProduct *= scaledNorm(chain, flow) * scaledNorm(chain, saltation);
    orbit.minImpactSpeed = std::min(orbit.minImpactSpeed, event.before.v2);
    orbit.minClearance = std::min(orbit.minClearance, flightClearance(chain, leaving, tau));
    previousTime = event.t;
    leaving = event.after;
  }
  orbit.period = previousTime;
  orbit.monodromy = monodromy;
  const BasicState<S>& end = orbit.events.back().after;
  orbit.checks.periodicityResidual = relativeDistance(chain, start, end);
  // the reduced Jacobian at fixed energy: lift (du1, dv1) onto the energy level at the start,
  // carry it by M, project along the flow onto H at the end
  const BasicModel<S>& m = chain.model;
  const S dEdu1 = m.k1 * start.u1 + stiffness2(chain) * (start.u1 - start.u2);
  const S dEdv1 = m.m1 * start.v1;
  const S dEdv2 = m.m2 * start.v2;
  // columns: the lifts of du1, dv1 and dE
  Eigen::Matrix<S, 4, 3> lifts = Eigen::Matrix<S, 4, 3>::Zero();
  lifts.col(0) << S(1), S(0), S(0), S(-dEdu1 / dEdv2);
  lifts.col(1) << S(0), S(0), S(1), S(-dEdv1 / dEdv2);
  lifts.col(2) << S(0), S(0), S(0), S(S(1) / dEdv2);
  const std::array<S, 4> flowAtEnd = field(chain, end);
  const Vector4<S> flow(flowAtEnd[0], flowAtEnd[1], flowAtEnd[2], flowAtEnd[3]);
  Eigen::Matrix<S, 4, 3> carried = monodromy * lifts;
  for (int c = 0; c < 3; ++c) {
    const S along = carried(1, c) / flow[1];  // the time shift that brings u2 back onto H
    carried.col(c) -= along * flow;
  }
  orbit.reduced << carried(0, 0), carried(0, 1), carried(2, 0), carried(2, 1);
  orbit.energyDerivative = {carried(0, 2), carried(2, 2)};
  {
    const S w = chain.omegaSlow;  // (u1 / d, v1 / (w d)): DP's entries as the continuation sees them
    orbit.amplification = std::max({S(1), abs(orbit.reduced(0, 0)), abs(orbit.reduced(1, 1)),
                                    abs(orbit.reduced(0, 1) * w), abs(orbit.reduced(1, 0) / w)});
  }
  const S trace = orbit.reduced.trace();
  orbit.traceError = epsilon<S>() * S(8 * (2 * impacts + 2)) * normProduct * orbit.amplification;
  const S det = orbit.reduced(0, 0) * orbit.reduced(1, 1) - orbit.reduced(0, 1) * orbit.reduced(1, 0);
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
    if (relativeDistance(chain, start, orbit.events[std::size_t(j - 1)].after) <= S(1e7) * epsilon<S>()) {
      return refuse(OrbitRefusal::Repeated, "the orbit is a " + std::to_string(j) + "-impact orbit repeated");
    }
  }
  if (!(orbit.minClearance > 0)) return refuse(OrbitRefusal::TouchesStop, "a flight touches or crosses the stop between impacts");
  orbit.admissible = true;
  return orbit;
}

}  // namespace

template <typename S>
PeriodicOrbit<S> evaluateOrbit(const TwoMassForm<S>& chain, const BasicState<S>& start, int impacts,
                               const S& closeTolerance) {
  return evaluateOn(readyChain(chain), start, impacts, closeTolerance);
}

template <typename S>
S locatedTraceError(const TwoMassForm<S>& chain, const PeriodicOrbit<S>& orbit) {
  using std::abs;
  using std::sqrt;
  const S h = sqrt(epsilon<S>());
  const std::array<S, 4> scale = stateScales(chain, orbit.state);
  S gradient = 0;
  for (int direction = 0; direction < 2; ++direction) {
    const S u1 = orbit.state.u1 + (direction == 0 ? S(h * scale[0]) : S(0));
    const S v1 = orbit.state.v1 + (direction == 1 ? S(h * scale[2]) : S(0));
    const std::optional<BasicState<S>> start = sectionState(chain, orbit.energy, u1, v1);
    if (!start) return std::numeric_limits<S>::infinity();
    const PeriodicOrbit<S> moved = evaluateOrbit(chain, *start, orbit.impacts, std::numeric_limits<S>::infinity());
    if (moved.events.size() != orbit.events.size()) return std::numeric_limits<S>::infinity();
    gradient += abs(moved.trace - orbit.trace) / h;
  }
  return orbit.traceError + gradient * std::max(orbit.checks.periodicityResidual, epsilon<S>());
}

template <typename S>
OrbitSearch<S> findOrbit(const TwoMassForm<S>& chain, const S& energy, const S& u1, const S& v1,
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
  const BasicReadyChain<S> ready = readyChain(chain);
  std::optional<PeriodicOrbit<S>> closed;  // the last iterate that closed within the tolerance
  S closedCorrection = std::numeric_limits<S>::infinity();  // the Newton step from it
  const auto accept = [&search, &closedCorrection](PeriodicOrbit<S> orbit) {
    using std::sqrt;
    search.correction = closedCorrection;
    // a stalled Newton: closed within the (amplified) tolerance, yet its own next step is far
    // larger than the rounding could explain
    if (closedCorrection > sqrt(closeTolerance(orbit))) {
      search.refusal = OrbitRefusal::NotClosed;
      search.problem = "Newton stalled at a residual of " + formatScalar(orbit.checks.periodicityResidual) +
                       " with a step of " + formatScalar(closedCorrection) +
                       " still to go (DP^k - I is nearly singular here: a flip, fold or branch point is near); "
                       "no orbit is given";
      return search;
    }
    if (!orbit.admissible) {
      search.refusal = orbit.refusal;
      search.problem = "the orbit found is not admissible: " + orbit.reason;
    } else {
      search.orbit = std::move(orbit);
    }
    return search;
  };
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
    if (!start && closed) return accept(std::move(*closed));
    if (!start) {
      search.problem = "Newton left the energy level at iteration " + std::to_string(iteration + 1) +
                       " (u1 = " + formatScalar(x) + ", v1 = " + formatScalar(y) +
                       "): give a guess nearer the orbit";
      return search;
    }
    PeriodicOrbit<S> orbit = evaluateOn(ready, *start, impacts, std::numeric_limits<S>::infinity());
    if (orbit.events.size() != std::size_t(impacts) ||
        std::any_of(orbit.events.begin(), orbit.events.end(),
                    [](const BasicEvent<S>& e) { return e.type != EventType::Impact; })) {
      if (closed) return accept(std::move(*closed));
      search.refusal = orbit.refusal;
      search.problem = "Newton left the " + std::to_string(impacts) + "-impact orbits at iteration " +
                       std::to_string(iteration + 1) + " (" + orbit.reason + ")";
      return search;
    }
    // within the tolerance Newton goes on while the residual still halves: the tolerance
    // allows for amplified rounding, and an iterate passing through it may be on its way to
    // another orbit (near a flip, to the k/2-impact orbit run twice)
    const bool closes = orbit.checks.periodicityResidual <= closeTolerance(orbit);
    if (closed && !(closes && orbit.checks.periodicityResidual < closed->checks.periodicityResidual / S(2))) {
      return accept(std::move(*closed));
    }
    if (closes) {
      // closed exactly: no step is left to take
      closedCorrection = orbit.checks.periodicityResidual == S(0) ? S(0) : std::numeric_limits<S>::infinity();
      if (closedCorrection == S(0)) return accept(std::move(orbit));
      closed = orbit;
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
    const S a = orbit.reduced(0, 0) - S(1), b = orbit.reduced(0, 1);
    const S c = orbit.reduced(1, 0), d = orbit.reduced(1, 1) - S(1);
    const S det = a * d - b * c;
    if (!(abs(det) > S(0)) || !isFinite(det)) {
      if (closed) return accept(std::move(*closed));
      search.problem = "the Jacobian DP^k - I is singular (a fold or branch point: tr DP^k = 2)";
      return search;
    }
    const S dx = (d * f0 - b * f1) / det;
    const S dy = (-c * f0 + a * f1) / det;
    if (closes) {
      const std::array<S, 4> scale = stateScales(chain, *start);
      closedCorrection = std::max(abs(dx) / scale[0], abs(dy) / scale[2]);
    }
    x -= dx;
    y -= dy;
  }
  if (closed) return accept(std::move(*closed));
  search.problem = "Newton did not converge in " + std::to_string(kIterations) + " iterations";
  return search;
}

namespace {

// what to try when S cannot decide
template <typename S>
const char* highestPrecisionHint() {
  return precisionOf<S>() == Precision::Quad ? " (binary128 is the highest precision there is)"
                                             : " (try a higher precision)";
}

// How the closed form's data lose digits near a multiple of T1 or T2: cot(w_j T / 2) is
// conditioned like (w_j T / 2) / sin(w_j T / 2) in T (at least 1)
template <typename S>
S closedFormConditioning(const TwoMassForm<S>& chain, const S& T) {
  using std::abs;
  using std::sin;
  S conditioning = 1;
  for (const S& w : {S(chain.ratio * chain.omegaSlow), chain.omegaSlow}) {
    const S half = w * T / S(2);
    conditioning = std::max(conditioning, S(abs(half / sin(half))));
  }
  return conditioning;
}

// How far the path from the closed form's data may be from closing by rounding alone. The data
// are off by O(eps) of the state's scale (the digits cot(w1 T / 2) loses near T1 sit in V, itself
// ~ T1 - T), and one return carries that error by DP - I, whose entries reach the orbit's
// amplification: near T1 the saltation's 2 a2 / v2 makes it about 2/3 of the conditioning. So
// closeTolerance's bound, without its cap (the data are an orbit: no "too far to be one" here),
// and with the conditioning in case the path's own amplification understates it.
template <typename S>
S closedFormClosingBound(const TwoMassForm<S>& chain, const PeriodicOrbit<S>& orbit, const S& T) {
  using std::abs;
  return defaultCloseTolerance<S>() * S(8 * std::max(1, orbit.impacts)) *
         std::max({S(1), S(abs(orbit.trace)), orbit.amplification, closedFormConditioning(chain, T)});
}

}  // namespace

template <typename S>
OrbitSearch<S> onePeriodicOrbitStability(const TwoMassForm<S>& chain, const S& T) {
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
    // det DP = 1 within what the trace's own error allows (near T1 binary128's amplified rounding
    // exceeds determinantChecked's fixed 5e5 ulps where long double's does not)
    const auto determinantPasses = [](const PeriodicOrbit<S>& found) {
      return abs(found.checks.detMinus1) <= std::max(S(1e3) * defaultCloseTolerance<S>(), found.traceError);
    };
    if (polished.orbit && abs(polished.orbit->period - T) <= S(1e-6) * T && determinantPasses(*polished.orbit)) {
      orbit = std::move(*polished.orbit);
    } else if (const S bound = closedFormClosingBound(chain, orbit, T); orbit.checks.periodicityResidual <= bound) {
      // the exact data are an orbit: a path that misses closing by no more than the rounding
      // amplified this near a multiple of T1 (the impact speed V ~ T1 - T, the return map's
      // 2 a2 / V) is not an open path, but an orbit S cannot decide
      const S conditioning = closedFormConditioning(chain, T);
      const S factor = std::max({S(abs(orbit.trace)), orbit.amplification, conditioning});
      const char* cause = factor == conditioning ? "the closed form's conditioning near a multiple of T1 or T2"
                          : factor == orbit.amplification ? "the return map's amplification"
                                                          : "the trace";
      char text[256];
      std::snprintf(text, sizeof text,
                    ": its path misses closing by %.1e (relative), within the %.1e that the rounding allows, "
                    "amplified %.1e times by %s",
                    toDouble(orbit.checks.periodicityResidual), toDouble(bound), toDouble(factor), cause);
      search.refusal = OrbitRefusal::Undecided;
      search.problem = "the 1IPP orbit of period " + formatScalar(T) + " cannot be decided in " +
                       std::string(toString(precisionOf<S>())) + text + highestPrecisionHint<S>();
      return search;
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
    search.dataError = S(8) * epsilon<S>() * closedFormConditioning(chain, T);
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
  template Matrix4<S> flowMatrix<S>(const TwoMassForm<S>&, const S&);                                    \
  template Matrix4<S> saltationMatrix<S>(const TwoMassForm<S>&, const BasicState<S>&);                   \
  template std::optional<BasicState<S>> sectionState<S>(const TwoMassForm<S>&, const S&, const S&,       \
                                                        const S&);                                 \
  template S defaultCloseTolerance<S>();                                                           \
  template S closeTolerance<S>(const PeriodicOrbit<S>&);                                          \
  template bool determinantChecked<S>(const PeriodicOrbit<S>&);                                   \
  template Stability decidedStability<S>(const PeriodicOrbit<S>&);                                \
  template S locatedTraceError<S>(const TwoMassForm<S>&, const PeriodicOrbit<S>&);                           \
  template PeriodicOrbit<S> evaluateOrbit<S>(const TwoMassForm<S>&, const BasicState<S>&, int,           \
                                             const S&);                                            \
  template OrbitSearch<S> findOrbit<S>(const TwoMassForm<S>&, const S&, const S&, const S&, int,         \
                                       std::stop_token);                                           \
  template OrbitSearch<S> onePeriodicOrbitStability<S>(const TwoMassForm<S>&, const S&);                 \
  template std::string orbitSymmetry<S>(const PeriodicOrbit<S>&, const S&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
