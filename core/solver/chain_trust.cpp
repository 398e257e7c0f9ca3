// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/chain_trust.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace grazelab::core {
namespace {

template <typename S>
std::string precisionName() {
  switch (precisionOf<S>()) {
    case Precision::Double: return "double";
    case Precision::Long: return "long double";
    case Precision::Quad: return "binary128";
  }
  return "";
}

}  // namespace

template <typename S>
ChainShadow<S> chainShadow(const BasicMassChain<S>& chain) {
  using H = ShadowScalar<S>;
  // one precision up; binary128 by binary128 on the chain scaled 3x in length and 1/sqrt(3) in
  // time (springs x 3, masses as given: w x sqrt(3))
  ChainShadow<S> shadow;
  shadow.scaled = std::is_same_v<S, H>;
  BasicMassChain<H> shadowChain = chainCast<H>(chain);
  if (shadow.scaled) {
    for (H& k : shadowChain.springs) k *= 3;
    shadowChain.rightSpring *= 3;
    shadowChain.gap *= 3;
    shadow.length = 3;
    using std::sqrt;
    shadow.time = sqrt(H(3));
  }
  shadow.ready = readyChain(shadowChain);
  const ChainVector<double> omega = chainModesIn<double>(chain).omega;
  shadow.slowest = twoPi<double>() / omega.minCoeff();
  shadow.fastest = omega.maxCoeff();
  shadow.gap = toDouble(chain.gap);
  return shadow;
}

template <typename S>
ChainTrustCheck<S>::ChainTrustCheck(const BasicMassChain<S>& chain, const BasicChainStart<S>& start, long maxContacts,
                                    std::type_identity_t<S> tEnd, TrustMode mode, std::stop_token stop)
    : ChainTrustCheck(mode == TrustMode::Off ? ChainShadow<S>{} : chainShadow(chain), start, maxContacts, tEnd, mode,
                      std::move(stop)) {}

template <typename S>
ChainTrustCheck<S>::ChainTrustCheck(const ChainShadow<S>& shadow, const BasicChainStart<S>& start, long maxContacts,
                                    std::type_identity_t<S> tEnd, TrustMode mode, std::stop_token stop)
    : m_mode(mode) {
  if (mode == TrustMode::Off) {
    m_trust.reason = "not estimated (--trust off)";
    return;
  }
  m_scaled = shadow.scaled;
  m_length = shadow.length;
  m_time = shadow.time;
  // the same modes still in the shadow's start (a chain scaled in length and time has the same modes)
  const BasicChainStart<H> shadowStart{{start.state.u.template cast<H>() * m_length,
                                        start.state.v.template cast<H>() * (m_length * m_time)},
                                       start.stillModes};
  // auto: the first contacts only (a budget fixed by the precision), when the run may make more
  if (mode == TrustMode::Auto && maxContacts > chainShadowContacts<S>()) m_cap = chainShadowContacts<S>();
  m_shadow = runChain(shadow.ready, shadowStart, m_cap > 0 ? m_cap : maxContacts, H(tEnd) / m_time, stop);
  if (stop.stop_requested()) {
    m_interrupted = true;
    m_trust.reason = "the estimate was interrupted";
    return;
  }
  // the scales: the largest |u_i| and |v_i| at the shadow's events, the gap at least and the
  // largest speed the motion's energy allows (sqrt(2 E / m_i)) at least: a grazing orbit meets
  // the stop at rest, its velocities there zero but for rounding, which must not be the scale
  // its rounding is measured against (it read "unreliable" on exactly periodic orbits)
  m_uScale = shadow.gap;
  using std::sqrt;
  const BasicMassChain<H>& numbers = shadow.ready.numbers;
  const H lightest = *std::min_element(numbers.masses.begin(), numbers.masses.end());
  double vScale = toDouble(sqrt(2 * chainEnergy(numbers, shadowStart.state) / lightest) / (m_length * m_time));
  for (const BasicChainEvent<H>& event : m_shadow.events) {
    m_uScale = std::max(m_uScale, toDouble(event.u.cwiseAbs().maxCoeff() / m_length));
    vScale = std::max(vScale, toDouble(event.vBefore.cwiseAbs().maxCoeff() / (m_length * m_time)));
  }
  m_vScale = vScale > 0 ? vScale : 1.0;
  m_slowest = shadow.slowest;
  // a state moves at most |v| <= vScale (over uScale) and |a| <= w_max^2 uScale (over vScale)
  m_rate = std::max(m_vScale / m_uScale, shadow.fastest * shadow.fastest * m_uScale / m_vScale);
}

