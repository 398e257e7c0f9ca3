// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>

#include "core/orbits/chain_atlas.h"
#include "core/solver/chain_run.h"
#include "ui/scenes/mass_chain_scenes.h"
#include "ui/scenes/scenes.h"
#include "ui/widgets/param_specs.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::ChainModesScene", text);
}

QString number(double value, int digits = 5) { return QString::number(value, 'g', digits); }

// The families followed up to this many impacts per period: the 1IPP parts and the families born
// at their doublings (a 3-mass chain's atlas to K = 2 takes about 0.4 s, to K = 4 about 0.8 s)
constexpr int kMaxImpacts = 2;

bool sameChain(const core::MassChain& a, const core::MassChain& b) {
  return a.masses == b.masses && a.springs == b.springs && a.rightSpring == b.rightSpring &&
         a.stopped() == b.stopped() && a.gap == b.gap;
}

// The chain's atlas and its figure: the ones in `cache` when they are this chain's, else computed
// (each family shown as it is finished) and kept; none when stopped.
std::pair<std::shared_ptr<const core::ChainAtlas<double>>, std::shared_ptr<const AtlasFigure>> atlasOf(
    const core::MassChain& chain, std::stop_token stop, const ScenePartial& partial, SceneCache& cache) {
  {
    const std::lock_guard lock(cache.mutex);
    if (cache.chainAtlasChain && sameChain(*cache.chainAtlasChain, chain)) return {cache.chainAtlas, cache.chainAtlasFigure};
  }
  const core::ReadyChain ready = core::readyChain(chain);
  const double slowPeriod = ready.dynamics.period > 0 ? ready.dynamics.period
                                                      : 2 * M_PI / core::slowestFrequency(ready.dynamics.omega);
  core::ChainAtlasOptions<double> options;
  options.maxImpacts = kMaxImpacts;
  const core::AtlasEnergyRange<double> range = core::defaultChainAtlasEnergyRange(ready);
  options.energyLow = range.low;
  options.energyHigh = range.high;
  core::ChainAtlas<double> sofar;
  const std::function<void(const core::ChainAtlasFamily<double>&)> familyDone =
      [&](const core::ChainAtlasFamily<double>& family) {
        sofar.families.push_back(family);
        if (!partial) return;
        SceneJob job;
        job.atlas = std::make_shared<const AtlasFigure>(atlasFigureOf(sofar, slowPeriod));
        partial(job, 0.0);
      };
  auto atlas = std::make_shared<const core::ChainAtlas<double>>(
      core::computeChainAtlas(ready, options, stop, familyDone));
  if (!atlas->complete) return {};
  auto figure = std::make_shared<const AtlasFigure>(atlasFigureOf(*atlas, slowPeriod));
  const std::lock_guard lock(cache.mutex);
  cache.chainAtlasChain = chain;
  cache.chainAtlas = atlas;
  cache.chainAtlasFigure = figure;
  return {atlas, figure};
}

}  // namespace

