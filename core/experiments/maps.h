// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/model.h"
#include "core/solver/chain_run.h"
#include "core/solver/trust.h"
#include "core/orbits/starts.h"

namespace grazelab::core {

/// Maps (issue 10): many independent exact runs over a 2-D grid, each reduced to a small
/// summary. Core starts no thread: the caller hands in how to run a loop (ParallelFor), serial
/// or on all cores; every grid point is computed alone, so the result does not depend on it.

/// What an axis of a map varies.
enum class MapVariable {
  U1,         ///< u1 of the start [length]
  V1,         ///< v1 of the start [length/time]
  V2,         ///< v2 of the start [length/time] (<= 0 on H: leaving the stop)
  Lambda,     ///< the start is GLO_lambda data
  Epsilon,    ///< size of the push: start + epsilon * direction
  MassRatio,  ///< m2/m1 (m1 fixed; a designed chain keeps its 1:2 k2)
  Gap,        ///< the gap d [length]
  Detuning,   ///< w1/w2 - 2: k2 for that ratio on the model's branch (upper for a chain given
              ///< by k2); 0 is the 1:2 design itself
};
/// "u1", "v1", "v2", "lambda", "epsilon", "mass-ratio", "gap", "detuning".
std::string_view toString(MapVariable variable);
std::optional<MapVariable> parseMapVariable(std::string_view text);
/// Every name parseMapVariable takes, for error messages: "u1, v1, ..., detuning".
std::string mapVariableNames();

/// `count` values from `from` to `to`, both included (one value: `from`).
struct MapAxis {
  MapVariable variable = MapVariable::U1;
  double from = 0;
  double to = 1;
  std::int64_t count = 1;
  /// The i-th value as numpy.linspace(from, to, count)[i] computes it: i * step + from, the
  /// last one `to` exactly.
  double at(std::int64_t i) const;

  friend bool operator==(const MapAxis&, const MapAxis&) = default;
};

/// A map: the chain, the start the axes modify, the two axes, the length of each run.
struct MapSpec {
  Model model;  ///< as given (design set: k2 follows m2/m1; unset: k2 as given)
  /// How each run starts before the axes change it (its own perturbation is not used). Nothing:
  /// the grazing-start plane (u1, gap, v1, 0) with u1 = v1 = 0 where no axis sets them.
  std::optional<StartSpec<double>> start;
  /// Added to the start after the axes set its coordinates; on an epsilon axis, the direction
  /// that epsilon scales (default (0, 0, 0, -1): mass 2 pushed off the stop).
  std::optional<State> perturbation;
  MapAxis x;  ///< columns
  MapAxis y;  ///< rows
  std::int64_t contacts = 1;  ///< contacts of each run
  bool estimateHorizon = false;  ///< a shadow run per point (TrustMode::Auto); costs about 2x

  friend bool operator==(const MapSpec&, const MapSpec&) = default;
};

/// Why the spec cannot be run (one line), or empty: counts >= 1 and at most 2^24 points along
/// an axis, finite ranges, two different variables, combinations that make sense (lambda sets
/// the whole start: no u1/v1/v2 axis and no explicit start beside it).
std::string checkMap(const MapSpec& spec);

/// The summary of one run. NaN where a value is not defined (no flight from the stop ended
/// within the run, no impact, an unusable model or start at that point); +infinity where the
/// run proved that it never comes (a resonant free flight that never reaches the stop). At a
/// point with no run (valid false) the counts are -1.
struct PointSummary {
  double fftFirst = 0;  ///< FFT of the first flight that leaves the stop [time]
  double fftMin = 0;    ///< min FFT / T2 over the run's flights from the stop
  double fftMax = 0;    ///< max FFT / T2
  double fftMean = 0;   ///< mean FFT / T2
  std::int64_t impacts = 0;
  std::int64_t grazings = 0;
  std::int64_t sticks = 0;
  double firstImpactTime = 0;  ///< time of the first impact [time]
  double horizon = 0;   ///< predictability horizon [time] (NaN unless estimateHorizon)
  bool valid = false;   ///< the point's model and start were usable

