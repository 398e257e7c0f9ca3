// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/model/two_mass_form.h"
#include "core/experiments/theorem_surveys.h"
#include "core/orbits/special_orbits.h"
#include "core/orbits/starts.h"
#include "ui/scenes/scenes.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::OneIppScene", text);
}

// The family's curves over (T_lo, T2), from core's samples.
struct Family {
  std::vector<QPointF> u1;      // (T/T2, u1 at impact)
  std::vector<QPointF> speed;   // (T/T2, |V|)
  std::vector<QPointF> energy;  // (log10 E, 2 pi / T): the frequency-energy curve
  std::vector<double> fraction;  // T/T2 of each point of `energy`
};

Family sampleFamily(const DerivedModel& derived, double lowEnd, std::stop_token stop) {
  Family family;
  const double T2 = derived.modes.T2;
  for (const core::OnePeriodicOrbit<double>& orbit :
       core::experiments::onePeriodicFamilySamples(derived.model, derived.modes, lowEnd, 240, stop)) {
    family.u1.emplace_back(orbit.T / T2, orbit.postImpact.u1);
    family.speed.emplace_back(orbit.T / T2, std::abs(orbit.V));
    if (orbit.energy > 0) {
      family.energy.emplace_back(std::log10(orbit.energy), 2 * std::numbers::pi / orbit.T);
      family.fraction.push_back(orbit.T / T2);
    }
  }
  return family;
}

// Axes that hold the upper 85 % of the family (near T_lo the data run off to infinity where
// g2(T) -> 0, and would squash the approach to T2 that the scene is about) and `also`.
void fixAxes(CurveFigure& figure, double lowFraction, double also) {
  const double cut = lowFraction + 0.15 * (1 - lowFraction);
  double low = also;
  double high = also;
  for (const QPointF& point : figure.curve) {
    if (point.x() < cut) continue;
    low = std::min(low, point.y());
    high = std::max(high, point.y());
  }
  const double pad = 0.06 * std::max(high - low, 1e-12);
  figure.xMin = lowFraction - 0.01 * (1 - lowFraction);
  figure.xMax = 1 + 0.02 * (1 - lowFraction);
  figure.yMin = low - pad;
  figure.yMax = high + pad;
}

}  // namespace

