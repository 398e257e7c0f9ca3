// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/methods/compare.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "core/methods/runners.h"
#include "core/methods/scaled_run.h"
#include "core/solver/chain_run.h"
#include "core/solver/simulate.h"
#include "core/solver/two_mass_run.h"

namespace grazelab::core::methods {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// the reference chain: lengths 3x, masses 5x, stiffnesses 15x, so times are 1/sqrt(3)
constexpr int kLengthFactor = 3;
constexpr int kMassFactor = 5;

State backToTask(const BasicState<Quad>& x, const Quad& speedFactor) {
  return {toDouble(Quad(x.u1 / kLengthFactor)), toDouble(Quad(x.u2 / kLengthFactor)),
          toDouble(Quad(x.v1 / speedFactor)), toDouble(Quad(x.v2 / speedFactor))};
}

/// What the matching reads of a contact, for either kind of run.
struct Contact {
  double t = 0;
  EventType type = EventType::Impact;
  double stopSpeed = 0;  ///< the stopped mass's velocity before it
};

std::vector<Contact> contactsOf(const Result& result, int) {
  std::vector<Contact> contacts;
  for (const Event& event : result.events) {
    if (isContact(event.type)) contacts.push_back({event.t, event.type, event.before.v2});
  }
  return contacts;
}

std::vector<Contact> contactsOf(const ChainRun& run, int stop) {
  std::vector<Contact> contacts;
  for (const ChainEvent& event : run.events) {
    if (isContact(event.type)) contacts.push_back({event.t, event.type, event.vBefore(stop)});
  }
  return contacts;
}

/// max |du| / X, |dv| / V between two final states.
double stateDistance(const State& a, const State& b, double X, double V) {
  return std::max({std::abs(a.u1 - b.u1) / X, std::abs(a.u2 - b.u2) / X, std::abs(a.v1 - b.v1) / V,
                   std::abs(a.v2 - b.v2) / V});
}

double stateDistance(const ChainState& a, const ChainState& b, double X, double V) {
  return std::max((a.u - b.u).cwiseAbs().maxCoeff() / X, (a.v - b.v).cwiseAbs().maxCoeff() / V);
}

/// The one matching of compare(), for either kind of run.
template <typename R>
Errors compareRuns(const BasicReference<R>& reference, const BasicMethodRun<R>& run) {
  Errors errors;
  errors.energyDrift = run.maxEnergyDrift;
  const bool bothComplete =
      run.status == RunStatus::Completed && reference.run.status == RunStatus::Completed;
  if (bothComplete) {
    errors.state = stateDistance(run.result.final, reference.run.result.final, reference.positionScale,
                                 reference.velocityScale);
    if (!std::isfinite(errors.state)) errors.state = kNaN;
  } else {
    errors.state = kNaN;
  }
  const std::vector<Contact> ref = contactsOf(reference.run.result, reference.stop);
  const std::vector<Contact> own = contactsOf(run.result, reference.stop);
  const double quarter = reference.period / 4;
  auto window = [&](std::size_t i) {
    double w = quarter;
    if (i > 0) w = std::min(w, (ref[i].t - ref[i - 1].t) / 2);
    if (i + 1 < ref.size()) w = std::min(w, (ref[i + 1].t - ref[i].t) / 2);
    return w;
  };
  // contacts after the end of a run that stopped early are not judged, nor unmatched ones at
  // the very end (within 1e-6 T2 they may fall on either side of it by the run's error)
  const double judgedUntil =
      std::min(run.result.tFinal, reference.run.result.tFinal) - 1e-6 * reference.period;
  double worstTime = 0, worstSpeed = 0;
  bool anyImpact = false;
  std::size_t i = 0, j = 0;
  while (i < ref.size() && j < own.size()) {
    const double offset = own[j].t - ref[i].t;
    if (std::abs(offset) <= window(i)) {
      ++errors.matched;
      worstTime = std::max(worstTime, std::abs(offset) / reference.period);
      if (ref[i].type == EventType::Impact && own[j].type == EventType::Impact) {
        anyImpact = true;
        worstSpeed = std::max(worstSpeed, std::abs(own[j].stopSpeed - ref[i].stopSpeed) /
                                              reference.velocityScale);
      }
      ++i;
      ++j;
    } else if (offset < 0) {
      if (own[j].t <= judgedUntil) ++errors.extra;
      ++j;
    } else {
      if (ref[i].t <= judgedUntil) ++errors.missed;
      ++i;
    }
  }
  for (; i < ref.size(); ++i) {
    if (ref[i].t <= judgedUntil) ++errors.missed;
  }
  for (; j < own.size(); ++j) {
    if (own[j].t <= judgedUntil) ++errors.extra;
  }
  errors.contactTime = errors.matched > 0 ? worstTime : kNaN;
  errors.impactSpeed = anyImpact ? worstSpeed : kNaN;
  if (ref.empty() && own.empty()) errors.contactTime = 0;
  return errors;
}

/// The status of a reference run that ended.
template <typename R>
void judgeReference(BasicMethodRun<R>& run, bool done, bool completed, bool cancelled, bool refused,
                    const std::string& message) {
  if (!done) {
    run.status = RunStatus::Budget;
    run.reason = "the binary128 reference ran out of its budget";
  } else if (completed) {
    run.status = RunStatus::Completed;
  } else if (cancelled) {
    run.status = RunStatus::Cancelled;
    run.reason = "cancelled";
  } else {
    run.status = refused ? RunStatus::Refused : RunStatus::Budget;
    run.reason = "binary128 reference: " + message;
  }
}

}  // namespace

