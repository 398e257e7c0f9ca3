// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QList>
#include <QString>

#include <functional>
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
  std::optional<MapJob> map;            ///< the landscape's map, when the scene shows it
  Figures figures;  ///< curves the scene computed itself (one per CurvePlot it shows)
  /// slider ranges that depend on the chain (the admissible T/T2 of the 1IPP family)
  std::map<ParamKey, std::pair<double, double>> sliderRanges;
};

/// A named preset: which parameters are exposed, which views are shown, and so what is
/// computed. Scenes are data: a Spec each, made by one function in its own file under
/// ui/scenes/ and listed once in the table of makeScenes().
class Scene {
 public:
  struct Spec {
    QString name;   ///< stable English name, used on the command line and in session files
    QString alias;  ///< short name for the command line ("grazing")
    QString title;  ///< translated name for menus
    /// what to look for and why, for students (rich text), beside the plots and in the README
    QString text;
    Params defaults;
    QList<ParamKey> parameters;
    QList<PlotKind> plots;
    /// the run for these parameters (derived.ok is true)
    std::function<SceneJob(const Scene&, const Params&, const DerivedModel&)> build;
  };

  explicit Scene(Spec spec) : m_spec(std::move(spec)) {}
  QString name() const { return m_spec.name; }
  QString alias() const { return m_spec.alias; }
  QString title() const { return m_spec.title; }
  QString description() const { return m_spec.text; }
  Params defaults() const { return m_spec.defaults; }
  QList<ParamKey> parameters() const { return m_spec.parameters; }
  QList<PlotKind> plots() const { return m_spec.plots; }
  SceneJob build(const Params& params, const DerivedModel& derived) const {
    return m_spec.build(*this, params, derived);
  }

 private:
  Spec m_spec;
};

/// The needs implied by a set of visible plots: dense samples only for traces and phase
/// portraits (over the first `sampleWindow` time units), Poincaré points and free flights only
/// when plotted.
core::Needs needsFor(const QList<PlotKind>& plots, const core::Modes& modes, double sampleWindow);

/// The parameters a scene runs with when it is entered: its own settings (start, push, length,
/// map region) as it last had them, on the chain the user was looking at (the chain is shared
/// on purpose: it is what the scenes compare).
Params enterScene(const Params& own, const Params& chain);

/// The start most scenes share: GLO(lambda) data pushed by the panel's perturbation, run for
/// the panel's number of contacts with the needs of the scene's views over `sampleWindow`, and
/// the GLO data marked on H.
SceneJob gloStartJob(const Scene& scene, const Params& params, const DerivedModel& derived,
                     double sampleWindow);

/// Applies the signed perturbation along its direction.
core::State perturbed(core::State state, const Params& params);

/// All scenes, in menu order (the first is the default).
std::vector<std::unique_ptr<Scene>> makeScenes();

/// Finds a scene by its name (case-insensitive) or by a short alias ("grazing", "near-grazing",
/// "1ipp"); -1 when none matches.
int findScene(const std::vector<std::unique_ptr<Scene>>& scenes, const QString& name);

}  // namespace grazelab::ui
