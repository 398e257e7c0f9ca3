// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <stop_token>
#include <vector>

#include "core/model/two_mass_form.h"
#include "core/numbers/scalar.h"
#include "core/orbits/special_orbits.h"

namespace grazelab::core {

/// The 1IPP orbits of the chain (admissible or not, each with its data) for `count` periods evenly spaced in (0, T2), T2 k/(count+1),
/// and for T2 (1 - 2^-k), k = 8 ... 40, where the family ends on the grazing orbit GLO_lambda*
/// (V -> 0), sorted by T. Periods at a multiple of T1 or T2 (no orbit) are left out. Each
/// member is computed in binary128 from its double period and rounded once.
/// A stop ends it early (the members so far).
std::vector<OnePeriodicOrbit<double>> onePeriodicFamily(const TwoMassForm<double>& chain, std::int64_t count,
                                                        std::stop_token stop = {});

/// The grazing end of the family: T = T2, the GLO_lambda* data (V = 0, u1 of GLO_lambda*) and
/// its energy; admissible as the family's limit.
OnePeriodicOrbit<double> grazingEnd(const TwoMassForm<double>& chain);

}  // namespace grazelab::core
