// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/table_csv.h"

#include <cmath>

#include "core/orbits/chain_monodromy.h"
#include "core/orbits/periodic_orbit.h"

namespace grazelab::cli {

QByteArray tableCsv(const std::vector<std::string>& columns, const std::vector<double>& table) {
  QByteArray csv;
  for (std::size_t c = 0; c < columns.size(); ++c) csv += (c ? "," : "") + QByteArray::fromStdString(columns[c]);
  csv += "\n";
  for (std::size_t at = 0; at + columns.size() <= table.size() && !columns.empty(); at += columns.size()) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const double value = table[at + c];
      if (c) csv += ",";
      if (!std::isfinite(value)) continue;
      // the classes as words: a two-mass family's trace's, a chain's multipliers'
      if (columns[c] == "stability") {
        csv += QByteArray(core::toString(core::Stability(int(value))).data());
      } else if (columns[c] == "class") {
        csv += QByteArray(core::toString(core::ChainStability(int(value))).data());
      } else {
        csv += QByteArray::number(value, 'g', 17);
      }
    }
    csv += "\n";
  }
  return csv;
}

}  // namespace grazelab::cli
