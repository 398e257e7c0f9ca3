// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QList>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

#include "core/simulate.h"
#include "ui/derived.h"
#include "ui/figures.h"
#include "ui/params.h"
#include "ui/sim_types.h"

namespace grazelab::ui {


/// What a scene asks the worker to compute, or why it cannot.
struct SceneJob {
  bool ok = false;
  QString message;  ///< why not ok
  core::Model model;
  core::Request request;
  std::optional<core::State> reference;  ///< a state on H worth marking (e.g. GLO_lambda* data)
  QString referenceLabel;
  std::optional<AccuracyJob> accuracy;  ///< the work-precision sweep, when the scene shows it
  Figures figures;  ///< curves the scene computed itself (one per CurvePlot it shows)
  /// slider ranges that depend on the chain (the admissible T/T2 of the 1IPP family)
  std::map<ParamKey, std::pair<double, double>> sliderRanges;
};

/// A named preset: which parameters are exposed, which plots are shown, and so what is computed.
/// Adding a scene is one new file in ui/scenes/ plus one line in makeScenes().
class Scene {
 public:
  virtual ~Scene() = default;
  /// Stable English name, used on the command line and in session files.
  virtual QString name() const = 0;
  /// Short alias for the command line ("grazing").
  virtual QString alias() const = 0;
  /// Translated name for menus.
  virtual QString title() const = 0;
  /// One or two sentences on what the scene shows.
  virtual QString description() const = 0;
  virtual Params defaults() const = 0;
  virtual QList<ParamKey> parameters() const = 0;
  virtual QList<PlotKind> plots() const = 0;
  /// The parameters this scene keeps for itself when the user switches scenes; the others (the
  /// chain and the start) belong to the session and carry over. By default the run's length
  /// and the 1IPP period are the scene's own.
  virtual QList<ParamKey> ownKeys() const { return {ParamKey::Horizon, ParamKey::Period}; }
  /// The run for these parameters (derived.ok is true).
  virtual SceneJob build(const Params& params, const DerivedModel& derived) const = 0;
};

/// The needs implied by a set of visible plots: dense samples only for traces and phase
/// portraits (over the first `sampleWindow` time units), Poincaré points and free flights only
/// when plotted.
core::Needs needsFor(const QList<PlotKind>& plots, const core::Modes& modes, double sampleWindow);

/// The parameters a scene runs with when it is entered: the session's chain and start, the
/// scene's own values for its ownKeys().
Params enterScene(const Scene& scene, const Params& session, const Params& own);

/// Applies the signed perturbation along its direction.
core::State perturbed(core::State state, const Params& params);

/// All scenes, in menu order (the first is the default).
std::vector<std::unique_ptr<Scene>> makeScenes();

/// Finds a scene by its name (case-insensitive) or by a short alias ("grazing", "near-grazing",
/// "1ipp"); -1 when none matches.
int findScene(const std::vector<std::unique_ptr<Scene>>& scenes, const QString& name);

}  // namespace grazelab::ui