template <typename S>
double ChainTrustCheck<S>::difference(const ChainVector<S>& au, const ChainVector<S>& av, const ChainVector<H>& bu,
                                      const ChainVector<H>& bv) const {
  using std::abs;
  double error = 0;
  for (Eigen::Index i = 0; i < au.size(); ++i) {
    error = std::max(error, toDouble(abs(H(au[i]) - bu[i] / m_length)) / m_uScale);
    error = std::max(error, toDouble(abs(H(av[i]) - bv[i] / (m_length * m_time))) / m_vScale);
  }
  return error;
}

template <typename S>
void ChainTrustCheck<S>::observe(const BasicChainEvent<S>& a) {
  if (m_mode == TrustMode::Off || m_interrupted || m_passed) return;
  const std::size_t k = m_observed++;
  const double t = toDouble(a.t);
  if (k >= m_shadow.events.size()) {  // past the shadow: its end is judged in finish()
    if (m_firstPastShadow < 0) m_firstPastShadow = t;
    return;
  }
  const BasicChainEvent<H>& b = m_shadow.events[k];
  if (a.type != b.type) {
    m_trust.reason = "the shadow run in " + precisionName<H>() + " meets another event at t = " + formatScalar(t) +
                     " (" + std::string(toString(a.type)) + " against " + std::string(toString(b.type)) + ")";
    m_passed = true;
    m_passedAt = t;
    return;
  }
  using std::abs;
  const double timeShift = toDouble(abs(H(a.t) - b.t * m_time));
  // the state at a given time: off by the event's own error, or by where the motion goes in the
  // time the event is off by (a stiff light mass's fast impacts: its u_s is exact at each event,
  // its timing not)
  const double stateError = std::max(difference(a.u, a.vBefore, b.u, b.vBefore),
                                     timeShift * m_rate);
  const double timeError = timeShift / m_slowest;
  const double error = std::max(stateError, timeError);
  m_trust.timeError = std::max(m_trust.timeError, timeError);
  m_trust.stateError = std::max(m_trust.stateError, stateError);
  ++m_trust.shadowEvents;
  if (error > 0 && m_firstError == 0) {
    m_firstError = error;
    m_firstTime = t;
  }
  m_lastError = error;
  m_lastTime = t;
  if (error > kHorizonTolerance) {
    m_passed = true;
    m_passedAt = t;
    m_trust.reason = "the shadow run in " + precisionName<H>() + " parts from the run by " + formatScalar(error) +
                     " at t = " + formatScalar(t);
  }
}

