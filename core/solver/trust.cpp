// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/trust.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <cstdio>

namespace grazelab::core {
namespace {

// an error this large means the shadow has left the run's path: it grows no faster from there
constexpr double kDiverged = 1e-2;

std::string scientific(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", value);
  return text;
}

// a shadow state back in the primary's units
template <typename H>
BasicState<H> scaled(const BasicState<H>& state, const H& length, const H& time) {
  if (length == 1 && time == 1) return state;
  const H speed = length * time;
  return {state.u1 / length, state.u2 / length, state.v1 / speed, state.v2 / speed};
}

}  // namespace

std::string_view toString(TrustMode mode) {
  switch (mode) {
    case TrustMode::Off:
      return "off";
    case TrustMode::Auto:
      return "auto";
    case TrustMode::Full:
      return "full";
  }
  return "auto";
}

std::optional<TrustMode> parseTrustMode(std::string_view text) {
  for (TrustMode mode : {TrustMode::Off, TrustMode::Auto, TrustMode::Full}) {
    if (text == toString(mode)) return mode;
  }
  return std::nullopt;
}

std::string_view toString(Verdict verdict) {
  switch (verdict) {
    case Verdict::Ok:
      return "ok";
    case Verdict::Degraded:
      return "degraded";
    case Verdict::Unreliable:
      return "unreliable";
    case Verdict::Unchecked:
      return "unchecked";
  }
  return "unchecked";
}

template <typename S>
TrustMonitor<S>::TrustMonitor(const BasicModel<H>& model, const BasicChainState<H>& start, long maxContacts,
                              std::type_identity_t<H> tEnd, TrustMode mode, std::stop_token stop,
                              ExactParameters exact, std::int64_t searchSteps,
                              const BasicReadyChain<H>* shadowChain)
    : m_mode(mode), m_stop(std::move(stop)) {
  if (mode == TrustMode::Off) {
    m_active = false;
    return;
  }
  BasicModel<H> shadowModel = model;
  BasicState<H> x = twoMassStateOf(start);
  H shadowEnd = tEnd;
  if constexpr (std::is_same_v<S, double>) {
    m_inputModel = model;
    m_inputStart = start;
    m_maxContacts = maxContacts;
    m_tEnd = tEnd;
  }
  if constexpr (std::is_same_v<S, H>) {
    // no wider type: the same precision on a chain 3 times as large, 5 times as heavy and
    // sqrt(3) times as fast rounds every length, speed and time differently, and the chain's
    // own constants too (the physics is scale-free)
    using std::sqrt;
    m_lengthFactor = 3;
    m_timeFactor = sqrt(H(3));
    const H speedFactor = m_lengthFactor * m_timeFactor;
    shadowModel.gap *= m_lengthFactor;
    shadowModel.m1 *= 5;
    shadowModel.m2 *= 5;
    shadowModel.k1 *= 15;  // k / m, and w^2, 3 times larger: times by 1 / sqrt(3)
    shadowModel.k2 *= 15;
    x = {x.u1 * m_lengthFactor, x.u2 * m_lengthFactor, x.v1 * speedFactor, x.v2 * speedFactor};
    // the shadow read the same decimal input in the same precision, so it shares its rounding;
    // a nudge of one rounding (never across the stop, never changing a sign) puts the input's
    // representation into the estimate, as a wider shadow does by reading it afresh: of the
    // state, and of the chain (a mass ratio near 9/16 amplifies its rounding ~1e7 in the
    // designed k2; m2/m1 is nudged down, toward the feasible side of the design)
    using std::abs;
    // a read is off by at most half an ulp, but a nudge that small is undone by the roundings
    // that follow (x (1 + 2^-113) rounds back to x; k2 * 15 / 15 rounds back to k2): the shadow
    // then had the run's own chain and missed its dominant error (a detuned chain amplifying
    // k2/k1's rounding to 6e-16 T2 in 20 contacts, estimated 1e-18). Four ulps survive them.
    // (the chain's parameters). The state keeps the half-ulp nudge: its rounding mostly stays,
    // and a whole ulp off a periodic orbit (1IPP) drifted 1000 times further than the run did
    const H eps = H(4) * epsilon<H>();
    const H stateEps = epsilon<H>() / H(2);
    const bool onStop = x.u2 == shadowModel.gap;
    if (!exact.m1) shadowModel.m1 += shadowModel.m1 * eps;
    if (!exact.m2) shadowModel.m2 -= shadowModel.m2 * eps;
    if (!exact.k1) shadowModel.k1 += shadowModel.k1 * eps;
    if (!exact.k2) shadowModel.k2 -= shadowModel.k2 * eps;
    if (!exact.gap) shadowModel.gap += shadowModel.gap * eps;
    x.u1 += abs(x.u1) * stateEps;
    x.u2 = onStop ? shadowModel.gap : H(x.u2 - abs(x.u2) * stateEps);
    x.v1 -= x.v1 * stateEps;
    x.v2 += x.v2 * stateEps;
    shadowEnd = tEnd / m_timeFactor;
  }
  std::vector<Problem> problems = validate(shadowModel);
  for (Problem& problem : validateState(shadowModel, x, "initial")) problems.push_back(std::move(problem));
  if (problems.empty()) {
    TwoMassFormOrProblem<H> formed = makeTwoMassForm(shadowModel);
    if (!formed.chain) problems.push_back({"model", formed.problem});
  }
  if (!problems.empty()) {
    m_stopNote = "the shadow run could not start (" + describe(problems) + ")";
    m_active = false;
    return;
  }
  // the caller's chain of this model, made ready once, where the shadow runs it as it stands (one
  // precision up: no scaling, no nudge); else made ready here for this shadow alone
  const bool given = shadowChain && !std::is_same_v<S, H> && shadowChain->notesModel == shadowModel;
  std::optional<BasicReadyChain<H>> ready;
  if (!given) ready = readyChain(shadowModel);
  m_shadowForm = given ? shadowChain->notes : ready->notes;
  // each shadow event, as the two masses' states before and after it (held until compared)
  const ChainEventSink<H> sink = [this](const BasicChainEvent<H>& event) {
    const BasicState<H> after{event.u[0], event.u[1], event.vBefore[0], event.vAfter};
    m_pending.push_back({event.t, event.type, {after.u1, after.u2, after.v1, event.vBefore[1]}, after});
  };
  m_shadow = given ? std::make_unique<BasicChainSimulator<H>>(*shadowChain, chainStateOf(x), maxContacts, shadowEnd,
                                                              sink, ChainSampling<H>{}, searchSteps)
                   : std::make_unique<BasicChainSimulator<H>>(std::move(*ready), chainStateOf(x), maxContacts,
                                                              shadowEnd, sink, ChainSampling<H>{}, searchSteps);
  m_omega = m_shadowForm->omegaSlow * m_timeFactor;  // in the primary's time
  m_period = twoPi<H>() / m_omega;
  using std::abs;
  m_scale[1] = abs(model.gap);
  widenScales(twoMassStateOf(start));
}

template <typename S>
std::string TrustMonitor<S>::shadowName() const {
  const std::string type = std::is_same_v<H, Quad> ? "binary128" : "long double";
  if constexpr (std::is_same_v<S, H>) {
    return "shadow run in " + type +
           " on a chain scaled 3x in length, 5x in mass, 1/sqrt(3) in time";
  } else {
    return "shadow run in " + type;
  }
}

template <typename S>
void TrustMonitor<S>::widenScales(const BasicState<H>& state) {
  using std::abs;
  using std::max;
  m_scale[0] = max(m_scale[0], abs(state.u1));
  m_scale[1] = max(m_scale[1], abs(state.u2));
  m_scale[2] = max(m_scale[2], abs(state.v1));
  m_scale[3] = max(m_scale[3], abs(state.v2));
}

template <typename S>
double TrustMonitor<S>::relativeStateError(const BasicState<H>& primary,
                                           const BasicState<H>& shadow) const {
  using std::abs;
  using std::max;
  // each component against its own scale, floored at 1e-3 of its kind (positions, velocities)
  // so that a component that stays near zero does not turn rounding into a large error
  const H positions = max(m_scale[0], m_scale[1]);
  const H velocities = max(max(m_scale[2], m_scale[3]), H(m_omega * positions));
  const H floors[4] = {positions, positions, velocities, velocities};
  const H differences[4] = {abs(primary.u1 - shadow.u1), abs(primary.u2 - shadow.u2),
                            abs(primary.v1 - shadow.v1), abs(primary.v2 - shadow.v2)};
  double worst = 0;
  for (int i = 0; i < 4; ++i) {
    const H scale = max(m_scale[i], H(floors[i] / H(1000)));
    if (scale > 0) worst = std::max(worst, toDouble(H(differences[i] / scale)));
  }
  return worst;
}

template <typename S>
bool TrustMonitor<S>::withinBudget() {
  if (m_mode == TrustMode::Full) return true;
  // auto: the shadow covers a number of events fixed by the precisions alone, so that the same
  // run always gets the same estimate (a wall-clock budget gave 9e7 one time and 4e8 the next):
  // about twice the run's own cost, at most a second or so (a long double shadow costs about
  // as much as the double run; binary128 about fifteen times a long double run)
  constexpr std::int64_t kEvents = std::is_same_v<S, double> ? (1 << 18) : std::is_same_v<S, long double> ? (1 << 14) : (1 << 16);
  return m_observed <= kEvents;
}

template <typename S>
std::optional<BasicEvent<typename TrustMonitor<S>::H>> TrustMonitor<S>::nextShadowEvent() {
  while (m_pending.empty() && !m_shadow->done()) m_shadow->advance(1, m_stop);
  if (m_pending.empty()) return std::nullopt;
  BasicEvent<H> event = m_pending.front();
  m_pending.pop_front();
  event.t *= m_timeFactor;
  event.before = scaled(event.before, m_lengthFactor, m_timeFactor);
  event.after = scaled(event.after, m_lengthFactor, m_timeFactor);
  return event;
}

template <typename S>
void TrustMonitor<S>::compare(const H& t, double stateError, double timeError) {
  m_worstTime = std::max(m_worstTime, timeError);
  m_lastState = stateError;
  m_envelope = std::max({m_envelope, stateError, timeError});
  m_lastCompared = t;
  if (!m_crossed) {
    if (m_envelope <= kHorizonTolerance) {
      m_heldUntil = t;
    } else {
      m_crossed = true;
    }
  }
  const double time = toDouble(t);
  if (m_growth.empty() || time > 1.05 * m_growth.back().t) {
    m_growth.push_back({time, m_envelope});
  }
}

template <typename S>
void TrustMonitor<S>::shadowUndecided() {
  m_active = false;
  m_shadowUndecided = true;
  m_stopNote = "the shadow cannot decide the contact after t = " +
               formatScalar(H(m_shadow->run().tFinal * m_timeFactor)) + ": compared up to there";
}

template <typename S>
void TrustMonitor<S>::observe(const BasicChainEvent<S>& event) {
  ++m_observed;
  if (!shadowing()) return;
  if (m_observed % 64 == 0 && !withinBudget()) {
    m_active = false;
    m_stopNote = "the shadow covered the first " + std::to_string(m_observed - 1) +
                 " events (--trust auto keeps it cheap)";
    return;
  }
  const std::optional<BasicEvent<H>> shadow = nextShadowEvent();
  if (!shadow && m_stop.stop_requested()) {
    // interrupted: the estimate holds up to here, the shadow took no other path
    m_active = false;
    m_stopNote = "the shadow was interrupted at event " + std::to_string(m_observed);
    return;
  }
  if (!shadow && m_shadow->run().stop == StopReason::Undecided) {
    // a contact the shadow cannot decide (a touch within its rounding, which a run of the same
    // precision going on through its touches met too): compared up to there, the rest unconfirmed
    shadowUndecided();
    return;
  }
  if (!shadow) {
    m_failure = "the shadow run ended before event " + std::to_string(m_observed) + " (t = " +
                formatScalar(event.t) + ")";
    m_active = false;
    return;
  }
  if (isContact(shadow->type) != isContact(event.type)) {
    m_failure = "event " + std::to_string(m_observed) + " is a " +
                std::string(toString(event.type)) + " in the run, a " +
                std::string(toString(shadow->type)) + " in the shadow";
    m_active = false;
    return;
  }
  const BasicState<H> after{H(event.u[0]), H(event.u[1]), H(event.vBefore[0]), H(event.vAfter)};
  const BasicState<H> before{after.u1, after.u2, after.v1, H(event.vBefore[1])};
  widenScales(shadow->before);
  widenScales(shadow->after);
  using std::abs;
  const double stateError = std::max(relativeStateError(before, shadow->before),
                                     relativeStateError(after, shadow->after));
  const double timeError = toDouble(H(abs(H(event.t) - shadow->t) / m_period));
  compare(H(event.t), stateError, timeError);
}

template <typename S>
double TrustMonitor<S>::phaseRounding(const BasicChainRun<S>& primary) const {
  using std::abs;
  const TwoMassForm<H>& chain = *m_shadowForm;
  const BasicState<H> x = convertState<H>(twoMassStateOf(primary.final));
  const H dt = H(epsilon<S>()) * (abs(H(primary.tFinal)) + m_period);
  const H w2 = m_omega * m_omega;
  const H stretch = x.u1 - x.u2;
  const BasicState<H> moved = {x.u1 + abs(x.v1) * dt, x.u2 + abs(x.v2) * dt,
                               x.v1 + abs(w2 * (chain.p * x.u1 + chain.q * stretch)) * dt,
                               x.v2 + abs(w2 * chain.w * stretch) * dt};
  return relativeStateError(x, moved);
}

template <typename S>
void TrustMonitor<S>::arbitrate(const BasicChainRun<S>& primary, Trust& trust) {
  // binary128 costs about 20 times a double run: up to 2e4 contacts, a second at most
  constexpr std::int64_t kArbiterContacts = 20000;
  if (!m_inputModel || primary.contacts > kArbiterContacts) return;
  if (m_stop.stop_requested()) return;
  const BasicChainState<Quad> start{m_inputStart.u.template cast<Quad>(), m_inputStart.v.template cast<Quad>()};
  const BasicChainRun<Quad> exact =
      runChain(readyChain(convertModel<Quad>(*m_inputModel)), start, m_maxContacts, Quad(m_tEnd), m_stop);
  if (exact.stop != primary.stop || exact.contacts != primary.contacts) return;  // confirmed
  using std::abs;
  const double stateError = relativeStateError(convertState<H>(twoMassStateOf(primary.final)),
                                               convertState<H>(twoMassStateOf(exact.final)));
  const double timeError = toDouble(Quad(abs(Quad(primary.tFinal) - exact.tFinal) / Quad(m_period)));
  const double worst = std::max(stateError, timeError);
  if (!(worst <= kHorizonTolerance)) return;  // the run itself left the path: the alarm holds
  const double eps = toDouble(epsilon<S>());
  trust.verdict = worst <= kOkTolerance ? Verdict::Ok : Verdict::Degraded;
  trust.stateError = std::max(stateError, eps);
  trust.timeError = std::max(timeError, eps * (toDouble(primary.tFinal) / toDouble(m_period) + 1));
  trust.horizon = toDouble(primary.tFinal);
  trust.horizonObserved = true;
  trust.horizonMethod = "binary128 run of the same input, to the end";
  trust.reason = "estimated error " + scientific(std::max(trust.stateError, trust.timeError)) +
                 " (a binary128 run of the same input agrees with this run; the " + shadowName() +
                 " took another path on its own rounding: a false alarm)";
}

template <typename S>
Trust TrustMonitor<S>::finish(const BasicChainRun<S>& primary) {
  Trust trust = estimate(primary);
  if (trust.verdict == Verdict::Unreliable) arbitrate(primary, trust);
  // past a contact the shadow cannot decide, nothing is confirmed: at best degraded
  if (m_shadowUndecided && trust.verdict == Verdict::Ok) trust.verdict = Verdict::Degraded;
  if (primary.stop == StopReason::SearchBudget) {
    // the run stopped undecided: whatever came before holds, what follows is not known
    if (trust.verdict != Verdict::Unreliable) trust.verdict = Verdict::Degraded;
    trust.reason = "no contact was decided within the search's budget; " + trust.reason;
  }
  return trust;
}

template <typename S>
Trust TrustMonitor<S>::estimate(const BasicChainRun<S>& primary) {
  Trust trust;
  trust.shadowEvents = m_observed;
  if (m_mode == TrustMode::Off) {
    trust.reason = "not estimated (--trust off)";
    return trust;
  }
  if (!m_shadow) {
    trust.reason = m_stopNote;
    return trust;
  }
  const bool interrupted = primary.stop == StopReason::Cancelled || m_stop.stop_requested();
  const bool complete = shadowing() && m_failure.empty();
  // a run that stopped undecided (a search out of budget) is compared up to there: its shadow
  // is not marched on to an end the run never reached
  const bool undecidedEnd =
      primary.stop == StopReason::SearchBudget || primary.stop == StopReason::Undecided;
  if (complete && !interrupted && !undecidedEnd) {
    // the shadow ends its own run (at most the rest of its last flight), then the final states
    // are compared
    while (!m_shadow->done()) m_shadow->advance(1, m_stop);
    const BasicChainRun<H>& shadow = m_shadow->run();
    if (shadow.stop == StopReason::Cancelled) {
      m_stopNote = "the shadow was interrupted";
    } else if (shadow.stop == StopReason::Undecided && m_pending.empty()) {
      shadowUndecided();
    } else if (!m_pending.empty()) {
      m_failure = "the shadow run has a contact the run has not (t = " +
                  formatScalar(H(m_pending.front().t * m_timeFactor)) + ")";
    } else if (shadow.stop != primary.stop) {
      m_failure = "the shadow run stopped with " + std::string(toString(shadow.stop)) +
                  ", the run with " + std::string(toString(primary.stop));
    } else {
      const BasicState<H> final = convertState<H>(twoMassStateOf(primary.final));
      const BasicState<H> shadowFinal = scaled(twoMassStateOf(shadow.final), m_lengthFactor, m_timeFactor);
      widenScales(shadowFinal);
      const double stateError = relativeStateError(final, shadowFinal);
      using std::abs;
      const double timeError =
          toDouble(H(abs(H(primary.tFinal) - shadow.tFinal * m_timeFactor) / m_period));
      compare(H(primary.tFinal), stateError, timeError);
    }
  }
  trust.horizonMethod = shadowName();
  if (!m_failure.empty()) {
    trust.verdict = Verdict::Unreliable;
    trust.stateError = 1;
    trust.timeError = std::max(m_worstTime, 1.0);
    trust.horizon = toDouble(m_heldUntil);
    trust.horizonObserved = true;
    trust.reason = "the " + shadowName() + " took another path: " + m_failure;
    return trust;
  }

  const double eps = toDouble(epsilon<S>());
  const double period = toDouble(m_period);
  const double end = toDouble(primary.tFinal);
  const double compared = toDouble(m_lastCompared);
  // growth of the error envelope: a power of t (regular motion: rounding accumulates), or an
  // exponential (chaos: a finite-time Lyapunov exponent), from its size now and at half the time
  const double now = std::max(m_envelope, eps);
  double earlierTime = 0;
  double earlierError = eps;
  for (const GrowthPoint& point : m_growth) {
    if (point.t > 0 && point.t <= compared / 2) {
      earlierTime = point.t;
      earlierError = std::max(point.error, eps);
    }
  }
  double power = 1;
  double rate = 0;  // per unit time, when exponential
  // the horizon beyond the comparison is extrapolated conservatively: as if the growth seen over
  // its second half were exponential (faster than any power from then on), and never beyond
  // twice the time compared (a run whose error still sits at the rounding shows no growth yet)
  double cautiousRate = 0;
  if (earlierTime > 0 && now > earlierError && now < kDiverged) {
    power = std::log(now / earlierError) / std::log(compared / earlierTime);
    if (power > 3) rate = std::log(now / earlierError) / (compared - earlierTime);
    cautiousRate = std::log(now / earlierError) / (compared - earlierTime);
  }
  power = std::max(power, 1.0);
  auto extrapolate = [&](double t) {
    if (compared <= 0 || t <= compared) return now;
    return rate > 0 ? now * std::exp(std::min(rate * (t - compared), 700.0))
                    : now * std::pow(t / compared, power);
  };
  const std::string growth =
      rate > 0 ? "exponential growth, FTLE " + scientific(rate * period) + " per T2"
               : "growth like t^" + scientific(power);

  double stateError = m_lastState;
  double timeError = m_worstTime;
  const bool extrapolated = !complete && !interrupted;
  if (extrapolated) {
    stateError = std::max(stateError, extrapolate(end));
    timeError = std::max(timeError, extrapolate(end));
  }
  // nothing is known better than its own rounding: a time to eps of its size (the phase
  // 2 pi k carries the rounding of pi itself, the same in any shadow of the same precision),
  // a state to eps, and a state at a given end time to how far it moves in that time error
  // (a state at a contact is pinned by the contact condition instead)
  const double pinned =
      primary.stop == StopReason::TimeLimit ? phaseRounding(primary) : 0.0;
  trust.stateError = std::max({stateError, eps, pinned});
  trust.timeError = std::max(timeError, eps * (end / period + 1));

  // the predictability horizon
  const double timeRounding = kHorizonTolerance / eps * period;  // when t's own ulp reaches it
  if (m_crossed) {
    trust.horizon = toDouble(m_heldUntil);
    trust.horizonObserved = true;
    trust.horizonMethod += "; observed";
  } else {
    double horizon = timeRounding;
    if (compared > 0 && now < kHorizonTolerance) {
      horizon = 2 * compared;
      if (cautiousRate > 0) horizon = std::min(horizon, compared + std::log(kHorizonTolerance / now) / cautiousRate);
    }
    trust.horizon = std::min(horizon, timeRounding);
    trust.horizonMethod += "; held to t = " + formatScalar(compared) +
                           "; beyond: extrapolated, conservatively (the growth seen taken as exponential, "
                           "at most twice the time compared)";
  }

  const double worst = std::max(trust.stateError, trust.timeError);
  const std::string estimate = "estimated error " + scientific(worst);
  if (worst > kHorizonTolerance) {
    trust.verdict = Verdict::Unreliable;
    trust.reason = "the run goes past its predictability horizon t = " +
                   scientific(trust.horizon) + " (" + estimate + " at the end): " +
                   (std::is_same_v<S, Quad> ? "shorten the run"
                                            : "shorten the run or raise --precision");
  } else if (worst > kOkTolerance) {
    trust.verdict = Verdict::Degraded;
    trust.reason = estimate + " (" + growth + ")";
  } else {
    trust.verdict = Verdict::Ok;
    trust.reason = estimate + " (" + shadowName() + ")";
  }
  if (interrupted) trust.reason += "; up to the interruption";
  if (!m_stopNote.empty()) trust.reason += "; " + m_stopNote;
  if (extrapolated) trust.reason += ", the rest extrapolated";
  return trust;
}

template class TrustMonitor<double>;
template class TrustMonitor<long double>;
template class TrustMonitor<Quad>;

}  // namespace grazelab::core
