// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/experiments/chain_series.h"

#include <algorithm>
#include <chrono>
#include <type_traits>
#include <cmath>
#include <numbers>
#include <optional>

#include "core/solver/budget.h"
#include "core/solver/trust.h"

namespace grazelab::core::experiments {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Each free flight ends at a contact: it started at the event before (or the start).
std::vector<ChainFlight> flightsOf(const ChainSeriesSpec& spec, const ChainRun& run) {
  const Eigen::Index s = spec.chain.stopped() - 1;
  std::vector<ChainFlight> flights;
  double from = 0;
  bool fromStop = spec.start.u[s] == spec.chain.gap && spec.start.v[s] <= 0;
  bool afterImpact = false;
  long contact = 0;
  for (const ChainEvent& event : run.events) {
    if (event.type == EventType::Release) {  // a flight from the stop begins
      from = event.t;
      fromStop = true;
      afterImpact = false;
      continue;
    }
    ++contact;
    if (event.type != EventType::Stick || event.t > from) {
      flights.push_back({contact, event.t - from, event.shortfall, fromStop, afterImpact});
    }
    from = event.t;
    fromStop = true;
    afterImpact = event.type == EventType::Impact;
  }
  return flights;
}

// The state at each contact (its velocities just before it): the section H as records.
StateRecords sectionOf(const ChainSeriesSpec& spec, const ChainRun& run) {
  StateRecords section{spec.chain.size()};
  for (const ChainEvent& event : run.events) {
    if (isContact(event.type)) section.push(event.t, event.u, event.vBefore);
  }
  return section;
}

template <typename S>
BasicChainState<S> stateIn(const ChainState& state) {
  BasicChainState<S> in{ChainVector<S>(state.u.size()), ChainVector<S>(state.v.size())};
  for (Eigen::Index i = 0; i < state.u.size(); ++i) {
    in.u[i] = S(state.u[i]);
    in.v[i] = S(state.v[i]);
  }
  return in;
}

// The series' chain in S: a designed chain's design root refined for S's numbers, as the command
// line runs it (where that fails, double's design widened: in the ratio to double's rounding)
template <typename S>
BasicMassChain<S> chainIn(const ChainSeriesSpec& spec) {
  BasicMassChain<S> chain = chainCast<S>(spec.chain);
  if constexpr (!std::is_same_v<S, double>) {
    if (spec.design) {
      if (const auto springs = designedSpringsIn<S>(chain.masses, chain.springs.front(), chain.rightSpring, *spec.design)) {
        chain.springs = *springs;
      }
    }
  }
  return chain;
}

// The series' start in S, with the modes its GLO weights leave exactly still
template <typename S>
BasicChainStart<S> startIn(const ChainSeriesSpec& spec) {
  BasicChainStart<S> start = stateIn<S>(spec.start);
  for (double weight : spec.gloWeights) start.stillModes.push_back(weight == 0);
  return start;
}

// The run of `spec` in S with its grid, reported as it grows; nothing when S cannot decide a
// contact and a higher precision is left (`lastResort` false: `undecidedAt` is then where), or
// on a stop.
template <typename S>
std::optional<ChainSeries> seriesIn(const ChainSeriesSpec& spec, const ChainSeries& frame, bool lastResort,
                                    std::stop_token stop, const ChainSeriesProgress& progress,
                                    double chunkSeconds, double& undecidedAt) {
  ChainSeries series = frame;
  ChainSampling<S> sampling;
  if (spec.window > 0 && spec.gridPoints > 1) {
    const int points = spec.free ? spec.gridPoints : std::max(spec.gridPoints, spec.maxGridPoints);
    for (int i = 0; i < points; ++i) sampling.times.push_back(spec.window * i / (spec.gridPoints - 1));
    sampling.sink = [&](double t, const BasicChainState<S>& state) {
      series.grid.push(t, state.u, state.v);
    };
  }
  const BasicMassChain<S> chain = chainIn<S>(spec);
  const BasicChainStart<S> start = startIn<S>(spec);
  if (spec.free) {
    // one closed-form flight over the grid, through the stop if it goes there
    const BasicChainDynamics<S> dynamics = chainDynamicsIn<S>(chain);
    const BasicChainFlight<S> flight = flightFrom(dynamics, start.state);
    if (sampling.sink) {
      for (double t : sampling.times) sampling.sink(t, stateAt(dynamics, flight, S(t)));
    }
    series.run.final = spec.start;
    series.run.stop = StopReason::TimeLimit;
    return series;
  }
  const BasicReadyChain<S> ready = readyChain(chain);
  BasicChainSimulator<S> simulator(ready, start, spec.contacts, S(0), {}, sampling);
  // pieces sized in contacts, adapted to the measured speed so that each costs about
  // chunkSeconds; before the first report, which comes a third of chunkSeconds in, pieces of 1,
  // 2, 4, ... contacts, to show something at once (a run of eight masses costs 1.6 ms a contact:
  // a drag's run is stopped by the next value after a grace of 40 ms, and showed nothing)
  std::int64_t budget = 1;
  auto sinceReport = std::chrono::steady_clock::now();
  double copySeconds = 0;
  bool reported = false;
  while (!simulator.done()) {
    const auto began = std::chrono::steady_clock::now();
    if (simulator.advance(long(budget), stop) || stop.stop_requested()) break;
    budget = reported ? nextChunkContacts(budget, std::max(secondsSince(began), 1e-6), chunkSeconds) : 2 * budget;
    const double due = reported ? std::max(chunkSeconds, 4 * copySeconds) : chunkSeconds / 3;
    if (!progress || secondsSince(sinceReport) < due) continue;
    reported = true;
    const auto copying = std::chrono::steady_clock::now();
    ChainSeries sofar = series;
    sofar.run = inDouble(simulator.run());
    sofar.flights = flightsOf(spec, sofar.run);
    sofar.section = sectionOf(spec, sofar.run);
    copySeconds = secondsSince(copying);
    progress(sofar, double(sofar.run.contacts) / double(std::max(1L, spec.contacts)));
    sinceReport = std::chrono::steady_clock::now();
  }
  if (stop.stop_requested()) return std::nullopt;
  if (!lastResort && simulator.run().stop == StopReason::Undecided) {
    undecidedAt = toDouble(simulator.run().tFinal);
    return std::nullopt;
  }
  // the run whole in double, once: shown before its error estimate (the shadow run costs about
  // as much again), then handed back with it
  series.run = inDouble(simulator.run());
  series.flights = flightsOf(spec, series.run);
  series.section = sectionOf(spec, series.run);
  if (progress && spec.trust != TrustMode::Off) {
    series.trustPending = true;
    progress(series, 1.0);
    series.trustPending = false;
  }
  // the run's error estimate: the chain and start read one precision up (binary128's shadow
  // scaled), compared event by event
  using H = ShadowScalar<S>;
  std::optional<BasicReadyChain<H>> widened;
  ChainShadow<S> shadow;
  if (spec.trust != TrustMode::Off) {
    if constexpr (std::is_same_v<S, H>) {
      shadow = chainShadow<S>(ready);
    } else {
      widened = readyChain(chainIn<H>(spec));
      shadow = chainShadow<S>(*widened);
    }
  }
  TrustMonitor<S> monitor(shadow, startIn<H>(spec), spec.contacts, H(0), spec.trust, stop);
  for (const BasicChainEvent<S>& event : simulator.run().events) monitor.observe(event);
  series.trust = monitor.finish(simulator.run());
  if (stop.stop_requested()) series.trust = {};  // an estimate cut short says nothing
  return series;
}

}  // namespace

