// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/model/two_mass_form.h"
#include "core/solver/events.h"
#include "core/solver/exact_stepper.h"

namespace grazelab::core {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Dense output: states every `spacing` time units from t = 0 up to tEnd, or at the given
/// `times`, computed only when asked for. Contact states are added too (unless told not to), so that
/// traces keep their corners.
struct SampleSpec {
  double spacing = 0;      ///< time between samples; 0 = no grid
  double tEnd = kInfinity; ///< last sample time (the run's end if earlier)
  /// Sample times, ascending, instead of the grid (the exact solver's runs; a time-stepping
  /// method has no motion between its steps to sample, and samples on the grid only).
  std::vector<double> times;
  std::size_t maxCount = 4'000'000;  ///< memory guard; samples past it are dropped (flagged)
  bool includeContacts = true;       ///< add the states just before and after each contact

  bool wanted() const { return spacing > 0 || !times.empty(); }
  /// The time of sample `index` (infinity past the last of `times`).
  double timeOf(std::int64_t index) const {
    if (times.empty()) return double(index) * spacing;
    return std::size_t(index) < times.size() ? times[std::size_t(index)] : kInfinity;
  }
};

/// What the caller will look at; nothing else is stored (docs/design.md "Needs").
struct Needs {
  bool events = true;              ///< the event list
  double eventsUntil = kInfinity;  ///< keep only events up to this time (a plot's window)
  bool poincare = false;           ///< (t, u1, v1, v2) at each contact
  bool freeFlights = false;        ///< free-flight time of each flight that starts on the stop
  SampleSpec samples;              ///< dense samples
};

/// A point on the contact plane H, recorded at each contact (display data: double).
struct PoincarePoint {
  double t = 0;
  double u1 = 0;
  double v1 = 0;
  double v2 = 0;  ///< post-contact velocity of mass 2 (<= 0)
  EventType type = EventType::Impact;
};

/// A free flight between a departure from the stop and the next contact (docs/model.md section 4).
struct FreeFlight {
  std::int64_t contactIndex = 0;  ///< index (0-based) of the contact that ends it
  double duration = 0;            ///< FFT [time]
  /// T2 - FFT, computed from the exact offset to the return when the contact is near T2, so
  /// that a flight shorter than T2 by less than an ulp of T2 still shows a positive value.
  double shortfall = 0;
};

/// A dense-output sample (display data: double).
struct Sample {
  double t = 0;
  State state;
};

/// What the run cost and how good it is (docs/design.md "Numerical contract").
struct Cost {
  std::int64_t contacts = 0;  ///< impacts + grazings + sticks
  std::int64_t impacts = 0;
  std::int64_t grazings = 0;
  std::int64_t sticks = 0;
  double wallSeconds = 0;          ///< time spent in the solver
  double maxRelEnergyDrift = 0;    ///< max |E - E0| / E0 over contact states
  double maxContactResidual = 0;   ///< max |u2 - gap| at the found contact times [length]
};


/// Everything a run produced, as plain values in physical units.
template <typename S>
struct BasicResult {
  std::vector<BasicEvent<S>> events;
  std::vector<PoincarePoint> poincare;
  std::vector<FreeFlight> freeFlights;
  std::vector<Sample> samples;
  bool samplesTruncated = false;
  S tFinal = 0;
  BasicState<S> final;
  S initialEnergy = 0;  ///< physical energy (infinite if beyond the range of S)
  Cost cost;
  StopReason stop = StopReason::ContactLimit;
  std::string message;  ///< the reason for InvalidInput, or a note (e.g. "never touches")
};

using Result = BasicResult<double>;

/// The same result in double (for display and for callers that hold doubles): events and
/// states rounded once, everything else as it is.
template <typename S>
Result toDoubleResult(const BasicResult<S>& from);

/// A time-stepping method's run of the note's chain kept as the exact run's (BasicResult): what
/// Needs asks for, in physical units, and the cost. Such a method has no motion between its steps
/// to sample: its steps are its samples.
class Recorder {
 public:
  /// `initial` is the scaled start state (its energy is the reference for the drift).
  Recorder(const TwoMassForm<double>& chain, const Scale<double>& scale, const State& initial, const Needs& needs,
           Result& result);

  /// Records the event of a step (Kind::Event).
  void record(const Step<double>& step);
  /// The method's state at scaled time tau, kept when a sample is due.
  void samplePoint(double tau, const State& scaled);
  /// Stores the final state (scaled, converted here) at physical time t.
  void finish(StopReason reason, double t, const State& scaled);

 private:
  void addSample(double t, const State& state);

  const TwoMassForm<double>& m_chain;
  Scale<double> m_scale;
  Needs m_needs;
  Result& m_result;
  double m_initialScaledEnergy = 0;
  double m_nextSampleTime = 0;
  std::int64_t m_nextSampleIndex = 0;
};

}  // namespace grazelab::core
