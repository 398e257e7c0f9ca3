// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>

#include <algorithm>

#include "core/experiments/theorem_surveys.h"
#include "core/orbits/special_orbits.h"
#include "ui/scenes/scenes.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::GrazingFamilyScene", text);
}

CurveFigure lemmaFigure(double lambda) {
  CurveFigure figure;
  figure.title = tr("Lemma 2.1: top of GLO(λ), max u₂ / d");
  figure.xTitle = tr("λ");
  figure.yTitle = tr("max u₂ / d");
  figure.toolTip = tr("The linear orbit (1 − λ) GLOM₁ + λ GLOM₂ reaches at most "
                      "max[(1 − λ) cos 2s + λ cos s] times the gap. It is exactly 1 (the orbit "
                      "touches the stop and stays below it: a grazing orbit) for λ in [0, 4/3]; "
                      "outside, the linear motion would pass through the stop.");
  figure.curveName = tr("max u₂ / d");
  constexpr int kPoints = 500;
  for (int i = 0; i <= kPoints; ++i) {
    const double x = -0.5 + 2.5 * i / kPoints;
    figure.curve.emplace_back(x, core::experiments::gloHighestReach(x));
  }
  figure.markerName = tr("λ = %1").arg(lambda, 0, 'g', 4);
  figure.markers = {QPointF(lambda, core::experiments::gloHighestReach(lambda))};
  figure.referenceName = tr("= 1 on [0, 4/3]: grazing");
  figure.reference = {QPointF(0, 1), QPointF(4.0 / 3.0, 1)};
  figure.xMin = -0.55;
  figure.xMax = 2.05;
  figure.yMin = 0.9;
  // the whole curve and the current lambda's dot inside the axes: a line past the plot's edge
  // ran over its title in SVG exports (Qt Charts clips on screen only)
  double top = 1.0;
  for (const QPointF& point : figure.curve) top = std::max(top, point.y());
  top = std::max(top, figure.markers.front().y());
  figure.xMin = std::min(figure.xMin, lambda - 0.05);
  figure.xMax = std::max(figure.xMax, lambda + 0.05);
  figure.yMax = top + 0.05 * (top - figure.yMin);
  return figure;
}

}  // namespace

Scene::Spec grazingFamilyScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Grazing family GLO_lambda");
  scene.alias = QStringLiteral("grazing");
  scene.title = tr("Lemma 2.1: the grazing family GLO(λ)");
  scene.text = tr("<b>Grazing orbits.</b> Each λ mixes the fast mode (1 − λ) and the slow mode "
                  "(λ) so that mass 2 just touches the stop. <i>Look for:</i> the orange-red dot on "
                  "the curve (top right) stays on the line 1 for λ in [0, 4/3]: the orbit "
                  "touches and stays below the stop. Outside that range the linear motion "
                  "would pass through the stop: for λ > 4/3 mass 2 starts pressed on it and "
                  "sticks. The push δ sends the start off the orbit so that it impacts; the "
                  "free-flight times stay at or below T₂. <i>Why:</i> every free motion repeats "
                  "after T₂ (ω₁ = 2 ω₂).");
  scene.defaults.lambda = 0.5;
  scene.defaults.perturbation = -0.05;
  scene.defaults.direction = PerturbDirection::V2;
  scene.defaults.horizon = 60;
  scene.parameters = {ParamKey::Lambda, ParamKey::M1, ParamKey::M2,           ParamKey::Gap,
                      ParamKey::K1,     ParamKey::K2, ParamKey::Perturbation, ParamKey::Horizon};
  scene.plots = {PlotKind::Trace, PlotKind::Chain,      PlotKind::GrazingMaximum,
                 PlotKind::Phase, PlotKind::FreeFlight, PlotKind::Poincare};
  scene.build = [](const Scene& self, const Params& params, const DerivedModel& derived,
                  std::stop_token) {
    // dense output over the whole run for short runs, over the first 400 T2 for long ones
    SceneJob job = gloStartJob(self, params, derived, 400 * derived.modes.T2);
    job.figures[PlotKind::GrazingMaximum] = lemmaFigure(params.lambda);
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
