// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>

#include <algorithm>

#include "core/model/linear_modes.h"
#include "core/orbits/special_orbits.h"
#include "core/model/resonance.h"
#include "core/orbits/starts.h"
#include "core/experiments/theorem_surveys.h"
#include "core/solver/chain_run.h"
#include "ui/scenes/scenes.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::DetunedScene", text);
}

// a detuned flight may be long: each is searched for at most this many slow periods (the run's)
constexpr double kSearchPeriods = core::kFlightSearchPeriods;

std::vector<QPointF> flights(const core::Model& model, const core::State& start,
                             std::int64_t contacts, std::stop_token stop) {
  std::vector<QPointF> points;
  for (const auto& [index, fraction] :
       core::experiments::flightTimesOverT2(model, start, contacts, stop)) {
    points.emplace_back(index, fraction);
  }
  return points;
}

CurveFigure flightFigure(const QString& title, std::vector<QPointF> points, bool fixed,
                         std::int64_t contacts) {
  CurveFigure figure;
  figure.title = title;
  figure.xTitle = tr("contact index");
  figure.yTitle = tr("flight time / T₂");
  figure.toolTip = tr("Free-flight time at each contact over the chain's own slow period T₂. "
                      "In 1:2 resonance it never passes 1; detuned, it wanders and can be far "
                      "longer (flights searched up to %1 T₂).").arg(kSearchPeriods);
  figure.curveName = tr("flights");
  figure.curve = std::move(points);
  figure.dots = true;  // one flight per contact
  figure.referenceName = tr("T₂");
  figure.reference = {QPointF(0, 1), QPointF(double(std::max<std::int64_t>(contacts, 1)), 1)};
  if (fixed) {
    double lowest = 1;
    for (const QPointF& point : figure.curve) lowest = std::min(lowest, point.y());
    figure.xMin = -0.02 * double(contacts);
    figure.xMax = 1.02 * double(contacts);
    figure.yMin = lowest - 0.05 * (1.1 - lowest);
    figure.yMax = 1.1;
  }
  return figure;
}

}  // namespace

Scene::Spec detunedScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Detuned contrast: off 1:2 resonance");
  scene.alias = QStringLiteral("detuned");
  scene.title = tr("Detuned contrast: off 1:2 resonance");
  scene.text = tr("<b>Why the resonance matters.</b> The same start on two chains: one tuned "
                  "to ω₁/ω₂ = 2 exactly (right), one with k₂ chosen for the ratio on the slider "
                  "(left, and its motion below). <i>Look for:</i> in resonance every free-flight "
                  "time stays at or below T₂; detuned, the times scatter, pass T₂ and grow "
                  "without a bound as the ratio leaves 2. <i>Why:</i> only at ω₁ = 2 ω₂ does "
                  "every free motion repeat after T₂; the theorems need that.");
  scene.defaults.lambda = 0.5;
  scene.defaults.perturbation = -0.05;
  scene.defaults.direction = PerturbDirection::V2;
  scene.defaults.horizon = 300;
  scene.defaults.frequencyRatio = 2.05;
  scene.parameters = {ParamKey::FrequencyRatio, ParamKey::Lambda,       ParamKey::M1,
                      ParamKey::M2,             ParamKey::Gap,          ParamKey::K1,
                      ParamKey::Perturbation,   ParamKey::Horizon};
  scene.plots = {PlotKind::DetunedFlights, PlotKind::ResonantFlights, PlotKind::Trace};
  scene.build = [](const Scene& self, const Params& params, const DerivedModel&, std::stop_token stop) {
    SceneJob job;
    const auto k2 = core::k2ForFrequencyRatio(params.m1, params.m2, params.k1,
                                              params.frequencyRatio, params.branch);
    if (!k2) {
      job.message = tr("No chain with these masses has ω₁/ω₂ = %1: try a ratio nearer 2")
                        .arg(params.frequencyRatio, 0, 'g', 6);
      return job;
    }
    // the resonant one is the 1:2 design whatever the design box says in other scenes
    const auto resonant =
        core::designedModel(params.m1, params.m2, params.k1, params.gap, params.branch);
    if (!resonant) {
      job.message = tr("No 1:2 resonant chain for m₂/m₁ = %1 to compare with (needs ≤ 9/16)")
                        .arg(params.m2 / params.m1, 0, 'g', 6);
      return job;
    }
    const core::Model detuned{params.m1, params.m2, params.k1, *k2, params.gap, std::nullopt};
    const core::Modes resonantModes = core::computeModes(*resonant);
    // the same start on both chains: GLO(lambda) of the resonant one, pushed, made as the
    // command line makes it (with its notes)
    const core::StartOrProblem<double> made = gloStart(*resonant, params);
    if (!made.start) {
      job.message = QString::fromStdString(made.problem);
      return job;
    }
    for (const std::string& note : made.start->notes) job.notes.append(QString::fromStdString(note));
    const core::State start = made.start->state;
    // at most 2000 contacts a chain: the pair is drawn whole, on fixed axes
    const auto contacts = std::int64_t(std::min(params.horizon, 2000.0));
    job.figures[PlotKind::DetunedFlights] = flightFigure(
        tr("Detuned, ω₁/ω₂ = %1: flight time / T₂").arg(params.frequencyRatio, 0, 'g', 5),
        flights(detuned, start, contacts, stop), false, contacts);
    job.figures[PlotKind::ResonantFlights] =
        flightFigure(tr("In 1:2 resonance: flight time / T₂"), flights(*resonant, start, contacts, stop),
                     true, contacts);
    job.spec.model = detuned;
    job.spec.run.initial = start;
    job.spec.run.maxContacts = std::int64_t(params.horizon);
    job.spec.run.needs = needsFor(self.plots(), core::computeModes(detuned), 40 * resonantModes.T2);
    job.ok = true;
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
