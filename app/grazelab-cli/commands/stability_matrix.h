// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <stop_token>
#include <string>
#include <vector>

#include "core/methods/stress_matrix.h"

// `stability` as a typed command, the one both faces call: the command line reads --methods,
// --quick and the chain (--masses ... or the built-in cases) into a StabilityRequest and writes
// the outcome as matrix.csv and matrix.md (commands/stability_command.h); the Python module hands
// the same table and text over. No Qt.
namespace grazelab::cli {

/// The matrix to run: every method of `methods` on every case of `cases`.
struct StabilityRequest {
  std::vector<core::methods::MethodKind> methods;
  std::vector<core::methods::StressCase> cases;
  bool quick = false;  ///< a subset of the settings, a budget of 0.5 s a cell (else 20 s)

  double budgetSeconds() const { return quick ? 0.5 : 20; }
};

enum class StabilityStatus {
  Computed,
  Interrupted,  ///< the stop token ended it: no matrix
};

/// The matrix run: its cells in the order they finished (case by case), the long exact run's
/// marks, each case's horizon, the wall time.
struct StabilityOutcome {
  StabilityStatus status = StabilityStatus::Interrupted;
  std::vector<core::methods::StressCell> cells;
  std::vector<core::methods::LongRunMark> marks;
  std::map<std::string, core::methods::CaseHorizon> horizons;
  double seconds = 0;
};

/// Called as each case starts: its index (0-based), the number of cases, its name.
using StabilityProgress = std::function<void(std::size_t index, std::size_t count, const std::string& name)>;

/// Runs the request's cases one after the other (core::methods::runStressCase).
StabilityOutcome stabilityMatrix(const StabilityRequest& request, std::stop_token stop = {},
                                 const StabilityProgress& progress = {});

}  // namespace grazelab::cli
