// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/compute/atlas_figure.h"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace grazelab::ui {

namespace {

QString word(std::string_view text) { return QString::fromUtf8(text.data(), qsizetype(text.size())); }

QString endLabel(std::string_view kind) { return QStringLiteral("end (%1)").arg(word(kind)); }

}  // namespace

AtlasFigure atlasFigureOf(const core::ModesAtlas<double>& atlas, double T2) {
  using Kind = AtlasFigure::MarkKind;
  AtlasFigure figure;
  figure.slowPeriod = T2;
  for (const core::ModeFamily<double>& family : atlas.families) {
    const int index = int(figure.families.size());
    AtlasFigure::Family drawn{family.id, family.impacts, {}};
    for (const core::FamilyOrbit<double>& orbit : family.orbits) {
      drawn.orbits.push_back({orbit.energy, orbit.period, orbit.stability == core::Stability::Elliptic,
                              core::chainStateOf(orbit.state)});
    }
    figure.families.push_back(std::move(drawn));
    for (const core::FamilyBifurcation<double>& b : family.bifurcations) {
      Kind kind = Kind::Other;
      QString label = word(core::toString(b.kind));
      if (b.kind == core::PointKind::PeriodDoubling) {
        // birthProblem is empty where no search was made (beyond the impacts shown)
        const bool orphan = b.born < 0 && !b.birthProblem.empty();
        kind = orphan ? Kind::OrphanFlip : Kind::Flip;
        if (orphan) label = QStringLiteral("flip, no family found");
      }
      figure.marks.push_back({kind, index, label, b.energy, b.T});
    }
    for (const core::FamilyEnd<double>* end : {&family.startEnd, &family.end}) {
      if (!(end->period > 0)) continue;
      const Kind kind = end->kind == core::PointKind::GrazingOrbit ? Kind::GrazingEnd : Kind::Other;
      figure.marks.push_back({kind, index, endLabel(core::toString(end->kind)), end->energy, end->period});
    }
  }
  return figure;
}

AtlasFigure atlasFigureOf(const core::ChainAtlas<double>& atlas, double slowPeriod) {
  using Kind = AtlasFigure::MarkKind;
  AtlasFigure figure;
  figure.slowPeriod = slowPeriod;
  for (const core::ChainAtlasFamily<double>& family : atlas.families) {
    const int index = int(figure.families.size());
    const std::vector<core::ChainPeriodicOrbit>& orbits = family.path.orbits;
    AtlasFigure::Family drawn{family.id, family.path.impacts, {}};
    for (const core::ChainPeriodicOrbit& orbit : orbits) {
      drawn.orbits.push_back({orbit.energy, orbit.period, orbit.monodromy.stability == core::ChainStability::Elliptic,
                              orbit.state});
    }
    figure.families.push_back(std::move(drawn));
    for (std::size_t i = 0; i < family.path.changes.size(); ++i) {
      const core::ChainFamilyChange<double>& change = family.path.changes[i];
      Kind kind = change.kind == core::ChainBifurcationKind::KreinCollision ? Kind::KreinCollision : Kind::Other;
      QString label = word(core::toString(change.kind));
      if (change.kind == core::ChainBifurcationKind::PeriodDoubling) {
        bool orphan = false;
        for (const core::ChainAtlasBranch& branch : family.branches) {
          orphan = orphan || (branch.change == i && branch.outcome == core::ChainBranchOutcome::NotFound);
        }
        kind = orphan ? Kind::OrphanFlip : Kind::Flip;
        if (orphan) label = QStringLiteral("flip, no family found");
      }
      figure.marks.push_back({kind, index, label, change.energy, change.period});
    }
    if (orbits.empty()) continue;
    const std::pair<const core::ChainAtlasEnd*, const core::ChainPeriodicOrbit*> ends[] = {
        {family.firstEnd ? &*family.firstEnd : nullptr, &orbits.front()}, {&family.lastEnd, &orbits.back()}};
    for (const auto& [end, orbit] : ends) {
      if (!end) continue;
      const Kind kind = end->kind == core::ChainFamilyEnd::GrazingOrbit ? Kind::GrazingEnd : Kind::Other;
      figure.marks.push_back({kind, index, endLabel(core::toString(end->kind)), orbit->energy, orbit->period});
    }
  }
  return figure;
}

namespace {

// the family's lowest and highest energies (its orbits: at least one)
std::pair<double, double> energySpan(const AtlasFigure::Family& family) {
  const auto [low, high] = std::minmax_element(
      family.orbits.begin(), family.orbits.end(),
      [](const AtlasFigure::Orbit& a, const AtlasFigure::Orbit& b) { return a.energy < b.energy; });
  return {low->energy, high->energy};
}

}  // namespace

std::size_t orbitNearestEnergy(const AtlasFigure::Family& family, double position) {
  if (family.orbits.empty()) return 0;
  const auto [low, high] = energySpan(family);
  const double wanted = std::log(low) + std::clamp(position, 0.0, 1.0) * (std::log(high) - std::log(low));
  std::size_t best = 0;
  for (std::size_t i = 1; i < family.orbits.size(); ++i) {
    if (std::abs(std::log(family.orbits[i].energy) - wanted) < std::abs(std::log(family.orbits[best].energy) - wanted)) {
      best = i;
    }
  }
  return best;
}

double energyPosition(const AtlasFigure::Family& family, double energy) {
  if (family.orbits.empty()) return 0;
  const auto [low, high] = energySpan(family);
  return high > low ? (std::log(energy) - std::log(low)) / (std::log(high) - std::log(low)) : 0.0;
}

ShownOrbit shownOrbitOf(const core::PeriodicOrbit<double>& orbit) {
  ShownOrbit shown;
  shown.energy = orbit.energy;
  shown.period = orbit.period;
  shown.impacts = orbit.impacts;
  for (const auto& mu : orbit.multipliers) shown.multipliers.emplace_back(mu[0], mu[1]);
  shown.stability = QString::fromUtf8(core::toString(core::decidedStability(orbit)).data());
  shown.trace = orbit.trace;
  return shown;
}

ShownOrbit shownOrbitOf(const core::ChainPeriodicOrbit& orbit) {
  ShownOrbit shown;
  shown.energy = orbit.energy;
  shown.period = orbit.period;
  shown.impacts = orbit.impacts;
  for (const core::ChainMultiplier<double>& mu : orbit.monodromy.multipliers) {
    shown.multipliers.emplace_back(mu.re, mu.im);
    shown.krein.push_back(mu.krein);
  }
  shown.stability = QString::fromUtf8(core::toString(orbit.monodromy.stability).data());
  return shown;
}

}  // namespace grazelab::ui
