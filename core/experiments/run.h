// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "core/experiments/chain_series.h"
#include "core/experiments/maps.h"
#include "core/methods/work_precision.h"
#include "core/model/model.h"
#include "core/solver/simulate.h"
#include "core/solver/trust.h"

/// An experiment as data, and the one function that computes it: the run from its start (the
/// one run of the chain, TwoMassRun, with its error estimate, raised to long double then
/// binary128 when double meets a contact it cannot decide), then the work-precision sweep or the
/// map it asks for. The explorer's worker calls only `run`; tests and benchmarks call the same
/// function. Qt-free, like all of core.
namespace grazelab::core::experiments {

/// The work-precision sweep beside the run (the Accuracy scene): every setting on the same
/// start, up to half a slow period past the run's last contact, against a binary128 reference.
struct AccuracySweep {
  std::vector<methods::MethodSetting> settings;
  methods::TimingPolicy timing{1, 0.5, 0.0, 1};
  /// per run: a long horizon ends some runs on their budget (shown) rather than hold the sweep
  methods::WorkBudget budget{200'000'000, 1.0};
};

/// One finished setting of the sweep, with its run (events and samples over the run's sample
/// window) for an overlay.
struct AccuracyPoint {
  methods::WorkPrecisionPoint point;
  std::shared_ptr<const Result> run;
};

/// The sweep so far.
struct AccuracyProgress {
  std::vector<AccuracyPoint> points;
  std::size_t total = 0;  ///< settings asked for
  double tEnd = 0;        ///< the end of the comparison [time]
};

/// A map as it is being computed: `run` fills `points` row after row and publishes how many
/// rows are done with each update; a reader looks only at the rows below that count (they are
/// never written again), so the grid is shared without copies.
struct MapProgress {
  MapSpec spec;
  std::shared_ptr<std::vector<PointSummary>> points;  ///< y.count x x.count, row-major
  std::int64_t rowsDone = 0;
  bool complete = false;
  double seconds = 0;  ///< computing time so far
};

/// The last complete map, kept between experiments by whoever runs them: the same map asked
/// again (a click on the landscape, a slider the map does not depend on) is then given at once.
struct MapCache {
  std::mutex mutex;
  std::optional<MapProgress> map;
};

/// What an experiment computes: one run of `model` from `run.initial` with `run.needs`, and
/// at most one of the sweeps after it; or, when `chains` is not empty, the runs of chains of N
/// masses it lists (the first is the run shown, any other is beside it: a detuned contrast)
/// instead.
struct Spec {
  Model model;
  Request run;
  /// the start's modes known to be exactly still (BasicChainStart: GLO_0 left unpushed names
  /// the slow mode), kept so by the run
  std::vector<bool> stillModes = {};
  std::optional<AccuracySweep> accuracy;
  std::optional<MapSpec> map;
  std::vector<ChainSeriesSpec> chains;
};

/// The runs of an experiment's chains of N masses, as far as computed.
using ChainRuns = std::vector<std::shared_ptr<const ChainSeries>>;

/// How to compute it: the run is reported in pieces of about `chunkSeconds` of work; the map
/// runs its rows with `parallelFor` (core starts no thread) and remembers itself in `mapCache`.
struct Options {
  double chunkSeconds = 0.030;
  ParallelFor parallelFor = serialFor();
  std::shared_ptr<MapCache> mapCache;  ///< none: nothing is remembered
};

/// One report of an experiment in progress, or its end. Every shared part is read-only once
/// reported.
struct Update {
  /// The run so far. A partial report carries only `chunk`; a reader that keeps the run appends
  /// the chunks. The run's last report carries the whole run here. None in an experiment of
  /// chains of N masses (`chains`).
  std::shared_ptr<const Result> result;
  /// An experiment of chains of N masses (Spec::chains): each run in full as far as it has gone
  /// (the last one reported may be partial until runDone), every one read-only once reported.
  ChainRuns chains;
  /// What the run added since the previous report: its new events, points, flights and
  /// samples, and the run's present totals (time, state, cost, stop reason).
  std::shared_ptr<const Result> chunk;
  double progress = 0;  ///< fraction of the requested work done, [0, 1]
  bool final = false;   ///< the experiment is over (complete, stopped or invalid)
  /// the run is over and this report carries all of it; a sweep or a map after it may still
  /// be going (final is then false)
  bool runDone = false;
  std::optional<Trust> trust;  ///< the run's error estimate, once it is known
  /// the whole run, sent before its error estimate; a report with the same run and its
  /// estimate follows (a display need not wait for the shadow run)
  bool trustPending = false;
  /// 0: the run as computed in double; 1 or 2: the run again in long double or binary128 from
  /// its start, because double met a contact it cannot decide (--precision auto's rule). A new
  /// attempt is a new run: a reader draws it from the start. (Of N masses: the first run's.)
  int attempt = 0;
  /// why the run was raised (the contact double could not decide); empty when it was not
  std::string precisionNote;
  std::shared_ptr<const AccuracyProgress> accuracy;  ///< the sweep so far
  std::optional<MapProgress> map;  ///< the map so far; rows below its rowsDone are final
};

/// Computes `spec`, reporting as it goes; the last report has `final` set (also when stopped,
/// with the run cancelled). Returns that last report.
/// (Of chains of N masses: a report about every chunk of work with the runs so far, the first
/// run whole before its contrasts; stopped, the last run reported is cancelled or missing.)
Update run(const Spec& spec, std::stop_token stop, const Options& options,
           const std::function<void(const Update&)>& report);

/// Copies a run's present totals (everything but its item lists: time, final state, energy,
/// cost, stop reason, message), as a chunk carries them.
void copyTotals(const Result& from, Result& to);

}  // namespace grazelab::core::experiments
