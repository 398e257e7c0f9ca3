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

#include "core/experiments/run.h"
#include "core/solver/chain_flight.h"
#include "ui/compute/atlas_figure.h"
#include "ui/compute/derived.h"
#include "ui/compute/figures.h"
#include "ui/compute/params.h"

namespace grazelab::ui {

// The experiment's parts, as the views read them (core/experiments/run.h).
using core::experiments::AccuracyPoint;
using core::experiments::AccuracyProgress;
using core::experiments::MapProgress;

/// A view's title and tooltip as a scene words them for one job, over the view's own.
struct ViewWords {
  QString title;
  QString toolTip;
  QString whyEmpty = {};  ///< said in place of the view when the job gives it nothing to draw
};

/// The time unit a scene gives its run views for one job (the 1IPP orbit's own period), over
/// the chain's period.
struct TimeUnit {
  double length = 0;  ///< [time]
  QString name;       ///< on an axis: "T"
  QString inWords;    ///< in a sentence: "the orbit's period T"
};

/// What an N-mass scene says of its chain under the chain editor: what it is (its springs,
/// frequencies and their ratio, period) or why there is none (`refused`), and how many designs
/// its resonance has.
struct ChainWords {
  QString summary;
  int designs = 0;
  bool refused = false;
};

/// What a scene computes for its parameters: the experiment (core's description of the run and
/// the sweep or map after it), the curves and surveys it computed itself, worded for its
/// views, or why there is nothing to run.
struct SceneJob {
  bool ok = false;
  QString message;  ///< why not ok
  QStringList notes;  ///< what the user should know about the start (core's makeStart notes)
  core::experiments::Spec spec;  ///< what the worker computes after the scene's own curves
  std::optional<core::State> reference;  ///< a state on H worth marking (e.g. GLO_lambda* data)
  QString referenceLabel;
  Figures figures;  ///< curves the scene computed itself (one per CurvePlot it shows)
  /// the atlas of the chain's periodic impacting families (the modes scenes), as drawn
  std::shared_ptr<const AtlasFigure> atlas;
  /// the periodic orbit the run follows, with its multipliers (the modes scenes)
  std::optional<ShownOrbit> orbit;
  /// slider ranges that depend on the chain (the admissible T/T2 of the 1IPP family)
  std::map<ParamKey, std::pair<double, double>> sliderRanges;
  /// the scene's words for some of its views, over theirs (the run views' presentation)
  std::map<PlotKind, ViewWords> viewWords;
  /// the run views' time unit, when not the chain's period
  std::optional<TimeUnit> timeUnit;
  /// the mass whose portrait the run views draw beside the stopped one (1-based: the scene's
  /// 'phase of'); 0: the stopped mass alone
  int chosenMass = 0;
  /// the coordinates the section H is drawn on, 1-based in the state (u1..uN, v1..vN: the
  /// scene's 'section on'); 0: mass 1's (u, v), or mass 2's when mass 1 is the stopped one
  std::pair<int, int> sectionOn = {0, 0};
  /// the N-mass scenes: the chain editor's words (ChainWords)
  ChainWords chain;
  /// the N-mass scenes' own words for the status line, before the run's (what the start is)
  QString status;
};

/// What a scene's own computation has so far, with the fraction of it done (0 when unknown).
using ScenePartial = std::function<void(const SceneJob& sofar, double progress)>;

/// One computation asked of the worker, as a value. The controller stamps the id.
///
/// The GUI thread only describes it (scene, parameters, derived chain): `prepare` is the
/// scene's own computation and runs on the worker, which stores what it gives in `job` before
/// the run, so that no scene can stall the window and latest-wins covers all of its work.
struct SimRequest {
  std::uint64_t id = 0;
  Params params;       ///< the parameters that produced it (for the display and snapshots)
  QString sceneName;
  /// a start chosen with the mouse (on H, the stop line, the map, the modes picture): the run
  /// starts there instead of the scene's own start; part of what reproduces the run. A chain's
  /// state: two masses' (core::chainStateOf) as N masses'
  std::optional<core::ChainState> clickedStart;
  DerivedModel derived;  ///< the chain of `params`, as the panel derived it
  /// the scene's computation; empty when `job` is already set (tests and benchmarks). A long
  /// one may show what it has so far through `partial` (the modes atlas, family by family).
  std::function<SceneJob(std::stop_token, const ScenePartial& partial)> prepare;
  SceneJob job;  ///< what the scene computed (filled by the worker from `prepare`)
};

/// A report of the experiment coming back from the worker, as a value (core's report, with
/// what was asked). Shared parts are read-only once sent. A partial report leaves the worker
/// with only `chunk`: the controller appends it to its copy of the run (on the GUI thread,
/// where the views read it) and sets `result`.
struct SimUpdate : core::experiments::Update {
  std::uint64_t id = 0;
  std::shared_ptr<const SimRequest> request;  ///< what was asked
  /// the scene's own computation so far (request->job holds it), before the run: no run yet
  /// (result is empty); only the views that draw the scene's data take it
  bool scenePartial = false;
  /// the whole run of an older request, shown while a newer one computes (during a drag, each
  /// job younger than the controller's grace runs to its end and is drawn: see
  /// SimController::setGrace); the newer request's results follow
  bool superseded = false;
};

}  // namespace grazelab::ui

Q_DECLARE_METATYPE(grazelab::ui::SimUpdate)