template <typename S>
Trust ChainTrustCheck<S>::finish(const BasicChainRun<S>& run) const {
  Trust trust = m_trust;
  if (m_mode == TrustMode::Off || m_interrupted) return trust;
  // the shadow stopped at its budget before the run's end: the rest is extrapolated
  const bool capped = m_cap > 0 && run.contacts > m_cap;
  bool passed = m_passed;
  double passedAt = m_passedAt;
  const double tFinal = toDouble(run.tFinal);
  // where the shadow itself could not decide a contact, nothing past it is confirmed: a run that
  // went on (deciding what the higher precision could not) is judged there, whatever it counted
  const double shadowEnd = toDouble(m_shadow.tFinal * m_time);
  if (!passed && m_shadow.stop == StopReason::Undecided && tFinal > shadowEnd) {
    passed = true;
    passedAt = shadowEnd;
    trust.reason = "the shadow run in " + precisionName<H>() + " cannot decide the contact at t = " +
                   formatScalar(shadowEnd) + ": the run past it is not confirmed";
  }
  // another number of events over the span both ran: judged at the first one without its match
  if (!passed && !capped && m_observed != m_shadow.events.size() &&
      (run.stop == StopReason::ContactLimit || run.stop == StopReason::TimeLimit)) {
    passed = true;
    passedAt = m_observed > m_shadow.events.size() ? m_firstPastShadow
                                                   : toDouble(m_shadow.events[m_observed].t * m_time);
    trust.reason = "the shadow run in " + precisionName<H>() + " ends with another number of events (" +
                   std::to_string(m_shadow.events.size()) + " against " + std::to_string(m_observed) + ")";
  }
  // both ended at the end time with the same events: their final states are the state at a given
  // time, compared directly (the last flight's drift since the last event included)
  double firstError = m_firstError, firstTime = m_firstTime, lastError = m_lastError, lastTime = m_lastTime;
  if (!passed && !capped && run.stop == StopReason::TimeLimit && m_shadow.stop == StopReason::TimeLimit) {
    const double finalError = difference(run.final.u, run.final.v, m_shadow.final.u, m_shadow.final.v);
    trust.stateError = std::max(trust.stateError, finalError);
    if (finalError > 0 && firstError == 0) {
      firstError = finalError;
      firstTime = tFinal;
    }
    if (finalError > 0) {
      lastError = finalError;
      lastTime = tFinal;
    }
    if (finalError > kHorizonTolerance) {
      passed = true;
      passedAt = tFinal;
      trust.reason = "the shadow run in " + precisionName<H>() + " parts from the run by " + formatScalar(finalError) +
                     " at its end, t = " + formatScalar(tFinal);
    }
  }
  trust.horizonMethod = "shadow run in " + precisionName<H>() + (m_scaled ? " (chain scaled 3x)" : "") + "; ";
  if (passed) {
    trust.horizon = passedAt;
    trust.horizonObserved = true;
    trust.horizonMethod += "observed";
    trust.verdict = Verdict::Unreliable;
    return trust;
  }
  // not passed where the shadow went: extrapolated as exponential growth from the first to the
  // last nonzero error, at most twice the time compared (the run's, when shadowed whole)
  const double compared = capped ? lastTime : std::max(tFinal, lastTime);
  double horizon = 2 * compared;
  if (firstError > 0 && lastError > firstError && lastTime > firstTime) {
    const double rate = std::log(lastError / firstError) / (lastTime - firstTime);
    horizon = std::min(horizon, lastTime + std::log(kHorizonTolerance / lastError) / rate);
  }
  trust.horizon = horizon;
  if (capped) {
    trust.horizonMethod += "the first " + std::to_string(trust.shadowEvents) +
                           " events (--trust auto keeps it cheap; full shadows the whole run); ";
  }
  trust.horizonMethod += capped ? "extrapolated (exponential growth, at most twice the time compared)"
                                : "extrapolated (exponential growth, at most twice the run's time)";
  const double worst = std::max(trust.stateError, trust.timeError);
  trust.verdict = worst < kOkTolerance ? Verdict::Ok : Verdict::Degraded;
  trust.reason = "the shadow run in " + precisionName<H>() + " agrees to " + formatScalar(worst) + " over " +
                 std::to_string(trust.shadowEvents) + " events";
  if (horizon < tFinal) {
    trust.verdict = Verdict::Unreliable;
    trust.reason += ", but its extrapolated horizon t = " + formatScalar(horizon) + " falls within the run";
  }
  return trust;
}

template <typename S>
Trust chainTrust(const ChainShadow<S>& shadow, const std::type_identity_t<BasicChainStart<S>>& start, const BasicChainRun<S>& run,
                 long maxContacts, std::type_identity_t<S> tEnd, TrustMode mode, std::stop_token stop) {
  ChainTrustCheck<S> check(shadow, start, maxContacts, tEnd, mode, stop);
  for (const BasicChainEvent<S>& event : run.events) check.observe(event);
  return check.finish(run);
}

template <typename S>
Trust chainTrust(const BasicMassChain<S>& chain, const std::type_identity_t<BasicChainStart<S>>& start, const BasicChainRun<S>& run,
                 long maxContacts, std::type_identity_t<S> tEnd, TrustMode mode, std::stop_token stop) {
  return chainTrust(mode == TrustMode::Off ? ChainShadow<S>{} : chainShadow(chain), start, run, maxContacts, tEnd, mode,
                    std::move(stop));
}

#define GRAZELAB_INSTANTIATE(S)                                                                       \
  template ChainShadow<S> chainShadow<S>(const BasicMassChain<S>&);                                       \
  template Trust chainTrust<S>(const ChainShadow<S>&, const BasicChainStart<S>&, const BasicChainRun<S>&, long, \
                               std::type_identity_t<S>, TrustMode, std::stop_token);                      \
  template Trust chainTrust<S>(const BasicMassChain<S>&, const BasicChainStart<S>&, const BasicChainRun<S>&, long, \
                               std::type_identity_t<S>, TrustMode, std::stop_token);                      \
  template class ChainTrustCheck<S>;
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
