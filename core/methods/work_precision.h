// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "core/methods/compare.h"
#include "core/solver/trust.h"

namespace grazelab::core::methods {

/// How a setting is timed: a fixed number of runs, fewer once a time cap is spent (at least
/// one), minimum and median kept (DiffEqDevTools' practice). A short run is repeated until
/// `minSeconds` are spent (at most `maxRuns` times): the minimum of five 50-microsecond runs
/// still carries a cold cache or a timer tick.
struct TimingPolicy {
  int runs = 5;
  double capSeconds = 3;
  double minSeconds = 0.2;
  int maxRuns = 1000;
};

/// One row of the work-precision report: one setting of one method.
struct WorkPrecisionPoint {
  MethodSetting setting;
  double secondsMin = 0;
  double secondsMedian = 0;
  int runs = 0;
  std::int64_t steps = 0;
  Errors errors;
  RunStatus status = RunStatus::Completed;
  std::string reason;
};

/// Times `setting` on the task and measures its errors against the reference (from its first
/// run; every run of a setting computes the same numbers). `firstRun`, when given, receives
/// that first run (for an overlay of its trajectory).
WorkPrecisionPoint measurePoint(const Task& task, const Reference& reference,
                                const MethodSetting& setting, const WorkBudget& budget,
                                const TimingPolicy& timing, std::stop_token stop = {},
                                MethodRun* firstRun = nullptr);
WorkPrecisionPoint measurePoint(const ChainTask& task, const ChainReference& reference,
                                const MethodSetting& setting, const WorkBudget& budget,
                                const TimingPolicy& timing, std::stop_token stop = {},
                                ChainMethodRun* firstRun = nullptr);

/// The CVODE tolerance of the penalty method in the report.
inline constexpr double kPenaltyReportRtol = 1e-12;

/// The settings the report sweeps for a method on a problem with slow period T2: steps h from
/// 1e-3 T2 down to 1e-6 T2 by quarter decades, tolerances 1e-3 ... 1e-15, k_c 1e2 ... 1e12
/// (relative to k1 of the model; then k_c = 1e12 k1 at tolerances 1e-4 ... 1e-10), the exact
/// solver in its three precisions. `quick`: fewer and cheaper ones.
std::vector<MethodSetting> reportSettings(MethodKind kind, double period, double k1, bool quick);

/// Which error a convergence fit uses.
enum class ErrorMeasure { State, ContactTime };

/// A least-squares slope of log(error) against log(parameter) over a method's points (for the
/// penalty method against log(1 / k_c), so that every slope is positive when the error falls).
struct Slope {
  double value = 0;
  int points = 0;  ///< points in the fit; no fit below 3
};

/// The fit over the asymptotic range: completed runs with every contact matched and the error
/// above the double-rounding floor (1e-13) and below 1e-2 (beyond it the motion has already
/// left the reference's path, and the error saturates). Nothing when fewer than 3 points qualify.
std::optional<Slope> fittedSlope(const std::vector<WorkPrecisionPoint>& points,
                                 ErrorMeasure measure);

/// The run time at which a method's state error reaches `target`: log-log interpolation
/// between its two points that bracket it (the cheapest one below it when none is above).
/// Nothing when no completed setting reaches it.
std::optional<double> secondsToReach(const std::vector<WorkPrecisionPoint>& points,
                                     double target);

/// The cheapest completed point whose state error is at most `target`.
const WorkPrecisionPoint* cheapestReaching(const std::vector<WorkPrecisionPoint>& points,
                                           double target);

/// The predictability horizon of a task's start: the trust estimate of the exact double run
/// (a long double shadow, issue 7).
Trust startTrust(const Task& task, std::stop_token stop = {});
Trust startTrust(const ChainTask& task, std::stop_token stop = {});

/// Where a comparison of methods on `task` may end: its own end, or, when the predictability
/// horizon of the start comes first, an eighth of a period before it (the horizon is the time
/// of the last contact within tolerance: an end on a contact would judge the methods on which
/// side of it they fall). `trust` receives the estimate for that end.
struct ComparisonEnd {
  double tEnd = 0;
  bool shortened = false;
  double horizon = 0;  ///< the predictability horizon found
  Trust trust;         ///< the estimate of the exact double run up to tEnd
};
ComparisonEnd comparisonEnd(const Task& task, std::stop_token stop = {});
ComparisonEnd comparisonEnd(const ChainTask& task, std::stop_token stop = {});

}  // namespace grazelab::core::methods
