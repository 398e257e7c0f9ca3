// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <cmath>

#include "core/experiments/chain_series.h"
#include "core/orbits/chain_glo.h"
#include "core/orbits/chain_onepp.h"
#include "ui/scenes/mass_chain_scenes.h"
#include "ui/scenes/scenes.h"
#include "ui/widgets/param_specs.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::ChainOnePeriodicScene", text);
}

QString number(double value, int digits = 4) { return QString::number(value, 'g', digits); }

// the family's admissible data against T/T*, the slider's orbit marked, the limit ringed at 1
CurveFigure familyFigure(const QString& title, const QString& yTitle, const QString& toolTip,
                         const std::vector<QPointF>& curve, const QPointF& here,
                         std::optional<QPointF> limit) {
  CurveFigure figure;
  figure.title = title;
  figure.xTitle = tr("T / T*");
  figure.yTitle = yTitle;
  figure.toolTip = toolTip;
  figure.curveName = tr("1IPP family");
  figure.curve = curve;
  figure.dots = true;  // separate orbits, and gaps where none is admissible
  figure.markerName = tr("the slider's T");
  figure.markers = {here};
  if (limit) {
    figure.referenceName = tr("grazing limit");
    figure.reference = {*limit};
  }
  return figure;
}

}  // namespace

Scene::Spec chainOnePeriodicScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("1IPP orbits of N masses near their grazing limit");
  scene.alias = QStringLiteral("chain-1ipp");
  scene.title = tr("1IPP orbits of N masses near their grazing limit");
  scene.text = tr(
      "<b>Theorem 2.1 for N masses.</b> A chain in 1:2:3 has, for each period T below its common "
      "period T*, a periodic motion with one impact per period (1IPP), in closed form. <i>Look "
      "for:</i> as T → T* the impact speed falls to 0 and the data after the impact tend to "
      "those of one grazing linear orbit (ringed at T/T* = 1), whose weights the theorem "
      "gives: a convex mix of the modes, each by its share aₛⱼ / ωⱼ². The slider's orbit "
      "over three periods (its trace, and the chain) impacts once a period. <i>Why:</i> near "
      "T* the impact is ever gentler, and the motion between impacts ever closer to the free "
      "motion that touches the stop.");
  scene.defaults.chainPeriodFraction = 0.9;
  scene.massChain = true;
  scene.gloWeights = false;  // it starts on the 1IPP orbit
  scene.parameters = {ParamKey::Gap, ParamKey::ChainPeriod};
  scene.plots = {PlotKind::OnePeriodicData, PlotKind::ImpactSpeed, PlotKind::Trace,
                 PlotKind::Chain};
  scene.build = [](const Scene&, const Params& params, const DerivedModel&, std::stop_token stop) {
    SceneJob job;
    const ChainChoice choice = chooseChain(params.massChain, params.gap, stop);
    if (!choice.chain) return refusedChainJob(choice.problem);
    const core::MassChain& chain = *choice.chain;
    const core::ChainModes modes = core::chainModes(chain);
    const core::SpectrumRatios ratios = core::detectRatios(modes.omega);
    if (!ratios.commensurate) {
      return refusedChainJob(
          tr("The 1IPP family ends at a grazing orbit only on a chain with a common period: pick a "
             "resonance"));
    }
    const double Tstar = core::chainOnePeriodicEnd(chain);
    const std::vector<double> limitWeights = core::onePeriodicGrazingWeights(chain, Tstar);
    const core::ChainGloStart limit = core::chainGloStart(chain, limitWeights);
    const std::vector<core::ChainFamilyRow> family = core::chainOnePeriodicFamily(chain, 300, stop);
    if (stop.stop_requested()) return job;
    const double d = chain.gap;
    const double speedScale = d * modes.omega.maxCoeff();
    std::vector<QPointF> data, speed;
    for (const core::ChainFamilyRow& row : family) {
      if (!row.orbit.admissible()) continue;
      data.emplace_back(row.T / Tstar, row.orbit.postImpact.u[0] / d);
      speed.emplace_back(row.T / Tstar, std::abs(row.orbit.V) / speedScale);
    }
    const double T = params.chainPeriodFraction * Tstar;
    const core::ChainOnePeriodicOrbit orbit = core::chainOnePeriodicOrbit(chain, T);
    if (!orbit.admissible()) {
      return refusedStartJob(
          tr("No admissible 1IPP orbit of period T = %1 T*: its flight meets the stop before T, or "
             "its impact speed is not into the stop. The dots show where the family is "
             "admissible.")
              .arg(number(params.chainPeriodFraction, 6)));
    }
    const QPointF limitData(
        1, limit.problem == core::GloStartProblem::None ? limit.state.u[0] / d : 0);
    job.figures[PlotKind::OnePeriodicData] = familyFigure(
        tr("u₁ after the impact / d"), tr("u₁ / d"),
        tr("Mass 1's displacement right after the impact, for each admissible period; as T → T* "
           "it tends to that of the grazing limit GLO (ringed)."),
        data, QPointF(params.chainPeriodFraction, orbit.postImpact.u[0] / d),
        limit.problem == core::GloStartProblem::None ? std::optional(limitData) : std::nullopt);
    job.figures[PlotKind::ImpactSpeed] = familyFigure(
        tr("Impact speed |V| / (d ω₁)"), tr("|V| / (d ω₁)"),
        tr("The stopped mass's speed at the impact: it falls to 0 as T → T*, where the orbit "
           "grazes."),
        speed, QPointF(params.chainPeriodFraction, std::abs(orbit.V) / speedScale), QPointF(1, 0));
    // the slider's orbit over three of its periods, every mass on the grid
    job.spec.chains = {{chain, orbit.postImpact, 3, 3 * T, 900, core::TrustMode::Auto}};
    job.spec.chains.front().design = choice.design;
    QStringList weights;
    for (double w : limitWeights) weights.append(number(w, 4));
    job.chain.summary =
        chainSummaryOf(chain, params.massChain, choice.designs, modes, ratios,
                       tr("As T → T* = %1 the 1IPP data tend to GLO with weights (%2) (fastest mode first).")
                           .arg(number(Tstar, 6), weights.join(QStringLiteral(", "))));
    job.chain.designs = choice.designs;
    double distance = 0;
    if (limit.problem == core::GloStartProblem::None)
      distance = (orbit.postImpact.u - limit.state.u).norm() / d;
    job.status =
        tr("1IPP orbit of T = %1 T*: impact speed V = %2, energy %3; its data are %4 d from the "
           "grazing limit's")
            .arg(number(params.chainPeriodFraction, 6), number(orbit.V, 6), number(orbit.energy, 6),
                 number(distance, 3));
    // the trace over the orbit's own period: it meets the stop at t = T, 2T, 3T
    const int stopped = chain.stopped();
    job.timeUnit = TimeUnit{T, tr("T"), tr("the orbit's period T")};
    job.viewWords[PlotKind::Trace] = {
        tr("The 1IPP orbit of T = %1 T*: u%2 / d").arg(number(params.chainPeriodFraction, 6), subscriptDigits(stopped)),
        tr("The stopped mass over three periods of the orbit, from right after an impact: it meets "
           "the stop once a period, at t = T, 2T, 3T (dots: the exact run's contacts).")};
    job.ok = true;
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
