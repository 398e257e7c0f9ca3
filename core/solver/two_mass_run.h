// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <optional>
#include <stop_token>
#include <vector>

#include "core/model/model.h"
#include "core/model/two_mass_form.h"
#include "core/solver/chain_run.h"
#include "core/solver/simulate.h"

namespace grazelab::core {

/// One event of the one run of a two-mass chain with the states before and after it.
template <typename S>
BasicEvent<S> twoMassEventOf(const BasicChainEvent<S>& event) {
  return {event.t, event.type, {event.u[0], event.u[1], event.vBefore[0], event.vBefore[1]},
          {event.u[0], event.u[1], event.vBefore[0], event.vAfter}};
}

/// A run of the note's chain kept as its two-mass views draw it (BasicResult: the events with
/// the states before and after, the Poincaré points on H, the free flights from the stop, the
/// dense samples with their contacts' corners, the cost), made by the one run of the chain
/// (BasicChainSimulator: the note's kernel, or the modal one for a start that names modes
/// exactly still), in pieces: the same events to the bit as every other run of the chain. A
/// contact S cannot decide ends the run there, undecided, as every run of the chain does. The
/// dense grid starts at t = 0.
/// Holds references to its own members: neither copied nor moved.
template <typename S>
class TwoMassRun {
 public:
  /// Validates the model and the request; an invalid one is done at once (StopReason::InvalidInput).
  /// `stillModes`: the start's modes known to be exactly still (BasicChainStart). `ready`: the
  /// model made ready already (readyChain(model)), which the run then holds by reference (a
  /// timed run does not pay for the chain's modes); it must outlive the run. Without it, the run
  /// makes the chain ready from its form (readyChain(form): no eigensolve) unless a mode is
  /// named still (the modal kernel's, from readyChain(model)).
  TwoMassRun(const BasicModel<S>& model, const BasicRequest<S>& request, std::vector<bool> stillModes = {},
             const BasicReadyChain<S>* ready = nullptr);
  TwoMassRun(const TwoMassRun&) = delete;
  TwoMassRun& operator=(const TwoMassRun&) = delete;

  /// Runs until `contactBudget` more contacts were made, the run is complete, or `stop` is
  /// requested. Returns true when the run is complete (or cancelled, or invalid).
  bool advance(std::int64_t contactBudget, std::stop_token stop = {});
  bool done() const { return m_done; }
  /// Fraction of the requested contacts or time done, in [0, 1].
  double progress() const;
  const BasicResult<S>& result() const { return m_result; }
  /// Where the run stands [time] (the last event's time until it is over).
  const S& time() const { return m_run ? m_run->time() : m_result.tFinal; }
  /// Hands over the result (the run is done with it).
  BasicResult<S> takeResult() { return std::move(m_result); }

 private:
  void take(const BasicChainEvent<S>& event);
  void addSample(double t, const BasicState<S>& state);
  void finish();

  BasicRequest<S> m_request;
  BasicResult<S> m_result;
  std::optional<TwoMassForm<S>> m_form;
  std::optional<BasicChainSimulator<S>> m_run;
  std::int64_t m_contacts = 0;
  bool m_fromStop = false;  ///< the flight under way started on the stop
  bool m_done = false;
};

}  // namespace grazelab::core
