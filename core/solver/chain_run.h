// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stop_token>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/model/two_mass_form.h"
#include "core/model/mass_chain.h"
#include "core/solver/chain_flight.h"
#include "core/solver/events.h"
#include "core/solver/exact_stepper.h"

namespace grazelab::core {

/// How far a run searches one flight for its contact when it has no end time, in slowest periods
/// (a flight of a chain not commensurate may never meet the stop again).
inline constexpr double kFlightSearchPeriods = 1000;

/// One contact of a chain of N masses with the stop.
template <typename S>
struct BasicChainEvent {
  S t = 0;                             ///< since the run's start [time]
  EventType type = EventType::Impact;  ///< Impact, Grazing, Stick, or Release (not a contact)
  ChainVector<S> u;                    ///< the displacements at the event (u_s = d)
  ChainVector<S> vBefore;              ///< the velocities before it
  S vAfter = 0;                        ///< the stopped mass's velocity after it
  /// the free flight this event ends: its length [time] from the event before (or the start), as
  /// the kernel computed it (not the difference of two rounded times), and how much shorter than
  /// the chain's period it is (the common period T, or the slowest mode's when not commensurate;
  /// exact where the note's kernel anchors the contact at the return after T, so that a flight
  /// short of T by less than an ulp of T still shows it). 0 for an event that ends no flight: a
  /// release, an impact at the instant of the event before, and the modal kernel's sticks (a
  /// stick there follows the contact or start it holds, at its instant; the note's kernel's
  /// stick at the end of a flight carries that flight).
  S flight = {};
  S shortfall = {};
};
using ChainEvent = BasicChainEvent<double>;

template <typename S>
struct BasicChainRun {
  std::vector<BasicChainEvent<S>> events;  ///< contacts and releases, in time order (none kept
                                           ///< when they went to a ChainEventSink)
  long contacts = 0;                       ///< the events that are contacts (all but releases)
  long impacts = 0, grazings = 0, sticks = 0, releases = 0;  ///< the events by type
  BasicChainState<S> final;                ///< the state at `tFinal`
  S tFinal = 0;
  StopReason stop = StopReason::ContactLimit;  ///< never InvalidInput
  S energyInitial = 0;
  S energyFinal = 0;
  /// the run's accuracy as it went: the largest |E / E0 - 1| over the states after its events
  /// (NaN once one was not finite), and the largest |u_s - d| at its contacts [length]
  double maxEnergyDrift = 0;
  double maxContactResidual = 0;
};
using ChainRun = BasicChainRun<double>;

/// Where a run's events go as they happen, instead of BasicChainRun::events: a run that streams
/// them holds none (its memory stays bounded however many contacts it makes).
template <typename S>
using ChainEventSink = std::function<void(const BasicChainEvent<S>&)>;

/// Dense samples of a run: the state every `spacing` from t = 0, or at the given `times`
/// (ascending), handed to `sink` as the run passes them, up to its end or `until`, whichever
/// comes first (a flight that never meets the stop again: to `until`, or one of its slowest
/// periods more when there is none); a sample at an event's time is the state just after it.
/// Computed from the same closed forms as the events (the note's kernel's grid a batch at a
/// time, by rotation), nothing stored.
template <typename S>
struct ChainSampling {
  double spacing = 0;
  std::vector<double> times;
  std::function<void(double t, const BasicChainState<S>& state)> sink;
  double until = std::numeric_limits<double>::infinity();  ///< no sample after this time

