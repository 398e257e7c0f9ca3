// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/sim_worker.h"

#include "core/budget.h"
#include "core/chain.h"
#include "core/trust.h"
#include "parallel/tbb_parallel_for.h"

#include <QElapsedTimer>

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace grazelab::ui {

namespace {

// --precision auto's rule in the explorer: the run again in S (long double, then binary128)
// from its start, when double met a contact it cannot decide; with its own error estimate.
// Nothing when S cannot decide either (and a higher precision is left), or on a stop.
template <typename S>
std::optional<std::pair<core::Result, core::Trust>> runRaised(const SimRequest& request,
                                                              bool lastResort,
                                                              std::stop_token stop) {
  using H = core::ShadowScalar<S>;
  core::BasicRequest<S> raised = core::convertRequest<S>(request.job.request);
  raised.stopAtUndecided = !lastResort;
  const core::BasicRequest<H> shadow = core::convertRequest<H>(request.job.request);
  // the explorer's parameters are the doubles of its panel, exact as they stand
  core::TrustMonitor<S> monitor(core::convertModel<H>(request.job.model), shadow,
                                core::TrustMode::Auto, stop,
                                core::ExactParameters{true, true, true, true, true});
  raised.onEvent = [&monitor](const core::BasicEvent<S>& event) { monitor.observe(event); };
  const core::BasicResult<S> result =
      core::simulate(core::convertModel<S>(request.job.model), raised, stop);
  if (result.stop == core::StopReason::Undecided || stop.stop_requested()) return std::nullopt;
  core::Trust trust = monitor.finish(result);
  return std::pair{core::toDoubleResult(result), std::move(trust)};
}

/// The Accuracy scene's sweep, after its exact run: every setting on the same start up to half
/// a period past the exact run's last contact, measured against the binary128 reference; a
/// partial update after each setting (its point appears at once), then the final one.
void sweepAccuracy(const SimRequest& request, SimUpdate last, std::stop_token stop,
                   const std::function<void(const SimUpdate&)>& report) {
  namespace methods = core::methods;
  const AccuracyJob& job = *request.job.accuracy;
  const core::ChainOrProblem<double> formed = core::makeChain(request.job.model);
  if (!formed.chain) {
    report(last);
    return;
  }
  const double period = core::twoPi<double>() / formed.chain->omegaSlow;
  // timed with the events only (every contact: the matching needs them all); the overlay's
  // run again with the trace's samples, which would tilt the timing (the exact solver
  // evaluates its flight at each sample, a time stepper only keeps its own steps)
  methods::Task task{request.job.model, request.job.request.initial, last.result->tFinal + period / 2, {}};
  task.needs.events = true;
  methods::Task overlayTask = task;
  overlayTask.needs.samples = request.job.request.needs.samples;
  // 40 runs are kept for the picker: each one's trace is capped (the first ~200 T2 of it)
  overlayTask.needs.samples.maxCount = std::min<std::size_t>(overlayTask.needs.samples.maxCount, 20'000);
  {
    // the exact run at once: the reference and the settings take a while
    SimUpdate shown = last;
    shown.final = false;
    shown.progress = 0;
    report(shown);
  }
  methods::Task referenceTask = task;
  methods::WorkBudget referenceBudget = job.budget;
  referenceBudget.maxSeconds = std::max(job.budget.maxSeconds, 60.0);  // it judges every run
  const methods::Reference reference = methods::makeReference(referenceTask, referenceBudget, stop);
  auto progress = std::make_shared<AccuracyProgress>();
  progress->total = job.settings.size();
  progress->tEnd = task.tEnd;
  for (const methods::MethodSetting& setting : job.settings) {
    if (stop.stop_requested()) break;
    const methods::WorkPrecisionPoint point =
        methods::measurePoint(task, reference, setting, job.budget, job.timing, stop);
    methods::MethodRun run = methods::runMethod(overlayTask, setting, job.budget, stop);
    if (stop.stop_requested()) break;
    auto next = std::make_shared<AccuracyProgress>(*progress);  // points are small; runs shared
    next->points.push_back({point, std::make_shared<const core::Result>(std::move(run.result))});
    progress = std::move(next);
    SimUpdate partial = last;
    partial.final = false;
    partial.progress = double(progress->points.size()) / double(std::max<std::size_t>(1, progress->total));
    partial.accuracy = progress;
    report(partial);
  }
  last.accuracy = progress;
  report(last);
}

/// The last complete map: a click on the landscape, or a slider the map does not depend on,
/// asks for the same map again, which is then shown at once.
struct MapCache {
  std::mutex mutex;
  std::optional<MapProgress> map;
};
MapCache& mapCache() {
  static MapCache cache;
  return cache;
}

/// The landscape scene's map, after its run: bands of rows on all cores, a partial update after
/// each band (its rows appear at once), then the final one.
void sweepMap(const SimRequest& request, SimUpdate last, std::stop_token stop,
              const std::function<void(const SimUpdate&)>& report) {
  const core::MapSpec& spec = request.job.map->spec;
  {
    const std::lock_guard lock(mapCache().mutex);
    if (mapCache().map && mapCache().map->spec == spec) {
      last.map = mapCache().map;
      report(last);
      return;
    }
  }
  MapProgress progress;
  progress.spec = spec;
  const std::int64_t columns = spec.x.count;
  const std::int64_t rows = spec.y.count;
  progress.points = std::make_shared<std::vector<core::PointSummary>>(std::size_t(columns * rows));
  const core::ParallelFor executor = parallel::tbbParallelFor(0);
  // bands of about 8192 points: a few milliseconds each on two cores
  const std::int64_t band = std::max<std::int64_t>(1, 8192 / std::max<std::int64_t>(1, columns));
  QElapsedTimer clock;
  clock.start();
  for (std::int64_t row = 0; row < rows && !stop.stop_requested(); row += band) {
    const core::MapRows part = core::computeMap(spec, {row, std::min(rows, row + band)}, executor, stop);
    if (!part.complete) break;
    // rows past progress.rowsDone: no reader looks at them yet
    std::copy(part.points.begin(), part.points.end(), progress.points->begin() + std::ptrdiff_t(row * columns));
    progress.rowsDone = part.rows.rowEnd;
    progress.seconds = clock.nsecsElapsed() * 1e-9;
    progress.complete = progress.rowsDone == rows;
    if (progress.complete) break;
    SimUpdate partial = last;
    partial.final = false;
    partial.progress = double(progress.rowsDone) / double(rows);
    partial.map = progress;
    report(partial);
  }
  if (progress.complete) {
    const std::lock_guard lock(mapCache().mutex);
    mapCache().map = progress;
  }
  last.map = progress;
  report(last);
}

// How many of each kind of item a run had when it was last reported.
struct ResultCounts {
  std::size_t events = 0;
  std::size_t poincare = 0;
  std::size_t freeFlights = 0;
  std::size_t samples = 0;
};

ResultCounts countsOf(const core::Result& result) {
  return {result.events.size(), result.poincare.size(), result.freeFlights.size(),
          result.samples.size()};
}

// The items past `sent`, with the run's present totals.
core::Result newSince(const core::Result& result, const ResultCounts& sent) {
  core::Result chunk;
  chunk.events.assign(result.events.begin() + std::ptrdiff_t(sent.events), result.events.end());
  chunk.poincare.assign(result.poincare.begin() + std::ptrdiff_t(sent.poincare), result.poincare.end());
  chunk.freeFlights.assign(result.freeFlights.begin() + std::ptrdiff_t(sent.freeFlights),
                           result.freeFlights.end());
  chunk.samples.assign(result.samples.begin() + std::ptrdiff_t(sent.samples), result.samples.end());
  copyTotals(result, chunk);
  return chunk;
}

}  // namespace

SimWorker::SimWorker(std::shared_ptr<SimMailbox> mailbox) : m_mailbox(std::move(mailbox)) {}

void SimWorker::wake() {
  std::optional<SimRequest> request;
  std::stop_token stop;
  {
    const std::lock_guard lock(m_mailbox->mutex);
    if (!m_mailbox->waiting) return;  // an earlier wake-up already took it
    request = std::move(m_mailbox->waiting);
    m_mailbox->waiting.reset();
    m_mailbox->running = std::stop_source();
    stop = m_mailbox->running.get_token();
  }
  run(*request, stop, 0.030, [this](const SimUpdate& update) { emit updated(update); });
}

void SimWorker::run(const SimRequest& described, std::stop_token stop, double chunkSeconds,
                    const std::function<void(const SimUpdate&)>& report) {
  // the scene's own computations first (curves, surveys, the start), here and not on the GUI
  // thread; what they give travels with every update
  SimRequest prepared = described;
  if (prepared.prepare) {
    prepared.job = prepared.prepare(stop);
    prepared.prepare = nullptr;
  }
  const auto asked = std::make_shared<const SimRequest>(std::move(prepared));
  const SimRequest& request = *asked;
  if (!request.job.ok || stop.stop_requested()) {
    // nothing to run: the final update says why (or that it was stopped before it began)
    auto nothing = std::make_shared<core::Result>();
    nothing->stop = stop.stop_requested() ? core::StopReason::Cancelled : core::StopReason::InvalidInput;
    nothing->message = request.job.message.toStdString();
    SimUpdate last;
    last.id = request.id;
    last.progress = 1.0;
    last.final = true;
    last.request = asked;
    last.result = std::move(nothing);
    report(last);
    return;
  }
  // the error estimate: a long double shadow of the same run, in lockstep, while it is cheap
  core::BasicRequest<long double> shadowRequest = core::convertRequest<long double>(request.job.request);
  core::TrustMonitor<double> monitor(core::convertModel<long double>(request.job.model),
                                     shadowRequest, core::TrustMode::Auto, stop);
  // Up to this many contacts the shadow runs after the result is shown, on the run's events
  // kept meanwhile (~1.6 MB for 20 000); beyond, in lockstep, at no memory cost. The shadow
  // took 7/8 of a 20 000-contact run's time: the plots no longer wait for it.
  constexpr std::int64_t kTrustAfterContacts = 200'000;
  const bool trustAfter = request.job.request.maxContacts <= kTrustAfterContacts && !request.job.accuracy;
  std::vector<core::Event> events;
  core::Request primary = request.job.request;
  primary.stopAtUndecided = true;  // then the run again in a higher precision (below)
  primary.onEvent = [&monitor, &request, &events, trustAfter](const core::Event& event) {
    if (trustAfter) events.push_back(event);
    else monitor.observe(event);
    if (request.job.request.onEvent) request.job.request.onEvent(event);
  };
  core::Simulator simulator(request.job.model, primary);
  // the chunk is sized in contacts and adapted to the measured speed, so that each partial
  // result costs about chunkSeconds; the first chunk is small to show something at once
  std::int64_t budget = 256;
  QElapsedTimer clock;
  QElapsedTimer sinceReport;
  sinceReport.start();
  double copySeconds = 0;
  ResultCounts sent;
  bool done = simulator.done();
  while (!done) {
    clock.start();
    done = simulator.advance(budget, stop);
    const double seconds = std::max(clock.nsecsElapsed() * 1e-9, 1e-6);
    if (done || stop.stop_requested()) break;
    budget = core::nextChunkContacts(budget, seconds, chunkSeconds);
    // a partial update carries what is new since the last one; if even that grows costly
    // (many samples per contact), it is sent less often: copying never takes more than a
    // fifth of the worker's time
    if (sinceReport.nsecsElapsed() * 1e-9 < std::max(chunkSeconds, 4 * copySeconds)) continue;
    clock.start();
    SimUpdate partial;
    partial.id = request.id;
    partial.chunk = std::make_shared<const core::Result>(newSince(simulator.result(), sent));
    sent = countsOf(simulator.result());
    partial.progress = simulator.progress();
    partial.request = asked;
    copySeconds = clock.nsecsElapsed() * 1e-9;
    report(partial);
    sinceReport.start();
  }
  SimUpdate last;
  last.id = request.id;
  last.progress = 1.0;
  last.final = true;
  last.runDone = true;
  last.request = asked;
  if (simulator.result().stop == core::StopReason::Undecided && !stop.stop_requested()) {
    // a contact double cannot tell a graze from an impact: long double, then binary128
    auto raised = runRaised<long double>(request, false, stop);
    last.attempt = 1;
    if (!raised && !stop.stop_requested()) {
      raised = runRaised<core::Quad>(request, true, stop);
      last.attempt = 2;
    }
    if (raised) {
      last.result = std::make_shared<const core::Result>(std::move(raised->first));
      last.trust = std::move(raised->second);
      last.precisionNote = simulator.result().message;
    }
  }
  const bool estimate = !last.result && simulator.result().stop != core::StopReason::InvalidInput;
  if (estimate && !trustAfter) last.trust = monitor.finish(simulator.result());
  if (!last.result) last.result = std::make_shared<const core::Result>(simulator.takeResult());
  if (estimate && trustAfter) {
    SimUpdate shown = last;
    shown.trustPending = true;
    report(shown);
    // then the estimate; a stop ends it without one (the final update still comes: the
    // controller waits for it)
    for (const core::Event& event : events) {
      if (stop.stop_requested()) break;
      monitor.observe(event);
    }
    if (!stop.stop_requested()) last.trust = monitor.finish(*last.result);
  }
  if (request.job.accuracy && last.result->stop != core::StopReason::InvalidInput &&
      !stop.stop_requested()) {
    sweepAccuracy(request, std::move(last), stop, report);
    return;
  }
  if (request.job.map && !stop.stop_requested()) {
    sweepMap(request, std::move(last), stop, report);
    return;
  }
  report(last);
}

}  // namespace grazelab::ui
