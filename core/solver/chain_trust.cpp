// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/chain_trust.h"

#include <algorithm>
#include <cmath>
#include <string>

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
Trust chainTrust(const MassChain& chain, const BasicChainState<S>& start, const BasicChainRun<S>& run,
                 long maxContacts, std::type_identity_t<S> tEnd, TrustMode mode, std::stop_token stop) {
  using H = ShadowScalar<S>;
  Trust trust;
  if (mode == TrustMode::Off) {
    trust.reason = "not estimated (--trust off)";
    return trust;
  }
  // the shadow: one precision up; binary128 by binary128 on the chain scaled 3x in length and
  // 1/sqrt(3) in time (springs x 3, masses as given: w x sqrt(3))
  const bool scaled = std::is_same_v<S, H>;
  MassChain shadowChain = chain;
  H length = 1, time = 1;  // shadow = primary x length, shadow times = primary times / time
  if (scaled) {
    for (double& k : shadowChain.springs) k *= 3;
    shadowChain.rightSpring *= 3;
    shadowChain.gap *= 3;
    length = 3;
    using std::sqrt;
    time = sqrt(H(3));
  }
  BasicChainState<H> shadowStart{start.u.template cast<H>() * length, start.v.template cast<H>() * (length * time)};
  // auto: the first contacts only (a budget fixed by the precision), when the run has more
  const bool capped = mode == TrustMode::Auto && run.contacts > chainShadowContacts<S>();
  const long shadowContacts = capped ? chainShadowContacts<S>() : maxContacts;
  const BasicChainRun<H> shadow =
      runChain(shadowChain, shadowStart, shadowContacts, capped ? H(0) : H(tEnd) / time, stop);
  if (stop.stop_requested()) {
    trust.reason = "the estimate was interrupted";
    return trust;
  }
  // the scales: the largest |u_i| and |v_i| at the run's events (the gap at least)
  const Eigen::Index n = start.u.size();
  double uScale = chain.gap, vScale = 0;
  for (const BasicChainEvent<S>& event : run.events) {
    uScale = std::max(uScale, toDouble(event.u.cwiseAbs().maxCoeff()));
    vScale = std::max(vScale, toDouble(event.vBefore.cwiseAbs().maxCoeff()));
  }
  if (!(vScale > 0)) vScale = 1;
  const ChainModes modes = chainModes(chain);
  const double slowest = twoPi<double>() / modes.omega.minCoeff();
  double firstError = 0, firstTime = 0, lastError = 0, lastTime = 0;
  bool passed = false;
  double passedAt = 0;
  const std::size_t count = std::min(run.events.size(), shadow.events.size());
  for (std::size_t k = 0; k < count; ++k) {
    const BasicChainEvent<S>& a = run.events[k];
    const BasicChainEvent<H>& b = shadow.events[k];
    const double t = toDouble(a.t);
    if (a.type != b.type) {
      trust.reason = "the shadow run in " + precisionName<H>() + " meets another event at t = " + formatScalar(t) +
                     " (" + std::string(toString(a.type)) + " against " + std::string(toString(b.type)) + ")";
      passed = true;
      passedAt = t;
      break;
    }
    double stateError = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      using std::abs;
      stateError = std::max(stateError, toDouble(abs(H(a.u[i]) - b.u[i] / length)) / uScale);
      stateError = std::max(stateError, toDouble(abs(H(a.vBefore[i]) - b.vBefore[i] / (length * time))) / vScale);
    }
    using std::abs;
    const double timeError = toDouble(abs(H(a.t) - b.t * time)) / slowest;
    const double error = std::max(stateError, timeError);
    trust.timeError = std::max(trust.timeError, timeError);
    trust.stateError = std::max(trust.stateError, stateError);
    ++trust.shadowEvents;
    if (error > 0 && firstError == 0) {
      firstError = error;
      firstTime = t;
    }
    lastError = error;
    lastTime = t;
    if (error > kHorizonTolerance) {
      passed = true;
      passedAt = t;
      trust.reason = "the shadow run in " + precisionName<H>() + " parts from the run by " + formatScalar(error) +
                     " at t = " + formatScalar(t);
      break;
    }
  }
  if (!passed && !capped && run.events.size() != shadow.events.size() && run.stop == ChainStop::ContactLimit) {
    passed = true;
    passedAt = toDouble(run.tFinal);
    trust.reason = "the shadow run in " + precisionName<H>() + " ends with another number of events";
  }
  const double tFinal = toDouble(run.tFinal);
  trust.horizonMethod = "shadow run in " + precisionName<H>() + (scaled ? " (chain scaled 3x)" : "") + "; ";
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

#define GRAZELAB_INSTANTIATE(S)                                                                       \
  template Trust chainTrust<S>(const MassChain&, const BasicChainState<S>&, const BasicChainRun<S>&, long, \
                               std::type_identity_t<S>, TrustMode, std::stop_token);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
