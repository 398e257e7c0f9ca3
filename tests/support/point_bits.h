// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <bit>
#include <cstdint>

#include "core/experiments/maps.h"

namespace grazelab::testing {

/// The same map point bit for bit (NaN included), field by field.
inline bool sameBits(const core::PointSummary& a, const core::PointSummary& b) {
  const double da[] = {a.fftFirst, a.fftMin, a.fftMax, a.fftMean, a.firstImpactTime, a.horizon};
  const double db[] = {b.fftFirst, b.fftMin, b.fftMax, b.fftMean, b.firstImpactTime, b.horizon};
  for (int i = 0; i < 6; ++i) {
    if (std::bit_cast<std::uint64_t>(da[i]) != std::bit_cast<std::uint64_t>(db[i])) return false;
  }
  return a.impacts == b.impacts && a.grazings == b.grazings && a.sticks == b.sticks &&
         a.valid == b.valid;
}

}  // namespace grazelab::testing
