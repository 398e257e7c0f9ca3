// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The exact solver (docs/model.md sections 3-4) behind the methods' interface, in double, long
// double or binary128: the model and start are read exactly (widening is exact), the result is
// handed back in double.
#include <chrono>
#include <cmath>

#include "core/methods/runners.h"
#include "core/methods/scaled_run.h"
#include "core/solver/simulate.h"

namespace grazelab::core::methods {
namespace {

template <typename S>
MethodRun runIn(const Task& task, const WorkBudget& budget, std::stop_token stop) {
  const auto started = std::chrono::steady_clock::now();
  BasicRequest<S> request;
  request.initial = convertState<S>(task.start);
  request.tEnd = S(task.tEnd);
  request.maxContacts = budget.maxSteps;
  request.needs = task.needs;
  BasicSimulator<S> simulator(convertModel<S>(task.model), request);
  MethodRun run;
  // in pieces, so that the time budget is checked between them
  std::int64_t piece = 1024;
  bool overTime = false;
  while (!simulator.advance(piece, stop)) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (seconds > budget.maxSeconds) {
      overTime = true;
      break;
    }
    piece = std::min<std::int64_t>(piece * 2, 1 << 20);
  }
  const BasicResult<S>& result = simulator.result();
  run.result = toDoubleResult(result);
  run.steps = result.cost.contacts;
  run.maxEnergyDrift = result.cost.maxRelEnergyDrift;
  if (simulator.chain()) {
    const S e0 = scaledEnergy(*simulator.chain(), simulator.scale().toScaled(request.initial));
    const S e1 = scaledEnergy(*simulator.chain(), simulator.state().x);
    using std::abs;
    if (e0 > 0) run.maxEnergyDrift = std::max(run.maxEnergyDrift, toDouble(S(abs(e1 - e0) / e0)));
  }
  switch (result.stop) {
    case StopReason::TimeLimit:
    case StopReason::NoFurtherContact:
      run.status = RunStatus::Completed;
      break;
    case StopReason::ContactLimit:
    case StopReason::SearchLimit:
      run.status = RunStatus::Budget;
      run.reason = "contact budget (" + std::to_string(budget.maxSteps) + " contacts) spent";
      break;
    case StopReason::SearchBudget:
    case StopReason::Undecided:
      run.status = RunStatus::Budget;
      run.reason = result.message;
      break;
    case StopReason::Cancelled:
      run.status = RunStatus::Cancelled;
      run.reason = "cancelled";
      break;
    case StopReason::InvalidInput:
      run.status = RunStatus::Refused;
      run.reason = result.message;
      break;
  }
  if (overTime) {
    run.status = RunStatus::Budget;
    run.reason = "time budget (" + std::to_string(budget.maxSeconds) + " s) spent";
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return run;
}

}  // namespace

MethodRun runExact(const Task& task, Precision precision, const WorkBudget& budget,
                   std::stop_token stop) {
  const std::string problem = taskProblem(task);
  if (!problem.empty()) return refusedRun(task, problem);
  switch (precision) {
    case Precision::Double:
      return runIn<double>(task, budget, stop);
    case Precision::Long:
      return runIn<long double>(task, budget, stop);
    case Precision::Quad:
      return runIn<Quad>(task, budget, stop);
  }
  return refusedRun(task, "unknown precision");
}

}  // namespace grazelab::core::methods