Scene::Spec onePeriodicScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("1IPP orbits approaching GLO_lambda*");
  scene.alias = QStringLiteral("1ipp");
  scene.title = tr("Theorem 2.1: 1IPP orbits approach GLO(λ*)");
  scene.text = tr("<b>One impact per period T.</b> Slide T/T₂ up towards 1. <i>Look for:</i> the "
                  "impact data u₁ (left) run into the value of the grazing orbit GLO(λ*), and "
                  "the impact speed |V| (right) falls to 0. <i>Why:</i> as T → T₂ the impact "
                  "becomes a touch; the only orbit that returns after T₂ touching the stop is "
                  "the grazing one with λ = λ*, fixed by the masses (Theorem 2.1). The orange-red dot "
                  "is the current T; the frequency–energy curve (bottom left) ends at that "
                  "grazing orbit's energy and ω₂; the plots beside it show the motion.");
  scene.defaults.periodFraction = 0.9;
  scene.defaults.perturbation = 0;
  scene.defaults.horizon = 20;
  // k2 too: it is what the "1:2 design" box hands over to the user when unticked
  scene.parameters = {ParamKey::Period, ParamKey::M1, ParamKey::M2, ParamKey::Gap,
                      ParamKey::K1,     ParamKey::K2, ParamKey::Horizon};
  scene.plots = {PlotKind::OnePeriodicData, PlotKind::ImpactSpeed, PlotKind::FrequencyEnergy,
                 PlotKind::Trace, PlotKind::Chain};
  scene.build = [](const Scene& self, const Params& params, const DerivedModel& derived,
                  std::stop_token stop) {
    SceneJob job;
    job.spec.model = derived.model;
    const double T2 = derived.modes.T2;
    const double lowEnd = core::onePeriodicLowerEnd(derived.model, derived.modes);
    const double lowFraction = lowEnd / T2;
    // the slider starts on an admissible period of this chain (rounded up to its 3 decimals)
    job.sliderRanges[ParamKey::Period] = {std::ceil(lowFraction * 1000 + 1e-9) / 1000, 0.999};
    const double period = params.periodFraction * T2;
    const core::OnePeriodicOrbit orbit = core::onePeriodicOrbit(derived.model, derived.modes, period);
    if (!orbit.admissible) {
      job.message = tr("No one-impact-per-period orbit for T/T₂ = %1: this chain's family spans "
                       "T/T₂ in (%2, 1) (%3)")
                        .arg(params.periodFraction, 0, 'g', 6)
                        .arg(lowFraction, 0, 'f', 4)
                        .arg(QString::fromStdString(orbit.reason));
      return job;
    }
    // the run's start as the command line's --onepp T makes it (core's one place for starts)
    const core::TwoMassFormOrProblem<double> formed = core::makeTwoMassForm(derived.model);
    if (!formed.chain) {
      job.message = QString::fromStdString(formed.problem);
      return job;
    }
    core::StartSpec<double> start;
    start.kind = core::StartSpec<double>::Kind::OnePeriodic;
    start.period = period;
    const core::StartOrProblem<double> made = core::makeStart(*formed.chain, start);
    if (!made.start) {
      job.message = QString::fromStdString(made.problem);
      return job;
    }
    for (const std::string& note : made.start->notes) job.notes.append(QString::fromStdString(note));
    job.spec.run.initial = made.start->state;
    job.spec.run.maxContacts = std::int64_t(params.horizon);
    job.spec.run.needs = needsFor(self.plots(), derived.modes, 400 * T2);
    const core::State star = core::gloData(derived.model, derived.modes, derived.lambdaStar);
    job.reference = star;
    job.referenceLabel = tr("GLO(λ*) data");

    const Family family = sampleFamily(derived, lowEnd, stop);
    const QString lambdaStar = QString::number(derived.lambdaStar, 'f', 3);
    CurveFigure data;
    data.title = tr("Impact data u₁ of the 1IPP orbit against T/T₂");
    data.xTitle = tr("T / T₂");
    data.yTitle = tr("u₁ at impact");
    data.toolTip = tr("Where mass 1 is when mass 2 hits the stop, for each period T of the "
                      "one-impact-per-period family. As T → T₂ it tends to u₁ of the grazing "
                      "orbit GLO(λ*) (dashed), λ* = %1 for these masses.").arg(lambdaStar);
    data.curveName = tr("1IPP family");
    data.curve = family.u1;
    data.markerName = tr("T/T₂ = %1").arg(params.periodFraction, 0, 'g', 6);
    data.markers = {QPointF(params.periodFraction, orbit.postImpact.u1)};
    data.referenceName = tr("GLO(λ*), λ* = %1").arg(lambdaStar);
    data.reference = {QPointF(lowFraction, star.u1), QPointF(1.0, star.u1)};
    fixAxes(data, lowFraction, star.u1);
    job.figures[PlotKind::OnePeriodicData] = std::move(data);

    CurveFigure speed;
    speed.title = tr("Impact speed |V| of the 1IPP orbit against T/T₂");
    speed.xTitle = tr("T / T₂");
    speed.yTitle = tr("|V|");
    speed.toolTip = tr("The speed at which mass 2 hits the stop on the one-impact-per-period "
                       "orbit of period T. It goes to 0 as T → T₂: the impact becomes grazing.");
    speed.curveName = tr("1IPP family");
    speed.curve = family.speed;
    speed.markerName = tr("|V| = %1").arg(std::abs(orbit.V), 0, 'g', 4);
    speed.markers = {QPointF(params.periodFraction, std::abs(orbit.V))};
    speed.referenceName = tr("T → T₂: V → 0");
    speed.reference = {QPointF(1.0, 0.0)};
    fixAxes(speed, lowFraction, 0.0);
    job.figures[PlotKind::ImpactSpeed] = std::move(speed);

    const double starEnergy = core::energy(derived.model, star);
    CurveFigure energy;
    energy.title = tr("Frequency against energy of the 1IPP family");
    energy.xTitle = tr("log₁₀ E");
    energy.yTitle = tr("2π/T");
    energy.toolTip = tr("The frequency–energy curve of the one-impact-per-period family, the "
                        "picture of nonsmooth modal analysis: as T → T₂ the frequency falls to "
                        "ω₂ and the energy to that of the grazing orbit GLO(λ*) (ringed), where "
                        "the family ends. grazelab-cli family --onepp writes the whole family, "
                        "admissible or not.");
    energy.curveName = tr("1IPP family");
    energy.curve = family.energy;
    const double currentEnergy = core::energy(derived.model, orbit.postImpact);
    energy.markerName = tr("T/T₂ = %1").arg(params.periodFraction, 0, 'g', 6);
    energy.markers = {QPointF(std::log10(currentEnergy), 2 * std::numbers::pi / period)};
    energy.referenceName = tr("grazing end GLO(λ*): E = %1, ω₂").arg(starEnergy, 0, 'g', 4);
    energy.reference = {QPointF(std::log10(starEnergy), derived.modes.omegaSlow)};
    // the axes of the upper 85 % of the family, as the other two curves (the energy runs off
    // to infinity towards T_lo)
    const double cut = lowFraction + 0.15 * (1 - lowFraction);
    double xLow = energy.reference[0].x(), xHigh = xLow;
    double yLow = energy.reference[0].y(), yHigh = yLow;
    for (std::size_t i = 0; i < family.energy.size(); ++i) {
      if (family.fraction[i] < cut) continue;
      xLow = std::min(xLow, family.energy[i].x());
      xHigh = std::max(xHigh, family.energy[i].x());
      yLow = std::min(yLow, family.energy[i].y());
      yHigh = std::max(yHigh, family.energy[i].y());
    }
    const double xPad = 0.06 * std::max(xHigh - xLow, 1e-9);
    const double yPad = 0.06 * std::max(yHigh - yLow, 1e-9);
    energy.xMin = xLow - xPad;
    energy.xMax = xHigh + xPad;
    energy.yMin = yLow - yPad;
    energy.yMax = yHigh + yPad;
    job.figures[PlotKind::FrequencyEnergy] = std::move(energy);
    job.ok = true;
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
