// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>

#include <algorithm>

#include "core/experiments/theorem_surveys.h"
#include "ui/scenes/scenes.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::RandomStartsScene", text);
}

constexpr int kStarts = 300;
constexpr double kBinWidth = 0.025;  // of FFT / T2
constexpr int kBins = 44;            // [0, 1.1)

CurveFigure histogram(const core::experiments::FlightSurvey& survey, std::int64_t contacts) {
  CurveFigure figure;
  figure.title = tr("Theorem 2.3: free-flight times of %1 random starts").arg(kStarts);
  figure.xTitle = tr("flight time / T₂");
  figure.yTitle = tr("number of flights");
  figure.toolTip = tr("Every free flight that starts on the stop, from %1 random starts below "
                      "it, each run to %2 contacts: %3 starts never touch the stop, %4 reach "
                      "all %2 contacts, %5 stop earlier. No flight lasts longer than T₂ "
                      "(largest FFT/T₂ = %6).")
                      .arg(kStarts)
                      .arg(contacts)
                      .arg(survey.neverTouch)
                      .arg(survey.reachedLimit)
                      .arg(survey.other)
                      .arg(survey.longest, 0, 'f', 12);
  figure.curveName = tr("%1 flights: %2 starts never touch, %3 reach %4 contacts")
                         .arg(survey.flights)
                         .arg(survey.neverTouch)
                         .arg(survey.reachedLimit)
                         .arg(contacts);
  int highest = 1;
  for (int bin = 0; bin < kBins; ++bin) {
    const double left = bin * kBinWidth;
    const int count = survey.counts[std::size_t(bin)];
    highest = std::max(highest, count);
    figure.curve.emplace_back(left, 0);
    figure.curve.emplace_back(left, count);
    figure.curve.emplace_back(left + kBinWidth, count);
    figure.curve.emplace_back(left + kBinWidth, 0);
  }
  figure.referenceName = tr("bound: T₂");
  figure.reference = {QPointF(1, 0), QPointF(1, 1.05 * highest)};
  figure.xMin = 0;
  figure.xMax = kBins * kBinWidth;
  figure.yMin = 0;
  figure.yMax = 1.08 * highest;
  return figure;
}

}  // namespace

Scene::Spec randomStartsScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Theorem 2.3: random starts");
  scene.alias = QStringLiteral("random-starts");
  scene.title = tr("Theorem 2.3: random starts");
  scene.text = tr("<b>Any start at all.</b> %1 random starts below the stop, each followed for "
                  "the chosen number of contacts (at most 200). <i>Look for:</i> a start either "
                  "never touches the stop or keeps touching it to the end (the counts under the "
                  "histogram), "
                  "and no free flight lasts longer than T₂: the histogram ends at the dashed "
                  "line. <i>Why:</i> a free motion repeats after T₂, so once it has touched the "
                  "stop it is back within T₂ (Theorem 2.3). The plots below follow the first "
                  "random start that touches.")
                  .arg(kStarts);
  scene.defaults.horizon = 40;
  scene.parameters = {ParamKey::M1, ParamKey::M2, ParamKey::Gap, ParamKey::K1, ParamKey::K2,
                      ParamKey::Horizon};
  scene.plots = {PlotKind::FlightHistogram, PlotKind::FreeFlight, PlotKind::Trace};
  scene.build = [](const Scene& self, const Params& params, const DerivedModel& derived,
                  std::stop_token stop) {
    SceneJob job;
    job.spec.model = derived.model;
    // 300 starts x at most 200 contacts: the survey stays short
    const auto contacts = std::int64_t(std::min(params.horizon, 200.0));
    // the same starts for a given chain (a fixed seed)
    const core::experiments::FlightSurvey found =
        core::experiments::surveyRandomStarts(derived.model, kStarts, contacts, 20261123, kBins, kBinWidth, stop);
    job.figures[PlotKind::FlightHistogram] = histogram(found, contacts);
    if (!found.firstTouching) {
      job.message = tr("none of the %1 random starts touches the stop").arg(kStarts);
      return job;
    }
    job.spec.run.initial = *found.firstTouching;
    job.spec.run.maxContacts = std::int64_t(params.horizon);
    job.spec.run.needs = needsFor(self.plots(), derived.modes, 40 * derived.modes.T2);
    job.ok = true;
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
