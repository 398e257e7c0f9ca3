// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/parameter_map.h"

#include <chrono>

#include "parallel/tbb_parallel_for.h"

namespace grazelab::cli {

std::int64_t MapRequest::columns() const {
  return std::visit([](const auto& s) -> std::int64_t {
    if constexpr (std::is_same_v<std::decay_t<decltype(s)>, core::MapSpec>) return s.x.count;
    else return s.x.range.count;
  }, spec);
}

std::int64_t MapRequest::totalRows() const {
  return std::visit([](const auto& s) -> std::int64_t {
    if constexpr (std::is_same_v<std::decay_t<decltype(s)>, core::MapSpec>) return s.y.count;
    else return s.y.range.count;
  }, spec);
}

core::RowRange MapRequest::rows() const { return core::stripe(totalRows(), stripe, stripes); }

MapOutcome parameterMap(const MapRequest& request, std::stop_token stop, const MapProgress& progress) {
  using Clock = std::chrono::steady_clock;
  const core::RowRange rows = request.rows();
  const std::int64_t points = (rows.rowEnd - rows.rowBegin) * request.columns();
  core::MapRowsProgress onProgress;
  if (progress) onProgress = [&progress, points](std::int64_t done) { progress(done, points); };
  const core::ParallelFor parallelFor = parallel::tbbParallelFor(request.threads);
  const auto started = Clock::now();
  const auto* twoMass = std::get_if<core::MapSpec>(&request.spec);
  const auto* chain = std::get_if<core::ChainMapSpec>(&request.spec);
  core::MapRows computed = twoMass ? core::computeMap(*twoMass, rows, parallelFor, stop, onProgress)
                                   : core::computeChainMap(*chain, rows, parallelFor, stop, onProgress);
  MapOutcome outcome;
  outcome.seconds = std::chrono::duration<double>(Clock::now() - started).count();
  if (!computed.complete) return outcome;
  outcome.status = MapStatus::Computed;
  map::StoredMap& stored = outcome.map;
  stored.description.spec = twoMass ? map::specJson(*twoMass, computed.period, request.picture)
                                    : map::chainSpecJson(*chain, computed.period, request.picture);
  stored.description.run = JsonValue::object(
      {{"seconds", JsonValue::number(outcome.seconds)},
       {"threads", JsonValue::of(std::int64_t(request.threads))},
       {"shard", JsonValue::of(std::to_string(request.stripe) + "/" + std::to_string(request.stripes))},
       {"complete", JsonValue::of(true)}});
  stored.rows = rows;
  stored.columns = computed.columns;
  stored.totalRows = request.totalRows();
  stored.points = std::move(computed.points);
  return outcome;
}

}  // namespace grazelab::cli
