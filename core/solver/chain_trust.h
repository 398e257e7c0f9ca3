// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <stop_token>
#include <type_traits>

#include "core/model/mass_chain.h"
#include "core/solver/chain_run.h"
#include "core/solver/trust.h"

namespace grazelab::core {

/// How far a run of a chain of N masses can be trusted (docs/model.md section 11): the same run
/// in the shadow precision (ShadowScalar: double by long double, long double by binary128,
/// binary128 by binary128 on the chain scaled 3x in length and 1/sqrt(3) in time, which changes
/// every rounding and not the motion), compared event by event. The time error is the largest
/// difference of an event's time, over the slowest period; the state error is the error of the
/// state at a given time: the largest of the displacements' and velocities' differences over their
/// scales (the largest sizes met at the events; the gap and the largest speed the energy allows at
/// least) at each event, or what its time's error moves the state by at the fastest rate the
/// motion allows (a light mass meeting the stop at speed V an event time error dt later is V dt
/// away at any given time), whichever is larger; and, for a run and a whole shadow that both end
/// at its end time, the difference of their final states. The horizon
/// is where that error first passes kHorizonTolerance (an event of another type or a missing one
/// counts as passing it): observed when the shadow shows
/// it, else extrapolated from the error's growth between the first and the last event as if
/// exponential, at most twice the run's time, so that the same run gets the same figure. Ok below
/// kOkTolerance, degraded below kHorizonTolerance, unreliable past the horizon within the run.
/// Full shadows the whole run; Auto its first chainShadowContacts<S>() contacts, a number fixed
/// by the precision alone (the same run gets the same estimate), its horizon then extrapolated
/// from them (at most twice the time they cover; unreliable when that falls within the run);
/// Off gives Unchecked.
template <typename S>
constexpr long chainShadowContacts() {
  // about the run's own cost or less: a long double shadow costs about what a double run does,
  // a binary128 one about twenty times a long double run, a binary128 one what the run does
  if constexpr (std::is_same_v<S, double>) return 1L << 16;
  else if constexpr (std::is_same_v<S, long double>) return 1L << 11;
  else return 1L << 14;
}

/// The shadow run's chain, made ready once: the chain in the shadow precision (scaled in binary128),
/// with the factors that map its motion back, and the primary chain's scales in double (the
/// units of the errors).
template <typename S>
struct ChainShadow {
  using H = ShadowScalar<S>;
  BasicReadyChain<H> ready;
  H length = 1, time = 1;  ///< shadow = primary x length, shadow times = primary times / time
  bool scaled = false;
  double slowest = 1;  ///< the primary chain's slowest period, in double
  double fastest = 1;  ///< the primary chain's fastest angular frequency, in double
  double gap = 1;      ///< the primary chain's gap, in double
};
/// The shadow of a usable chain.
template <typename S>
ChainShadow<S> chainShadow(const BasicMassChain<S>& chain);

template <typename S>
Trust chainTrust(const ChainShadow<S>& shadow, const std::type_identity_t<BasicChainStart<S>>& start, const BasicChainRun<S>& run,
                 long maxContacts, std::type_identity_t<S> tEnd, TrustMode mode, std::stop_token stop = {});
/// The same, the shadow made here.
template <typename S>
Trust chainTrust(const BasicMassChain<S>& chain, const std::type_identity_t<BasicChainStart<S>>& start, const BasicChainRun<S>& run,
                 long maxContacts, std::type_identity_t<S> tEnd, TrustMode mode, std::stop_token stop = {});

/// chainTrust for a run whose events stream (a ChainEventSink): the shadow is run first and
/// held (Auto: its first chainShadowContacts<S>() contacts at most; Full: all of them), each of
/// the run's events is compared as it comes, and the estimate is made when the run has ended.
/// The scales are the largest sizes met at the shadow's events (the gap, and the largest speed
/// the energy allows, at least).
template <typename S>
class ChainTrustCheck {
 public:
  using H = ShadowScalar<S>;
  ChainTrustCheck(const ChainShadow<S>& shadow, const BasicChainStart<S>& start, long maxContacts,
                  std::type_identity_t<S> tEnd, TrustMode mode, std::stop_token stop = {});
  /// The same, the shadow made here (Off makes none).
  ChainTrustCheck(const BasicMassChain<S>& chain, const BasicChainStart<S>& start, long maxContacts,
                  std::type_identity_t<S> tEnd, TrustMode mode, std::stop_token stop = {});
  /// The run's next event.
  void observe(const BasicChainEvent<S>& event);
  /// The estimate of the run that has ended (its events all observed; its own list unused).
  Trust finish(const BasicChainRun<S>& run) const;

 private:
  /// the largest difference of a state (u, v) of the run and one of the shadow, over the scales
  double difference(const ChainVector<S>& u, const ChainVector<S>& v, const ChainVector<H>& shadowU,
                    const ChainVector<H>& shadowV) const;
  TrustMode m_mode;
  bool m_interrupted = false;
  bool m_scaled = false;
  H m_length = 1, m_time = 1;  // shadow = primary x length, shadow times = primary times / time
  BasicChainRun<H> m_shadow;
  long m_cap = 0;  // the shadow's contact budget (Auto), 0 when it ran as far as the run may
  double m_uScale = 0, m_vScale = 1, m_slowest = 1;
  double m_rate = 0;  // the fastest a state error can grow from a time error, per unit time
  // the comparison so far
  std::size_t m_observed = 0;
  double m_firstError = 0, m_firstTime = 0, m_lastError = 0, m_lastTime = 0;
  bool m_passed = false;
  double m_passedAt = 0;
  double m_firstPastShadow = -1;  // the time of the run's first event past the shadow's last (-1: none)
  Trust m_trust;
};

}  // namespace grazelab::core
