// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>

#include <algorithm>
#include <cmath>

#include "core/experiments/theorem_surveys.h"
#include "core/orbits/special_orbits.h"
#include "ui/scenes/scenes.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::PerturbationScene", text);
}

constexpr int kSpreadContacts = 200;  // contacts per push size in the spread curve

// max over the first contacts of 1 - FFT/T2 after a push of size epsilon (its sign and
// direction from the panel); 0 when no flight ended (no contact) or all lasted T2 exactly
double spreadAfterPush(const DerivedModel& derived, const Params& params, double epsilon,
                       std::stop_token stop) {
  Params pushed = params;
  pushed.perturbation = std::copysign(epsilon, params.perturbation == 0 ? -1.0 : params.perturbation);
  const core::State start = perturbed(core::gloData(derived.model, derived.modes, params.lambda), pushed);
  return core::experiments::largestShortfall(derived.model, start, kSpreadContacts, stop).value_or(0.0);
}

CurveFigure spreadFigure(const DerivedModel& derived, const Params& params, std::stop_token stop) {
  CurveFigure figure;
  figure.title = tr("Theorem 2.2: free-flight time (FFT) below T₂ against the push |δ|");
  figure.xTitle = tr("log₁₀ |δ| (push)");
  figure.yTitle = tr("log₁₀ max (1 − FFT/T₂)");
  figure.toolTip = tr("For pushes of size |δ| off GLO(λ) (in the panel's direction), the largest "
                      "shortfall 1 − FFT/T₂ over the first %1 contacts. It shrinks with |δ|: "
                      "near a grazing orbit every free flight lasts almost T₂ and never more "
                      "(Theorem 2.2; GLOM₁, λ = 0, is the exception).")
                      .arg(kSpreadContacts);
  figure.curveName = tr("first %1 contacts").arg(kSpreadContacts);
  for (int step = 0; step <= 24 && !stop.stop_requested(); ++step) {
    const double exponent = -7.0 + 0.25 * step;
    const double spread = spreadAfterPush(derived, params, std::pow(10.0, exponent), stop);
    if (spread > 0) figure.curve.emplace_back(exponent, std::log10(spread));
  }
  const double size = std::abs(params.perturbation);
  const double current = size > 0 ? spreadAfterPush(derived, params, size, stop) : 0;
  if (current > 0) {
    figure.markerName = tr("|δ| = %1").arg(size, 0, 'g', 3);
    figure.markers = {QPointF(std::log10(size), std::log10(current))};
  }
  return figure;
}

}  // namespace

Scene::Spec perturbationScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Theorem 2.2: perturbations of a grazing orbit");
  scene.alias = QStringLiteral("perturbations");
  scene.title = tr("Theorem 2.2: perturbations of a grazing orbit");
  scene.text = tr("<b>Pushed a little off a grazing orbit.</b> A push δ (the panel's "
                  "perturbation) sends GLO(λ) into the stop. <i>Look for:</i> every free-flight time "
                  "(left) stays at or just below T₂, and (top right) the largest shortfall "
                  "1 − FFT/T₂ shrinks steadily with |δ|. <i>Why:</i> the motion stays close to "
                  "a T₂-periodic grazing orbit, and a contact cannot come later than T₂ "
                  "(Theorem 2.2). Try λ = 0 (GLOM₁), the exception.");
  scene.defaults.lambda = 0.5;
  scene.defaults.perturbation = -0.001;
  scene.defaults.direction = PerturbDirection::V2;
  scene.defaults.horizon = 200;
  scene.parameters = {ParamKey::Lambda, ParamKey::M1, ParamKey::M2,           ParamKey::Gap,
                      ParamKey::K1,     ParamKey::K2, ParamKey::Perturbation, ParamKey::Horizon};
  scene.plots = {PlotKind::FreeFlight, PlotKind::SpreadAgainstSize, PlotKind::Trace};
  scene.build = [](const Scene& self, const Params& params, const DerivedModel& derived,
                  std::stop_token stop) {
    SceneJob job = gloStartJob(self, params, derived, 40 * derived.modes.T2);
    job.figures[PlotKind::SpreadAgainstSize] = spreadFigure(derived, params, stop);
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