  bool wanted() const { return sink && (spacing > 0 || !times.empty()); }
};

/// A usable chain (validate(chain) empty) made ready to run: its numbers and its dynamics (the
/// modes, exact multiples n_j w0 when commensurate: a binary128 eigensolve), computed once and
/// shared by every run, shadow run and document of it. Immutable.
///
/// Its runs take one of two kernels, the same everywhere else (events, stops, samples, pieces):
/// the modal one (closed-form flights in the chain's modes, firstContact's certified search), or,
/// for the note's chain, the note's (`notes`): two masses, the stop on the second, no right wall,
/// in 1:2 resonance or not commensurate at all, run in the scaled two-mass form by its exact
/// stepper (closed-form flight, the resonant quartic search, the detuned certified march), which
/// gives the note's results bit for bit however the chain is written. A start naming modes that
/// are exactly still (BasicChainStart) is run by the modal kernel, which keeps them still.
template <typename S>
struct BasicReadyChain {
  BasicMassChain<S> numbers;
  BasicChainDynamics<S> dynamics;
  std::optional<TwoMassForm<S>> notes;  ///< the note's kernel's form of it; empty: the modal kernel
  /// the note's model of it, with `notes` (its design branch when it is a 1:2 design's): what
  /// the documents say of the note's chain (T2, lambda*, ...)
  std::optional<BasicModel<S>> notesModel = {};
};
using ReadyChain = BasicReadyChain<double>;

/// Whether a run of `chain` from `start` takes the note's kernel: the chain has its form, and the
/// start names no mode as exactly still (such a start is the modal kernel's, which keeps them so;
/// the note's kernel has only the rounded state, which holds 1e-17 of them again).
template <typename S>
bool takesTheNotesKernel(const BasicReadyChain<S>& chain, const BasicChainStart<S>& start) {
  return chain.notes && std::find(start.stillModes.begin(), start.stillModes.end(), true) == start.stillModes.end();
}

/// Which kernel a chain's runs take: the note's wherever it applies, or the modal one always (to
/// compare the two on the note's chain).
enum class Kernel { Best, Modal };

/// A chain made ready; with Kernel::Best a two-mass chain whose k2 is a 1:2 design's to rounding
/// (1024 ulps) runs as the note's chain of that branch, and one not commensurate as the note's
/// chain of those springs; any other (near 1:2 but off the design, another ratio, a chain the
/// note's form cannot be made for in S) on the modal kernel.
template <typename S>
BasicReadyChain<S> readyChain(const BasicMassChain<S>& chain, Kernel kernel = Kernel::Best);
/// The note's chain given by its model (a usable one: validate(model) empty), ready to run by
/// the note's kernel; the modal one when the model's ratios are beyond the range of S.
template <typename S>
BasicReadyChain<S> readyChain(const BasicModel<S>& model);
/// The note's chain given by its form, ready for runs by the note's kernel (a start that names no
/// still mode): its modes from the form's closed forms (w1 = ratio w2, shapes (rho, 1)),
/// commensurate when resonant, with no eigensolve (a periodic orbit's check run makes one per
/// Newton step). The same events, to the bit, as readyChain(form.model) from a start that names
/// no mode still; the same modes to rounding (a detuned form is never commensurate here, where
/// readyChain(form.model) takes ratios within 1e-9 of commensurate as such: the modal kernel's
/// runs, from a start naming a mode still, want readyChain(form.model)).
template <typename S>
BasicReadyChain<S> readyChain(const TwoMassForm<S>& form);

/// The energy 1/2 v^T M v + 1/2 u^T K u of a chain's state.
template <typename S>
S chainEnergy(const BasicMassChain<S>& chain, const BasicChainState<S>& state);

/// A run of a chain of N masses in pieces, for callers that show it as it grows (the explorer's
/// worker): each advance() makes at most a given number of more contacts and the run grows in
/// place; runChain is one advance to the end. The pieces change nothing: a run advanced in any
/// pieces is the run made at once, bit for bit (the loop stops and resumes between flights).
template <typename S>
class BasicChainSimulator {
 public:
  /// As runChain's arguments (below); `sink` and `sampling` are kept, and so is the chain: one
  /// given by name is held by reference and must outlive the simulator (runs of one chain share
  /// it; a map runs thousands), a temporary is kept here.
  /// `searchSteps`: the note's kernel's budget for one detuned flight's certified march, in steps
  /// (0: about a second's worth, defaultSearchSteps); running out ends the run SearchBudget. (The
  /// modal kernel's searches are bounded by 1000 slowest periods, or tEnd.)
  BasicChainSimulator(const BasicReadyChain<S>& chain, const BasicChainStart<S>& start, long maxContacts,
                      std::type_identity_t<S> tEnd = 0, ChainEventSink<std::type_identity_t<S>> sink = {},
                      ChainSampling<std::type_identity_t<S>> sampling = {}, std::int64_t searchSteps = 0)
      : BasicChainSimulator(std::nullopt, &chain, start, maxContacts, tEnd, std::move(sink), std::move(sampling),
                            searchSteps) {}
  BasicChainSimulator(BasicReadyChain<S>&& chain, const BasicChainStart<S>& start, long maxContacts,
                      std::type_identity_t<S> tEnd = 0, ChainEventSink<std::type_identity_t<S>> sink = {},
                      ChainSampling<std::type_identity_t<S>> sampling = {}, std::int64_t searchSteps = 0)
      : BasicChainSimulator(std::move(chain), nullptr, start, maxContacts, tEnd, std::move(sink), std::move(sampling),
                            searchSteps) {}
  /// (a constant temporary would bind to the reference above and be gone before the run)
  BasicChainSimulator(const BasicReadyChain<S>&& chain, const BasicChainStart<S>& start, long maxContacts,
                      std::type_identity_t<S> tEnd = 0, ChainEventSink<std::type_identity_t<S>> sink = {},
                      ChainSampling<std::type_identity_t<S>> sampling = {}, std::int64_t searchSteps = 0) = delete;
  /// The same, the chain made ready here.
  BasicChainSimulator(const BasicMassChain<S>& chain, const BasicChainStart<S>& start, long maxContacts,
                      std::type_identity_t<S> tEnd = 0, ChainEventSink<std::type_identity_t<S>> sink = {},
                      ChainSampling<std::type_identity_t<S>> sampling = {})
      : BasicChainSimulator(readyChain(chain), start, maxContacts, tEnd, std::move(sink), std::move(sampling)) {}
  // the note's kernel holds a reference to the simulator's own chain
  BasicChainSimulator(const BasicChainSimulator&) = delete;
  BasicChainSimulator& operator=(const BasicChainSimulator&) = delete;

