// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <stop_token>
#include <vector>

#include "core/model/chain.h"
#include "core/numbers/scalar.h"

namespace grazelab::core {

/// One member of the one-impact-per-period family (docs/model.md section 5), as a frequency-energy
/// curve shows it.
struct FamilyPoint {
  double T = 0;          ///< period [time]
  double omega = 0;      ///< 2 pi / T [1/time]
  double V = 0;          ///< post-impact velocity of mass 2 [length/time] (< 0 when admissible)
  double u1 = 0;         ///< u1 at the impact [length]
  double energy = 0;     ///< energy of the orbit (constant along it)
  bool admissible = false;  ///< V < 0 and the open flight stays below the stop (exact search)
};

/// The 1IPP orbits of the chain for `count` periods evenly spaced in (0, T2), T2 k/(count+1),
/// and for T2 (1 - 2^-k), k = 8 ... 40, where the family ends on the grazing orbit GLO_lambda*
/// (V -> 0), sorted by T. Periods at a multiple of T1 or T2 (no orbit) are left out. Each
/// member is computed in binary128 from its double period and rounded once.
/// A stop ends it early (the members so far).
std::vector<FamilyPoint> onePeriodicFamily(const Chain<double>& chain, std::int64_t count,
                                           std::stop_token stop = {});

/// The grazing end of the family: the GLO_lambda* data (V = 0, u1 of GLO_lambda*) and its energy.
FamilyPoint grazingEnd(const Chain<double>& chain);

}  // namespace grazelab::core
