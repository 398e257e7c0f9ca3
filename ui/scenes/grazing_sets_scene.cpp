// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/experiments/chain_series.h"
#include "core/orbits/chain_glo.h"
#include "ui/scenes/mass_chain_scenes.h"
#include "ui/scenes/scenes.h"
#include "ui/widgets/chain_editor.h"
#include "ui/widgets/param_specs.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::GrazingSetsScene", text);
}

QString number(double value, int digits = 6) { return QString::number(value, 'g', digits); }

QString verdictInWords(core::GloGrazing verdict) {
  switch (verdict) {
    case core::GloGrazing::Grazes:
      return tr("grazes: it touches the stop once a period and stays below it");
    case core::GloGrazing::Boundary:
      return tr("is on the set's edge: a touch within double's rounding");
    case core::GloGrazing::Crosses:
      return tr("crosses the stop: it is not a grazing orbit");
  }
  return {};
}

// Lemma 2.1 for two modes: the top of u_s/d over a period against the slow mode's weight
// (`name`: the panel's name of that weight, the slider it is moved by)
CurveFigure intervalFigure(int fast, int slow, const core::GrazingInterval& set, double lambda, const QString& name) {
  CurveFigure figure;
  const QString ratio = QStringLiteral("%1:%2").arg(slow).arg(fast);
  figure.title =
      tr("%1: GLO grazes for %2 in [%3, %4]").arg(ratio, name, number(set.low, 4), number(set.high, 4));
  figure.xTitle = tr("%1 (the slow mode's weight)").arg(name);
  figure.yTitle = tr("top of u / d over a period");
  figure.toolTip =
      tr("GLO(λ) = (1 − λ) GLOM(fast) + λ GLOM(slow). Its top over a period is 1 (it touches the "
         "stop and stays below) exactly on the grazing set, whose ends are certified (the "
         "note's [0, 4/3] for 1:2; [0, n²/(n² − 1)] for 1:n); elsewhere it passes the stop. Drag "
         "the dot, or click, to move the panel's λ.");
  const double width = set.high - set.low;
  const double from = std::min(-0.5, set.low - 0.25 * width),
               to = std::max(1.5, set.high + 0.25 * width);
  figure.curveName = tr("top of GLO(λ)");
  for (const auto& [x, top] : core::gloTopCurve(fast, slow, from, to, 240, 1024))
    figure.curve.emplace_back(x, top);
  figure.referenceName = tr("grazing set");
  figure.reference = {QPointF(set.low, 1), QPointF(set.high, 1)};
  figure.markerName = tr("%1 = %2").arg(name, number(lambda, 4));
  const auto here = core::gloTopCurve(fast, slow, lambda, lambda, 0, 4096);
  figure.markers = {QPointF(lambda, here.front().second)};
  double lowest = 1, highest = 1;
  for (const QPointF& point : figure.curve) {
    lowest = std::min(lowest, point.y());
    highest = std::max(highest, point.y());
  }
  figure.xMin = from;
  figure.xMax = to;
  figure.yMin = lowest - 0.05 * (highest - lowest);
  figure.yMax = highest + 0.05 * (highest - lowest);
  return figure;
}

// three modes: the region in the (λ2, λ3) plane, the pure modes and the weights asked for
CurveFigure regionFigure(const std::vector<int>& harmonics,
                         const std::vector<core::GrazingRegionPoint>& boundary, double lambda2,
                         double lambda3) {
  CurveFigure figure;
  figure.title = tr("%1:%2:%3: the weights that graze (inside)")
                     .arg(harmonics[2])
                     .arg(harmonics[1])
                     .arg(harmonics[0]);
  figure.xTitle = tr("λ₂");
  figure.yTitle = tr("λ₃");
  figure.toolTip =
      tr("GLO(λ) = λ₁ GLOM₁ + λ₂ GLOM₂ + λ₃ GLOM₃ with λ₁ = 1 − λ₂ − λ₃ grazes exactly inside this "
         "convex region (its boundary certified along rays from the centre); the simplex of "
         "non-negative weights is always inside. The ring is the weights of the panel: drag it, or "
         "click in the plane, to move them.");
  figure.curveName = tr("boundary of the grazing set");
  for (const core::GrazingRegionPoint& point : boundary)
    figure.curve.emplace_back(point.lambda2, point.lambda3);
  if (!figure.curve.empty()) figure.curve.push_back(figure.curve.front());  // closed
  figure.markerName = tr("pure modes GLOM₁, GLOM₂, GLOM₃");
  figure.markers = {QPointF(0, 0), QPointF(1, 0), QPointF(0, 1)};
  figure.referenceName = tr("the panel's weights");
  figure.reference = {QPointF(lambda2, lambda3)};
  return figure;
}

}  // namespace