  /// Runs until `contactBudget` more contacts were made, the run is over, or `stop` is requested
  /// (then over: StopReason::Cancelled). Returns true when the run is over.
  bool advance(long contactBudget, std::stop_token stop = {});

  bool done() const { return m_done; }
  /// The run so far: its events (none kept with a sink) and counts; `final`, `tFinal`,
  /// `energyFinal` and `stop` once it is over.
  const BasicChainRun<S>& run() const { return m_run; }
  BasicChainRun<S> takeRun() { return std::move(m_run); }
  /// Where the run stands: the time of its last event (or the start), in [0, the end].
  const S& time() const { return m_t; }

 private:
  /// the chain kept (`owned`) or the one given
  BasicChainSimulator(std::optional<BasicReadyChain<S>> owned, const BasicReadyChain<S>* given,
                      const BasicChainStart<S>& start, long maxContacts, S tEnd, ChainEventSink<S> sink,
                      ChainSampling<S> sampling, std::int64_t searchSteps);
  /// the energy of a state of the run (the note's kernel: as the note's simulator measures it)
  S energyOf(const BasicChainState<S>& at) const;
  /// ends the run there, for `reason`; true (advance's answer)
  bool finish(StopReason reason, const BasicChainState<S>& at, const S& when);
  /// `residual`: a contact's |u_s - d| as its flight reached it (before it is put on the stop)
  /// `flight`: the length of the flight it ends (0: none), `shortfall` its T - length
  void record(EventType type, const BasicChainState<S>& at, const ChainVector<S>& vBefore, const S& when,
              const S& residual = 0, const S& flight = 0, const S& shortfall = 0);
  /// advance() by the note's kernel
  bool advanceNotes(long pieceEnd);
  double sampleTime(std::size_t index) const;
  template <typename At>
  void samplePiece(const S& from, const S& until, bool withEnd, const At& at);
  /// samplePiece over the note's kernel's last step, from `from` (its grid a batch at a time)
  void sampleStep(const S& from, const S& until, bool withEnd);
  /// where a flight from `from` that never meets the stop again is drawn to
  S neverEnds(const S& from) const;

