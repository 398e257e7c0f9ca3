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
ChainShadow<S> chainShadow(const BasicReadyChain<ShadowScalar<S>>& input, ExactParameters exact) {
  using H = ShadowScalar<S>;
  ChainShadow<S> shadow;
  shadow.input = &input;
  shadow.exact = std::move(exact);
  if constexpr (std::is_same_v<S, H>) {
    // no wider type: the same precision on a chain 3 times as large, 5 times as heavy and
    // sqrt(3) times as fast rounds every length, speed and time differently, and the chain's
    // own constants too (the physics is scale-free)
    using std::sqrt;
    shadow.length = 3;
    shadow.time = sqrt(H(3));
    // the shadow read the same decimal input in the same precision, so it shares its rounding; a
    // nudge of one rounding puts the input's representation into the estimate, as a wider shadow
    // does by reading it afresh (a mass ratio near 9/16 amplifies its rounding ~1e7 in the
    // note's designed k2; m2/m1 is nudged down, toward the feasible side of the design). A read
    // is off by at most half an ulp, but a nudge that small is undone by the roundings that
    // follow (x (1 + 2^-113) rounds back to x; k2 * 15 / 15 rounds back to k2): the shadow then
    // had the run's own chain and missed its dominant error (a detuned chain amplifying k2/k1's
    // rounding to 6e-16 T2 in 20 contacts, estimated 1e-18). Four ulps survive them.
    const H eps = H(4) * epsilon<H>();
    const ExactParameters& read = shadow.exact;
    // odd masses and springs (1-based) nudged up, even ones down; the right spring and gap up
    const auto nudge = [&](H& value, const std::vector<bool>& exactly, std::size_t i) {
      if (i < exactly.size() && !exactly[i]) value += (i % 2 == 0 ? value : H(-value)) * eps;
    };
    if (input.notesModel) {
      // the note's chain scaled as its model, which keeps its 1:2 design exact (k2 designed
      // again for the nudged masses)
      BasicModel<H> model = *input.notesModel;
      model.gap *= shadow.length;
      model.m1 *= 5;
      model.m2 *= 5;
      model.k1 *= 15;  // k / m, and w^2, 3 times larger: times by 1 / sqrt(3)
      model.k2 *= 15;
      nudge(model.m1, read.masses, 0);
      nudge(model.m2, read.masses, 1);
      nudge(model.k1, read.springs, 0);
      nudge(model.k2, read.springs, 1);
      if (!read.gap) model.gap += model.gap * eps;
      std::vector<Problem> problems = validate(model);
      if (problems.empty() && !makeTwoMassForm(model).chain) problems.push_back({"model", "no two-mass form"});
      if (!problems.empty()) {
        shadow.problem = describe(problems);
        return shadow;
      }
      shadow.scaledChain = readyChain(model);
    } else {
      BasicMassChain<H> chain = input.numbers;
      for (std::size_t i = 0; i < chain.masses.size(); ++i) {
        chain.masses[i] *= 5;
        chain.springs[i] *= 15;
        nudge(chain.masses[i], read.masses, i);
        nudge(chain.springs[i], read.springs, i);
      }
      chain.rightSpring *= 15;
      chain.gap *= shadow.length;
      if (!read.rightSpring) chain.rightSpring += chain.rightSpring * eps;
      if (!read.gap) chain.gap += chain.gap * eps;
      shadow.scaledChain = readyChain(chain);
    }
  }
  return shadow;
}

