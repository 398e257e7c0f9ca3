// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/compute/scene.h"

#include "ui/scenes/scenes.h"

#include <QCoreApplication>

#include "core/model/two_mass_form.h"
#include "core/orbits/special_orbits.h"
#include "core/orbits/starts.h"

namespace grazelab::ui {

core::Needs needsFor(const QList<PlotKind>& plots, const core::Modes& modes, double sampleWindow) {
  core::Needs needs;
  const bool dense = plots.contains(PlotKind::Trace) || plots.contains(PlotKind::Phase) ||
                     plots.contains(PlotKind::PhaseU1V1) || plots.contains(PlotKind::Chain);
  // contacts are marked on the u2(t) trace and flash in the animation, over the sample window
  needs.events = plots.contains(PlotKind::Trace) || plots.contains(PlotKind::Chain);
  needs.eventsUntil = sampleWindow;
  // the landscape draws the run's points on H over its map
  needs.poincare = plots.contains(PlotKind::Poincare) || plots.contains(PlotKind::Landscape);
  needs.freeFlights = plots.contains(PlotKind::FreeFlight);
  if (dense) {
    // 48 samples per fast period draw a smooth curve at any zoom a screen can show
    needs.samples.spacing = modes.T1 / 48.0;
    needs.samples.tEnd = sampleWindow;
    needs.samples.maxCount = 400'000;
  }
  return needs;
}

Params enterScene(const Params& own, const Params& chain) {
  Params params = own;
  params.m1 = chain.m1;
  params.m2 = chain.m2;
  params.gap = chain.gap;
  params.k1 = chain.k1;
  params.k2 = chain.k2;
  params.resonantDesign = chain.resonantDesign;
  params.branch = chain.branch;
  // (a chain of N masses stays with its scene: each N-mass scene is about its own chain)
  return params;
}

core::StartOrProblem<double> gloStart(const core::Model& model, const Params& params) {
  // core's one place for starts, as the command line's --glo L --perturb ...: the same state
  // and the same notes (a push below one ulp of the start)
  const core::TwoMassFormOrProblem<double> formed = core::makeTwoMassForm(model);
  if (!formed.chain) return {std::nullopt, formed.problem};
  core::StartSpec<double> spec;
  spec.kind = core::StartSpec<double>::Kind::Glo;
  spec.lambda = params.lambda;
  if (params.perturbation != 0) spec.perturbation = perturbed(core::State{}, params);
  return core::makeStart(*formed.chain, spec);
}

SceneJob gloStartJob(const Scene& scene, const Params& params, const DerivedModel& derived,
                     double sampleWindow) {
  SceneJob job;
  job.spec.model = derived.model;
  const core::StartOrProblem<double> made = gloStart(derived.model, params);
  if (!made.start) {
    job.message = QString::fromStdString(made.problem);
    return job;
  }
  for (const std::string& note : made.start->notes) job.notes.append(QString::fromStdString(note));
  const core::State start = core::gloData(derived.model, derived.modes, params.lambda);
  job.spec.run.initial = made.start->state;
  job.spec.stillModes = made.start->stillModes;  // GLO_0 unpushed: the slow mode exactly still
  job.spec.run.maxContacts = std::int64_t(params.horizon);
  job.spec.run.needs = needsFor(scene.plots(), derived.modes, sampleWindow);
  job.reference = start;
  job.referenceLabel = QCoreApplication::translate("grazelab::ui::Scene", "GLO(λ) data");
  job.ok = true;
  return job;
}

core::State perturbed(core::State state, const Params& params) {
  switch (params.direction) {
    case PerturbDirection::V2: state.v2 += params.perturbation; break;
    case PerturbDirection::U2: state.u2 += params.perturbation; break;
    case PerturbDirection::U1: state.u1 += params.perturbation; break;
    case PerturbDirection::V1: state.v1 += params.perturbation; break;
  }
  return state;
}

QString sceneShortcut(int index) {
  if (index < 9) return QStringLiteral("Ctrl+%1").arg(index + 1);
  if (index == 9) return QStringLiteral("Ctrl+M");
  // the N-mass scenes after the note's: Alt+1 ... (Ctrl+Shift+digit is a symbol on many layouts)
  if (index < 19) return QStringLiteral("Alt+%1").arg(index - 9);
  return {};
}

std::vector<std::unique_ptr<Scene>> makeScenes() {
  // the table of scenes, in the order of the note: a new scene is one line here and a file
  const std::vector<Scene::Spec (*)()> table = {
      grazingFamilyScene, onePeriodicScene, perturbationScene, randomStartsScene,
      stickingScene,      detunedScene,     nearGrazingScene,  landscapeScene,
      accuracyScene,      modesScene,       threeMassesScene, grazingSetsScene,
      chainOnePeriodicScene, eightMassesScene, chainModesScene,
  };
  std::vector<std::unique_ptr<Scene>> scenes;
  for (auto make : table) scenes.push_back(std::make_unique<Scene>(make()));
  return scenes;
}

int findScene(const std::vector<std::unique_ptr<Scene>>& scenes, const QString& name) {
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    if (scenes[i]->name().compare(name, Qt::CaseInsensitive) == 0) return int(i);
    if (scenes[i]->alias().compare(name, Qt::CaseInsensitive) == 0) return int(i);
  }
  return -1;
}

}  // namespace grazelab::ui