Scene::Spec grazingSetsScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Grazing sets of other resonances");
  scene.alias = QStringLiteral("grazing-sets");
  scene.title = tr("Grazing sets of other resonances");
  scene.text =
      tr("<b>Lemma 2.1 for any resonance.</b> A weighted sum of the pure-mode grazing orbits, "
         "GLO(λ) = Σ λⱼ GLOMⱼ (weights summing to 1), touches the stop at t = 0. It is a grazing "
         "orbit when it never passes the stop over a period. <i>Look for:</i> with two modes, the "
         "top of u/d over a period against λ is 1 on an interval, the grazing set (for 1:2 the "
         "note's [0, 4/3], for 1:3 [0, 9/8]); with three, the weights that graze fill a convex "
         "region of the (λ₂, λ₃) plane. Move the weights (drag the point in the plot, or the panel's "
         "sliders): the orbit over one period (its trace and the chain) touches the stop, or passes it. <i>Why:</i> each phase of the "
         "period gives one linear condition on the weights, so the set is convex and holds every "
         "non-negative mix.");
  scene.defaults.perturbation = 0;
  scene.defaults.massChain.masses = {1.0, 0.3};
  scene.defaults.massChain.springs = {1.0, 1.0};
  scene.defaults.massChain.harmonics = {3, 1};
  scene.defaults.massChain.weights = {0.5, 0.5};
  scene.massChain = true;
  scene.parameters = {ParamKey::Gap};
  scene.plots = {PlotKind::GrazingSet, PlotKind::Trace, PlotKind::Chain};
  scene.build = [](const Scene&, const Params& params, const DerivedModel&, std::stop_token stop) {
    SceneJob job;
    const MassChainParams& given = params.massChain;
    const ChainChoice choice = chooseChain(given, params.gap, stop);
    if (!choice.chain) return refusedChainJob(choice.problem);
    const core::MassChain& chain = *choice.chain;
    const core::GrazingModes used = core::grazingModes(chain);
    if (!used.ratios.commensurate) {
      return refusedChainJob(
          tr("No grazing set: the modes that move the stopped mass are not commensurate (no common "
             "period). Pick a resonance."));
    }
    if (used.modes.size() < 2 || used.modes.size() > 3) {
      return refusedChainJob(
          tr("Grazing sets are drawn for two or three modes that move the stopped mass; this chain "
             "has %1.")
              .arg(used.modes.size()));
    }
    const core::ChainGloStart glo = core::chainGloStart(chain, given.weights);
    if (glo.problem != core::GloStartProblem::None) {
      return refusedStartJob(gloStartProblemInWords(glo.problem));
    }
    std::vector<double> weights;  // on the modes that move the stopped mass
    for (int mode : used.modes) weights.push_back(given.weights[std::size_t(mode)]);
    const std::vector<int>& harmonics = used.ratios.harmonics;
    const core::GloGrazing verdict = core::gloGrazing(harmonics, weights);
    if (used.modes.size() == 2) {
      job.figures[PlotKind::GrazingSet] =
          intervalFigure(harmonics[0], harmonics[1],
                         core::grazingInterval(harmonics[0], harmonics[1]), weights[1],
                         QStringLiteral("λ") + subscriptDigits(used.modes[1] + 1));
      job.figures[PlotKind::GrazingSet].draggedModes = used.modes;
    } else {
      const auto boundary = core::grazingRegion(harmonics[0], harmonics[1], harmonics[2], 48, stop);
      if (stop.stop_requested()) return job;
      job.figures[PlotKind::GrazingSet] = regionFigure(harmonics, boundary, weights[1], weights[2]);
      job.figures[PlotKind::GrazingSet].draggedModes = used.modes;
    }
    // the orbit itself over one period (unpushed: GLO(λ) as it is), every mass on the grid: the
    // linear motion, so that weights outside the set are seen to pass the stop
    const double period = 2 * std::numbers::pi / used.ratios.omega0;
    core::experiments::ChainSeriesSpec free{chain, glo.state, 1, period, 900, core::TrustMode::Off};
    free.free = true;
    job.spec.chains = {free};
    const core::ChainModes modes = core::chainModes(chain);
    job.chain.summary = chainSummaryOf(chain, given, choice.designs, modes, core::detectRatios(modes.omega));
    job.chain.designs = choice.designs;
    QStringList written;
    for (double w : weights) written.append(number(w, 4));
    job.status = tr("GLO with weights (%1) %2").arg(written.join(QStringLiteral(", ")), verdictInWords(verdict));
    // (the orbit's period: that of the modes it weighs, which a chain with no common period has too)
    job.timeUnit = TimeUnit{period, tr("T"), tr("the orbit's period T")};
    const int stopped = chain.stopped();
    job.viewWords[PlotKind::Trace] = {
        tr("GLO(λ) over one period: u%1 / d").arg(subscriptDigits(stopped)),
        tr("The stopped mass of GLO(λ) over its period T, the stop dashed: a grazing orbit stays "
           "at or below it and touches it at t = 0 and T; weights outside the set pass it (the "
           "linear motion is drawn, as if the stop were not there).")};
    job.ok = true;
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
