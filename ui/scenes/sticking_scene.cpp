// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>

#include "core/orbits/special_orbits.h"
#include "ui/scenes/scenes.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::StickingScene", text);
}

}  // namespace

Scene::Spec stickingScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Sticking: a start pressed on the stop");
  scene.alias = QStringLiteral("sticking");
  scene.title = tr("Sticking: a start pressed on the stop");
  scene.text = tr("<b>Pressed on the stop.</b> For λ beyond 4/3 the grazing data put mass 1 "
                  "past the gap (u₁ > d): its spring pushes mass 2 into the stop. <i>Look "
                  "for:</i> u₂(t) stays flat on the stop (orange triangle: stick) until the push "
                  "turns into a pull (release), then ordinary impacts follow. <i>Why:</i> the "
                  "stop can push but not pull, so mass 2 stays on it while the force points "
                  "into it; the motion then is that of mass 1 alone. At λ = 4/3 exactly the "
                  "force is zero (u₁ = d): the border.");
  scene.defaults.lambda = 1.9;
  scene.defaults.perturbation = 0;
  scene.defaults.horizon = 12;
  scene.parameters = {ParamKey::Lambda, ParamKey::M1, ParamKey::M2, ParamKey::Gap,
                      ParamKey::K1,     ParamKey::K2, ParamKey::Horizon};
  scene.plots = {PlotKind::Trace, PlotKind::Chain, PlotKind::Phase, PlotKind::PhaseU1V1};
  scene.build = [](const Scene& self, const Params& params, const DerivedModel& derived,
                  std::stop_token) {
    SceneJob job;
    job.spec.model = derived.model;
    Params pressed = params;
    pressed.perturbation = 0;  // unperturbed: the press is the point
    const core::StartOrProblem<double> made = gloStart(derived.model, pressed);
    if (!made.start) {
      job.message = QString::fromStdString(made.problem);
      return job;
    }
    const core::State start = made.start->state;
    job.spec.run.initial = start;
    job.spec.run.maxContacts = std::int64_t(params.horizon);
    job.spec.run.needs = needsFor(self.plots(), derived.modes, 400 * derived.modes.T2);
    job.reference = start;
    job.referenceLabel = tr("GLO(λ) data");
    job.ok = true;
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
