// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "commands/modes_atlas_command.h"
#include "io/json_value.h"

// The atlas of a chain of N masses as `modes` writes it: its JSON document and each family's
// table (commands/modes_atlas_command.h says what they hold). No Qt.
namespace grazelab::cli {

/// energy, period, omega, class, min_impact_speed, u1..uN, v1..vN, then muK_re, muK_im,
/// muK_krein for K = 1 .. 2N - 2.
std::vector<std::string> chainModesColumns(int masses);

/// The rows of family `index`, row-major over chainModesColumns, in double.
template <typename S>
std::vector<double> chainModesTable(const ChainAtlasIn<S>& in, std::size_t index);

/// The atlas's JSON document; with `base` each family names its CSV file (BASE-family-N.csv).
template <typename S>
JsonValue chainModesDocument(const ChainAtlasIn<S>& in, const ModesOutcome& outcome,
                             const std::optional<std::string>& base);

}  // namespace grazelab::cli
