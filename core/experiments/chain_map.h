// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>

#include "core/experiments/maps.h"
#include "core/model/mass_chain.h"
#include "core/solver/chain_flight.h"

namespace grazelab::core {

/// Maps of a chain of N masses: the two-mass maps' grid, summaries and files (maps.h), over
/// coordinates of the start: an axis sets u_i or v_i (mass i) of every run's start, or the
/// weight lambda_i of mode i (fastest first) of a GLO_lambda start.
struct ChainMapAxis {
  enum class Kind { Position, Velocity, Weight };
  Kind kind = Kind::Position;  ///< u_i, v_i or lambda_i
  int index = 1;               ///< i, 1..N
  MapAxis range;               ///< the values (its `variable` unused)

  /// "u3", "v1", "w2".
  std::string name() const;
  bool weight() const { return kind == Kind::Weight; }
  friend bool operator==(const ChainMapAxis&, const ChainMapAxis&) = default;
};

/// "u3", "v1" or "w2" as an axis variable, i from 1 to n; nothing otherwise.
std::optional<ChainMapAxis> parseChainMapVariable(std::string_view text, Eigen::Index n);

struct ChainMapSpec {
  MassChain chain;
  ChainState start;  ///< every run's start before the axes set their coordinates (u/v axes)
  /// weight axes (both of them): every run starts on GLO_lambda at its touch (chainGloStart)
  /// plus `push`; lambda is `weights` (all 0 when empty) with the axes' weights set and the
  /// balancing weight, the last mode's no axis sets, 1 minus the others
  std::vector<double> weights;
  ChainState push;
  ChainMapAxis x;    ///< columns
  ChainMapAxis y;    ///< rows
  std::int64_t contacts = 1;  ///< contacts of each run
  /// each point's predictability horizon from a shadow run one precision up (TrustMode::Auto,
  /// compared event by event as the run goes: TrustMonitor); costs about 2x
  bool estimateHorizon = false;
};

/// Why the spec cannot be run (one line), or empty: a usable chain, the start's size, counts
/// >= 1 and at most 2^24 along an axis, finite ranges, two different coordinates; weight axes
/// both or neither, on three modes or more (one weight balances the others), with the push's
/// and the weights' sizes.
std::string checkChainMap(const ChainMapSpec& spec);

/// The mode whose weight balances a weight map's others (0-based): the last one no axis sets.
int balancingWeight(const ChainMapSpec& spec);

/// The period the free-flight times are measured in: the common period T of a commensurate
/// chain, else its slowest mode's period.
double chainMapPeriod(const MassChain& chain);

/// One point: the run from the start with the axes' coordinates set (or from its GLO_lambda
/// plus the push; no run where chainGloStart refuses the weights), `contacts` contacts, in
/// double and again one precision up where a contact or release is undecided (as simulate's
/// --precision auto). A flight from the stop starts at an impact, a grazing or a release and
/// ends at the next contact: fftFirst is the first one's length [time] (+inf when the flight
/// stays below the stop forever, NaN when the run has none), fftMin/Max/Mean over the run's
/// flights from the stop in units of chainMapPeriod; impacts, grazings, sticks counted; the
/// first impact's time; the horizon with estimateHorizon (NaN otherwise, or where the estimate
/// is unchecked). A start past the stop (u_s > d), or a run
/// that stays undecided in binary128 (a start on the stop whose departure its first three
/// derivatives do not decide), is no run: NaN and counts -1.
PointSummary chainMapPoint(const ChainMapSpec& spec, std::int64_t column, std::int64_t row,
                           std::stop_token stop = {});

/// Rows `rows` of the map, as computeMap does them. Precondition: checkChainMap(spec) is empty.
MapRows computeChainMap(const ChainMapSpec& spec, RowRange rows, const ParallelFor& parallelFor,
                        std::stop_token stop = {}, const MapRowsProgress& progress = {});

}  // namespace grazelab::core
