// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <functional>
#include <stop_token>
#include <string>
#include <vector>

#include "core/experiments/state_records.h"
#include "core/model/chain_design.h"
#include "core/numbers/scalar.h"
#include "core/model/mass_chain.h"
#include "core/solver/chain_run.h"
#include "core/solver/trust.h"

namespace grazelab::core::experiments {

/// A run of a chain of N masses as the explorer's N-mass scenes draw it (docs/explorer.md): the
/// exact run (core/solver/chain_run.h), the chain's spectrum and common period, every free
/// flight's length, and every mass's state on a time grid over the run's first `window` (or, with
/// `maxGridPoints`, at that step over the whole run).
struct ChainSeriesSpec {
  MassChain chain;   ///< usable (validate(chain) empty)
  ChainState start;  ///< u_s <= d
  long contacts = 200;
  double window = 0;  ///< [time] the grid's span from t = 0 (0: none)
  int gridPoints = 1500;  ///< over `window`: the grid's step is window / (gridPoints - 1)
  TrustMode trust = TrustMode::Auto;  ///< the run's error estimate (core/solver/trust.h)
  /// the linear motion alone, the stop ignored (a grazing linear orbit that passes the stop is
  /// drawn passing it): the grid only, no run (no events, no flights)
  bool free = false;
  /// more than gridPoints: the grid goes on past `window` at the same step to the run's end, or
  /// to this many points (a view that shows `window` at a time can then follow the whole run)
  int maxGridPoints = 0;
  /// when `start` is GLO_lambda at its touch, unpushed: its weights (fastest mode first). Its modes
  /// of weight 0 are then exactly still (BasicChainStart; GLOM_1 of a 3:2:1 chain grazes at T/3),
  /// and the run's command line gives the start as these weights. Empty: `start` as it is.
  std::vector<double> gloWeights = {};
  /// the design the chain's springs are (core/model/chain_design.h), when designed: a run raised
  /// to long double or binary128 takes them refined for its numbers there, as the command line
  /// does (designedSpringsIn), not double's rounding of them
  std::optional<DesignChoice> design = {};
};

/// One free flight: from an event (or the start) to the next contact.
struct ChainFlight {
  long contact = 0;       ///< the contact that ends it (1-based)
  double duration = 0;    ///< [time]
  /// the chain's period (T, or the slowest mode's) less the flight's length, as the run computed
  /// it: exact near the period, where duration / period would round to 1 (ChainEvent::shortfall)
  double shortfall = 0;
  bool fromStop = false;  ///< it starts on the stop (after an impact, a grazing or a release)
  bool afterImpact = false;
};

struct ChainSeries {
  MassChain chain;
  ChainState start;
  std::vector<double> gloWeights;  ///< ChainSeriesSpec::gloWeights
  long contactsAsked = 0;
  ChainRun run;
  ChainModes modes;
  SpectrumRatios ratios;
  double period =
      0;  ///< T = 2 pi / w0 when commensurate (every flight from the stop ends by it), else 0
  std::vector<ChainFlight> flights;
  StateRecords grid;  ///< every mass's state on the grid (t, u1..uN, v1..vN)
  /// the state at each contact of the stopped mass, its velocities just before it: the points
  /// of the section H (u_s = d)
  StateRecords section;
  Trust trust;  ///< the run again one precision up, compared event by event (Unchecked: off)
  /// the precision the run was made in: double, or long double then binary128 when double met
  /// a contact it could not decide (--precision auto's rule); its numbers here rounded to double
  Precision precision = Precision::Double;
  /// the time of the contact the precision below could not decide (raised runs only) [time]
  double undecidedAt = 0;
  /// the run is whole and its error estimate is being made (`trust` Unchecked until then): the
  /// report that shows the run before its estimate, which costs about as much again
  bool trustPending = false;
};

/// What a series in progress hands on: the series so far (the run's events, flights and grid up
/// to its last contact; its totals those of the run so far) and the fraction of the asked
/// contacts made; last, when an estimate is asked for, the whole run before it (trustPending). A
/// raised run starts again from t = 0 (its `precision` says so).
using ChainSeriesProgress = std::function<void(const ChainSeries& sofar, double progress)>;

/// Runs `spec` in double, handing the series so far to `progress` about every `chunkSeconds` of
/// work (never spending more than a fifth of the time on the copies); when double meets a contact
/// it cannot decide, the series again from its start in long double, then binary128. Stops early
/// (run cancelled) when `stop` is requested. In pieces or at once, the same bits.
ChainSeries chainSeries(const ChainSeriesSpec& spec, std::stop_token stop = {},
                        const ChainSeriesProgress& progress = {}, double chunkSeconds = 0.030);

}  // namespace grazelab::core::experiments