Reference makeReference(const Task& task, const WorkBudget& budget, std::stop_token stop) {
  const auto started = std::chrono::steady_clock::now();
  Reference reference;
  const std::string problem = taskProblem(task);
  if (!problem.empty()) {
    reference.run = refusedRun(task, problem);
    return reference;
  }
  const TwoMassForm<double> chain = *makeTwoMassForm(task.model).chain;
  reference.period = twoPi<double>() / chain.omegaSlow;
  reference.positionScale = task.model.gap;
  reference.velocityScale = chain.ratio * chain.omegaSlow * task.model.gap;

  BasicModel<Quad> model = convertModel<Quad>(task.model);
  model.m1 *= kMassFactor;
  model.m2 *= kMassFactor;
  model.k1 *= kMassFactor * kLengthFactor;
  model.k2 *= kMassFactor * kLengthFactor;
  model.gap *= kLengthFactor;
  const Quad timeFactor = sqrt(Quad(kLengthFactor));  // reference times are the task's / this
  const Quad speedFactor = Quad(kLengthFactor) * timeFactor;
  const BasicState<Quad> start = convertState<Quad>(task.start);
  BasicRequest<Quad> request;
  request.initial = {start.u1 * kLengthFactor, start.u2 * kLengthFactor, start.v1 * speedFactor,
                     start.v2 * speedFactor};
  request.tEnd = Quad(task.tEnd) / timeFactor;
  request.maxContacts = budget.maxSteps;
  request.needs.events = true;
  TwoMassRun<Quad> simulator(model, request);
  while (!simulator.advance(4096, stop)) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (seconds > budget.maxSeconds) break;
  }
  const BasicResult<Quad>& result = simulator.result();
  MethodRun& run = reference.run;
  for (const BasicEvent<Quad>& e : result.events) {
    run.result.events.push_back({toDouble(Quad(e.t * timeFactor)), e.type,
                                 backToTask(e.before, speedFactor),
                                 backToTask(e.after, speedFactor)});
  }
  run.result.final = backToTask(result.final, speedFactor);
  run.result.tFinal = toDouble(Quad(result.tFinal * timeFactor));
  run.result.cost = result.cost;
  run.result.stop = result.stop;
  run.maxEnergyDrift = result.cost.maxRelEnergyDrift;
  run.steps = result.cost.contacts;
  judgeReference(run, simulator.done(),
                 result.stop == StopReason::TimeLimit || result.stop == StopReason::NoFurtherContact,
                 result.stop == StopReason::Cancelled, result.stop == StopReason::InvalidInput,
                 result.message.empty() ? std::string(toString(result.stop)) : result.message);
  reference.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  run.seconds = reference.seconds;
  return reference;
}

ChainReference makeReference(const ChainTask& task, const WorkBudget& budget, std::stop_token stop) {
  const auto started = std::chrono::steady_clock::now();
  ChainReference reference;
  const std::string problem = taskProblem(task);
  if (!problem.empty()) {
    reference.run = refusedRun(task, problem);
    return reference;
  }
  double slowest = 0, fastest = 0;
  if (task.prepared) {
    slowest = task.prepared->slowest;
    fastest = task.prepared->fastest;
  } else {
    const ChainModes modes = chainModes(task.chain);
    slowest = slowestFrequency(modes.omega);
    fastest = modes.omega.maxCoeff();
  }
  reference.period = twoPi<double>() / slowest;
  reference.positionScale = task.chain.gap;
  reference.velocityScale = fastest * task.chain.gap;
  reference.stop = task.chain.stopped() - 1;

  BasicMassChain<Quad> chain = chainCast<Quad>(task.chain);
  for (Quad& m : chain.masses) m *= kMassFactor;
  for (Quad& k : chain.springs) k *= kMassFactor * kLengthFactor;
  chain.rightSpring *= kMassFactor * kLengthFactor;
  chain.gap *= kLengthFactor;
  const Quad timeFactor = sqrt(Quad(kLengthFactor));  // reference times are the task's / this
  const Quad speedFactor = Quad(kLengthFactor) * timeFactor;
  const BasicChainStart<Quad> start{{task.start.u.cast<Quad>() * Quad(kLengthFactor),
                                     task.start.v.cast<Quad>() * speedFactor},
                                    task.stillModes};
  BasicChainSimulator<Quad> simulator(readyChain(chain), start, long(budget.maxSteps),
                                      Quad(task.tEnd) / timeFactor);
  while (!simulator.advance(4096, stop)) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (seconds > budget.maxSeconds) break;
  }
  // back to the task's units in binary128, then rounded once
  BasicChainRun<Quad> result = simulator.run();
  for (BasicChainEvent<Quad>& e : result.events) {
    e.t *= timeFactor;
    e.u /= Quad(kLengthFactor);
    e.vBefore /= speedFactor;
    e.vAfter /= speedFactor;
  }
  result.final.u /= Quad(kLengthFactor);
  result.final.v /= speedFactor;
  result.tFinal *= timeFactor;
  reference.run.result = inDouble(result);
  reference.run.steps = result.contacts;
  const bool completed = result.stop == StopReason::TimeLimit || result.stop == StopReason::NoFurtherContact;
  std::string message = result.stop == StopReason::Undecided ? "a contact undecided even in binary128"
                        : result.stop == StopReason::SearchBudget
                            ? "the contact search ran out of its budget"
                            : "contact budget spent";
  judgeReference(reference.run, simulator.done(), completed, result.stop == StopReason::Cancelled, false,
                 message);
  reference.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  reference.run.seconds = reference.seconds;
  return reference;
}

Errors compare(const Reference& reference, const MethodRun& run) { return compareRuns(reference, run); }
Errors compare(const ChainReference& reference, const ChainMethodRun& run) {
  return compareRuns(reference, run);
}

}  // namespace grazelab::core::methods
