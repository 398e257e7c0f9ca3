// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>

#include <string>
#include <vector>

namespace grazelab::cli {

/// A table of doubles (row-major over `columns`) as CSV, the way `family` and `modes` write it: a
/// header of the column names, each number with 17 significant digits, an empty cell where there
/// is no value (not finite), and a column named "stability" as its class in words.
QByteArray tableCsv(const std::vector<std::string>& columns, const std::vector<double>& table);

}  // namespace grazelab::cli
