// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QList>
#include <QString>

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <vector>

#include "core/orbits/chain_atlas.h"
#include "core/orbits/modes_atlas.h"
#include "core/orbits/starts.h"
#include "core/solver/simulate.h"
#include "ui/compute/derived.h"
#include "ui/compute/figures.h"
#include "ui/compute/params.h"
#include "ui/compute/sim_types.h"

namespace grazelab::ui {

/// What scenes keep from one computation to the next, owned by the window and handed to each
/// computation it asks the worker for: the last atlas of modes of two masses and of N, which
/// depend on the chain only (moving a slider along it, the run's length or a click gets it again
/// at once), with their figures. The lock: a test may compute on a thread of its own while the
/// worker computes.
struct SceneCache {
  std::mutex mutex;
  std::optional<core::Model> atlasModel;
  std::shared_ptr<const core::ModesAtlas<double>> atlas;
  std::shared_ptr<const AtlasFigure> atlasFigure;
  std::optional<core::MassChain> chainAtlasChain;
  std::shared_ptr<const core::ChainAtlas<double>> chainAtlas;
  std::shared_ptr<const AtlasFigure> chainAtlasFigure;
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
    /// a scene of a chain of N masses: the panel edits Params::massChain (ChainEditor) instead
    /// of the two-mass chain
    bool massChain = false;
    /// the N-mass scene starts on a grazing linear orbit of the editor's weights (shown)
    bool gloWeights = true;
    QList<PlotKind> plots;
    /// everything the scene computes for these parameters (derived.ok is true): its curves,
    /// surveys and the run's start. Called by the worker, never on the GUI thread; long loops
    /// end early when `stop` is requested.
    std::function<SceneJob(const Scene&, const Params&, const DerivedModel&, std::stop_token stop)>
        build;
    /// instead of `build`, for a scene whose computation depends on a start chosen with the
    /// mouse (the Nonlinear modes scene: the orbit clicked); `clicked` is empty otherwise
    std::function<SceneJob(const Scene&, const Params&, const DerivedModel&,
                           const std::optional<core::ChainState>& clicked, std::stop_token stop,
                           const ScenePartial& partial, SceneCache& cache)>
        buildFromStart;
  };

  explicit Scene(Spec spec) : m_spec(std::move(spec)) {}
  QString name() const { return m_spec.name; }
  QString alias() const { return m_spec.alias; }
  QString title() const { return m_spec.title; }
  QString description() const { return m_spec.text; }
  Params defaults() const { return m_spec.defaults; }
  QList<ParamKey> parameters() const { return m_spec.parameters; }
  bool massChain() const { return m_spec.massChain; }
  bool gloWeights() const { return m_spec.gloWeights; }
  QList<PlotKind> plots() const { return m_spec.plots; }
  /// `cache`: what the scene kept from before (none: it starts afresh).
  SceneJob build(const Params& params, const DerivedModel& derived, std::stop_token stop = {},
                 const std::optional<core::ChainState>& clicked = std::nullopt,
                 const ScenePartial& partial = {}, SceneCache* cache = nullptr) const {
    if (m_spec.buildFromStart) {
      SceneCache fresh;
      return m_spec.buildFromStart(*this, params, derived, clicked, stop, partial, cache ? *cache : fresh);
    }
    return m_spec.build(*this, params, derived, stop);
  }

 private:
  Spec m_spec;
};

/// The grid of a chain's whole run (W): at most this many points (~15 MB for eight masses), at
/// the step of the scene's window.
constexpr int kWholeRunGridPoints = 100'000;

/// The needs implied by a set of visible plots: dense samples only for traces and phase
/// portraits (over the first `sampleWindow` time units), Poincaré points and free flights only
/// when plotted.
core::Needs needsFor(const QList<PlotKind>& plots, const core::Modes& modes, double sampleWindow);

/// The parameters a scene runs with when it is entered: its own settings (start, push, length,
/// map region) as it last had them, on the chain the user was looking at (the chain is shared
/// on purpose: it is what the scenes compare). The chain of N masses of the N-mass scenes is
/// their own (a string of eight masses, a 1:3 pair, three masses in 1:2:3) and stays with them.
Params enterScene(const Params& own, const Params& chain);

/// The start most scenes share: GLO(lambda) data pushed by the panel's perturbation, run for
/// the panel's number of contacts with the needs of the scene's views over `sampleWindow`, and
/// the GLO data marked on H.
SceneJob gloStartJob(const Scene& scene, const Params& params, const DerivedModel& derived,
                     double sampleWindow);

/// GLO(lambda) data pushed by the panel's perturbation, made by core's makeStart (as the
/// command line makes it), with its notes; or why there is none.
core::StartOrProblem<double> gloStart(const core::Model& model, const Params& params);

/// Applies the signed perturbation along its direction.
core::State perturbed(core::State state, const Params& params);

/// The key that chooses the scene at `index` (0-based) in the menu order: Ctrl+1 ... Ctrl+9,
/// then Ctrl+M for the tenth (Ctrl+0 resets the view), then Alt+1 ... Alt+9; empty beyond.
QString sceneShortcut(int index);

/// All scenes, in menu order (the first is the default).
std::vector<std::unique_ptr<Scene>> makeScenes();

/// Finds a scene by its name (case-insensitive) or by a short alias ("grazing", "near-grazing",
/// "1ipp"); -1 when none matches.
int findScene(const std::vector<std::unique_ptr<Scene>>& scenes, const QString& name);

}  // namespace grazelab::ui
