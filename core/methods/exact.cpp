// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The exact solver (docs/model.md sections 3-4) behind the methods' interface, in double, long
// double or binary128: the model and start are read exactly (widening is exact), the result is
// handed back in double.
#include <chrono>
#include <optional>
#include <cmath>
#include <type_traits>

#include "core/methods/runners.h"
#include "core/methods/scaled_run.h"
#include "core/solver/chain_run.h"
#include "core/solver/simulate.h"
#include "core/solver/two_mass_run.h"

namespace grazelab::core::methods {
namespace {

/// A prepared chain in S.
template <typename S>
const BasicReadyChain<S>& readyIn(const PreparedChain& prepared) {
  if constexpr (std::is_same_v<S, double>) {
    return prepared.inDouble;
  } else if constexpr (std::is_same_v<S, long double>) {
    return prepared.inLong;
  } else {
    return prepared.inQuad;
  }
}

/// Advances an exact run (either engine's simulator) in growing pieces until it is over, the stop
/// token, or the time budget; true when the time budget ended it.
template <typename Simulator>
bool advanceWithin(Simulator& simulator, const WorkBudget& budget, std::stop_token stop,
                   std::chrono::steady_clock::time_point started) {
  long piece = 1024;
  while (!simulator.advance(piece, stop)) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (seconds > budget.maxSeconds) return true;
    piece = std::min<long>(piece * 2, 1 << 20);
  }
  return false;
}

/// The end of an exact run: over its time budget, and its wall time.
template <typename R>
void finishExact(BasicMethodRun<R>& run, bool overTime, const WorkBudget& budget,
                 std::chrono::steady_clock::time_point started) {
  if (overTime) {
    run.status = RunStatus::Budget;
    run.reason = "time budget (" + std::to_string(budget.maxSeconds) + " s) spent";
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

template <typename S>
MethodRun runIn(const Task& task, const WorkBudget& budget, std::stop_token stop) {
  const auto started = std::chrono::steady_clock::now();
  BasicRequest<S> request;
  request.initial = convertState<S>(task.start);
  request.tEnd = S(task.tEnd);
  request.maxContacts = budget.maxSteps;
  request.needs = task.needs;
  // the one run of the chain (a contact S cannot decide ends it: the report says so)
  TwoMassRun<S> simulator(convertModel<S>(task.model), request, {}, task.prepared ? &readyIn<S>(*task.prepared) : nullptr);
  MethodRun run;
  const bool overTime = advanceWithin(simulator, budget, stop, started);
  const BasicResult<S>& result = simulator.result();
  run.result = toDoubleResult(result);
  run.steps = result.cost.contacts;
  run.maxEnergyDrift = result.cost.maxRelEnergyDrift;  // (at the events; at the end too once over)
  switch (result.stop) {
    case StopReason::TimeLimit:
    case StopReason::NoFurtherContact:
      run.status = RunStatus::Completed;
      break;
    case StopReason::ContactLimit:
      run.status = RunStatus::Budget;
      run.reason = "contact budget (" + std::to_string(budget.maxSteps) + " contacts) spent";
      break;
    case StopReason::SearchBudget:
      run.status = RunStatus::Budget;
      run.reason = result.message;
      break;
    case StopReason::Undecided:
      run.status = RunStatus::Undecided;
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
  finishExact(run, overTime, budget, started);
  return run;
}

template <typename S>
ChainMethodRun runIn(const ChainTask& task, const WorkBudget& budget, std::stop_token stop) {
  const auto started = std::chrono::steady_clock::now();
  const BasicMassChain<S> chain = chainCast<S>(task.chain);
  const BasicChainStart<S> start{{task.start.u.template cast<S>(), task.start.v.template cast<S>()}, task.stillModes};
  std::optional<BasicReadyChain<S>> unprepared;
  if (!task.prepared) unprepared = readyChain(chain);
  BasicChainSimulator<S> simulator(task.prepared ? readyIn<S>(*task.prepared) : *unprepared, start,
                                   long(budget.maxSteps), S(task.tEnd));
  ChainMethodRun run;
  const bool overTime = advanceWithin(simulator, budget, stop, started);
  run.result = inDouble(simulator.run());
  run.steps = run.result.contacts;
  // the drift over every contact state and the end, in the run's own precision
  const S e0 = chainEnergy(chain, start.state);
  using std::abs;
  auto driftAt = [&](const BasicChainState<S>& x) { return toDouble(S(abs(chainEnergy(chain, x) - e0) / e0)); };
  if (e0 > 0) {
    for (const BasicChainEvent<S>& e : simulator.run().events) {
      if (e.type != EventType::Release) run.maxEnergyDrift = std::max(run.maxEnergyDrift, driftAt({e.u, e.vBefore}));
    }
    if (simulator.done()) run.maxEnergyDrift = std::max(run.maxEnergyDrift, driftAt(simulator.run().final));
  }
  switch (simulator.done() ? simulator.run().stop : StopReason::ContactLimit) {
    case StopReason::TimeLimit:
    case StopReason::NoFurtherContact:
      run.status = RunStatus::Completed;
      break;
    case StopReason::ContactLimit:
      run.status = RunStatus::Budget;
      run.reason = "contact budget (" + std::to_string(budget.maxSteps) + " contacts) spent";
      break;
    case StopReason::SearchBudget:
      run.status = RunStatus::Budget;
      run.reason = "the contact search ran out of its budget before deciding";
      break;
    case StopReason::Undecided:
      run.status = RunStatus::Undecided;
      run.reason = "a contact undecided in " + std::string(toString(precisionOf<S>()));
      break;
    case StopReason::Cancelled:
      run.status = RunStatus::Cancelled;
      run.reason = "cancelled";
      break;
    case StopReason::InvalidInput:
      run.status = RunStatus::Refused;
      run.reason = std::string(toString(simulator.run().stop));
      break;
  }
  finishExact(run, overTime, budget, started);
  return run;
}

template <typename T>
typename ScaledRun<T>::Output exactIn(const T& task, Precision precision, const WorkBudget& budget,
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

}  // namespace

MethodRun runExact(const Task& task, Precision precision, const WorkBudget& budget,
                   std::stop_token stop) {
  return exactIn(task, precision, budget, std::move(stop));
}

ChainMethodRun runExact(const ChainTask& task, Precision precision, const WorkBudget& budget,
                        std::stop_token stop) {
  return exactIn(task, precision, budget, std::move(stop));
}

}  // namespace grazelab::core::methods
