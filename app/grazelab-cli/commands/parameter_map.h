// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <functional>
#include <stop_token>
#include <string>
#include <variant>

#include "core/experiments/chain_map.h"
#include "core/experiments/maps.h"
#include "io/map_document.h"

// `map` as a typed command, the one both faces call (as `orbit` and `glo-set` are): the command
// line reads --x, --y, the chain, --shard, --threads into a MapRequest and writes the outcome's
// files and picture; the Python module hands the same map over as arrays. No Qt.
namespace grazelab::cli {

/// A map to compute: a two-mass map (the note's engine) or a map of a chain of N masses, the
/// stripe of its rows, on how many threads, and the quantity its picture draws (kept in the
/// document: the picture itself is the command line's).
struct MapRequest {
  std::variant<core::MapSpec, core::ChainMapSpec> spec;
  std::int64_t stripe = 1;   ///< K of --shard K/N (1-based)
  std::int64_t stripes = 1;  ///< N
  int threads = 1;
  std::string picture = "fft_first";

  /// The grid's columns and, all stripes together, rows.
  std::int64_t columns() const;
  std::int64_t totalRows() const;
  /// The rows this request computes: stripe K of N.
  core::RowRange rows() const;
};

enum class MapStatus {
  Computed,
  Interrupted,  ///< the stop token ended it: no map
};

/// The map computed: its document's spec and run (seconds, threads, shard) and its points.
struct MapOutcome {
  MapStatus status = MapStatus::Interrupted;
  map::StoredMap map;
  double seconds = 0;
};

/// Called after each piece with the points done and the points of the request, from any thread.
using MapProgress = std::function<void(std::int64_t done, std::int64_t total)>;

/// Computes the request's rows on its threads (oneTBB). Precondition: the spec is checked
/// (core::checkMap, core::checkChainMap).
MapOutcome parameterMap(const MapRequest& request, std::stop_token stop = {}, const MapProgress& progress = {});

}  // namespace grazelab::cli
