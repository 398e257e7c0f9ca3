// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/experiments/chain_map.h"
#include "core/experiments/maps.h"
#include "io/json_value.h"

// A map as a document and its points, without files (io/map_files.h writes and reads them):
// what the typed map computes and the Python module hands over. No Qt.
namespace grazelab::cli::map {

/// What was run: `spec` is the map's identity (equal for every shard of one map); `run` how
/// (threads, seconds, which rows).
struct MapDescription {
  JsonValue spec;
  JsonValue run;
};

/// The spec object of a map: format, version, axes (with their values), model (with T2),
/// start, contacts, the trust setting, the picture's quantity and the quantities' units.
JsonValue specJson(const core::MapSpec& spec, double period, const std::string& pictureQuantity);

/// The spec object of an N-mass map: the two-mass map's fields (specJson), the chain and its
/// period instead of the model, the axes by name (u3, v1, w2), the start.
JsonValue chainSpecJson(const core::ChainMapSpec& spec, double period, const std::string& pictureQuantity);

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

/// An axis as the spec object describes it.
core::MapAxis axisOf(const JsonValue& spec, const char* which);

/// The name of the variable of axis `which` ("x", "y") as the spec gives it ("u1", "w2", ...).
std::string axisVariable(const JsonValue& spec, const char* which);

}  // namespace grazelab::cli::map
