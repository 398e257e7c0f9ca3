// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>

#include <cmath>
#include <memory>
#include <mutex>
#include <optional>

#include "core/model/two_mass_form.h"
#include "core/orbits/modes_atlas.h"
#include "core/orbits/special_orbits.h"
#include "core/orbits/periodic_orbit.h"
#include "ui/scenes/scenes.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::ModesScene", text);
}

// The chain's atlas and its figure, over the command line's default energies and impacts: the
// ones kept in `cache` when they are this chain's, else computed (each family shown as it is
// finished) and kept; none when stopped.
std::pair<std::shared_ptr<const core::ModesAtlas<double>>, std::shared_ptr<const AtlasFigure>> atlasOf(
    const core::TwoMassForm<double>& chain, const DerivedModel& derived, std::stop_token stop,
    const ScenePartial& partial, SceneCache& cache) {
  {
    const std::lock_guard lock(cache.mutex);
    if (cache.atlasModel == derived.model) return {cache.atlas, cache.atlasFigure};
  }
  core::ModesAtlas<double> sofar;
  const auto familyDone = [&](const core::ModeFamily<double>& family) {
    sofar.families.push_back(family);
    if (!partial) return;
    SceneJob job;
    job.spec.model = derived.model;
    job.atlas = std::make_shared<const AtlasFigure>(atlasFigureOf(sofar, derived.modes.T2));
    partial(job, 0.0);
  };
  const core::AtlasEnergyRange<double> energies = core::defaultAtlasEnergyRange(chain);
  auto atlas = std::make_shared<const core::ModesAtlas<double>>(core::computeModesAtlas<double>(
      chain, core::kDefaultAtlasMaxImpacts, energies.low, energies.high, stop, familyDone));
  if (!atlas->complete) return {};
  auto figure = std::make_shared<const AtlasFigure>(atlasFigureOf(*atlas, derived.modes.T2));
  const std::lock_guard lock(cache.mutex);
  cache.atlasModel = derived.model;
  cache.atlas = atlas;
  cache.atlasFigure = figure;
  return {atlas, figure};
}

}  // namespace

Scene::Spec modesScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Nonlinear modes: periodic motions with impacts");
  scene.alias = QStringLiteral("modes");
  scene.title = tr("Nonlinear modes: periodic motions with impacts");
  scene.text = tr("<b>The chain's periodic motions with impacts.</b> Each dot of the top-left "
                  "picture is a motion that repeats after k impacts, at its frequency and energy; "
                  "the families of them are the chain's <i>nonlinear normal modes</i>. Filled dots "
                  "are stable, rings unstable; colours count the impacts k. <i>Look for:</i> the "
                  "lower one-impact branch (blue, k = 1) ends at low energy on the grazing orbit "
                  "GLO(λ*) (black dot; the upper blue branch ends on GLOM₁); where its multipliers "
                  "(top middle) meet at −1 it <i>flips</i> (squares): it turns unstable and a family "
                  "with twice the impacts (orange, k = 2) is born at half the frequency, which can "
                  "flip again (green, k = 4). <i>Click</i> any dot to see that motion repeat in "
                  "u₂(t), its phase portrait, its impacts on H and the chain.");
  scene.defaults.periodFraction = 0.9;
  scene.defaults.perturbation = 0;
  scene.defaults.horizon = 40;
  scene.parameters = {ParamKey::Period, ParamKey::M1, ParamKey::M2, ParamKey::Gap,
                      ParamKey::K1,     ParamKey::K2, ParamKey::Horizon};
  scene.plots = {PlotKind::ModesAtlas, PlotKind::Multipliers, PlotKind::Trace,
                 PlotKind::Phase,  PlotKind::Poincare,    PlotKind::Chain};
  scene.buildFromStart = [](const Scene& self, const Params& params, const DerivedModel& derived,
                            const std::optional<core::ChainState>& clickedChain, std::stop_token stop,
                            const ScenePartial& partial, SceneCache& cache) {
    SceneJob job;
    job.spec.model = derived.model;
    const core::TwoMassFormOrProblem<double> formed = core::makeTwoMassForm(derived.model);
    if (!formed.chain) {
      job.message = QString::fromStdString(formed.problem);
      return job;
    }
    const core::TwoMassForm<double>& chain = *formed.chain;
    if (!chain.resonant) {
      job.message = tr("the nonlinear modes start from the one-impact family of the 1:2 resonant "
                       "chain: tick the 1:2 design");
      return job;
    }
    const double T2 = derived.modes.T2;
    const double lowFraction = core::onePeriodicLowerEnd(derived.model, derived.modes) / T2;
    job.sliderRanges[ParamKey::Period] = {std::ceil(lowFraction * 1000 + 1e-9) / 1000, 0.999};
    const auto [atlas, figure] = atlasOf(chain, derived, stop, partial, cache);
    if (!atlas) return job;  // stopped
    job.atlas = figure;
    std::optional<core::PeriodicOrbit<double>> shown;
    // the orbit followed: the one clicked on the atlas, or the 1IPP orbit of the slider's period
    const std::optional<core::State> clicked =
        clickedChain && clickedChain->u.size() == 2 ? std::optional(core::twoMassStateOf(*clickedChain)) : std::nullopt;
    if (clicked) {
      // an orbit of the atlas, with its family's impacts per period (closing to 1e-9: the
      // atlas's states close to ~1e-14)
      const std::optional<int> impacts = core::impactsOfAtlasOrbit(*atlas, *clicked);
      if (impacts) shown = core::evaluateOrbit(chain, *clicked, *impacts, 1e-9);
      if (!shown || !shown->admissible) {
        job.message = tr("the start chosen is not an orbit of the atlas: click a dot of the modes picture");
        return job;
      }
    } else {
      const core::OrbitSearch<double> found = core::onePeriodicOrbitStability(chain, params.periodFraction * T2);
      if (!found.orbit) {
        job.message = tr("No one-impact orbit of stable form for T/T₂ = %1 (%2): move the slider")
                          .arg(params.periodFraction, 0, 'g', 6)
                          .arg(QString::fromStdString(found.problem));
        return job;
      }
      shown = found.orbit;
    }
    const core::PeriodicOrbit<double>& orbit = *shown;
    job.orbit = shownOrbitOf(orbit);
    const std::string symmetry = core::orbitSymmetry(orbit, core::symmetryTolerance<double>());
    job.notes.append(tr("The orbit shown: %1 per period T = %2 (%3 T₂), energy %4, %5%6")
                         .arg(orbit.impacts == 1 ? tr("1 impact") : tr("%1 impacts").arg(orbit.impacts))
                         .arg(orbit.period, 0, 'g', 6)
                         .arg(orbit.period / T2, 0, 'g', 5)
                         .arg(orbit.energy, 0, 'g', 5)
                         .arg(QString::fromUtf8(core::toString(core::decidedStability(orbit)).data()))
                         .arg(symmetry.empty() ? QString() : tr(", symmetric (type %1)").arg(QString::fromStdString(symmetry))));
    job.spec.run.initial = orbit.state;
    job.spec.run.maxContacts = std::int64_t(params.horizon);
    job.spec.run.needs = needsFor(self.plots(), derived.modes, 400 * T2);
    job.reference = orbit.state;
    job.referenceLabel = tr("the orbit's impact");
    job.ok = true;
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