ChainSeries chainSeries(const ChainSeriesSpec& spec, std::stop_token stop, const ChainSeriesProgress& progress,
                        double chunkSeconds) {
  ChainSeries frame;
  frame.chain = spec.chain;
  frame.start = spec.start;
  frame.gloWeights = spec.gloWeights;
  frame.contactsAsked = spec.contacts;
  frame.grid.masses = spec.chain.size();
  frame.section.masses = spec.chain.size();
  frame.modes = chainModes(spec.chain);
  frame.ratios = detectRatios(frame.modes.omega);
  if (frame.ratios.commensurate) frame.period = 2 * std::numbers::pi / frame.ratios.omega0;
  // --precision auto's rule: double; where it cannot decide a contact, long double, then binary128
  double undecidedAt = 0;
  std::optional<ChainSeries> series = seriesIn<double>(spec, frame, false, stop, progress, chunkSeconds, undecidedAt);
  for (const Precision raised : {Precision::Long, Precision::Quad}) {
    if (series || stop.stop_requested()) break;
    frame.undecidedAt = undecidedAt;  // the contact the precision below could not decide
    frame.precision = raised;
    series = raised == Precision::Long
                 ? seriesIn<long double>(spec, frame, false, stop, progress, chunkSeconds, undecidedAt)
                 : seriesIn<Quad>(spec, frame, true, stop, progress, chunkSeconds, undecidedAt);
  }
  if (series) return std::move(*series);
  // stopped: the frame, its run cancelled
  frame.run.stop = StopReason::Cancelled;
  return frame;
}

}  // namespace grazelab::core::experiments
