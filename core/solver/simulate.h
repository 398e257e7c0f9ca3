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
  /// (Cost::undecidedTouches), and the error estimate says so.
  bool stopAtUndecided = false;
  Needs needs;
  /// Called with every event as it happens, whatever `needs` keeps (streaming output).
  std::function<void(const BasicEvent<S>&)> onEvent;
};

using Request = BasicRequest<double>;

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

}  // namespace grazelab::core
