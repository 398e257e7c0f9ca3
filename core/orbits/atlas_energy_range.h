// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

namespace grazelab::core {

/// The energies over which an atlas follows families: its default for a chain is 1/100 to 10000
/// times the energy of the grazing end of the chain's 1IPP family, where the families are born
/// and end (defaultAtlasEnergyRange for the note's form, defaultChainAtlasEnergyRange for any
/// chain).
template <typename S>
struct AtlasEnergyRange {
  S low = 0;
  S high = 0;
};

}  // namespace grazelab::core
