// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>

#include <algorithm>

#include "core/experiments/chain_series.h"
#include "core/model/linear_modes.h"
#include "core/model/mass_chain.h"
#include "core/model/resonance.h"
#include "core/solver/chain_flight.h"
#include "ui/scenes/scenes.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::DetunedScene", text);
}

// the trace spans four slow periods (as the N-mass scenes' do), on this many points
constexpr int kGridPoints = 1500;
// the contrast's contacts at most
constexpr int kContrastContacts = 2000;

}  // namespace

// An experiment of two runs from one start, as the N-mass contrast is: the 1:2 design (the run
// shown: its flights, bounded by T2, and its motion) and the chain detuned to the slider's ratio
// (its flights over the same T2, the contrast view).
Scene::Spec detunedScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Detuned contrast: off 1:2 resonance");
  scene.alias = QStringLiteral("detuned");
  scene.title = tr("Detuned contrast: off 1:2 resonance");
  scene.text = tr("<b>Why the resonance matters.</b> The same start on two chains: one tuned "
                  "to ω₁/ω₂ = 2 exactly (left; its motion u₂(t) bottom right), one with k₂ chosen "
                  "for the ratio on the slider (top right). <i>Look for:</i> in resonance every free-flight "
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
  scene.plots = {PlotKind::FreeFlight, PlotKind::ContrastFlights, PlotKind::Trace};
  scene.build = [](const Scene&, const Params& params, const DerivedModel&, std::stop_token) {
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
    // the same start on both chains: GLO(lambda) of the resonant one, pushed, made as the
    // command line makes it (with its notes)
    const core::StartOrProblem<double> made = gloStart(*resonant, params);
    if (!made.start) {
      job.message = QString::fromStdString(made.problem);
      return job;
    }
    for (const std::string& note : made.start->notes) job.notes.append(QString::fromStdString(note));
    const core::ChainState start = core::chainStateOf(made.start->state);
    const double T2 = core::computeModes(*resonant).T2;
    // the contrast's flights alone, at most kContrastContacts of them (a detuned flight may be
    // searched for 1000 slow periods), and no error estimate, which would cost more than the rest
    // of the scene
    const long contrast = long(std::min(params.horizon, double(kContrastContacts)));
    job.spec.chains = {
        {core::massChainOf(*resonant), start, long(params.horizon), 4 * T2, kGridPoints, core::TrustMode::Auto},
        {core::massChainOf(detuned), start, contrast, 0, 0, core::TrustMode::Off}};
    job.viewWords[PlotKind::ContrastFlights] = {
        tr("Detuned, ω₁/ω₂ = %1").arg(params.frequencyRatio, 0, 'g', 5),
        tr("The same start on the chain with k₂ chosen for ω₁/ω₂ = %1: each free flight from the stop, over "
           "the resonant chain's T₂ (its first %2 contacts at most). In 1:2 resonance no flight lasts longer "
           "(Theorem 2.3); detuned, the times wander and can be far longer.")
            .arg(params.frequencyRatio, 0, 'g', 5)
            .arg(kContrastContacts),
        QString()};
    job.ok = true;
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
