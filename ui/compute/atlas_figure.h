// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <complex>
#include <optional>
#include <vector>

#include "core/orbits/chain_atlas.h"
#include "core/orbits/modes_atlas.h"
#include "core/orbits/periodic_orbit.h"
#include "core/solver/chain_flight.h"

// The atlas of modes and the orbit a scene follows, as the explorer's views draw them: one form
// for the two-mass atlas and for the atlas of any chain, so that one modes picture and one
// multipliers view serve both (made from core's results, nothing computed).
namespace grazelab::ui {

struct AtlasFigure {
  struct Orbit {
    double energy = 0;
    double period = 0;
    bool stable = false;     ///< elliptic: every nontrivial multiplier on the unit circle
    core::ChainState state;  ///< just after an impact: the start that follows it
  };
  struct Family {
    int id = 0;
    int impacts = 1;
    std::vector<Orbit> orbits;  ///< in the order followed
  };
  enum class MarkKind {
    Flip,            ///< a period doubling where a family of twice the impacts was found or reached
    OrphanFlip,      ///< a period doubling where the search found no family
    KreinCollision,  ///< two pairs of opposite Krein signature meet and leave the circle (N >= 3)
    GrazingEnd,      ///< a family's end at a linear orbit grazing the stop
    Other,           ///< another change (a fold) or end (an energy limit): listed, not drawn
  };
  struct Mark {
    MarkKind kind = MarkKind::Flip;
    int family = 0;  ///< the index of its family
    QString label;   ///< core's word for it ("period-doubling", "end (grazing-orbit)", ...)
    double energy = 0;
    double period = 0;
  };
  std::vector<Family> families;
  std::vector<Mark> marks;
  /// the chain's slow period (T2; a chain of N masses: its common period, or its slowest mode's):
  /// the unit of the CSV's T column
  double slowPeriod = 0;
};

/// The orbit a scene follows with its multipliers.
struct ShownOrbit {
  double energy = 0;
  double period = 0;
  int impacts = 1;
  /// the nontrivial multipliers (2 for two masses, 2N - 2 for N)
  std::vector<std::complex<double>> multipliers;
  /// each multiplier's Krein signature (+1, -1; 0 off the circle or on the real axis); empty for
  /// two masses, whose pair on the circle is always one of each
  std::vector<int> krein;
  QString stability;  ///< its class in words ("elliptic", "complex-quadruplet", ...)
  std::optional<double> trace;  ///< two masses: tr DP^k, which decides the class
};

/// The two-mass atlas (core/orbits/modes_atlas.h) as a figure: flips, flips without a family and
/// grazing ends marked.
AtlasFigure atlasFigureOf(const core::ModesAtlas<double>& atlas, double T2);
/// The atlas of any chain (core/orbits/chain_atlas.h) as a figure: its doublings (without a
/// family where none was found), Krein collisions and grazing ends marked.
AtlasFigure atlasFigureOf(const core::ChainAtlas<double>& atlas, double slowPeriod);

/// Where an orbit of energy `energy` lies along `family`'s energies, from 0 (its lowest) to 1 (its
/// highest) on a log scale: the position an energy slider along the family takes.
double energyPosition(const AtlasFigure::Family& family, double energy);
/// The index of the family's orbit nearest (in log E) the energy at `position` (clamped to
/// [0, 1]); with a fold, the first of those equally near.
std::size_t orbitNearestEnergy(const AtlasFigure::Family& family, double position);

ShownOrbit shownOrbitOf(const core::PeriodicOrbit<double>& orbit);
ShownOrbit shownOrbitOf(const core::ChainPeriodicOrbit& orbit);

}  // namespace grazelab::ui
