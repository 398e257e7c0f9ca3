// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/methods/scaled_run.h"

#include <cmath>
#include <sstream>

namespace grazelab::core::methods {
namespace {

std::string formatNumber(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

bool finiteState(const State& x) {
  return std::isfinite(x.u1) && std::isfinite(x.u2) && std::isfinite(x.v1) &&
         std::isfinite(x.v2);
}

}  // namespace

std::string taskProblem(const Task& task) {
  std::vector<core::Problem> problems = validate(task.model);
  for (core::Problem& problem : validateState(task.model, task.start, "start")) {
    problems.push_back(std::move(problem));
  }
  if (!(task.tEnd > 0) || !std::isfinite(task.tEnd)) {
    problems.push_back({"t-end", "must be positive and finite (got " + formatNumber(task.tEnd) + ")"});
  }
  if (problems.empty()) {
    const ChainOrProblem<double> formed = makeChain(task.model);
    if (!formed.chain) problems.push_back({"model", formed.problem});
  }
  return describe(problems);
}

MethodRun refusedRun(const Task& task, std::string reason) {
  MethodRun run;
  run.status = RunStatus::Refused;
  run.reason = std::move(reason);
  run.result.stop = StopReason::InvalidInput;
  run.result.message = run.reason;
  run.result.final = task.start;
  return run;
}

FixedSteps fixedSteps(double tauEnd, double hScaled) {
  const double count = std::ceil(tauEnd / hScaled * (1 - 1e-12));
  FixedSteps steps;
  steps.count = std::max<std::int64_t>(1, std::int64_t(count));
  steps.h = tauEnd / double(steps.count);
  return steps;
}

ScaledRun::ScaledRun(const Task& task, const WorkBudget& budget, std::stop_token stop)
    : m_budget(budget), m_stop(std::move(stop)) {
  const std::string problem = taskProblem(task);
  if (!problem.empty()) {
    m_run = refusedRun(task, problem);
    return;
  }
  m_chain = makeChain(task.model).chain;
  m_scale = chooseScale(*m_chain, task.start);
  m_tauEnd = m_scale.toScaledTime(task.tEnd);
  const State x0 = m_scale.toScaled(task.start);
  m_scaledStart = x0;
  m_initialEnergy = scaledEnergy(*m_chain, x0);
  m_run.result.initialEnergy = physicalEnergy(*m_chain, task.start);
  m_run.result.final = task.start;
  m_recorder.emplace(*m_chain, m_scale, x0, task.needs, nullptr, m_run.result);
  m_recorder->samplePoint(0.0, x0);
}

double ScaledRun::scaledStopStiffness(double kc) const {
  const double omega = m_chain->omegaSlow;
  return kc / (m_chain->model.m2 * omega * omega);
}

void ScaledRun::contact(EventType type, double tau, const State& before, const State& after) {
  Step<double> step;
  step.kind = Step<double>::Kind::Event;
  step.type = type;
  step.tau = tau;
  step.before = before;
  step.after = after;
  step.residual = std::abs(before.u2 - m_scale.gap);
  m_recorder->record(step);  // it keeps the energy drift at contacts (cost.maxRelEnergyDrift)
}

void ScaledRun::release(double tau, const State& x) {
  Step<double> step;
  step.kind = Step<double>::Kind::Event;
  step.type = EventType::Release;
  step.tau = tau;
  step.before = x;
  step.after = x;
  m_recorder->record(step);
}

void ScaledRun::sample(double tau, const State& x) { m_recorder->samplePoint(tau, x); }

bool ScaledRun::mustStop(std::int64_t steps, double tau, const State& x) {
  if (m_stop.stop_requested()) {
    finish(RunStatus::Cancelled, "cancelled", tau, x);
    return true;
  }
  if (!finiteState(x) || std::abs(x.u1) + std::abs(x.u2) + std::abs(x.v1) + std::abs(x.v2) > 1e100) {
    finish(RunStatus::Failed,
           "diverged: the state left every bound (|x| > 1e100 or not finite) at t = " +
               formatNumber(m_scale.toPhysicalTime(tau)),
           tau, x);
    return true;
  }
  if (steps >= m_budget.maxSteps) {
    finish(RunStatus::Budget,
           "step budget (" + formatNumber(double(m_budget.maxSteps)) + " steps) spent at t = " +
               formatNumber(m_scale.toPhysicalTime(tau)),
           tau, x);
    return true;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - m_started).count();
  if (seconds > m_budget.maxSeconds) {
    finish(RunStatus::Budget,
           "time budget (" + formatNumber(m_budget.maxSeconds) + " s) spent at t = " +
               formatNumber(m_scale.toPhysicalTime(tau)),
           tau, x);
    return true;
  }
  return false;
}

void ScaledRun::complete(const State& x) {
  if (finiteState(x)) {
    finish(RunStatus::Completed, "", m_tauEnd, x);
  } else {
    finish(RunStatus::Failed, "diverged: the state at the end is not finite", m_tauEnd, x);
  }
}

void ScaledRun::finish(RunStatus status, std::string reason, double tau, const State& x) {
  m_run.status = status;
  if (!reason.empty()) m_run.reason = std::move(reason);
  const StopReason stop = status == RunStatus::Completed   ? StopReason::TimeLimit
                          : status == RunStatus::Cancelled ? StopReason::Cancelled
                                                           : StopReason::ContactLimit;
  m_recorder->finish(stop, m_scale.toPhysicalTime(tau), x);
  m_run.result.message = m_run.reason;
  m_run.maxEnergyDrift = m_run.result.cost.maxRelEnergyDrift;
  if (finiteState(x)) {
    const double drift = std::abs(scaledEnergy(*m_chain, x) - m_initialEnergy) /
                         (m_initialEnergy > 0 ? m_initialEnergy : 1.0);
    m_run.maxEnergyDrift = std::max(m_run.maxEnergyDrift, drift);
  } else {
    m_run.maxEnergyDrift = std::numeric_limits<double>::infinity();
  }
}

MethodRun ScaledRun::take() {
  m_run.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - m_started).count();
  m_run.result.cost.wallSeconds = m_run.seconds;
  return std::move(m_run);
}

}  // namespace grazelab::core::methods
