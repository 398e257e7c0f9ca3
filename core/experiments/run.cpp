// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/experiments/run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include "core/solver/budget.h"
#include "core/solver/two_mass_run.h"
#include "core/model/two_mass_form.h"

namespace grazelab::core::experiments {

namespace {

// Seconds on a monotonic clock since `start` was taken.
class Stopwatch {
 public:
  Stopwatch() { restart(); }
  void restart() { m_start = std::chrono::steady_clock::now(); }
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  }

 private:
  std::chrono::steady_clock::time_point m_start;
};

// the run's bounds as its shadow takes them (no end time: 0)
long shadowContacts(const Request& run) {
  return long(std::min<std::int64_t>(run.maxContacts, std::numeric_limits<long>::max()));
}
template <typename H>
H shadowEnd(const Request& run) {
  return std::isfinite(run.tEnd) ? H(run.tEnd) : H(0);
}
// the run's start read in the shadow's precision, with the modes it names still
template <typename H>
BasicChainStart<H> shadowStart(const Spec& spec) {
  return {chainStateOf(convertState<H>(spec.run.initial)), spec.stillModes};
}
// a search budget the run was given (0: the shadow precision's own default, as the run's)
std::int64_t shadowSteps(const Request& run) {
  return run.flightSearchSteps != defaultSearchSteps<double>() ? run.flightSearchSteps : 0;
}

// --precision auto's rule: the run again in S (long double, then binary128) from its start,
// when double met a contact it cannot decide; with its own error estimate. Nothing when S
// cannot decide either (and a higher precision is left), or on a stop.
template <typename S>
std::optional<std::pair<Result, Trust>> runRaised(const Spec& spec, bool lastResort,
                                                  std::stop_token stop) {
  using H = ShadowScalar<S>;
  BasicRequest<S> raised = convertRequest<S>(spec.run);
  // the parameters are doubles, exact as they stand
  const BasicReadyChain<H> input = readyChain(convertModel<H>(spec.model));
  const ChainShadow<S> shadow = chainShadow<S>(input);
  TrustMonitor<S> monitor(shadow, shadowStart<H>(spec), shadowContacts(spec.run), shadowEnd<H>(spec.run),
                          TrustMode::Auto, stop, shadowSteps(spec.run));
  raised.onEvent = [&monitor](const BasicEvent<S>& event) { monitor.observe(chainEventOf(event)); };
  TwoMassRun<S> run(convertModel<S>(spec.model), raised, spec.stillModes);
  run.advance(std::numeric_limits<std::int64_t>::max(), stop);
  const BasicResult<S>& result = run.result();
  // binary128 undecided too: its run as far as it could decide, shown as such
  if ((result.stop == StopReason::Undecided && !lastResort) || stop.stop_requested()) return std::nullopt;
  Trust trust = monitor.finish(chainTotalsOf(result));
  return std::pair{toDoubleResult(result), std::move(trust)};
}

// The work-precision sweep after the run: every setting on the same start up to half a period
// past the run's last contact, measured against the binary128 reference; a report after each
// setting, then the final one.
Update sweepAccuracy(const Spec& spec, Update last, std::stop_token stop,
                     const std::function<void(const Update&)>& report) {
  const AccuracySweep& sweep = *spec.accuracy;
  const TwoMassFormOrProblem<double> formed = makeTwoMassForm(spec.model);
  if (!formed.chain) {
    report(last);
    return last;
  }
  const double period = twoPi<double>() / formed.chain->omegaSlow;
  // timed with the events only (every contact: the matching needs them all); the overlay's
  // run again with the samples, which would tilt the timing (the exact solver evaluates its
  // flight at each sample, a time stepper only keeps its own steps)
  methods::Task task =
      methods::prepared(methods::Task{spec.model, spec.run.initial, last.result->tFinal + period / 2, {}});
  task.needs.events = true;
  methods::Task overlayTask = task;
  overlayTask.needs.samples = spec.run.needs.samples;
  // 40 runs are kept for an overlay picker: each one's samples are capped (~200 T2)
  overlayTask.needs.samples.maxCount = std::min<std::size_t>(overlayTask.needs.samples.maxCount, 20'000);
  {
    // the run at once: the reference and the settings take a while
    Update shown = last;
    shown.final = false;
    shown.progress = 0;
    report(shown);
  }
  methods::WorkBudget referenceBudget = sweep.budget;
  referenceBudget.maxSeconds = std::max(sweep.budget.maxSeconds, 60.0);  // it judges every run
  const methods::Reference reference = methods::makeReference(task, referenceBudget, stop);
  auto progress = std::make_shared<AccuracyProgress>();
  progress->total = sweep.settings.size();
  progress->tEnd = task.tEnd;
  for (const methods::MethodSetting& setting : sweep.settings) {
    if (stop.stop_requested()) break;
    const methods::WorkPrecisionPoint point =
        methods::measurePoint(task, reference, setting, sweep.budget, sweep.timing, stop);
    methods::MethodRun overlay = methods::runMethod(overlayTask, setting, sweep.budget, stop);
    if (stop.stop_requested()) break;
    auto next = std::make_shared<AccuracyProgress>(*progress);  // points are small; runs shared
    next->points.push_back({point, std::make_shared<const Result>(std::move(overlay.result))});
    progress = std::move(next);
    Update partial = last;
    partial.final = false;
    partial.progress = double(progress->points.size()) / double(std::max<std::size_t>(1, progress->total));
    partial.accuracy = progress;
    report(partial);
  }
  last.accuracy = progress;
  report(last);
  return last;
}

// The map after the run: bands of rows, a report after each band (its rows appear at once),
// then the final one.
Update sweepMap(const Spec& spec, const Options& options, Update last, std::stop_token stop,
                const std::function<void(const Update&)>& report) {
  const MapSpec& map = *spec.map;
  if (options.mapCache) {
    const std::lock_guard lock(options.mapCache->mutex);
    if (options.mapCache->map && options.mapCache->map->spec == map) {
      last.map = options.mapCache->map;
      report(last);
      return last;
    }
  }
  MapProgress progress;
  progress.spec = map;
  const std::int64_t columns = map.x.count;
  const std::int64_t rows = map.y.count;
  progress.points = std::make_shared<std::vector<PointSummary>>(std::size_t(columns * rows));
  // bands of about 8192 points: a few milliseconds each on two cores
  const std::int64_t band = std::max<std::int64_t>(1, 8192 / std::max<std::int64_t>(1, columns));
  const Stopwatch clock;
  for (std::int64_t row = 0; row < rows && !stop.stop_requested(); row += band) {
    const MapRows part = computeMap(map, {row, std::min(rows, row + band)}, options.parallelFor, stop);
    if (!part.complete) break;
    // rows past progress.rowsDone: no reader looks at them yet
    std::copy(part.points.begin(), part.points.end(), progress.points->begin() + std::ptrdiff_t(row * columns));
    progress.rowsDone = part.rows.rowEnd;
    progress.seconds = clock.seconds();
    progress.complete = progress.rowsDone == rows;
    if (progress.complete) break;
    Update partial = last;
    partial.final = false;
    partial.progress = double(progress.rowsDone) / double(rows);
    partial.map = progress;
    report(partial);
  }
  if (progress.complete && options.mapCache) {
    const std::lock_guard lock(options.mapCache->mutex);
    options.mapCache->map = progress;
  }
  last.map = progress;
  report(last);
  return last;
}

// How many of each kind of item a run had when it was last reported.
struct ResultCounts {
  std::size_t events = 0;
  std::size_t poincare = 0;
  std::size_t freeFlights = 0;
  std::size_t samples = 0;
};

ResultCounts countsOf(const Result& result) {
  return {result.events.size(), result.poincare.size(), result.freeFlights.size(),
          result.samples.size()};
}

// The items past `sent`, with the run's present totals.
Result newSince(const Result& result, const ResultCounts& sent) {
  Result chunk;
  chunk.events.assign(result.events.begin() + std::ptrdiff_t(sent.events), result.events.end());
  chunk.poincare.assign(result.poincare.begin() + std::ptrdiff_t(sent.poincare), result.poincare.end());
  chunk.freeFlights.assign(result.freeFlights.begin() + std::ptrdiff_t(sent.freeFlights),
                           result.freeFlights.end());
  chunk.samples.assign(result.samples.begin() + std::ptrdiff_t(sent.samples), result.samples.end());
  copyTotals(result, chunk);
  return chunk;
}

// An experiment of chains of N masses: each run in turn, streamed (chainSeries), raised in
// precision where double cannot decide a contact.
Update runChains(const Spec& spec, std::stop_token stop, const Options& options,
                 const std::function<void(const Update&)>& report) {
  const double count = double(spec.chains.size());
  ChainRuns done;
  // Update::attempt counts as Precision does: 0 double, 1 long double, 2 binary128
  const auto precisionOf = [](const ChainSeries& series) { return int(series.precision); };
  Update last;
  for (std::size_t i = 0; i < spec.chains.size() && !stop.stop_requested(); ++i) {
    const auto partial = [&](const ChainSeries& sofar, double fraction) {
      Update update;
      update.chains = done;
      update.chains.push_back(std::make_shared<const ChainSeries>(sofar));
      update.progress = (double(i) + fraction) / count;
      update.attempt = precisionOf(*update.chains.front());
      // the shown run whole, its error estimate to come
      update.runDone = update.trustPending = i == 0 && sofar.trustPending;
      report(update);
    };
    done.push_back(std::make_shared<const ChainSeries>(chainSeries(spec.chains[i], stop, partial, options.chunkSeconds)));
    if (i == 0) {
      last.attempt = precisionOf(*done.front());
      if (done.front()->precision != Precision::Double) {
        char note[96];
        std::snprintf(note, sizeof note, "the precision below could not decide the contact at t = %.9g",
                      done.front()->undecidedAt);
        last.precisionNote = note;
      }
      if (spec.chains.size() > 1 && !stop.stop_requested()) {
        // the run shown, whole, before the runs beside it
        Update shown = last;
        shown.chains = done;
        shown.runDone = true;
        shown.progress = 1 / count;
        report(shown);
      }
    }
  }
  last.chains = std::move(done);
  last.progress = 1.0;
  last.final = true;
  last.runDone = true;
  report(last);
  return last;
}

}  // namespace

void copyTotals(const Result& from, Result& to) {
  to.samplesTruncated = from.samplesTruncated;
  to.tFinal = from.tFinal;
  to.final = from.final;
  to.initialEnergy = from.initialEnergy;
  to.cost = from.cost;
  to.stop = from.stop;
  to.message = from.message;
}

Update run(const Spec& spec, std::stop_token stop, const Options& options,
           const std::function<void(const Update&)>& report) {
  if (!spec.chains.empty()) return runChains(spec, stop, options, report);
  // the error estimate: a long double shadow of the same run, in lockstep, while it is cheap
  const BasicReadyChain<long double> input = readyChain(convertModel<long double>(spec.model));
  const ChainShadow<double> shadow = chainShadow<double>(input);
  TrustMonitor<double> monitor(shadow, shadowStart<long double>(spec), shadowContacts(spec.run),
                               shadowEnd<long double>(spec.run), TrustMode::Auto, stop, shadowSteps(spec.run));
  // Up to this many contacts the shadow runs after the run is reported, on its events kept
  // meanwhile (~1.6 MB for 20 000); beyond, in lockstep, at no memory cost. The shadow took
  // 7/8 of a 20 000-contact run's time: a display no longer waits for it.
  constexpr std::int64_t kTrustAfterContacts = 200'000;
  const bool trustAfter = spec.run.maxContacts <= kTrustAfterContacts && !spec.accuracy;
  std::vector<Event> events;
  Request primary = spec.run;
  primary.onEvent = [&monitor, &spec, &events, trustAfter](const Event& event) {
    if (trustAfter) events.push_back(event);
    else monitor.observe(chainEventOf(event));
    if (spec.run.onEvent) spec.run.onEvent(event);
  };
  // a contact double cannot decide ends it: then the run again in a higher precision (below)
  TwoMassRun<double> primaryRun(spec.model, primary, spec.stillModes);
  // the chunk is sized in contacts and adapted to the measured speed, so that each report
  // costs about chunkSeconds; the first chunk is small to show something at once
  std::int64_t budget = 256;
  Stopwatch sinceReport;
  double copySeconds = 0;
  ResultCounts sent;
  bool done = primaryRun.done();
  while (!done) {
    const Stopwatch clock;
    done = primaryRun.advance(budget, stop);
    const double seconds = std::max(clock.seconds(), 1e-6);
    if (done || stop.stop_requested()) break;
    budget = nextChunkContacts(budget, seconds, options.chunkSeconds);
    // a report carries what is new since the last one; if even that grows costly (many
    // samples per contact), it is sent less often: copying never takes more than a fifth of
    // the time
    if (sinceReport.seconds() < std::max(options.chunkSeconds, 4 * copySeconds)) continue;
    const Stopwatch copying;
    Update partial;
    partial.chunk = std::make_shared<const Result>(newSince(primaryRun.result(), sent));
    sent = countsOf(primaryRun.result());
    partial.progress = primaryRun.progress();
    copySeconds = copying.seconds();
    report(partial);
    sinceReport.restart();
  }
  Update last;
  last.progress = 1.0;
  last.final = true;
  last.runDone = true;
  if (primaryRun.result().stop == StopReason::Undecided && !stop.stop_requested()) {
    // a contact double cannot tell a graze from an impact: long double, then binary128
    auto raised = runRaised<long double>(spec, false, stop);
    last.attempt = 1;
    if (!raised && !stop.stop_requested()) {
      raised = runRaised<Quad>(spec, true, stop);
      last.attempt = 2;
    }
    if (raised) {
      last.result = std::make_shared<const Result>(std::move(raised->first));
      last.trust = std::move(raised->second);
      last.precisionNote = primaryRun.result().message;
    }
  }
  const bool estimate = !last.result && primaryRun.result().stop != StopReason::InvalidInput;
  if (estimate && !trustAfter) last.trust = monitor.finish(chainTotalsOf(primaryRun.result()));
  if (!last.result) last.result = std::make_shared<const Result>(primaryRun.takeResult());
  if (estimate && trustAfter) {
    Update shown = last;
    shown.trustPending = true;
    report(shown);
    // then the estimate; a stop ends it without one (the final report still comes: a reader
    // may wait for it)
    for (const Event& event : events) {
      if (stop.stop_requested()) break;
      monitor.observe(chainEventOf(event));
    }
    if (!stop.stop_requested()) last.trust = monitor.finish(chainTotalsOf(*last.result));
  }
  if (spec.accuracy && last.result->stop != StopReason::InvalidInput && !stop.stop_requested()) {
    return sweepAccuracy(spec, std::move(last), stop, report);
  }
  if (spec.map && !stop.stop_requested()) {
    return sweepMap(spec, options, std::move(last), stop, report);
  }
  report(last);
  return last;
}

}  // namespace grazelab::core::experiments