template <typename S>
TrustMonitor<S>::TrustMonitor(const ChainShadow<S>& shadow, const BasicChainStart<H>& start, long maxContacts,
                              std::type_identity_t<H> tEnd, TrustMode mode, std::stop_token stop,
                              std::int64_t searchSteps)
    : m_chain(&shadow),
      m_mode(mode),
      m_stop(std::move(stop)),
      m_inputStart(start),
      m_maxContacts(maxContacts),
      m_tEnd(tEnd),
      m_searchSteps(searchSteps) {
  if (mode == TrustMode::Off) {
    m_active = false;
    return;
  }
  if (!shadow.usable()) {
    m_stopNote = "the shadow run could not start (" + (shadow.problem.empty() ? std::string("no shadow chain") : shadow.problem) + ")";
    m_active = false;
    return;
  }
  const BasicReadyChain<H>& ready = shadow.ready();
  const Eigen::Index s = ready.dynamics.stop;
  m_stopped = s;
  BasicChainStart<H> x = start;
  H shadowEnd = tEnd;
  if constexpr (std::is_same_v<S, H>) {
    const H speed = shadow.length * shadow.time;
    x.state.u *= shadow.length;
    x.state.v *= speed;
    if (!shadow.exact.start) {
      // the state keeps a half-ulp nudge (never across the stop, never changing a sign): its
      // rounding mostly stays, and a whole ulp off a periodic orbit (1IPP) drifted 1000 times
      // further than the run did
      using std::abs;
      const H stateEps = epsilon<H>() / H(2);
      // (on the stop as read: a start there stays on the stop, the nudged one)
      const bool onStop = x.state.u[s] == H(shadow.input->numbers.gap * shadow.length);
      for (Eigen::Index i = 0; i < x.state.u.size(); ++i) {
        H& u = x.state.u[i];
        H& v = x.state.v[i];
        if (i == s) {
          u = onStop ? ready.numbers.gap : H(u - abs(u) * stateEps);
          v += v * stateEps;
        } else {
          u += abs(u) * stateEps;
          v -= v * stateEps;
        }
      }
    }
    shadowEnd = tEnd / shadow.time;
  }
  if (!x.state.u.allFinite() || !x.state.v.allFinite() || !(x.state.u[s] <= ready.numbers.gap)) {
    m_stopNote = "the shadow run could not start (its start is not finite and below the stop)";
    m_active = false;
    return;
  }
  // each shadow event, held until compared
  const ChainEventSink<H> sink = [this](const BasicChainEvent<H>& event) {
    if (m_pendingCount == m_pending.size()) {
      // full: the ring laid out from its first slot, one slot more
      std::rotate(m_pending.begin(), m_pending.begin() + std::ptrdiff_t(m_pendingFirst), m_pending.end());
      m_pendingFirst = 0;
      m_pending.push_back(event);
    } else {
      m_pending[(m_pendingFirst + m_pendingCount) % m_pending.size()] = event;
    }
    ++m_pendingCount;
  };
  m_shadow = std::make_unique<BasicChainSimulator<H>>(ready, x, maxContacts, shadowEnd, sink, ChainSampling<H>{},
                                                      searchSteps);
  // the slowest and the fastest angular frequency in the primary's time (the shadow's chain runs
  // `time` times as fast; the note's slowest from its closed form)
  m_omega = (ready.notes ? ready.notes->omegaSlow : H(slowestFrequency(ready.dynamics.omega))) / shadow.time;
  m_fastest = H(ready.dynamics.omega.maxCoeff()) / shadow.time;
  m_period = twoPi<H>() / m_omega;
  using std::abs;
  m_scaleU = Vector::Zero(start.state.u.size());
  m_scaleV = Vector::Zero(start.state.v.size());
  m_scaleU[s] = abs(shadow.input->numbers.gap);
  widenScales({start.state.u, start.state.v});
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
void TrustMonitor<S>::fromShadow(Point& into, const ChainVector<H>& u, const ChainVector<H>& v) const {
  if (m_chain->length == 1 && m_chain->time == 1) {
    into.u = u;
    into.v = v;
    return;
  }
  const H speed = m_chain->length * m_chain->time;
  into.u = u / m_chain->length;
  into.v = v / speed;
}

template <typename S>
void TrustMonitor<S>::widenScales(const Point& state) {
  m_scaleU = m_scaleU.cwiseMax(state.u.cwiseAbs());
  m_scaleV = m_scaleV.cwiseMax(state.v.cwiseAbs());
}

template <typename S>
double TrustMonitor<S>::relativeStateError(const Point& primary, const Point& shadow) const {
  using std::abs;
  using std::max;
  // each component against its own scale, floored at 1e-3 of its kind (positions, velocities)
  // so that a component that stays near zero does not turn rounding into a large error
  const H positions = m_scaleU.maxCoeff();
  const H velocities = max(H(m_scaleV.maxCoeff()), H(m_omega * positions));
  double worst = 0;
  const auto against = [&](const Vector& a, const Vector& b, const Vector& scales, const H& floor) {
    for (Eigen::Index i = 0; i < a.size(); ++i) {
      const H scale = max(scales[i], H(floor / H(1000)));
      if (scale > 0) worst = std::max(worst, toDouble(H(abs(a[i] - b[i]) / scale)));
    }
  };
  against(primary.u, shadow.u, m_scaleU, positions);
  against(primary.v, shadow.v, m_scaleV, velocities);
  return worst;
}

template <typename S>
typename TrustMonitor<S>::H TrustMonitor<S>::fastestRate() const {
  // over the scales: a state moves at most |v| <= velocities (over positions) and
  // |a| <= w_max^2 positions (over velocities)
  using std::max;
  const H positions = max(H(m_scaleU.maxCoeff()), H(epsilon<H>()));
  const H velocities = max(H(m_scaleV.maxCoeff()), H(m_omega * positions));
  return max(H(velocities / positions), H(m_fastest * m_fastest * positions / velocities));
}

template <typename S>
bool TrustMonitor<S>::withinBudget() const {
  return m_mode == TrustMode::Full || m_observed <= autoShadowEvents<S>();
}

template <typename S>
const BasicChainEvent<typename TrustMonitor<S>::H>* TrustMonitor<S>::nextShadowEvent() {
  while (m_pendingCount == 0 && !m_shadow->done()) m_shadow->advance(1, m_stop);
  return m_pendingCount > 0 ? &m_pending[m_pendingFirst] : nullptr;
}

template <typename S>
void TrustMonitor<S>::popShadowEvent() {
  m_pendingFirst = (m_pendingFirst + 1) % m_pending.size();
  --m_pendingCount;
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
               formatScalar(H(m_shadow->run().tFinal * m_chain->time)) + ": compared up to there";
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
  const BasicChainEvent<H>* shadow = nextShadowEvent();
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
  // the states before and after the event (the stopped mass's velocity changes; a release or a
  // stick's end changes nothing of them), in vectors reused from event to event
  m_before.u = event.u.template cast<H>();
  m_before.v = event.vBefore.template cast<H>();
  m_after.u = m_before.u;
  m_after.v = m_before.v;
  m_after.v[m_stopped] = H(event.vAfter);
  fromShadow(m_shadowBefore, shadow->u, shadow->vBefore);
  m_shadowAfter.u = m_shadowBefore.u;
  m_shadowAfter.v = m_shadowBefore.v;
  m_shadowAfter.v[m_stopped] = m_chain->length == 1 && m_chain->time == 1
                                   ? shadow->vAfter
                                   : H(shadow->vAfter / (m_chain->length * m_chain->time));
  widenScales(m_shadowBefore);
  widenScales(m_shadowAfter);
  using std::abs;
  const H timeShift = abs(H(event.t) - H(shadow->t * m_chain->time));
  double stateError = std::max(relativeStateError(m_before, m_shadowBefore), relativeStateError(m_after, m_shadowAfter));
  if (!m_chain->ready().notes) {
    // the state at a given time: also where the motion goes in the time the event is off by (a
    // stiff light mass meets the stop thousands of times a period, u_s = d exactly at each, but
    // at speed V an event dt late is V dt away at any given time)
    stateError = std::max(stateError, toDouble(H(timeShift * fastestRate())));
  }
  const double timeError = toDouble(H(timeShift / m_period));
  popShadowEvent();
  compare(H(event.t), stateError, timeError);
  ++m_compared;
}

template <typename S>
double TrustMonitor<S>::phaseRounding(const BasicChainRun<S>& primary) const {
  using std::abs;
  const Point x{primary.final.u.template cast<H>(), primary.final.v.template cast<H>()};
  const H dt = H(epsilon<S>()) * (abs(H(primary.tFinal)) + m_period);
  // where the state moves in dt at its own speed and acceleration
  Point moved{x.u + x.v.cwiseAbs() * dt, x.v};
  const BasicReadyChain<H>& shadow = m_chain->ready();
  if (shadow.notes) {
    // the note's chain, its acceleration in the two-mass form
    const TwoMassForm<H>& chain = *shadow.notes;
    const H w2 = m_omega * m_omega;
    const H stretch = x.u[0] - x.u[1];
    moved.v[0] += abs(w2 * (chain.p * x.u[0] + chain.q * stretch)) * dt;
    moved.v[1] += abs(w2 * chain.w * stretch) * dt;
  } else {
    const BasicMassChain<H>& chain = m_chain->input->numbers;
    const Vector force = stiffnessMatrix(chain) * x.u;
    for (Eigen::Index i = 0; i < x.v.size(); ++i) moved.v[i] += abs(force[i] / chain.masses[std::size_t(i)]) * dt;
  }
  return relativeStateError(x, moved);
}

template <typename S>
void TrustMonitor<S>::arbitrate(const BasicChainRun<S>& primary, Trust& trust) {
  if constexpr (!std::is_same_v<S, double>) {
    return;  // (a long double run's shadow is binary128 already)
  } else {
    // binary128 costs about 20 times a double run of the note's chain: up to 2e4 contacts, a
    // second at most (the note's chain only: a chain of more masses, or a search over long
    // flights, costs seconds for a hundred contacts there)
    constexpr std::int64_t kArbiterContacts = 20000;
    if (!m_chain->usable() || !m_chain->input->notes || primary.contacts > kArbiterContacts) return;
    if (m_stop.stop_requested()) return;
    // the input as the shadow read it, in binary128 (the note's chain by its model: a design
    // stays a design there)
    const BasicReadyChain<H>& input = *m_chain->input;
    const BasicReadyChain<Quad> chain = input.notesModel ? readyChain(convertModel<Quad>(*input.notesModel))
                                                         : readyChain(chainCast<Quad>(input.numbers));
    const BasicChainStart<Quad> start{{m_inputStart.state.u.template cast<Quad>(), m_inputStart.state.v.template cast<Quad>()},
                                      m_inputStart.stillModes};
    const BasicChainRun<Quad> exact = runChain(chain, start, m_maxContacts, Quad(m_tEnd), m_stop);
    if (exact.stop != primary.stop || exact.contacts != primary.contacts) return;  // confirmed
    using std::abs;
    const double stateError =
        relativeStateError({primary.final.u.template cast<H>(), primary.final.v.template cast<H>()},
                           {exact.final.u.template cast<H>(), exact.final.v.template cast<H>()});
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
}

template <typename S>
Trust TrustMonitor<S>::finish(const BasicChainRun<S>& primary) {
  Trust trust = estimate(primary);
  if (m_shadowUndecided) {
    const BasicChainRun<H>& shadow = m_shadow->run();
    const double undecidedAt = toDouble(H(shadow.tFinal * m_chain->time));
    if (m_observed > shadow.contacts + shadow.releases && primary.stop != StopReason::Cancelled) {
      // the run decided a contact its shadow cannot: nothing past it is confirmed (the binary128
      // arbiter below may still confirm a double run)
      trust.verdict = Verdict::Unreliable;
      trust.horizon = std::min(trust.horizon, undecidedAt);
      trust.horizonObserved = true;
      trust.reason = "the " + shadowName() + " cannot decide the contact after t = " + formatScalar(undecidedAt) +
                     ": the run past it is not confirmed";
    } else if (trust.verdict == Verdict::Ok) {
      // the run stopped there too: what came before is compared, and no more is claimed
      trust.verdict = Verdict::Degraded;
    }
  }
  if (trust.verdict == Verdict::Unreliable) arbitrate(primary, trust);
  if (primary.stop == StopReason::SearchBudget || primary.stop == StopReason::Undecided) {
    // the run stopped undecided: whatever came before holds, what follows is not known
    if (trust.verdict != Verdict::Unreliable) trust.verdict = Verdict::Degraded;
    trust.reason = (primary.stop == StopReason::SearchBudget
                        ? "no contact was decided within the search's budget; "
                        : "the run ended at a contact its precision cannot decide; ") +
                   trust.reason;
  }
  return trust;
}

template <typename S>
Trust TrustMonitor<S>::estimate(const BasicChainRun<S>& primary) {
  Trust trust;
  trust.shadowEvents = m_compared;
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
    } else if (shadow.stop == StopReason::Undecided && m_pendingCount == 0) {
      shadowUndecided();
    } else if (m_pendingCount > 0) {
      m_failure = "the shadow run has an event the run has not (t = " +
                  formatScalar(H(m_pending[m_pendingFirst].t * m_chain->time)) + ")";
    } else if (shadow.stop != primary.stop) {
      m_failure = "the shadow run stopped with " + std::string(toString(shadow.stop)) +
                  ", the run with " + std::string(toString(primary.stop));
    } else {
      const Point final{primary.final.u.template cast<H>(), primary.final.v.template cast<H>()};
      Point shadowFinal;
      fromShadow(shadowFinal, shadow.final.u, shadow.final.v);
      widenScales(shadowFinal);
      const double stateError = relativeStateError(final, shadowFinal);
      using std::abs;
      const double timeError =
          toDouble(H(abs(H(primary.tFinal) - shadow.tFinal * m_chain->time) / m_period));
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
      rate > 0 ? "exponential growth, FTLE " + scientific(rate * period) + (m_chain->ready().notes ? " per T2" : " per slowest period")
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

template <typename S>
ChainShadow<S> widenedShadow(const BasicReadyChain<S>& chain, std::optional<BasicReadyChain<ShadowScalar<S>>>& widened) {
  if constexpr (std::is_same_v<S, ShadowScalar<S>>) {
    return chainShadow<S>(chain);
  } else {
    widened = widenedChain(chain);
    return chainShadow<S>(*widened);
  }
}

template <typename S>
Trust trustOf(const BasicReadyChain<S>& chain, const std::type_identity_t<BasicChainStart<S>>& start,
              const BasicChainRun<S>& run, long maxContacts, std::type_identity_t<S> tEnd, TrustMode mode,
              std::stop_token stop) {
  using H = ShadowScalar<S>;
  std::optional<BasicReadyChain<H>> widened;
  const ChainShadow<S> shadow = mode == TrustMode::Off ? ChainShadow<S>{} : widenedShadow(chain, widened);
  TrustMonitor<S> monitor(shadow, {{start.state.u.template cast<H>(), start.state.v.template cast<H>()}, start.stillModes},
                          maxContacts, H(tEnd), mode, std::move(stop));
  for (const BasicChainEvent<S>& event : run.events) monitor.observe(event);
  return monitor.finish(run);
}

#define GRAZELAB_INSTANTIATE(S)                                                                               \
  template ChainShadow<S> widenedShadow<S>(const BasicReadyChain<S>&, std::optional<BasicReadyChain<ShadowScalar<S>>>&); \
  template Trust trustOf<S>(const BasicReadyChain<S>&, const BasicChainStart<S>&, const BasicChainRun<S>&, long, S,  \
                            TrustMode, std::stop_token);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE
template ChainShadow<double> chainShadow<double>(const BasicReadyChain<long double>&, ExactParameters);
template ChainShadow<long double> chainShadow<long double>(const BasicReadyChain<Quad>&, ExactParameters);
template ChainShadow<Quad> chainShadow<Quad>(const BasicReadyChain<Quad>&, ExactParameters);
template class TrustMonitor<double>;
template class TrustMonitor<long double>;
template class TrustMonitor<Quad>;

}  // namespace grazelab::core