  std::optional<BasicReadyChain<S>> m_owned;  ///< the chain, when handed over as a temporary
  const BasicMassChain<S>& m_chain;           ///< the ready chain's numbers and dynamics
  const BasicChainDynamics<S>& m_dynamics;
  long m_maxContacts;
  S m_tEnd;
  std::int64_t m_searchSteps;  ///< the note's kernel's, per flight
  S m_slowest;
  S m_period;  ///< what a flight's shortfall is measured from: the common period, or m_slowest
  ChainEventSink<S> m_sink;
  ChainSampling<S> m_sampling;
  std::stop_token m_stop;
  BasicChainRun<S> m_run;
  BasicChainState<S> m_state;
  std::vector<bool> m_stillModes;  ///< the start's modes known to be still (its first flight's)
  S m_t = 0;
  bool m_done = false;
  // the last event, kept here as well: a streamed run holds no list to look back in
  bool m_anyEvent = false;
  EventType m_lastType = EventType::Impact;
  S m_lastTime = 0;
  std::size_t m_sampleIndex = 0;            ///< the next sample due
  std::optional<BasicLeaving<S>> m_leaving;  ///< set when the flight starts at a release
  bool m_flightKept = false;  ///< m_flight goes on from `m_state` (through a periodic touch)
  // reused from flight to flight: no allocation for them once sized
  BasicChainFlight<S> m_flight;
  BasicChainState<S> m_at;
  ChainVector<S> m_vBefore;
  BasicChainEvent<S> m_event;  ///< what the sink is handed
  // the note's kernel (ReadyChain::notes): its chain, its scales, its stepper on that chain and
  // where it stands (scaled); unused by the modal kernel
  std::optional<TwoMassForm<S>> m_notes;
  Scale<S> m_scale;
  std::optional<ExactStepper<S>> m_stepper;
  IntegrationState<S> m_scaled;
};
using ChainSimulator = BasicChainSimulator<double>;

/// A chain run's numbers in double, each rounded once (a run raised to long double or binary128
/// as the explorer and the reports show it).
template <typename S>
ChainRun inDouble(const BasicChainRun<S>& run);

/// An exact run of a usable chain (validate(chain) empty) from `start` (u_s <= d): closed-form
/// flights in the chain's modes, each contact by firstContact (certified: none missed), elastic
/// impacts (v_s reversed), grazing touches that leave the flight unchanged, and sticks: a mass
/// reaching the stop at rest pressed into it is held there (stuckPhase: the chain split at the
/// clamp into two exact chains) until the force on it falls to zero (releaseOf, certified); up
/// to `maxContacts` contacts or `tEnd` (0: none). A search without `tEnd` (a flight of a
/// non-commensurate chain, a stuck phase) goes up to 1000 of the slowest periods. In the
/// precision of the chain: double, long double or binary128 (Quad). A start may name modes that
/// are exactly still in it (BasicChainStart): its first flight has none of them. With a `sink`, each event is
/// handed to it as it happens and none is kept; with `sampling`, the states it asks for.
template <typename S>
BasicChainRun<S> runChain(const BasicMassChain<S>& chain, const std::type_identity_t<BasicChainStart<S>>& start,
                          long maxContacts,
                          std::type_identity_t<S> tEnd = 0, std::stop_token stop = {},
                          const ChainEventSink<std::type_identity_t<S>>& sink = {},
                          const ChainSampling<std::type_identity_t<S>>& sampling = {});
/// The same for a chain made ready once (its runs skip the eigensolve); `searchSteps` as
/// BasicChainSimulator's.
template <typename S>
BasicChainRun<S> runChain(const BasicReadyChain<S>& chain, const std::type_identity_t<BasicChainStart<S>>& start,
                          long maxContacts,
                          std::type_identity_t<S> tEnd = 0, std::stop_token stop = {},
                          const ChainEventSink<std::type_identity_t<S>>& sink = {},
                          const ChainSampling<std::type_identity_t<S>>& sampling = {}, std::int64_t searchSteps = 0);

}  // namespace grazelab::core
