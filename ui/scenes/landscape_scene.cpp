// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>

#include "core/orbits/special_orbits.h"
#include "ui/scenes/scenes.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::LandscapeScene", text);
}

// cells per side of the map: 65 536 runs, about a tenth of a second on two cores
constexpr std::int64_t kResolution = 256;
// contacts of each run of the map: the first flight and a few more for min, max and mean
constexpr std::int64_t kMapContacts = 10;

}  // namespace

core::MapSpec landscapeSpec(const Params& params, const DerivedModel& derived) {
  core::MapSpec spec;
  spec.model = derived.model;
  const double d = derived.model.gap;
  const double v = d * derived.modes.omegaSlow;
  const Params::MapRegion& r = params.mapRegion;
  spec.x = {core::MapVariable::U1, r.u1From * d, r.u1To * d, kResolution};
  spec.y = {core::MapVariable::V1, r.v1From * v, r.v1To * v, kResolution};
  spec.contacts = kMapContacts;
  return spec;
}

Scene::Spec landscapeScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Landscape: free flights over the grazing-start plane");
  scene.alias = QStringLiteral("landscape");
  scene.title = tr("Landscape: free flights over the grazing-start plane");
  scene.text = tr("<b>Every start on the stop at once.</b> Each point of the map is a start with "
                  "mass 2 on the stop at rest (u₂ = d, v₂ = 0) and mass 1 at (u₁, v₁), run for "
                  "10 contacts. <i>Look for:</i> the bright region where the first flight lasts "
                  "T₂ exactly — starts whose linear motion never crosses the stop, with the "
                  "grazing family GLO(λ) (dashed) across it — and everywhere else flights shorter "
                  "than T₂; to the right of u₁ = d mass 1 presses mass 2 on the stop and it sticks "
                  "first. Click a point for its run (its contacts appear on the map); drag a "
                  "rectangle to compute that region anew. <i>Why:</i> every free motion repeats "
                  "after T₂, so no flight from the stop can last longer (Theorem 2.3).");
  scene.defaults.lambda = 0.5;
  scene.defaults.perturbation = -0.05;
  scene.defaults.horizon = 200;
  scene.parameters = {ParamKey::Lambda, ParamKey::M1,           ParamKey::M2,     ParamKey::Gap,
                      ParamKey::K1,     ParamKey::Perturbation, ParamKey::Horizon};
  scene.plots = {PlotKind::Landscape, PlotKind::Trace, PlotKind::Phase};
  scene.build = [](const Scene& self, const Params& params, const DerivedModel& derived,
                  std::stop_token) {
    SceneJob job = gloStartJob(self, params, derived, 30 * derived.modes.T2);
    if (!derived.model.design) {
      job.ok = false;
      job.message = tr("the landscape needs the 1:2 resonant chain: tick the 1:2 design");
      return job;
    }
    job.spec.map = landscapeSpec(params, derived);
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