  friend bool operator==(const PointSummary&, const PointSummary&) = default;
};

/// The quantities of a map, as the files name them, in this order.
enum class Quantity {
  FftFirst, FftMin, FftMax, FftMean, Impacts, Grazings, Sticks, FirstImpactTime, Horizon
};
struct QuantityInfo {
  Quantity quantity;
  std::string_view name;     ///< "fft_first", ...
  std::string_view unit;     ///< "time", "T2", "count"
  bool integer;              ///< a count (stored as int64)
  std::string_view meaning;  ///< one line
};
const std::array<QuantityInfo, 9>& quantities();
std::optional<Quantity> parseQuantity(std::string_view name);
/// The quantity as a number (counts too); NaN at a point with no run.
double valueOf(const PointSummary& point, Quantity quantity);

/// Rows [rowBegin, rowEnd) of the grid: all of it, or stripe k (1-based) of n.
struct RowRange {
  std::int64_t rowBegin = 0;
  std::int64_t rowEnd = 0;
};
/// Stripe k of n over `rows` rows: rows [(k-1) rows / n, k rows / n). Precondition 1 <= k <= n.
RowRange stripe(std::int64_t rows, std::int64_t k, std::int64_t n);

/// The computed part of a map: row-major (row = y index, column = x index).
struct MapRows {
  RowRange rows;
  std::int64_t columns = 0;
  std::vector<PointSummary> points;  ///< (rowEnd - rowBegin) x columns
  /// T2 of the model as given [time] (NaN if it cannot be formed); with a mass-ratio or
  /// detuning axis each point's FFT/T2 uses that point's own T2
  double period = 0;
  bool complete = false;    ///< false when stopped early: points not reached stay invalid
  std::int64_t computed = 0;  ///< points computed
};

/// Runs `body(begin, end)` over pieces that cover [0, count) exactly once, possibly at the
/// same time on several threads, and returns when all are done.
using ParallelFor =
    std::function<void(std::int64_t count, const std::function<void(std::int64_t, std::int64_t)>& body)>;
/// One piece on the calling thread.
ParallelFor serialFor();

/// Called after each piece with the number of points done so far; may be called from several
/// threads at once.
using MapRowsProgress = std::function<void(std::int64_t done)>;

/// Rows `rows` of a grid of `columns` columns whose point (column, row) is `point(column, row,
/// stop)`, every point `unset` until computed: pieces handed to `parallelFor`, each watching a
/// stop token of its own (computeMap's and computeChainMap's loop; `period` left 0).
using MapPoint = std::function<PointSummary(std::int64_t column, std::int64_t row, std::stop_token stop)>;
MapRows computeRows(std::int64_t columns, RowRange rows, const MapPoint& point, const PointSummary& unset,
                    const ParallelFor& parallelFor, std::stop_token stop = {},
                    const MapRowsProgress& progress = {});

/// The summary of one run of a chain made ready (any chain; the note's by its kernel) from
/// `start`: `contacts` contacts and, until its first flight from the stop has ended, up to three
/// more (a start pressed on the stop sticks first); the free-flight times as the kernel computed
/// them, over `period`; with `estimateHorizon`, the horizon of its error estimate (TrustMonitor).
/// In S. Returns false, leaving `summary` alone, when the run met a contact S cannot decide and
/// `raise` asks for a higher precision to decide it; without `raise` such a run is no run (NaN,
/// -1). `shadow`: the chain's shadow, when the caller made it once for many runs (else made here
/// from the chain widened: a map's parameters are the numbers it was given, read exactly).
template <typename S>
bool summarizeRun(const BasicReadyChain<S>& chain, const BasicChainStart<S>& start, std::int64_t contacts,
                  double period, bool estimateHorizon, bool raise, std::stop_token stop, PointSummary& summary,
                  const ChainShadow<S>* shadow = nullptr);

/// Computes rows `rows` of the map. Precondition: checkMap(spec) is empty.
MapRows computeMap(const MapSpec& spec, RowRange rows, const ParallelFor& parallelFor,
               std::stop_token stop = {}, const MapRowsProgress& progress = {});

/// One point of the map, alone (what sweep computes at column i, row j).
PointSummary mapPoint(const MapSpec& spec, std::int64_t column, std::int64_t row,
                        std::stop_token stop = {});

}  // namespace grazelab::core
