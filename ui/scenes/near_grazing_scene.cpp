// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>

#include "core/orbits/special_orbits.h"
#include "ui/scenes/scenes.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::NearGrazingScene", text);
}

}  // namespace

Scene::Spec nearGrazingScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Near grazing: Poincaré points on H");
  scene.alias = QStringLiteral("near-grazing");
  scene.title = tr("Near grazing: Poincaré points on H");
  scene.text = tr("<b>Many contacts near a grazing orbit.</b> A start just off GLO(λ), followed "
                  "for 10 000 contacts. <i>Look for:</i> the points (u₁, v₁) of mass 1 at each "
                  "contact (left) stay on a closed curve around the grazing data (square), and "
                  "the free-flight times (top right) never pass the dashed line T₂. <i>Why:</i> "
                  "between contacts the motion is linear and repeats after T₂, so it must be "
                  "back on the stop by then (Theorem 2.3).");
  scene.defaults.lambda = 0.5;
  scene.defaults.perturbation = -0.01;
  scene.defaults.direction = PerturbDirection::V2;
  scene.defaults.horizon = 10000;
  scene.parameters = {ParamKey::Lambda, ParamKey::M1, ParamKey::M2,           ParamKey::Gap,
                      ParamKey::K1,     ParamKey::K2, ParamKey::Perturbation, ParamKey::Horizon};
  scene.plots = {PlotKind::Poincare, PlotKind::FreeFlight, PlotKind::Trace};
  scene.build = [](const Scene& self, const Params& params, const DerivedModel& derived,
                  std::stop_token) {
    // the trace is a glance at the first periods only; the section is the point of the scene
    return gloStartJob(self, params, derived, 30 * derived.modes.T2);
  };
  return scene;
}

}  // namespace grazelab::ui
