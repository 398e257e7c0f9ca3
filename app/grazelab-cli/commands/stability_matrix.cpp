// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/stability_matrix.h"

#include <chrono>

namespace grazelab::cli {

StabilityOutcome stabilityMatrix(const StabilityRequest& request, std::stop_token stop,
                                 const StabilityProgress& progress) {
  using namespace core::methods;
  WorkBudget budget;
  budget.maxSeconds = request.budgetSeconds();
  const auto started = std::chrono::steady_clock::now();
  StabilityOutcome outcome;
  for (std::size_t index = 0; index < request.cases.size(); ++index) {
    const StressCase& row = request.cases[index];
    if (progress) progress(index, request.cases.size(), row.name);
    outcome.horizons[row.name] = runStressCase(
        row, request.methods, budget, [&outcome](const StressCell& cell) { outcome.cells.push_back(cell); },
        &outcome.marks, stop);
    if (stop.stop_requested()) return StabilityOutcome{};
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  outcome.status = StabilityStatus::Computed;
  return outcome;
}

}  // namespace grazelab::cli
