// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <optional>

#include "core/experiments/maps.h"
#include "io/json_value.h"

namespace grazelab::cli::map {

/// The files of a map (issue 10): PREFIX-QUANTITY.npy for each quantity (row index = y, column
/// index = x; counts int64, the rest float64), PREFIX.json (axes, model, start, version, which
/// rows), PREFIX.csv for small grids. Each file is written atomically (QSaveFile).

/// Grids up to this many points also get a CSV file.
inline constexpr std::int64_t kCsvMaxPoints = 100'000;

/// What was run: `spec` is the map's identity (equal for every shard of one map); `run` how
/// (threads, seconds, which rows).
struct MapDescription {
  JsonValue spec;
  JsonValue run;
};

/// The spec object of a map: format, version, axes (with their values), model (with T2),
/// start, contacts, the trust setting, the picture's quantity and the quantities' units.
JsonValue specJson(const core::MapSpec& spec, double period, const QString& pictureQuantity);

/// A map as its files hold it: a stripe (rows of totalRows) or the whole map.
struct StoredMap {
  MapDescription description;
  core::RowRange rows;
  std::int64_t columns = 0;
  std::int64_t totalRows = 0;
  std::vector<core::PointSummary> points;  ///< row-major, rows.rowEnd - rows.rowBegin rows
};

/// The JSON document of a map: its spec and its run (rows, total_rows, shape), with `files`
/// (names relative to the document) when it has files.
JsonValue mapDocument(const StoredMap& map, JsonValue files = JsonValue::null());

/// Writes every file of `map` under `prefix`. Returns false with a reason; no file is left
/// half-written (those already complete stay).
bool writeMapFiles(const QString& prefix, const StoredMap& map, QString& error);

/// Reads what writeMapFiles wrote under `prefix`.
std::optional<StoredMap> readMapFiles(const QString& prefix, QString& error);

/// Joins the stripes of one map into the whole map; refuses stripes of different maps, gaps and
/// overlaps. The result's description is the parts' spec, with run.seconds the sum.
std::optional<StoredMap> mergeStripes(std::vector<StoredMap> parts, QString& error);

/// An axis as the spec object describes it.
core::MapAxis axisOf(const JsonValue& spec, const char* which);

/// The name of the variable of axis `which` ("x", "y") as the spec gives it ("u1", "w2", ...).
std::string axisVariable(const JsonValue& spec, const char* which);

}  // namespace grazelab::cli::map
