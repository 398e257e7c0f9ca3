// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/methods/stress_matrix.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/methods/scaled_run.h"
#include "core/methods/work_precision.h"
#include "core/orbits/chain_glo.h"
#include "core/orbits/special_orbits.h"
#include "core/orbits/starts.h"
#include "core/solver/simulate.h"
#include "core/solver/two_mass_run.h"

namespace grazelab::core::methods {
namespace {

/// The default problem's push, (0, 0, 0.05, -0.05) at w2 = 1/sqrt(2), d = 1, in units of w2 d.
constexpr double kDefaultPush = 0.05 * 1.4142135623730951;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

/// GLO_lambda of a chain pushed by `push` w2 d in (v1, -v2).
StressCase gloCase(std::string name, std::string description, const Model& model,
                      double lambda, double push) {
  StressCase result{std::move(name), std::move(description), std::nullopt, {}, {}, {}, 0};
  const std::string problem = describe(validate(model));
  if (!problem.empty()) {
    result.problem = problem;
    return result;
  }
  const TwoMassFormOrProblem<double> formed = makeTwoMassForm(model);
  if (!formed.chain) {
    result.problem = formed.problem;
    return result;
  }
  const TwoMassForm<double>& chain = *formed.chain;
  StartSpec<double> spec;
  spec.kind = StartSpec<double>::Kind::Glo;
  spec.lambda = lambda;
  const double speed = push * chain.omegaSlow * model.gap;
  if (push != 0) spec.perturbation = State{0, 0, speed, -speed};
  const StartOrProblem<double> start = makeStart(chain, spec);
  if (!start.start) {
    result.problem = start.problem;
    return result;
  }
  const double period = twoPi<double>() / chain.omegaSlow;
  result.task = prepared(Task{model, start.start->state, kCasePeriods * period, {}});
  return result;
}

Model designed(double beta, Branch branch, double gap = 1) {
  Model model;
  model.m1 = 1;
  model.m2 = beta;
  model.k1 = 1;
  model.gap = gap;
  model.design = branch;
  model.k2 = designKappa(beta, branch);
  return model;
}

/// k2/k1 of the chain with m1 = k1 = 1, m2 = beta whose frequencies have the ratio r (upper
/// branch): from (1 + r^2)^2 / r^2 = s^2 / p with s = 1 + k + k / beta, p = k / beta, solved in
/// long double and rounded once.
double kappaForRatio(double beta, long double r) {
  const long double c = (1 + r * r) * (1 + r * r) / (r * r);
  const long double a = 1 + 1 / (long double)beta;
  const long double b = c / beta - 2 * a;
  return double((b + std::sqrt(b * b - 4 * a * a)) / (2 * a * a));
}

Model detuned(double beta, double kappa) {
  Model model;
  model.m2 = beta;
  model.k2 = kappa;
  model.design.reset();
  return model;
}

}  // namespace

std::string_view toString(CellVerdict verdict) {
  switch (verdict) {
    case CellVerdict::Ok:
      return "ok";
    case CellVerdict::Inaccurate:
      return "inaccurate";
    case CellVerdict::Refused:
      return "refused";
    case CellVerdict::Budget:
      return "budget";
    case CellVerdict::Undecided:
      return "undecided";
    case CellVerdict::Failed:
      return "failed";
  }
  return "failed";
}

std::vector<StressCase> stressCases(bool quick) {
  std::vector<StressCase> cases;
  const double push = kDefaultPush;
  cases.push_back(gloCase("default", "m2/m1 = 1/2 upper, d = 1, GLO_0.5 pushed (the report's problem)",
                          designed(0.5, Branch::Upper), 0.5, push));
  const std::vector<double> ratios =
      quick ? std::vector<double>{1e-12} : std::vector<double>{1e-12, 1e-6, 1e-3, 0.1, 0.5, 0.5625};
  for (Branch branch : {Branch::Upper, Branch::Lower}) {
    if (quick && branch == Branch::Lower) break;
    for (double beta : ratios) {
      const std::string b(toString(branch));
      cases.push_back(gloCase("mass-ratio-" + number(beta) + "-" + b,
                              "m2/m1 = " + number(beta) + ", " + b + " branch, GLO_0.5 pushed",
                              designed(beta, branch), 0.5, push));
    }
  }
  for (double kappa : quick ? std::vector<double>{1e6} : std::vector<double>{1e-6, 1e-3, 1, 1e3, 1e6}) {
    cases.push_back(gloCase("detuned-k2-" + number(kappa),
                            "detuned: k2/k1 = " + number(kappa) + ", m2/m1 = 1/2, GLO_0.5 data pushed",
                            detuned(0.5, kappa), 0.5, push));
  }
  for (double offset : quick ? std::vector<double>{1e-13} : std::vector<double>{1e-4, 1e-7, 1e-10, 1e-13}) {
    for (int sign : {+1, -1}) {
      const Model model = detuned(0.5, kappaForRatio(0.5, 2.0L + sign * (long double)offset));
      const TwoMassFormOrProblem<double> formed = makeTwoMassForm(model);
      const std::string ratio = std::string(sign > 0 ? "2+" : "2-") + number(offset);
      const std::string actual =
          formed.chain ? (formed.chain->resonant ? "exactly resonant after rounding"
                                                 : "w1/w2 - 2 = " + number(formed.chain->detuning))
                       : "no chain";
      cases.push_back(gloCase("near-resonant-" + ratio, "w1/w2 = " + ratio + " (k2 rounded: " + actual + "), GLO_0.5 pushed",
                              model, 0.5, push));
    }
  }
  for (double gap : quick ? std::vector<double>{1e12} : std::vector<double>{1e-12, 1e12}) {
    cases.push_back(gloCase("gap-" + number(gap), "gap d = " + number(gap) + ", GLO_0.5 pushed (push scaled with d)",
                            designed(0.5, Branch::Upper, gap), 0.5, push));
  }
  for (double epsilon : quick ? std::vector<double>{1e-15} : std::vector<double>{1e-15, 1e-12, 1e-9, 1e-6, 1e-3, 1e-1}) {
    cases.push_back(gloCase("perturbation-" + number(epsilon),
                            "GLO_0.5 pushed by " + number(epsilon) + " w2 d in (v1, -v2): near grazing",
                            designed(0.5, Branch::Upper), 0.5, epsilon));
  }
  for (double lambda : quick ? std::vector<double>{4.0 / 3.0} : std::vector<double>{0, 1, 4.0 / 3.0, 1.5}) {
    const std::string what = lambda > 4.0 / 3.0 ? "pressed on the stop: sticks" : "grazing every T2";
    cases.push_back(gloCase("lambda-" + number(lambda), "GLO_lambda, lambda = " + number(lambda) + ", unperturbed (" + what + ")",
                            designed(0.5, Branch::Upper), lambda, 0));
  }
  {
    StressCase sticking{"sticking-start", "on the stop at rest with u1 = 1.5 d: pressed, stuck, released",
                           std::nullopt, {}, {}, {}, 0};
    const Model model = designed(0.5, Branch::Upper);
    const double period = twoPi<double>() / makeTwoMassForm(model).chain->omegaSlow;
    sticking.task = prepared(Task{model, State{1.5, 1, 0, 0}, kCasePeriods * period, {}});
    cases.push_back(sticking);
  }
  for (double kc : quick ? std::vector<double>{1e12} : std::vector<double>{1e2, 1e4, 1e6, 1e8, 1e10, 1e12}) {
    StressCase row = gloCase("penalty-kc-" + number(kc), "the default problem with penalty stiffness k_c = " + number(kc) + " k1",
                                designed(0.5, Branch::Upper), 0.5, push);
    row.only = MethodKind::Penalty;
    row.penaltyStiffness = kc;
    cases.push_back(row);
  }
  {
    const std::int64_t contacts = quick ? 100'000 : 10'000'000;
    StressCase row = gloCase("long-run-" + number(double(contacts)),
                                number(double(contacts)) + " contacts of the default problem: energy drift and time per contact along the run",
                                designed(0.5, Branch::Upper), 0.5, push);
    row.longRunContacts = contacts;
    cases.push_back(row);
  }
  return cases;
}

namespace {

// A row of the chain matrix: `chain` from `start` over kCasePeriods of its slowest periods, or
// refused with why it cannot be formed. (A start's still modes are those of the chain given: a
// variant with other springs or masses has other modes, and its start none.)
StressCase chainCase(std::string name, std::string description, const MassChain& chain, const ChainStart& start) {
  StressCase row{std::move(name), std::move(description), std::nullopt, {}, {}, {}, 0};
  if (const auto problems = validate(chain); !problems.empty()) {
    row.problem = describe(problems);
    return row;
  }
  const Eigen::Index s = chain.stopped() - 1;
  if (!(start.state.u[s] <= chain.gap)) {
    row.problem = "its start is past the stop (u" + std::to_string(s + 1) + " > d)";
    return row;
  }
  ChainTask task = prepared(ChainTask{chain, start.state, 0, {}, start.stillModes});
  task.tEnd = kCasePeriods * twoPi<double>() / task.prepared->slowest;
  row.task = std::move(task);
  return row;
}

// The chain with every length times `factor`: the gap and the start (the motion the same, scaled,
// its modes the same).
StressCase scaledCase(const MassChain& chain, const ChainStart& start, double factor) {
  MassChain scaled = chain;
  scaled.gap *= factor;
  return chainCase("gap-" + number(factor), "every length times " + number(factor) + " (the gap and the start)",
                   scaled, ChainStart{{start.state.u * factor, start.state.v * factor}, start.stillModes});
}

}  // namespace

std::vector<StressCase> chainStressCases(const MassChain& chain, const ChainStart& start,
                                         const std::vector<double>& gloWeights, bool quick) {
  std::vector<StressCase> cases;
  const int n = chain.size();
  const int stopped = chain.stopped();
  const Eigen::Index s = stopped - 1;
  cases.push_back(chainCase("given", std::to_string(n) + " masses, stop on mass " + std::to_string(stopped) +
                                         ", from the start given",
                            chain, start));
  for (double factor : quick ? std::vector<double>{1e-6} : std::vector<double>{1e-6, 1e-12}) {
    MassChain light = chain;
    light.masses[std::size_t(s)] *= factor;
    cases.push_back(chainCase("stopped-mass-x" + number(factor),
                              "the stopped mass " + number(1 / factor) + " times lighter (springs as given: stiff)",
                              light, start.state));
  }
  const std::size_t spring = n >= 2 ? 1 : 0;
  for (double factor : quick ? std::vector<double>{1e6} : std::vector<double>{1e6, 1e-6}) {
    MassChain detuned = chain;
    detuned.springs[spring] *= factor;
    cases.push_back(chainCase("spring-" + std::to_string(spring + 1) + "-x" + number(factor),
                              "k" + std::to_string(spring + 1) + " times " + number(factor) + " (frequencies far apart)",
                              detuned, start.state));
  }
  for (double factor : quick ? std::vector<double>{1e12} : std::vector<double>{1e-12, 1e12}) {
    cases.push_back(scaledCase(chain, start, factor));
  }
  // near grazing: the grazing orbit of the weights (or the slowest mode that moves the stopped
  // mass, alone) pushed off the stop along v_s by epsilon d w_N
  const ChainModes modes = chainModes(chain);
  std::vector<double> weights = gloWeights;
  std::string whose = "the weights given";
  if (weights.empty()) {
    weights.assign(std::size_t(n), 0.0);
    for (Eigen::Index j = n - 1; j >= 0; --j) {
      if (!modes.nodeAtStop[std::size_t(j)]) {
        weights[std::size_t(j)] = 1;
        whose = "mode " + std::to_string(j + 1) + " alone";
        break;
      }
    }
  }
  const ChainGloStart glo = chainGloStart(chain, weights);
  const double slowest = slowestFrequency(modes.omega);
  for (double epsilon : quick ? std::vector<double>{1e-15} : std::vector<double>{1e-15, 1e-9, 1e-3}) {
    const std::string name = "push-" + number(epsilon);
    const std::string description =
        "the grazing orbit of " + whose + " pushed off the stop by " + number(epsilon) + " d w_N: near grazing";
    if (glo.problem != GloStartProblem::None) {
      StressCase refused{name, description, std::nullopt, "its weights make no grazing orbit", {}, {}, 0};
      cases.push_back(refused);
      continue;
    }
    ChainState pushed = glo.state;
    pushed.v[s] -= epsilon * chain.gap * slowest;
    cases.push_back(chainCase(name, description, chain, pushed));
  }
  MassChain walled = chain;
  walled.rightSpring = chain.rightSpring > 0 ? 0.0 : chain.springs.front();
  cases.push_back(chainCase(chain.rightSpring > 0 ? "no-right-wall" : "right-wall",
                            chain.rightSpring > 0 ? "the right wall taken away"
                                                  : "a right wall added (k = k1)",
                            walled, start));
  if (n >= 3 && !quick) {
    MassChain inside = chain;
    inside.stopMass = (n + 1) / 2 == stopped ? (n + 1) / 2 + 1 : (n + 1) / 2;
    cases.push_back(chainCase("stop-on-" + std::to_string(inside.stopMass),
                              "the stop moved to mass " + std::to_string(inside.stopMass) + " (inside the chain)",
                              inside, start));
  }
  return cases;
}

MethodSetting standardSetting(MethodKind kind, double period, double k1,
                              std::optional<double> penaltyStiffness) {
  switch (kind) {
    case MethodKind::Exact:
      return {kind, 0, Precision::Double};
    case MethodKind::MoreauJean:
    case MethodKind::MoreauJeanTheta1:
    case MethodKind::SchatzmanPaoli:
      return {kind, period / 1000};
    case MethodKind::Dopri5Events:
    case MethodKind::CvodeAdams:
    case MethodKind::CvodeBdf:
      return {kind, 1e-8};
    case MethodKind::Penalty:
      return {kind, k1 * penaltyStiffness.value_or(1e8), Precision::Double, 1e-10};
  }
  return {kind, 0};
}

namespace {

CellVerdict verdictOf(RunStatus status) {
  switch (status) {
    case RunStatus::Completed:
      return CellVerdict::Ok;
    case RunStatus::Budget:
      return CellVerdict::Budget;
    case RunStatus::Undecided:
      return CellVerdict::Undecided;
    case RunStatus::Refused:
      return CellVerdict::Refused;
    case RunStatus::Failed:
    case RunStatus::Cancelled:
      return CellVerdict::Failed;
  }
  return CellVerdict::Failed;
}

// The verdict of a run that completed: ok, or inaccurate with every reason.
void judge(StressCell& cell, double tolerance) {
  std::vector<std::string> problems;
  const Errors& e = cell.errors;
  if (!(e.state <= tolerance)) problems.push_back("state error " + number(e.state) + " > " + number(tolerance));
  if (e.contactTime > tolerance) problems.push_back("contact time error " + number(e.contactTime) + " T2");
  if (e.missed > 0) problems.push_back(std::to_string(e.missed) + " contacts missed");
  if (e.extra > 0) problems.push_back(std::to_string(e.extra) + " extra contacts");
  if (!std::isfinite(e.energyDrift)) problems.push_back("energy not finite");
  if (problems.empty()) return;
  cell.verdict = CellVerdict::Inaccurate;
  for (std::size_t i = 0; i < problems.size(); ++i) cell.reason += (i ? "; " : "") + problems[i];
}

void runLong(const StressCase& row, const std::vector<MethodKind>& methods,
             const WorkBudget& budget, const std::function<void(const StressCell&)>& onCell,
             std::vector<LongRunMark>* marks, std::stop_token stop) {
  const Task& task = std::get<Task>(*row.task);
  for (MethodKind kind : methods) {
    StressCell cell;
    cell.caseName = row.name;
    cell.method = kind;
    cell.setting = standardSetting(kind, task.tEnd / kCasePeriods, task.model.k1);
    cell.errors.state = cell.errors.contactTime = cell.errors.impactSpeed =
        std::numeric_limits<double>::quiet_NaN();
    if (kind != MethodKind::Exact) {
      // as long as the exact run takes, at most; the time steppers need ~1000 steps per T2
      Task longTask = task;
      longTask.tEnd = task.tEnd / kCasePeriods * double(row.longRunContacts);
      longTask.needs.events = false;
      WorkBudget shortBudget = budget;
      shortBudget.maxSeconds = std::min(budget.maxSeconds, 2.0);
      const MethodRun run = runMethod(longTask, cell.setting, shortBudget, stop);
      cell.seconds = run.seconds;
      cell.errors.energyDrift = run.maxEnergyDrift;
      cell.verdict = verdictOf(run.status);
      cell.reason = run.status == RunStatus::Completed ? "" : run.reason;
      if (onCell) onCell(cell);
      continue;
    }
    Request request;
    request.initial = task.start;
    request.maxContacts = row.longRunContacts;
    request.needs.events = false;
    TwoMassRun<double> simulator(task.model, request);
    const auto started = std::chrono::steady_clock::now();
    auto previous = started;
    std::int64_t previousContacts = 0;
    for (std::int64_t mark = 1000; mark <= row.longRunContacts && !stop.stop_requested(); mark *= 10) {
      simulator.advance(mark - simulator.result().cost.contacts, stop);
      const auto now = std::chrono::steady_clock::now();
      const Result& result = simulator.result();
      const std::int64_t contacts = result.cost.contacts;
      if (marks) {
        marks->push_back({contacts, simulator.time(),
                          result.cost.maxRelEnergyDrift,
                          std::chrono::duration<double, std::nano>(now - previous).count() /
                              double(std::max<std::int64_t>(1, contacts - previousContacts))});
      }
      previous = now;
      previousContacts = contacts;
      if (simulator.done()) break;
    }
    const Result& result = simulator.result();
    cell.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    cell.errors.energyDrift = result.cost.maxRelEnergyDrift;
    if (stop.stop_requested()) {
      cell.verdict = CellVerdict::Failed;
      cell.reason = "cancelled";
    } else if (result.cost.contacts < row.longRunContacts) {
      cell.verdict = CellVerdict::Failed;
      cell.reason = "stopped after " + std::to_string(result.cost.contacts) + " contacts: " +
                    std::string(toString(result.stop));
    } else if (!(result.cost.maxRelEnergyDrift <= kExactTolerance)) {
      cell.verdict = CellVerdict::Inaccurate;
      cell.reason = "energy drift " + number(result.cost.maxRelEnergyDrift);
    }
    if (onCell) onCell(cell);
  }
}

}  // namespace

namespace {

// The largest size the reference meets, in the units of the errors (X = d, V = w1 X): the trust
// estimate is relative to the motion's own size.
double amplitudeOf(const Reference& reference) {
  double amplitude = 1;
  auto widen = [&](const State& x) {
    amplitude = std::max({amplitude, std::abs(x.u1) / reference.positionScale,
                          std::abs(x.u2) / reference.positionScale,
                          std::abs(x.v1) / reference.velocityScale,
                          std::abs(x.v2) / reference.velocityScale});
  };
  for (const Event& event : reference.run.result.events) widen(event.before);
  widen(reference.run.result.final);
  return amplitude;
}
double amplitudeOf(const ChainReference& reference) {
  double amplitude = 1;
  auto widen = [&](const ChainVector<double>& u, const ChainVector<double>& v) {
    amplitude = std::max({amplitude, u.cwiseAbs().maxCoeff() / reference.positionScale,
                          v.cwiseAbs().maxCoeff() / reference.velocityScale});
  };
  for (const ChainEvent& event : reference.run.result.events) widen(event.u, event.vBefore);
  widen(reference.run.result.final.u, reference.run.result.final.v);
  return amplitude;
}

double firstSpring(const Task& task) { return task.model.k1; }
double firstSpring(const ChainTask& task) { return task.chain.springs.front(); }

template <typename T>
void runCase(const StressCase& row, const T& task, const std::vector<MethodKind>& methods,
             const WorkBudget& budget, const std::function<void(const StressCell&)>& onCell,
             CaseHorizon& horizon, std::stop_token stop) {
  T withEvents = task;
  if constexpr (std::is_same_v<T, Task>) withEvents.needs.events = true;
  const ComparisonEnd end = comparisonEnd(task, stop);
  const Trust& trust = end.trust;
  withEvents.tEnd = end.tEnd;
  horizon.tEnd = end.tEnd;
  horizon.shortened = end.shortened;
  horizon.horizon = end.horizon;
  horizon.estimatedError = trust.stateError;
  WorkBudget referenceBudget = budget;
  referenceBudget.maxSeconds = std::max(budget.maxSeconds, 60.0);
  const auto reference = makeReference(withEvents, referenceBudget, stop);
  horizon.period = reference.period;
  // in the errors' units the tolerance grows with the motion's amplitude
  const double exactTolerance =
      std::max(kExactTolerance, kEstimateMargin * trust.stateError * amplitudeOf(reference));
  for (MethodKind kind : methods) {
    StressCell cell;
    cell.caseName = row.name;
    cell.method = kind;
    cell.setting = standardSetting(kind, reference.period, firstSpring(task), row.penaltyStiffness);
    if (row.only && *row.only != kind) {
      cell.verdict = CellVerdict::Refused;
      cell.reason = "not applicable: this row varies the penalty stiffness only (the other "
                    "methods on this problem: row 'default')";
      cell.errors.state = cell.errors.contactTime = cell.errors.impactSpeed =
          cell.errors.energyDrift = std::numeric_limits<double>::quiet_NaN();
      if (onCell) onCell(cell);
      continue;
    }
    const auto run = runMethod(withEvents, cell.setting, budget, stop);
    cell.seconds = run.seconds;
    cell.errors = compare(reference, run);
    if (reference.run.status != RunStatus::Completed) {
      cell.verdict = CellVerdict::Refused;
      cell.reason = "not judged: no binary128 reference (" + reference.run.reason + ")";
    } else {
      cell.verdict = verdictOf(run.status);
      if (cell.verdict != CellVerdict::Ok) {
        cell.reason = run.reason.empty() ? std::string(toString(run.status)) : run.reason;
      } else {
        judge(cell, kind == MethodKind::Exact ? exactTolerance : kStabilityTolerance);
      }
    }
    if (onCell) onCell(cell);
  }
}

}  // namespace

CaseHorizon runStressCase(const StressCase& row, const std::vector<MethodKind>& methods,
                          const WorkBudget& budget, const std::function<void(const StressCell&)>& onCell,
                          std::vector<LongRunMark>* longRun, std::stop_token stop) {
  CaseHorizon horizon;
  if (!row.task) {
    for (MethodKind kind : methods) {
      StressCell cell;
      cell.caseName = row.name;
      cell.method = kind;
      cell.verdict = CellVerdict::Refused;
      cell.reason = "the case cannot be formed: " + row.problem;
      cell.errors.state = cell.errors.contactTime = cell.errors.impactSpeed =
          cell.errors.energyDrift = std::numeric_limits<double>::quiet_NaN();
      if (onCell) onCell(cell);
    }
    return horizon;
  }
  if (const Task* task = std::get_if<Task>(&*row.task)) {
    horizon.tEnd = task->tEnd;
    horizon.period = twoPi<double>() / makeTwoMassForm(task->model).chain->omegaSlow;
    if (row.longRunContacts > 0) {
      runLong(row, methods, budget, onCell, longRun, stop);
      return horizon;
    }
    runCase(row, *task, methods, budget, onCell, horizon, stop);
  } else {
    runCase(row, std::get<ChainTask>(*row.task), methods, budget, onCell, horizon, stop);
  }
  return horizon;
}

}  // namespace grazelab::core::methods
