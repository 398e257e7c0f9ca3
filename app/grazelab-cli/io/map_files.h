// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <optional>

#include "io/json_value.h"
#include "io/map_document.h"

namespace grazelab::cli::map {

/// The files of a map (issue 10): PREFIX-QUANTITY.npy for each quantity (row index = y, column
/// index = x; counts int64, the rest float64), PREFIX.json (axes, model, start, version, which
/// rows), PREFIX.csv for small grids. Each file is written atomically (QSaveFile).

/// Grids up to this many points also get a CSV file.
inline constexpr std::int64_t kCsvMaxPoints = 100'000;

/// Writes every file of `map` under `prefix` and returns their names (the document's `files`:
/// quantity -> PREFIX-QUANTITY.npy, csv, relative to the JSON's folder); nothing, with a reason,
/// when one could not be written (no file is left half-written; those already complete stay).
std::optional<JsonValue> writeMapFiles(const QString& prefix, const StoredMap& map, QString& error);

/// Reads what writeMapFiles wrote under `prefix`.
std::optional<StoredMap> readMapFiles(const QString& prefix, QString& error);

/// Joins the stripes of one map into the whole map; refuses stripes of different maps, gaps and
/// overlaps. The result's description is the parts' spec, with run.seconds the sum.
std::optional<StoredMap> mergeStripes(std::vector<StoredMap> parts, QString& error);

}  // namespace grazelab::cli::map
