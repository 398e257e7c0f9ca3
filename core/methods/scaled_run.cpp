// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/methods/scaled_run.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace grazelab::core::methods {
namespace {

std::string formatNumber(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

template <typename V>
bool finite(const V& q, const V& v) {
  return q.allFinite() && v.allFinite();
}

std::string horizonProblem(double tEnd) {
  if (!(tEnd > 0) || !std::isfinite(tEnd)) {
    return "t-end must be positive and finite (got " + formatNumber(tEnd) + ")";
  }
  return {};
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
    const TwoMassFormOrProblem<double> formed = makeTwoMassForm(task.model);
    if (!formed.chain) problems.push_back({"model", formed.problem});
  }
  return describe(problems);
}

std::string taskProblem(const ChainTask& task) {
  const std::string chain = describe(validate(task.chain));
  if (!chain.empty()) return chain;
  const long n = task.chain.size();
  if (task.start.u.size() != n || task.start.v.size() != n) {
    return "the start must give " + std::to_string(n) + " displacements and " + std::to_string(n) +
           " velocities";
  }
  if (!finite(task.start.u, task.start.v)) return "the start must be finite";
  const int s = task.chain.stopped() - 1;
  if (task.start.u(s) > task.chain.gap) {
    return "the start has u" + std::to_string(s + 1) + " = " + formatNumber(task.start.u(s)) +
           " past the stop (gap " + formatNumber(task.chain.gap) + ")";
  }
  return horizonProblem(task.tEnd);
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

ChainMethodRun refusedRun(const ChainTask& task, std::string reason) {
  ChainMethodRun run;
  run.status = RunStatus::Refused;
  run.reason = std::move(reason);
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

template <typename T>
ScaledRun<T>::ScaledRun(const T& task, const WorkBudget& budget, std::stop_token stop)
    : m_budget(budget), m_stop(std::move(stop)) {
  const std::string problem = taskProblem(task);
  if (!problem.empty()) {
    m_run = refusedRun(task, problem);
    return;
  }
  m_refused = false;
  m_run.result.final = task.start;
  if constexpr (kNotesChain) {
    m_chain = makeTwoMassForm(task.model).chain;
    const TwoMassForm<double>& c = *m_chain;
    m_scale = chooseScale(c, task.start);
    m_timeRate = m_scale.omegaSlow;
    m_stiffnessUnit = c.model.m2 * c.omegaSlow * c.omegaSlow;
    m_system.left = Eigen::Vector2d(c.p, c.w);
    m_system.right = Eigen::Vector2d(c.q, 0.0);
    m_system.stop = 1;
    m_system.gap = m_scale.gap;
    m_tauEnd = m_scale.toScaledTime(task.tEnd);
    const State x0 = m_scale.toScaled(task.start);
    m_q0 = Eigen::Vector2d(x0.u1, x0.u2);
    m_v0 = Eigen::Vector2d(x0.v1, x0.v2);
    m_initialEnergy = scaledEnergy(c, x0);
    m_run.result.initialEnergy = physicalEnergy(c, task.start);
    m_recorder.emplace(c, m_scale, x0, task.needs, m_run.result);
    m_recorder->samplePoint(0.0, x0);
  } else {
    m_massChain = task.chain;
    const MassChain& chain = m_massChain;
    const int n = chain.size();
    const double omega =  // the slowest mode
        task.prepared ? task.prepared->slowest : slowestFrequency(chainModes(chain).omega);
    // lengths in units of L = 2^e, e = ilogb of the larger of the gap and the start's size (as
    // for the note's chain: a method's absolute tolerance is relative to the motion's size)
    const double size = std::max({chain.gap, task.start.u.cwiseAbs().maxCoeff(),
                                  task.start.v.cwiseAbs().maxCoeff() / omega});
    const int exponent = std::ilogb(size);
    m_length = std::ldexp(1.0, exponent);
    m_timeRate = omega;
    const int s = chain.stopped() - 1;
    m_stiffnessUnit = chain.masses[std::size_t(s)] * omega * omega;
    m_system.left.resize(n);
    m_system.right.resize(n);
    for (int i = 0; i < n; ++i) {
      const double unit = chain.masses[std::size_t(i)] * omega * omega;
      m_system.left(i) = chain.springs[std::size_t(i)] / unit;
      m_system.right(i) = (i + 1 < n ? chain.springs[std::size_t(i + 1)] : chain.rightSpring) / unit;
    }
    m_system.stop = s;
    m_system.gap = std::ldexp(chain.gap, -exponent);
    m_tauEnd = task.tEnd * omega;
    m_q0 = task.start.u / m_length;
    m_v0 = task.start.v / (omega * m_length);
    m_initialEnergy = chainEnergy(chain, task.start);
    m_run.result.energyInitial = m_initialEnergy;
  }
}

template <typename T>
ChainState ScaledRun<T>::physical(const Vector& q, const Vector& v) const {
  return {q * m_length, v * (m_timeRate * m_length)};
}

template <typename T>
double ScaledRun<T>::drift(const Vector& q, const Vector& v) const {
  if (!finite(q, v)) return std::numeric_limits<double>::infinity();
  double energy = 0;
  if constexpr (kNotesChain) {
    energy = scaledEnergy(*m_chain, twoMass(q, v));
  } else {
    energy = chainEnergy(m_massChain, physical(q, v));
  }
  return std::abs(energy - m_initialEnergy) / (m_initialEnergy > 0 ? m_initialEnergy : 1.0);
}

template <typename T>
void ScaledRun<T>::contact(EventType type, double tau, const Vector& qBefore, const Vector& vBefore,
                           const Vector& qAfter, const Vector& vAfter) {
  if constexpr (kNotesChain) {
    Step<double> step;
    step.kind = Step<double>::Kind::Event;
    step.type = type;
    step.tau = tau;
    step.before = twoMass(qBefore, vBefore);
    step.after = twoMass(qAfter, vAfter);
    step.residual = std::abs(qBefore(1) - m_scale.gap);
    m_recorder->record(step);  // it keeps the energy drift at contacts (cost.maxRelEnergyDrift)
  } else {
    const ChainState before = physical(qBefore, vBefore);
    const double speed = m_timeRate * m_length;
    ChainRun& result = m_run.result;
    result.events.push_back({physicalTime(tau), type, before.u, before.v, vAfter(stop()) * speed});
    if (type != EventType::Release) {
      ++result.contacts;
      m_maxContactDrift = std::max(m_maxContactDrift, drift(qAfter, vAfter));  // as the recorder does
    }
    switch (type) {
      case EventType::Impact: ++result.impacts; break;
      case EventType::Grazing: ++result.grazings; break;
      case EventType::Stick: ++result.sticks; break;
      case EventType::Release: ++result.releases; break;
    }
  }
}

template <typename T>
void ScaledRun<T>::release(double tau, const Vector& q, const Vector& v) {
  contact(EventType::Release, tau, q, v, q, v);
}

template <typename T>
bool ScaledRun<T>::mustStop(std::int64_t steps, double tau, const Vector& q, const Vector& v) {
  if (m_stop.stop_requested()) {
    finish(RunStatus::Cancelled, "cancelled", tau, q, v);
    return true;
  }
  if (!finite(q, v) || q.template lpNorm<1>() + v.template lpNorm<1>() > 1e100) {
    finish(RunStatus::Failed,
           "diverged: the state left every bound (|x| > 1e100 or not finite) at t = " +
               formatNumber(physicalTime(tau)),
           tau, q, v);
    return true;
  }
  if (steps >= m_budget.maxSteps) {
    finish(RunStatus::Budget,
           "step budget (" + formatNumber(double(m_budget.maxSteps)) + " steps) spent at t = " +
               formatNumber(physicalTime(tau)),
           tau, q, v);
    return true;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - m_started).count();
  if (seconds > m_budget.maxSeconds) {
    finish(RunStatus::Budget,
           "time budget (" + formatNumber(m_budget.maxSeconds) + " s) spent at t = " +
               formatNumber(physicalTime(tau)),
           tau, q, v);
    return true;
  }
  return false;
}

template <typename T>
void ScaledRun<T>::complete(const Vector& q, const Vector& v) {
  if (finite(q, v)) {
    finish(RunStatus::Completed, "", m_tauEnd, q, v);
  } else {
    finish(RunStatus::Failed, "diverged: the state at the end is not finite", m_tauEnd, q, v);
  }
}

template <typename T>
void ScaledRun<T>::finish(RunStatus status, std::string reason, double tau, const Vector& q,
                          const Vector& v) {
  m_run.status = status;
  if (!reason.empty()) m_run.reason = std::move(reason);
  if constexpr (kNotesChain) {
    const StopReason stop = status == RunStatus::Completed   ? StopReason::TimeLimit
                            : status == RunStatus::Cancelled ? StopReason::Cancelled
                                                             : StopReason::ContactLimit;
    m_recorder->finish(stop, m_scale.toPhysicalTime(tau), twoMass(q, v));
    m_run.result.message = m_run.reason;
    m_run.maxEnergyDrift = std::max(m_run.result.cost.maxRelEnergyDrift, drift(q, v));
  } else {
    ChainRun& result = m_run.result;
    result.stop = status == RunStatus::Completed   ? StopReason::TimeLimit
                  : status == RunStatus::Cancelled ? StopReason::Cancelled
                                                   : StopReason::ContactLimit;
    result.tFinal = physicalTime(tau);
    result.final = physical(q, v);
    result.energyFinal = finite(q, v) ? chainEnergy(m_massChain, result.final)
                                      : std::numeric_limits<double>::infinity();
    m_run.maxEnergyDrift = std::max(m_maxContactDrift, drift(q, v));
  }
}

template <typename T>
typename ScaledRun<T>::Output ScaledRun<T>::take() {
  m_run.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - m_started).count();
  if constexpr (kNotesChain) m_run.result.cost.wallSeconds = m_run.seconds;
  return std::move(m_run);
}

template class ScaledRun<Task>;
template class ScaledRun<ChainTask>;

}  // namespace grazelab::core::methods
