// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <functional>
#include <stop_token>

#include "core/model/model.h"
#include "core/model/two_mass_form.h"
#include "core/solver/chain_run.h"
#include "core/solver/recorder.h"

namespace grazelab::core {

/// A run of the note's chain: where it starts, when it stops, what it keeps. Defaults are sane
/// for a quick look.
template <typename S>
struct BasicRequest {
  BasicState<S> initial;              ///< start state; u2 <= gap
  std::int64_t maxContacts = 1000;    ///< stop after this many contacts (impact, grazing, stick)
  S tEnd = S(kInfinity);              ///< stop at this time; a finite one also bounds the search
  /// Detuned chains: the most march steps one flight's contact search may take. Running out
  /// ends the run with StopReason::SearchBudget (never "no contact": the search did not decide).
  /// Without an end time a flight is searched kFlightSearchPeriods slow periods at most.
  std::int64_t flightSearchSteps = defaultSearchSteps<S>();
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
  if (from.flightSearchSteps != defaultSearchSteps<From>()) {
    to.flightSearchSteps = from.flightSearchSteps;
  }
  to.needs = from.needs;
  return to;
}

/// Runs a request to its end: the one run of the chain (TwoMassRun), kept as the two-mass
/// views draw it. The stop token is checked between contacts (and inside long detuned flights).
template <typename S>
BasicResult<S> simulate(const BasicModel<S>& model, const BasicRequest<S>& request,
                        std::stop_token stop = {});

/// A two-mass run's event as the one run writes it (chain_run.h), for what reads the one run's
/// events (the error estimate).
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
  run.stop = result.stop;
  return run;
}

}  // namespace grazelab::core
