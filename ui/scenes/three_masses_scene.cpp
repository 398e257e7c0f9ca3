// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/experiments/chain_series.h"
#include "core/model/chain_design.h"
#include "core/model/mass_chain.h"
#include "core/model/model.h"
#include "core/orbits/chain_glo.h"
#include "ui/compute/time_text.h"
#include "ui/scenes/mass_chain_scenes.h"
#include "ui/scenes/scenes.h"
#include "ui/widgets/chain_editor.h"
#include "ui/widgets/param_specs.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::ThreeMassesScene", text);
}

constexpr int kGridPoints = 1500;  // over the window of four slowest periods

// The detuned contrast's flights from the stop over the resonant chain's period T, against the
// index (0-based) of the contact that ends each, with the resonant chain's bound 1.
CurveFigure contrastFigure(const QString& title, const core::experiments::ChainSeries& series, double T) {
  CurveFigure figure;
  figure.title = title;
  figure.xTitle = tr("contact index");
  figure.yTitle = tr("flight / T");
  figure.toolTip =
      tr("The same start on the chain with k₂ 5 % stiffer: each free flight from the stop, over the "
         "resonant chain's period T. The resonant chain's free motion repeats after T, so none of its "
         "flights lasts longer (Theorem 2.3 for any N); detuned, no period bounds them.");
  figure.curveName = tr("flights");
  figure.dots = true;
  figure.whyEmpty = tr("No contact with the stop in this run: no flight from it to draw.");
  long last = 1;
  for (const core::experiments::ChainFlight& flight : series.flights) {
    if (!flight.fromStop) continue;
    figure.curve.emplace_back(double(flight.contact - 1), flight.duration / T);
    last = std::max(last, flight.contact - 1);
  }
  figure.referenceName = tr("T");
  figure.reference = {QPointF(0, 1), QPointF(double(last), 1)};
  return figure;
}

// The scene's figures and status of its runs so far: the run shown, then (when asked) the same
// start on the detuned chain.
void presentThreeMasses(SceneJob& job, const core::experiments::ChainRuns& runs, bool contrast,
                        core::TrustMode trust) {
  const core::experiments::ChainSeries& series = *runs.front();
  const core::MassChain& chain = series.chain;
  const bool resonant = series.period > 0;

  // the contrast: the same start on the chain with k2 5 % stiffer (no common period)
  if (contrast && runs.size() > 1) {
    const core::experiments::ChainSeries& detuned = *runs[1];
    CurveFigure figure = contrastFigure(tr("k₂ 5 % off: flights / the resonant T"), detuned, series.period);
    // its flights past T last 10 to 200 T: the axis stops at 3 T, and they are drawn on its top
    // edge as their own dots, counted in the title (1 % off hid its two such flights above the
    // axis, and a class saw every flight below T)
    std::vector<QPointF> below;
    for (const QPointF& point : figure.curve) {
      if (point.y() > 3) {
        figure.markers.emplace_back(point.x(), 3.0);
      } else {
        below.push_back(point);
      }
    }
    if (!figure.markers.empty()) {
      figure.curve = std::move(below);
      figure.title = tr("k₂ 5 % off: flights / T (%1 past 3 T, on the top edge)").arg(figure.markers.size());
      figure.markerName = tr("past 3 T");
      double last = 1;
      for (const QPointF& point : figure.curve) last = std::max(last, point.x());
      for (const QPointF& point : figure.markers) last = std::max(last, point.x());
      figure.xMin = 0;
      figure.xMax = last * 1.02;
      figure.yMin = 0;
      figure.yMax = 3.1;
    }
    if (detuned.run.stop == core::StopReason::SearchBudget) {
      // its last flight never came back within the search's 1000 slowest periods: say so,
      // rather than let the chart end as if the run had
      const std::size_t flights = figure.curve.size() + figure.markers.size();
      figure.title = flights == 0   ? tr("k₂ 5 % off: no flight from the stop ends in 1000 slow periods")
                     : flights == 1 ? tr("k₂ 5 % off: 1 flight, then none in 1000 slow periods")
                                    : tr("k₂ 5 % off: %1 flights, then none in 1000 slow periods").arg(flights);
    }
    job.figures[PlotKind::DetunedFlights] = figure;
  } else if (contrast) {
    CurveFigure none;
    none.title = chain.size() < 2 ? tr("Detuned contrast: needs two masses or more")
                 : resonant       ? tr("k₂ 5 % off: computing…")
                                  : tr("Detuned contrast: only for a resonant chain");
    if (chain.size() < 2) none.whyEmpty = tr("The contrast detunes k₂, the spring between masses 1 and 2: a chain of one mass has none.");
    else if (!resonant) none.whyEmpty = tr("The contrast detunes a resonant chain: this one has no common period to lose.");
    none.xTitle = tr("contact index");
    none.yTitle = tr("flight / T");
    job.figures[PlotKind::DetunedFlights] = none;
  }
  job.status = chainStatusOf(series);
  if (trust == core::TrustMode::Off) {
    job.status += tr(
        " · no error estimate here (its shadow run in long double would take seconds on a "
        "chain with no common period: grazelab-cli simulate --masses … --trust auto gives it)");
  }
}

}  // namespace

