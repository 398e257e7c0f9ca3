// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <stop_token>

#include "core/model/two_mass_form.h"
#include "core/solver/exact_stepper.h"
#include "core/model/model.h"
#include "core/solver/recorder.h"
#include "core/solver/trust.h"

namespace grazelab::core {

/// A run: where it starts, when it stops, what it keeps. Defaults are sane for a quick look.
template <typename S>
struct BasicRequest {
  BasicState<S> initial;              ///< start state; u2 <= gap
  std::int64_t maxContacts = 1000;    ///< stop after this many contacts (impact, grazing, stick)
  S tEnd = S(kInfinity);              ///< stop at this time; a finite one also bounds the search
  /// Detuned chains without an end time: the longest free flight searched for a contact, in
  /// units of T2. A resonant flight needs no limit (one period decides).
  double flightSearchPeriods = 1000;
  /// Detuned chains: the most march steps one flight's contact search may take. Running out
  /// ends the run with StopReason::SearchBudget (never "no contact": the search did not decide).
  std::int64_t flightSearchSteps = defaultSearchSteps<S>();
  /// Stop, with StopReason::Undecided and the state before that flight, at the first contact
  /// whose class (touch or crossing) the precision cannot decide: --precision auto then runs
  /// again in a higher one. Off: such a contact is taken as a touch and counted
  /// (Cost::undecidedTouches), and the error estimate says so. (The note's simulator only: the
  /// one run, TwoMassRun's, always stops there.)
  bool stopAtUndecided = false;
  Needs needs;
  /// Called with every event as it happens, whatever `needs` keeps (streaming output).
  std::function<void(const BasicEvent<S>&)> onEvent;
};

using Request = BasicRequest<double>;

/// What is wrong with a request (bounds, the samples asked for); empty when it is usable.
template <typename S>
std::vector<Problem> validate(const BasicRequest<S>& request);

/// The same request in another precision (the start widened exactly); no onEvent. A search
/// budget left at its default becomes the default of the new precision (about a second's worth).
template <typename To, typename From>
BasicRequest<To> convertRequest(const BasicRequest<From>& from) {
  BasicRequest<To> to;
  to.initial = convertState<To>(from.initial);
  to.maxContacts = from.maxContacts;
  to.tEnd = To(from.tEnd);
  to.flightSearchPeriods = from.flightSearchPeriods;
  if (from.flightSearchSteps != defaultSearchSteps<From>()) {
    to.flightSearchSteps = from.flightSearchSteps;
  }
  to.stopAtUndecided = from.stopAtUndecided;
  to.needs = from.needs;
  return to;
}

/// A run in pieces, for callers that stream partial results: each advance() does at most a
/// given number of contacts; the result grows in place. The exact stepper moves a small
/// IntegrationState; the recorder keeps what the request needs (docs/design.md "Inside core").
/// Holds references to its own members: neither copied nor moved.
template <typename S>
class BasicSimulator {
 public:
  /// Validates the model and the request; an invalid one is done at once (StopReason::InvalidInput).
  BasicSimulator(const BasicModel<S>& model, const BasicRequest<S>& request);
  BasicSimulator(const BasicSimulator&) = delete;
  BasicSimulator& operator=(const BasicSimulator&) = delete;

  /// Runs until `contactBudget` more contacts were made, the run is complete, or `stop` is
  /// requested. Returns true when the run is complete (or cancelled, or invalid).
  bool advance(std::int64_t contactBudget, std::stop_token stop = {});

  bool done() const { return m_done; }
  /// Fraction of the requested contacts or time done, in [0, 1].
  double progress() const;
  const BasicResult<S>& result() const { return m_result; }
  /// Hands over the result (the simulator is done with it).
  BasicResult<S> takeResult() { return std::move(m_result); }
  /// The nondimensional chain (empty for invalid input).
  const std::optional<TwoMassForm<S>>& chain() const { return m_chain; }
  /// Where the run stands (scaled units), and its scales.
  const IntegrationState<S>& state() const { return m_state; }
  const Scale<S>& scale() const { return m_scale; }

 private:
  void finish(StopReason reason, const S& t, const BasicState<S>& scaled);

  BasicRequest<S> m_request;
  BasicResult<S> m_result;
  std::optional<TwoMassForm<S>> m_chain;
  Scale<S> m_scale;
  std::optional<ExactStepper<S>> m_stepper;
  std::optional<Recorder<S>> m_recorder;
  IntegrationState<S> m_state;
  S m_tauEnd = S(kInfinity);
  S m_searchHorizon = S(kInfinity);
  bool m_done = false;
};

using Simulator = BasicSimulator<double>;

/// Runs a request to its end. The stop token is checked between contacts (and inside long
/// detuned flights).
template <typename S>
BasicResult<S> simulate(const BasicModel<S>& model, const BasicRequest<S>& request,
                        std::stop_token stop = {});

/// A two-mass run's event as the one run writes it (chain_run.h), for what reads the one run's
/// events (the error estimate) while this run still has its own callers.
template <typename S>
BasicChainEvent<S> chainEventOf(const BasicEvent<S>& event) {
  return {event.t, event.type, chainStateOf(event.after).u, chainStateOf(event.before).v, event.after.v2};
}

/// A two-mass run's totals (stop, end, final state, counts) as the one run's; no events.
template <typename S>
BasicChainRun<S> chainTotalsOf(const BasicResult<S>& result) {
  BasicChainRun<S> run;
  run.contacts = long(result.cost.contacts);
  run.impacts = long(result.cost.impacts);
  run.grazings = long(result.cost.grazings);
  run.sticks = long(result.cost.sticks);
  run.final = chainStateOf(result.final);
  run.tFinal = result.tFinal;
  // the one run's name for a search that decided nothing within its bounds
  run.stop = result.stop == StopReason::SearchLimit ? StopReason::SearchBudget : result.stop;
  return run;
}

/// Contacts that touched the stop within rounding (Cost::undecidedTouches) in the precision of
/// the result: whether they graze or impact is not known, so the verdict is at best degraded,
/// the reason names the first, and the error estimate is at least the size a crossing hidden
/// in rounding could have (an impact speed of about sqrt(32 eps) of the velocity scale, and
/// the same share of T2 in time). Applied after TrustMonitor::finish by the callers whose runs
/// go on through such contacts (the one run stops at them instead).
template <typename S>
void accountForUndecidedTouches(Trust& trust, const BasicResult<S>& result);

}  // namespace grazelab::core
