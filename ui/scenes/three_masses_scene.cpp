// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>

#include <numbers>

#include "core/experiments/chain_series.h"
#include "core/model/chain_design.h"
#include "core/model/mass_chain.h"
#include "core/orbits/chain_glo.h"
#include "ui/scenes/mass_chain_scenes.h"
#include "ui/scenes/scenes.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::ThreeMassesScene", text);
}

constexpr int kGridPoints = 1500;  // over the window of four slowest periods

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
                 PlotKind::Phase, PlotKind::Poincare, PlotKind::ContrastFlights};
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
    const double slowest = 2 * std::numbers::pi / core::slowestFrequency(modes.omega);
    const bool contrast = self.plots().contains(PlotKind::ContrastFlights);
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
    job.chain.summary = chainSummaryOf(chain, given, choice.designs, modes, ratios);
    job.chain.designs = choice.designs;
    if (contrast) {
      job.viewWords[PlotKind::ContrastFlights] = {
          chain.size() < 2 ? tr("Detuned contrast: needs two masses or more")
          : ratios.commensurate ? tr("k₂ 5 % off")
                                : tr("Detuned contrast: only for a resonant chain"),
          tr("The same start on the chain with k₂ 5 % stiffer: each free flight from the stop, over the "
             "resonant chain's period T. The resonant chain's free motion repeats after T, so none of its "
             "flights lasts longer (Theorem 2.3 for any N); detuned, no period bounds them."),
          chain.size() < 2 ? tr("The contrast detunes k₂, the spring between masses 1 and 2: a chain of one "
                                "mass has none.")
                           : tr("The contrast detunes a resonant chain: this one has no common period to lose.")};
    }
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
