// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>
#include <span>
#include <stop_token>

#include "core/model/two_mass_form.h"
#include "core/solver/contact.h"
#include "core/solver/events.h"
#include "core/solver/free_flight.h"
#include "core/solver/sticking.h"

namespace grazelab::core {

/// Where a run stands, in scaled units: a small copyable value, so that a run can restart from
/// any event or be handed to another method.
template <typename S>
struct IntegrationState {
  S tau = 0;              ///< scaled time since the start of the run (w2 t)
  BasicState<S> x;        ///< scaled state
  bool stuck = false;     ///< a Stick event was recorded; the stuck motion runs next
  /// exact u1 minus x.u1 (scaled) after a contact: at a return a hair below the stop, u1 - gap
  /// is far below an ulp of u1, and it decides how the next flight leaves (or whether it sticks)
  S u1Residual = 0;
  // tau kept without drift: whole slow periods counted apart from the sum of the offsets, which
  // is compensated (Kahan), so that tau = 2 pi periods + offset rounds once however long the run
  // (a plain sum of 10^6 flights of 2 pi was off by 1.5e-6 T2)
  long long periods = 0;
  S offset = 0;
  S offsetCompensation = 0;

  /// Moves tau on by `elapsed` (whole periods and an offset).
  void advanceTime(long long elapsedPeriods, const S& elapsedOffset) {
    periods += elapsedPeriods;
    const S term = elapsedOffset - offsetCompensation;
    const S sum = offset + term;
    offsetCompensation = (sum - offset) - term;
    offset = sum;
    tau = periods == 0 ? offset : S(twoPi<S>() * S(periods) + offset);
  }
};

/// What one step of the exact method did.
template <typename S>
struct Step {
  enum class Kind {
    Event,             ///< an event (contact or release) happened: see the fields below
    End,               ///< the end time came first; the state is at it
    NoFurtherContact,  ///< the free motion never reaches the stop (resonant, or its amplitudes short of it)
    SearchLimit,       ///< detuned: no contact within the search horizon
    SearchBudget,      ///< detuned: the search ran out of steps before the horizon
    Undecided,         ///< a contact its precision cannot decide: the state is left where the
                       ///< flight began, `tau` is the contact's
    Cancelled,         ///< the stop token ended a long search
  };
  Kind kind = Kind::Event;
  S segmentStart = 0;  ///< tau at which the motion of this step began
  EventType type = EventType::Impact;
  S tau = 0;                ///< when the event happened (or where the run ended)
  BasicState<S> before;     ///< scaled state just before (or at the end)
  BasicState<S> after;      ///< scaled state just after
  S residual = 0;           ///< |x2 - delta| at the found contact time (scaled)
  // for events that end a free flight
  bool endsFlight = false;
  bool flightFromStop = false;         ///< the flight started on the stop (its FFT is defined)
  FlightTime<S> flightDuration;        ///< its duration, anchored near 2 pi when it ends there
  S flightEnergyError = 0;             ///< relative energy error before restoring (see .cpp)
};

/// The exact event-driven method (docs/model.md sections 3-4): closed-form free flight, contact
/// times from polynomial roots, the impact law, stuck phases in closed form. Each advance() moves
/// the state to the next event; the motion of that step stays available for dense samples.
template <typename S>
class ExactStepper {
 public:
  /// The chain is held by reference and must outlive the stepper.
  ExactStepper(const TwoMassForm<S>& chain, const S& scaledGap);

  /// Advances `state` to the next event, or to `tauEnd` if it comes first. `searchHorizon`
  /// bounds a detuned flight's search (scaled time), `searchSteps` the steps of its march.
  /// A contact whose class (touch or crossing) the precision cannot decide is not taken: the
  /// step is Kind::Undecided and the state stays as it was.
  Step<S> advance(IntegrationState<S>& state, const S& tauEnd, const S& searchHorizon,
                  const std::stop_token& stop = {}, std::int64_t searchSteps = defaultSearchSteps<S>());

  /// The state at absolute scaled time `tau` inside the motion of the last step.
  BasicState<S> segmentAt(const S& tau) const;
  /// The states at absolute scaled times first + k step inside the motion of the last step:
  /// dense display samples (a flight's by Flight::statesOnGrid, within 1e-14 of segmentAt).
  void segmentOnGrid(const S& first, const S& step, std::span<BasicState<S>> out) const;

 private:
  const TwoMassForm<S>& m_chain;
  S m_gap;
  std::optional<Flight<S>> m_flight;
  std::optional<StuckMotion<S>> m_stuck;
  S m_segmentStart = 0;
  BasicState<S> m_segmentState{};  ///< where the step began: the motion of a zero-length step
};

/// Moves a state on the stop back onto the energy level `target` (scaled), along the energy
/// gradient with x2 held: a correction of rounding size. Returns the relative energy error it
/// removed.
template <typename S>
S restoreEnergy(const TwoMassForm<S>& chain, BasicState<S>& state, const S& target);

}  // namespace grazelab::core