Scene::Spec chainModesScene() {
  Scene::Spec scene;
  scene.name = QStringLiteral("Modes of three masses");
  scene.alias = QStringLiteral("modes-three");
  scene.title = tr("Modes of three masses");
  scene.text = tr(
      "<b>Nonlinear modes of a chain of three masses, and Krein collisions.</b> Each dot of the "
      "modes picture is a motion that repeats after k impacts (k = 1 blue, 2 orange), at its "
      "frequency and energy; filled dots are stable, rings unstable. The orbit shown (large "
      "ring) is on the family chosen, at the energy of the slider. <i>Look for:</i> its four "
      "multipliers against the unit circle, coloured by their Krein signature. It starts between "
      "two Krein collisions of family 1 (triangles on the picture): its multipliers are off the "
      "circle as four, a complex quadruplet, and the orbit is unstable. Drag the energy up a "
      "little: the four come back onto the circle as two pairs of opposite signature (blue and "
      "green), and the orbit is stable; down, the same at the other collision. No chain of two "
      "masses can show this. Two of the same colour pass through each other and stay on. "
      "<i>Click</i> any dot to follow that orbit in the "
      "trace and the chain.");
  scene.defaults.massChain = MassChainParams{};
  scene.defaults.massChain.masses = {1.0, 0.7, 0.4};
  scene.defaults.massChain.harmonics = {3, 2, 1};
  scene.defaults.modeFamily = 1;
  scene.defaults.modeEnergy = 0.032;  // family 1 between its two Krein collisions (E = 0.58 to 0.62)
  scene.massChain = true;
  scene.gloWeights = false;  // it starts on an orbit of the atlas
  scene.parameters = {ParamKey::Gap, ParamKey::ModeFamily, ParamKey::ModeEnergy};
  scene.plots = {PlotKind::ModesAtlas, PlotKind::Multipliers, PlotKind::Trace, PlotKind::Chain};
  scene.buildFromStart = [](const Scene&, const Params& params, const DerivedModel&,
                            const std::optional<core::ChainState>&, std::stop_token stop,
                            const ScenePartial& partial, SceneCache& cache) {
    const ChainChoice choice = chooseChain(params.massChain, params.gap, stop);
    if (!choice.chain) return refusedChainJob(choice.problem);
    const core::MassChain& chain = *choice.chain;
    const core::ChainModes modes = core::chainModes(chain);
    const core::SpectrumRatios ratios = core::detectRatios(modes.omega);
    SceneJob job;
    job.chain.summary = chainSummaryOf(chain, params.massChain, choice.designs, modes, ratios);
    job.chain.designs = choice.designs;
    const auto [atlas, figure] = atlasOf(chain, stop, partial, cache);
    if (!atlas) return job;  // stopped
    job.atlas = figure;
    if (atlas->searchBudgetExhausted) {
      SceneJob refused = refusedChainJob(tr("The returns of this chain's flights cannot be searched within the "
                                            "budget (its modes are too far apart): no atlas. Bring the masses or "
                                            "springs nearer"));
      refused.atlas = figure;  // (empty: the last chain's picture is not left standing)
      return refused;
    }
    if (figure->families.empty()) {
      SceneJob refused = refusedStartJob(tr("This chain has no admissible periodic orbit with impacts in the "
                                            "atlas's energies: change the masses or the resonance"));
      refused.atlas = figure;
      return refused;
    }
    const int last = int(figure->families.size()) - 1;
    job.sliderRanges[ParamKey::ModeFamily] = {0, double(std::max(last, 1))};
    const int f = std::clamp(int(std::lround(params.modeFamily)), 0, last);
    if (figure->families[std::size_t(f)].orbits.empty()) {  // (the atlas keeps none such: said, not indexed)
      return refusedStartJob(tr("Family %1 has no orbit: choose another").arg(f));
    }
    const std::size_t i = orbitNearestEnergy(figure->families[std::size_t(f)], params.modeEnergy);
    const core::ChainPeriodicOrbit& orbit = atlas->families[std::size_t(f)].path.orbits[i];
    job.orbit = shownOrbitOf(orbit);
    // the orbit over three of its periods, every mass on the grid
    core::experiments::ChainSeriesSpec run{chain, orbit.state, long(3 * orbit.impacts), 3 * orbit.period, 900,
                                           core::TrustMode::Auto};
    run.design = choice.design;
    job.spec.chains = {run};
    const AtlasFigure::Family& family = figure->families[std::size_t(f)];
    job.status = tr("Family %1 (%2 per period), orbit %3 of %4: energy %5, period %6, %7")
                     .arg(family.id)
                     .arg(family.impacts == 1 ? tr("1 impact") : tr("%1 impacts").arg(family.impacts))
                     .arg(i + 1)
                     .arg(family.orbits.size())
                     .arg(number(orbit.energy), number(orbit.period), job.orbit->stability);
    if (atlas->undecidedPeriods > 0) {
      job.status += tr(" · %1 periods of the 1IPP family undecided in double: parts may be missing "
                       "(grazelab-cli modes --precision long decides more)")
                        .arg(atlas->undecidedPeriods);
    }
    const int stopped = chain.stopped();
    job.timeUnit = TimeUnit{orbit.period, tr("T"), tr("the orbit's period T")};
    job.viewWords[PlotKind::Trace] = {
        tr("The orbit shown: u%1 / d over three periods").arg(subscriptDigits(stopped)),
        tr("The stopped mass over three periods of the orbit, from right after an impact: it meets the "
           "stop %1 times a period (dots: the exact run's contacts).")
            .arg(orbit.impacts)};
    job.ok = true;
    return job;
  };
  return scene;
}

}  // namespace grazelab::ui
