// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <limits>
#include <stop_token>
#include <string>
#include <vector>

#include "core/events.h"
#include "core/model.h"
#include "core/modes.h"
#include "core/state.h"

namespace grazelab::core {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Dense output: states every `spacing` time units on [tBegin, tEnd], computed only when asked
/// for (spacing > 0). Contact states are added too, so that traces keep their corners.
struct SampleSpec {
  double spacing = 0;      ///< time between samples; 0 = no samples
  double tBegin = 0;       ///< first sample time
  double tEnd = kInfinity; ///< last sample time (the run's end if earlier)
  std::size_t maxCount = 4'000'000;  ///< memory guard; samples past it are dropped (flagged)
  bool includeContacts = true;       ///< add the states just before and after each contact
};

/// What the caller will look at; nothing else is stored (DESIGN.md "Needs").
struct Needs {
  bool events = true;         ///< the event list
  double eventsUntil = kInfinity;  ///< keep only events up to this time (a plot's window)
  bool poincare = false;      ///< (t, u1, v1, v2) at each contact
  bool freeFlights = false;   ///< free-flight time of each flight that starts on the stop
  SampleSpec samples;         ///< dense samples
};

/// A run: where it starts, when it stops, what it keeps. Defaults are sane for a quick look.
struct Request {
  State initial;                      ///< start state; u2 <= gap
  std::int64_t maxContacts = 1000;    ///< stop after this many contacts (impact, grazing, stick)
  double tEnd = kInfinity;            ///< stop at this time
  /// Detuned chains only: the longest free flight searched for a contact, in units of T2.
  /// A resonant flight needs no limit (one period decides).
  double flightSearchPeriods = 1000;
  Needs needs;
};

/// A point on the contact plane H, recorded at each contact.
struct PoincarePoint {
  double t = 0;
  double u1 = 0;
  double v1 = 0;
  double v2 = 0;  ///< post-contact velocity of mass 2 (<= 0)
  EventType type = EventType::Impact;
};

/// A free flight between a departure from the stop and the next contact (MODEL.md section 4).
struct FreeFlight {
  std::int64_t contactIndex = 0;  ///< index (0-based) of the contact that ends it
  double duration = 0;            ///< FFT [time]
  /// T2 - FFT, computed from the exact offset to the return when the contact is near T2, so
  /// that a flight shorter than T2 by less than an ulp of T2 still shows a positive value.
  double shortfall = 0;
};

/// A dense-output sample.
struct Sample {
  double t = 0;
  State state;
};

/// Why a run stopped.
enum class StopReason {
  ContactLimit,      ///< maxContacts reached
  TimeLimit,         ///< tEnd reached
  NoFurtherContact,  ///< a resonant free flight that never reaches the stop (linear forever)
  SearchLimit,       ///< detuned: no contact within flightSearchPeriods * T2
  Cancelled,         ///< the stop token was triggered
  InvalidInput,      ///< the model or the initial state is unusable (see message)
};
std::string_view toString(StopReason reason);

/// What the run cost and how good it is (DESIGN.md "Numerical contract").
struct Cost {
  std::int64_t contacts = 0;  ///< impacts + grazings + sticks
  std::int64_t impacts = 0;
  std::int64_t grazings = 0;
  std::int64_t sticks = 0;
  double wallSeconds = 0;          ///< time spent in the solver
  double maxRelEnergyDrift = 0;    ///< max |E - E0| / E0 over contact states
  /// max relative energy error of one computed free flight, before its end state is restored
  /// to the energy level of its start (see simulate.cpp): the raw accuracy of the flight
  double maxFlightEnergyError = 0;
  double maxContactResidual = 0;   ///< max |u2 - gap| at the found contact times, before snapping
};

/// Everything a run produced, as plain values.
struct Result {
  Modes modes;
  std::vector<Event> events;
  std::vector<PoincarePoint> poincare;
  std::vector<FreeFlight> freeFlights;
  std::vector<Sample> samples;
  bool samplesTruncated = false;
  double tFinal = 0;
  State final;
  double initialEnergy = 0;
  Cost cost;
  StopReason stop = StopReason::ContactLimit;
  std::string message;  ///< the reason for InvalidInput, or a note (e.g. "never touches")
};

/// Runs a request to its end. The stop token is checked between contacts.
Result simulate(const Model& model, const Request& request, std::stop_token stop = {});

/// The same run in pieces, for callers that stream partial results (the explorer's worker).
/// Each advance() does at most a given number of contacts; the result grows in place.
class Simulator {
 public:
  /// Validates the model and the request; an invalid one is done at once (StopReason::InvalidInput).
  Simulator(const Model& model, const Request& request);

  /// Runs until `contactBudget` more contacts were made, the run is complete, or `stop` is
  /// requested. Returns true when the run is complete (or cancelled, or invalid).
  bool advance(std::int64_t contactBudget, std::stop_token stop = {});

  bool done() const { return m_done; }
  /// Fraction of the requested contacts or time done, in [0, 1].
  double progress() const;
  const Result& result() const { return m_result; }
  /// Hands over the result (the simulator is done with it).
  Result takeResult() { return std::move(m_result); }

 private:
  void finish(StopReason reason, double t, const State& state);
  void recordContact(const Event& event, double residual);
  void addSample(double t, const State& state);
  template <typename Motion>
  void addSamplesUntil(double tEndOfPhase, const Motion& motionFromPhaseStart);
  void stepStuck();
  void stepFlight();

  Model m_model;
  Request m_request;
  Result m_result;
  State m_state;
  double m_t = 0;
  double m_nextSampleTime = 0;
  std::int64_t m_nextSampleIndex = 0;
  bool m_stuck = false;  // the Stick event is recorded, the stuck motion not yet run
  bool m_done = false;
};

}  // namespace grazelab::core
