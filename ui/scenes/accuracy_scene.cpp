// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/scenes/scenes.h"

#include <QCoreApplication>

#include "core/methods/work_precision.h"
#include "core/orbits/special_orbits.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::AccuracyScene", text);
}

}  // namespace

Scene::Spec accuracyScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Accuracy: methods against the exact solver");
  scene.alias = QStringLiteral("accuracy");
  scene.title = tr("Accuracy: methods against the exact solver");
  scene.text = tr("<b>How good is a numerical method?</b> The standard methods of nonsmooth "
                  "mechanics (Moreau–Jean, Schatzman–Paoli, event-driven Runge–Kutta, CVODE, a "
                  "penalty spring) run on the same start at several step sizes or tolerances. "
                  "<i>Look for:</i> each method's error against its run time (right), and the "
                  "exact solver far below and to the left. Pick a run to draw its u₂(t) over "
                  "the exact motion: missed or extra contacts show as gaps and spikes. "
                  "<i>Why:</i> near grazing a small error in a contact time changes which "
                  "contacts happen at all.");
  scene.defaults.lambda = 0.5;
  scene.defaults.perturbation = -0.05;
  scene.defaults.direction = PerturbDirection::V2;
  scene.defaults.horizon = 50;
  scene.parameters = {ParamKey::Lambda, ParamKey::M1, ParamKey::M2,           ParamKey::Gap,
                      ParamKey::K1,     ParamKey::K2, ParamKey::Perturbation, ParamKey::Horizon};
  scene.plots = {PlotKind::Trace, PlotKind::WorkPrecision};
  scene.build = [](const Scene& self, const Params& params, const DerivedModel& derived,
                  std::stop_token) {
    // the trace shows the whole comparison: it is what the overlay is drawn on
    SceneJob job = gloStartJob(self, params, derived, (params.horizon + 1) * derived.modes.T2);
    core::experiments::AccuracySweep accuracy;
    for (core::methods::MethodKind kind : core::methods::kAllMethods) {
      for (const auto& setting :
           core::methods::reportSettings(kind, derived.modes.T2, derived.model.k1, true)) {
        accuracy.settings.push_back(setting);
      }
    }
    job.spec.accuracy = std::move(accuracy);
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