Scene::Spec threeMassesScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Three masses in 1:2:3");
  scene.alias = QStringLiteral("three-masses");
  scene.title = tr("Three masses in 1:2:3");
  scene.text = tr(
      "<b>What generalises to N masses.</b> A chain of three masses with its springs designed so "
      "that the frequencies are in the ratio 1:2:3 starts on a grazing linear orbit, a "
      "weighted sum of the modes that just touches the stop, pushed off it by δ. <i>Look "
      "for:</i> the impacts of the stopped mass (its trace, and the chain moving) and its "
      "free-flight times: every one stays at or below the common period T, as for two "
      "masses; the same start on the chain detuned by 5 % has flights far past T (on the top "
      "edge of its plot, past 3 T). <i>Why:</i> "
      "with ω₁ : ω₂ : ω₃ = 3 : 2 : 1 every free motion repeats after T, so a flight from the "
      "stop meets it again by then. Change the masses, the resonance (some are impossible for "
      "some masses: you are told why), or the number of masses.");
  scene.defaults.perturbation = -0.05;
  scene.defaults.horizon = 200;
  scene.defaults.massChain = MassChainParams{};
  scene.massChain = true;
  scene.parameters = {ParamKey::Gap, ParamKey::Perturbation, ParamKey::Horizon};
  scene.plots = {PlotKind::Trace, PlotKind::Chain, PlotKind::FreeFlight,
                 PlotKind::Phase, PlotKind::Poincare, PlotKind::DetunedFlights};
  scene.build = [](const Scene& self, const Params& params, const DerivedModel&, std::stop_token stop) {
    const MassChainParams& given = params.massChain;
    const ChainChoice choice = chooseChain(given, params.gap, stop);
    if (!choice.chain) return refusedChainJob(choice.problem);
    const core::MassChain& chain = *choice.chain;
    const core::ChainGloStart glo = core::chainGloStart(chain, given.weights);
    if (glo.problem != core::GloStartProblem::None) {
      return refusedStartJob(gloStartProblemInWords(glo.problem));
    }
    core::ChainState start = glo.state;
    const Eigen::Index s = chain.stopped() - 1;
    start.v[s] += params.perturbation;  // pushed off the orbit along the stopped mass's velocity
    const core::ChainModes modes = core::chainModes(chain);
    const core::SpectrumRatios ratios = core::detectRatios(modes.omega);
    const double slowest = 2 * std::numbers::pi / modes.omega.minCoeff();
    const bool contrast = self.plots().contains(PlotKind::DetunedFlights);
    // (the error estimate of a chain with no common period shadows long searches in long
    // double: its own scene asks for none, and says so). The trace, the phase portrait and the
    // animation span four slowest periods: six drew twenty fast swings into a plot a third of a
    // projector wide, lines merging into a band in presentation's thick pen
    core::experiments::ChainSeriesSpec run{chain, start, long(params.horizon), 4 * slowest, kGridPoints,
                                           contrast ? core::TrustMode::Auto : core::TrustMode::Off};
    if (params.perturbation == 0) run.gloWeights = given.weights;  // GLO itself: its still modes kept
    SceneJob job;
    run.design = choice.design;
    job.spec.chains = {run};
    if (contrast && ratios.commensurate && chain.size() >= 2) {
      // the contrast: the same start on the chain with k2 5 % stiffer (no common period); its
      // flights only: no error estimate, which would cost more than the rest of the scene
      core::MassChain detuned = chain;
      detuned.springs[1] *= 1.05;
      job.spec.chains.push_back({detuned, start, long(params.horizon), 0, 0, core::TrustMode::Off});
    }
    job.chosenMass = given.shown();
    job.sectionOn = {given.sectionXResolved(), given.sectionYResolved()};
    job.chainSummary = chainSummaryOf(chain, given, choice.designs, modes, ratios);
    job.chainDesigns = choice.designs;
    job.presentRuns = [contrast, trust = run.trust](
                          SceneJob& shown, const core::experiments::ChainRuns& runs) {
      presentThreeMasses(shown, runs, contrast, trust);
    };
    job.ok = true;
    return job;
  };
  return scene;
}

Scene::Spec eightMassesScene() {
  Scene::Spec scene = threeMassesScene();
  scene.name = QStringLiteral("A string of eight masses");
  scene.alias = QStringLiteral("eight-masses");
  scene.title = tr("A string of eight masses");
  scene.text = tr(
      "<b>Many modes, exact contacts.</b> Eight equal masses on equal springs, the stop on mass 5 "
      "(inside the string), start on its slowest mode alone with its top on the stop, pushed "
      "off by δ along mass 5's velocity. Its frequencies are not commensurate: no common period "
      "bounds the flights. <i>Look for:</i> the string moving and mass 5's trace: near the top "
      "of the mode the first contacts are soft impacts, at under 1 % of the mode's speed, "
      "over so soon that a sign-change event finder stepping across them would miss them; here "
      "each is found by a certified search (every window of time excluded by a bound on the "
      "motion's derivatives). <i>Why:</i> a soft impact is nearly a double root of u₅(t) − d (a "
      "touch is one), whose change of sign lasts a moment. Try 2 to 8 masses, other stops, or "
      "a resonance.");
  scene.defaults.massChain = MassChainParams{}.resized(8);
  scene.defaults.massChain.masses.assign(8, 1.0);
  scene.defaults.massChain.springs.assign(8, 1.0);
  scene.defaults.massChain.stopMass = 5;
  scene.defaults.massChain.weights.assign(8, 0.0);
  scene.defaults.massChain.weights.back() = 1.0;  // the slowest mode alone
  scene.defaults.perturbation = -1e-4;
  scene.defaults.horizon = 100;
  scene.plots = {PlotKind::Trace, PlotKind::Chain, PlotKind::FreeFlight,
                 PlotKind::Phase, PlotKind::Poincare};
  return scene;
}

}  // namespace grazelab::ui
