// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stop_token>
#include <string>
#include <variant>
#include <vector>

#include "core/methods/compare.h"
#include "core/methods/work_precision.h"

// `report` as a typed command, the one both faces call: the command line reads the chain, its
// start, the horizon, --methods and --quick into a ReportRequest and writes the outcome as
// results.csv, report.md and two pictures (commands/report_command.h); the Python module hands
// the same table and text over. No Qt.
namespace grazelab::cli {

/// The work-precision report to run: every setting of every method of `methods` on `task` (the
/// note's chain, or a chain of N masses), against the exact solver in binary128.
struct ReportRequest {
  std::variant<core::methods::Task, core::methods::ChainTask> task;  ///< tEnd: the horizon asked for
  std::vector<core::methods::MethodKind> methods;
  bool quick = false;  ///< fewer settings and timed runs, a budget of 5 s a setting (else 60 s)
  double period = 0;   ///< T2, the chain's slowest period: the steps h are fractions of it
  double k1 = 0;       ///< the wall's spring: the penalty's k_c are multiples of it

  core::methods::TimingPolicy timing() const;
  core::methods::WorkBudget budget() const;
};

enum class ReportStatus {
  Computed,
  NoReference,  ///< the binary128 reference did not complete: `problem`, no table
  Interrupted,  ///< the stop token ended it: no table
};

/// The report run: where the comparison ended, the reference's cost, and a point per setting, in
/// the plan's order (method by method, coarse to fine).
struct ReportOutcome {
  ReportStatus status = ReportStatus::Interrupted;
  std::string problem;
  core::methods::ComparisonEnd end;  ///< end.shortened: moved before the start's predictability horizon
  double tEnd = 0;                   ///< the horizon compared up to
  std::int64_t referenceContacts = 0;
  double referenceSeconds = 0;
  double referencePeriod = 0;
  std::vector<core::methods::WorkPrecisionPoint> points;
};

/// What a long report says as it goes: before the horizon's estimate, before the reference run
/// (its end), after each point (how many of how many).
struct ReportProgress {
  std::function<void()> horizon;
  std::function<void(double tEnd)> reference;
  std::function<void(std::size_t done, std::size_t total, const core::methods::WorkPrecisionPoint&)> point;
};

/// Runs the report (core::methods: comparisonEnd, makeReference, measurePoint).
ReportOutcome workPrecisionReport(const ReportRequest& request, std::stop_token stop = {},
                                  const ReportProgress& progress = {});

}  // namespace grazelab::cli
