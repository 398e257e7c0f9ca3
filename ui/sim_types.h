// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QMetaType>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>

#include "core/methods/work_precision.h"
#include "core/simulate.h"
#include "core/maps.h"
#include "core/trust.h"
#include "ui/derived.h"
#include "ui/figures.h"
#include "ui/params.h"

namespace grazelab::ui {

/// The work-precision sweep a scene asks for beside its exact run (the Accuracy scene): every
/// setting is run on the same start, up to half a period past the exact run's last contact.
struct AccuracyJob {
  std::vector<core::methods::MethodSetting> settings;
  core::methods::TimingPolicy timing{1, 0.5, 0.0, 1};
  /// per run: a long horizon ends some runs on their budget (shown) rather than hold the sweep
  core::methods::WorkBudget budget{200'000'000, 1.0};
};

/// One finished setting of the sweep, with its run (events and samples over the trace's
/// window) for the overlay on u2(t).
struct AccuracyPoint {
  core::methods::WorkPrecisionPoint point;
  std::shared_ptr<const core::Result> run;
};

/// The sweep so far.
struct AccuracyProgress {
  std::vector<AccuracyPoint> points;
  std::size_t total = 0;  ///< settings asked for
  double tEnd = 0;        ///< the end of the comparison [time]
};

/// The landscape scene's map, computed by the worker after the run, on all cores.
struct MapJob {
  core::MapSpec spec;
};

/// A map as it is being computed: the worker fills `points` row after row and publishes how
/// many rows are done with each update; a reader looks only at the rows below that count (the
/// worker never writes them again), so the grid is shared without copies.
struct MapProgress {
  core::MapSpec spec;
  std::shared_ptr<std::vector<core::PointSummary>> points;  ///< y.count x x.count, row-major
  std::int64_t rowsDone = 0;
  bool complete = false;
  double seconds = 0;  ///< computing time so far
};

/// What a scene computes for its parameters: its own curves and surveys, the run (model and
/// request) and what goes with it, or why there is nothing to run.
struct SceneJob {
  bool ok = false;
  QString message;  ///< why not ok
  QStringList notes;  ///< what the user should know about the start (core's makeStart notes)
  core::Model model;
  core::Request request;
  std::optional<core::State> reference;  ///< a state on H worth marking (e.g. GLO_lambda* data)
  QString referenceLabel;
  std::optional<AccuracyJob> accuracy;  ///< the work-precision sweep, when the scene shows it
  std::optional<MapJob> map;            ///< the landscape's map, when the scene shows it
  Figures figures;  ///< curves the scene computed itself (one per CurvePlot it shows)
  /// slider ranges that depend on the chain (the admissible T/T2 of the 1IPP family)
  std::map<ParamKey, std::pair<double, double>> sliderRanges;
};

/// One computation asked of the worker, as a value. The controller stamps the id.
///
/// The GUI thread only describes it (scene, parameters, derived chain): `prepare` is the
/// scene's own computation and runs on the worker, which stores what it gives in `job` before
/// the run, so that no scene can stall the window and latest-wins covers all of its work.
struct SimRequest {
  std::uint64_t id = 0;
  Params params;       ///< the parameters that produced it (for the display and snapshots)
  QString sceneName;
  DerivedModel derived;  ///< the chain of `params`, as the panel derived it
  /// the scene's computation; empty when `job` is already set (tests and benchmarks)
  std::function<SceneJob(std::stop_token)> prepare;
  SceneJob job;  ///< what the scene computed (filled by the worker from `prepare`)
};

/// Copies a run's present totals (everything but its item lists: time, final state, energy,
/// cost, stop reason, message), as a partial update's chunk carries them.
inline void copyTotals(const core::Result& from, core::Result& to) {
  to.samplesTruncated = from.samplesTruncated;
  to.tFinal = from.tFinal;
  to.final = from.final;
  to.initialEnergy = from.initialEnergy;
  to.cost = from.cost;
  to.stop = from.stop;
  to.message = from.message;
}

/// A partial or final result coming back from the worker, as a value. The result is shared
/// read-only between the worker's copy and the display, never written after it is sent.
struct SimUpdate {
  std::uint64_t id = 0;
  /// The run so far. A partial update leaves the worker without it, carrying only `chunk`;
  /// the controller appends the chunk to its copy of the run (on the GUI thread, where the
  /// views read it) and sets this. The final update carries the worker's whole result.
  std::shared_ptr<const core::Result> result;
  /// What the run added since the worker's previous report: the new events, points, flights
  /// and samples, and the run's present totals (time, state, cost, stop reason).
  std::shared_ptr<const core::Result> chunk;
  double progress = 0;  ///< fraction of the requested work done, [0, 1]
  bool final = false;   ///< the run is over (complete, cancelled or invalid)
  /// the run itself is over and this update carries all of it; a sweep or map after it may
  /// still be going (final is then false)
  bool runDone = false;
  std::shared_ptr<const SimRequest> request;  ///< what was asked
  std::optional<core::Trust> trust;  ///< the error estimate, on the final update
  /// the final result, sent before its error estimate; another final update with the same
  /// result and its trust follows (the plots need not wait for the shadow run)
  bool trustPending = false;
  /// 0: the run as computed in double; 1 or 2: the run again in long double or binary128 from
  /// its start, because double met a contact it cannot decide (--precision auto's rule). A new
  /// attempt is a new run for the views: they draw it from the start.
  int attempt = 0;
  /// Why the run was raised (the contact double could not decide); empty when it was not.
  std::string precisionNote;
  std::shared_ptr<const AccuracyProgress> accuracy;  ///< the sweep so far (Accuracy scene)
  /// the map so far (landscape scene); rows below its rowsDone are final
  std::optional<MapProgress> map;
};

}  // namespace grazelab::ui

Q_DECLARE_METATYPE(grazelab::ui::SimUpdate)
