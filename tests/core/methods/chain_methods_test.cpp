// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The comparison methods on chains of N masses (issue 47): the same kernels as for the note's
// chain, so the note's chain written as a chain of two masses runs the same methods; each
// converges to the exact run on chains of 3 to 10 masses, interior stops and right walls
// included; the exact method is the chain engine; the errors count what a method misses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/methods/compare.h"
#include "core/methods/stress_matrix.h"
#include "core/methods/work_precision.h"
#include "core/model/chain_design.h"
#include "core/model/mass_chain.h"
#include "core/orbits/chain_glo.h"
#include "core/solver/chain_run.h"
#include "support/cases.h"

namespace grazelab::core::methods {
namespace {

constexpr MethodKind kSteppers[] = {MethodKind::MoreauJean, MethodKind::SchatzmanPaoli};
constexpr MethodKind kEventDriven[] = {MethodKind::Dopri5Events, MethodKind::CvodeAdams, MethodKind::CvodeBdf};

double slowestPeriod(const MassChain& chain) { return twoPi<double>() / chainModes(chain).omega.minCoeff(); }

ChainState stateOf(std::initializer_list<double> u, std::initializer_list<double> v) {
  ChainState state{Eigen::VectorXd(Eigen::Index(u.size())), Eigen::VectorXd(Eigen::Index(v.size()))};
  Eigen::Index i = 0;
  for (double x : u) state.u(i++) = x;
  i = 0;
  for (double x : v) state.v(i++) = x;
  return state;
}

struct NamedTask {
  std::string name;
  ChainTask task;
};

/// Chains the issue does not name: three unequal masses, four with an interior stop and a right
/// wall, ten equal masses; each over `periods` of its slowest mode, from a start that hits.
std::vector<NamedTask> chainTasks(double periods) {
  std::vector<NamedTask> tasks;
  MassChain three;
  three.masses = {1.0, 2.0, 0.5};
  three.springs = {1.0, 0.7, 1.3};
  three.gap = 0.8;
  tasks.push_back({"three", {three, stateOf({0.1, -0.2, 0.5}, {0.0, 0.3, 0.9}), 0, {}, {}}});
  MassChain interior;
  interior.masses = {1.0, 0.6, 1.4, 0.9};
  interior.springs = {1.0, 2.0, 0.8, 1.1};
  interior.rightSpring = 0.5;
  interior.stopMass = 2;
  interior.gap = 0.5;
  tasks.push_back({"interior-stop-right-wall", {interior, stateOf({0.0, 0.3, 0.0, -0.2}, {0.2, 0.8, -0.1, 0.0}), 0, {}, {}}});
  MassChain ten;
  ten.masses.assign(10, 1.0);
  ten.springs.assign(10, 1.0);
  ChainState start{Eigen::VectorXd::Zero(10), Eigen::VectorXd::Zero(10)};
  start.u(9) = 0.5;
  start.v(9) = 1.5;
  start.v(0) = -0.4;
  tasks.push_back({"ten", {ten, start, 0, {}, {}}});
  for (NamedTask& named : tasks) named.task.tEnd = periods * slowestPeriod(named.task.chain);
  return tasks;
}

TEST(ChainMethods, TheNotesChainWrittenAsAChainRunsTheSameMethods) {
  // the note's chain as Task (its scaled form, its recorder) and as ChainTask (masses and
  // springs, scaled by its slowest mode and its gap): the same equations in other units, so
  // every method makes the same contacts and ends in the same state up to rounding
  for (const double m2 : {0.5, 0.3}) {
    const Model model = testing::resonantChain(m2);
    const TwoMassForm<double> chain = *makeTwoMassForm(model).chain;
    const double period = twoPi<double>() / chain.omegaSlow;
    // a start that hits squarely (near grazing, CVODE's methods may slide through the stop in
    // either form: that is theirs, not the form's)
    Task task{model, State{0.3, 0.8, 0.2, 0.5}, 6 * period, {}};
    task.needs.events = true;
    const ChainTask chainTask{massChainOf(model), stateOf({task.start.u1, task.start.u2}, {task.start.v1, task.start.v2}),
                              task.tEnd, {}, {}};
    for (MethodKind kind : {MethodKind::MoreauJean, MethodKind::MoreauJeanTheta1, MethodKind::SchatzmanPaoli,
                            MethodKind::Dopri5Events, MethodKind::CvodeAdams, MethodKind::CvodeBdf, MethodKind::Penalty}) {
      const bool stepper = kind == MethodKind::MoreauJean || kind == MethodKind::MoreauJeanTheta1 ||
                           kind == MethodKind::SchatzmanPaoli;
      const MethodSetting setting{kind, stepper ? 1e-3 * period : kind == MethodKind::Penalty ? 1e8 : 1e-9};
      SCOPED_TRACE(setting.label() + " m2 = " + std::to_string(m2));
      const MethodRun a = runMethod(task, setting);
      const ChainMethodRun b = runMethod(chainTask, setting);
      ASSERT_EQ(a.status, RunStatus::Completed) << a.reason;
      ASSERT_EQ(b.status, RunStatus::Completed) << b.reason;
      EXPECT_EQ(a.result.cost.contacts, b.result.contacts);
      const State& x = a.result.final;
      const Eigen::Vector4d both(x.u1 - b.result.final.u(0), x.u2 - b.result.final.u(1), x.v1 - b.result.final.v(0),
                                 x.v2 - b.result.final.v(1));
      // rounding, amplified by the motion's sensitivity over six periods
      EXPECT_LT(both.cwiseAbs().maxCoeff(), 1e-7 * model.gap);
      EXPECT_NEAR(a.maxEnergyDrift, b.maxEnergyDrift, 1e-6 + 1e-3 * a.maxEnergyDrift);
    }
  }
}

TEST(ChainMethods, ScaleFreeAsThePhysics) {
  // lengths 2^20 times larger, masses and springs 4 times: the same unit-free run, bit for bit
  for (const NamedTask& named : chainTasks(4)) {
    SCOPED_TRACE(named.name);
    ChainTask large = named.task;
    const double factor = std::ldexp(1.0, 20);
    large.chain.gap *= factor;
    for (double& m : large.chain.masses) m *= 4;
    for (double& k : large.chain.springs) k *= 4;
    large.chain.rightSpring *= 4;
    large.start.u *= factor;
    large.start.v *= factor;
    for (MethodKind kind : {MethodKind::MoreauJean, MethodKind::SchatzmanPaoli, MethodKind::Dopri5Events,
                            MethodKind::CvodeBdf, MethodKind::Penalty}) {
      const double value = kind == MethodKind::MoreauJean || kind == MethodKind::SchatzmanPaoli
                               ? 1e-3 * slowestPeriod(named.task.chain)
                           : kind == MethodKind::Penalty ? 1e6
                                                         : 1e-8;
      const ChainMethodRun a = runMethod(named.task, {kind, value});
      const ChainMethodRun b = runMethod(large, {kind, kind == MethodKind::Penalty ? 4 * value : value});
      SCOPED_TRACE(std::string(methodName(kind)));
      ASSERT_EQ(a.status, RunStatus::Completed) << a.reason;
      EXPECT_EQ(Eigen::VectorXd(factor * a.result.final.u), b.result.final.u);
      EXPECT_EQ(Eigen::VectorXd(factor * a.result.final.v), b.result.final.v);
      EXPECT_EQ(a.result.events.size(), b.result.events.size());
    }
  }
}

TEST(ChainMethods, TheExactMethodIsTheChainEngine) {
  for (const NamedTask& named : chainTasks(5)) {
    SCOPED_TRACE(named.name);
    const ChainTask& task = named.task;
    const ChainRun engine = runChain(task.chain, task.start, 1'000'000, task.tEnd);
    const ChainMethodRun exact = runMethod(task, {MethodKind::Exact, 0, Precision::Double});
    ASSERT_EQ(exact.status, RunStatus::Completed) << exact.reason;
    EXPECT_EQ(exact.result.final.u, engine.final.u);
    EXPECT_EQ(exact.result.final.v, engine.final.v);
    ASSERT_EQ(exact.result.events.size(), engine.events.size());
    for (std::size_t i = 0; i < engine.events.size(); ++i) {
      EXPECT_EQ(exact.result.events[i].t, engine.events[i].t);
      EXPECT_EQ(exact.result.events[i].vBefore, engine.events[i].vBefore);
    }
    EXPECT_EQ(exact.steps, engine.contacts);
  }
}

TEST(ChainMethods, AGlomOfAFastModeIsDecidedByTheExactColumnTheHorizonAndTheMatrix) {
  // GLOM_1 of a 3:2:1 chain grazes every T/3 when its still modes are kept (issue 47, item 5):
  // the exact method, the reference, the start's error estimate (the report's horizon) and the
  // stability matrix's rows of the chain given and its scaled copies keep them too; dropped
  // anywhere, that part stopped undecided at t = 0 while simulate decided
  MassChain chain;
  chain.masses = {1.0, 0.2, 0.05};
  chain.springs = designSprings(chain.masses, 1.0, {3, 2, 1}).designs.at(0).springs;
  const ChainGloStart glo = chainGloStart(chain, {1, 0, 0});
  const double period = chainDynamics(chain).period;
  // (its end between two returns: at one, the precisions' sums of T/3 may fall on either side)
  ChainTask task = prepared(ChainTask{chain, glo.state, 10.5 * period, {}, glo.stillModes});
  const ChainMethodRun exact = runMethod(task, {MethodKind::Exact, 0, Precision::Double});
  ASSERT_EQ(exact.status, RunStatus::Completed) << exact.reason;
  EXPECT_EQ(exact.result.grazings, 31);
  const Trust trust = startTrust(task);
  EXPECT_EQ(trust.verdict, Verdict::Ok) << trust.reason;
  EXPECT_GE(trust.shadowEvents, 31);
  const ComparisonEnd end = comparisonEnd(task);
  EXPECT_FALSE(end.shortened);
  EXPECT_EQ(end.tEnd, task.tEnd);
  const std::vector<StressCase> cases = chainStressCases(chain, glo.start(), {}, true);
  int decided = 0;
  for (const StressCase& row : cases) {
    if (row.name != "given" && row.name.rfind("gap-", 0) != 0) continue;
    ASSERT_TRUE(row.task) << row.name << ": " << row.problem;
    const ChainTask& given = std::get<ChainTask>(*row.task);
    EXPECT_EQ(given.stillModes, glo.stillModes) << row.name;
    const ChainMethodRun run = runMethod(given, {MethodKind::Exact, 0, Precision::Double});
    EXPECT_EQ(run.status, RunStatus::Completed) << row.name << ": " << run.reason;
    ++decided;
  }
  EXPECT_EQ(decided, 2);  // quick: the chain given and one scaled copy
}

TEST(ChainMethods, AContactDoubleCannotDecideIsUndecidedNotABudgetAndBinary128DecidesIt) {
  // three masses, the stopped one pushed 1e-15 off its grazing start: the exact solver in
  // double meets a contact it cannot decide and stops there, said as such (the cell's verdict
  // too), not as a budget spent; in binary128 the same run completes
  MassChain chain;
  chain.masses = {1.0, 0.3, 0.6};
  chain.springs = {1.0, 0.7, 1.3};
  chain.gap = 0.4;
  const ChainStart start(stateOf({0.1, 0, 0.4}, {0, 0.2, -0.3}));
  const std::vector<StressCase> cases = chainStressCases(chain, start, {}, true);
  const auto push = std::find_if(cases.begin(), cases.end(), [](const StressCase& row) { return row.name == "push-1e-15"; });
  ASSERT_NE(push, cases.end());
  ASSERT_TRUE(push->task) << push->problem;
  const ChainTask& task = std::get<ChainTask>(*push->task);
  const ChainMethodRun inDouble = runMethod(task, {MethodKind::Exact, 0, Precision::Double});
  ASSERT_EQ(inDouble.status, RunStatus::Undecided) << inDouble.reason;
  EXPECT_NE(inDouble.reason.find("undecided in double"), std::string::npos) << inDouble.reason;
  const ChainMethodRun inQuad = runMethod(task, {MethodKind::Exact, 0, Precision::Quad});
  EXPECT_EQ(inQuad.status, RunStatus::Completed) << inQuad.reason;
  std::vector<StressCell> cells;
  runStressCase(*push, {MethodKind::Exact}, {}, [&cells](const StressCell& cell) { cells.push_back(cell); }, nullptr);
  ASSERT_EQ(cells.size(), 1u);
  EXPECT_EQ(cells[0].verdict, CellVerdict::Undecided) << cells[0].reason;
  EXPECT_EQ(toString(cells[0].verdict), "undecided");
}

TEST(ChainMethods, APreparedTaskRunsTheSameBits) {
  // the chain made ready once (what the report times) or by each run: the same runs
  for (const NamedTask& named : chainTasks(3)) {
    SCOPED_TRACE(named.name);
    const ChainTask ready = prepared(named.task);
    ASSERT_TRUE(ready.prepared);
    for (const MethodSetting& setting :
         {MethodSetting{MethodKind::Exact, 0, Precision::Double}, MethodSetting{MethodKind::Exact, 0, Precision::Long},
          MethodSetting{MethodKind::Exact, 0, Precision::Quad}, MethodSetting{MethodKind::MoreauJean, 1e-2},
          MethodSetting{MethodKind::Dopri5Events, 1e-8}}) {
      const ChainMethodRun a = runMethod(named.task, setting);
      const ChainMethodRun b = runMethod(ready, setting);
      SCOPED_TRACE(setting.label());
      EXPECT_EQ(a.result.final.u, b.result.final.u);
      EXPECT_EQ(a.result.final.v, b.result.final.v);
      EXPECT_EQ(a.result.events.size(), b.result.events.size());
    }
    const ChainReference plain = makeReference(named.task);
    const ChainReference fromReady = makeReference(ready);
    EXPECT_EQ(plain.period, fromReady.period);
    EXPECT_EQ(plain.velocityScale, fromReady.velocityScale);
  }
}

TEST(ChainMethods, EveryMethodConvergesToTheExactRunOnChainsOfThreeToTenMasses) {
  for (const NamedTask& named : chainTasks(5)) {
    SCOPED_TRACE(named.name);
    const ChainTask& task = named.task;
    const ChainReference reference = makeReference(task);
    ASSERT_EQ(reference.run.status, RunStatus::Completed) << reference.run.reason;
    ASSERT_GE(reference.run.result.contacts, 3);
    for (Precision precision : {Precision::Double, Precision::Long, Precision::Quad}) {
      const Errors e = compare(reference, runMethod(task, {MethodKind::Exact, 0, precision}));
      EXPECT_EQ(e.missed, 0);
      EXPECT_EQ(e.extra, 0);
      EXPECT_LT(e.state, precision == Precision::Double ? 1e-11 : 1e-14);
    }
    // the time steppers: at least first order in the contact times (Schatzman-Paoli's symmetric
    // impact law may do better), every contact found once h is small
    const double period = reference.period;
    for (MethodKind kind : kSteppers) {
      SCOPED_TRACE(std::string(methodName(kind)));
      const Errors coarse = compare(reference, runMethod(task, {kind, 1e-3 * period}));
      const Errors fine = compare(reference, runMethod(task, {kind, 1e-3 * period / 16}));
      EXPECT_EQ(fine.missed, 0);
      EXPECT_EQ(fine.extra, 0);
      const double order = std::log(coarse.contactTime / fine.contactTime) / std::log(16.0);
      EXPECT_GT(order, 0.7);
      EXPECT_LT(order, 2.5);
    }
    // the event-driven methods: their error follows their tolerance
    for (MethodKind kind : kEventDriven) {
      SCOPED_TRACE(std::string(methodName(kind)));
      const Errors loose = compare(reference, runMethod(task, {kind, 1e-6}));
      const Errors tight = compare(reference, runMethod(task, {kind, 1e-11}));
      EXPECT_EQ(tight.missed, 0);
      EXPECT_EQ(tight.extra, 0);
      EXPECT_LT(tight.state, 1e-5);
      EXPECT_LT(tight.state, loose.state);
    }
    const Errors stiff = compare(reference, runMethod(task, {MethodKind::Penalty, 1e10 * task.chain.springs[0]}));
    const Errors soft = compare(reference, runMethod(task, {MethodKind::Penalty, 1e4 * task.chain.springs[0]}));
    EXPECT_LT(stiff.contactTime, soft.contactTime);
  }
}

TEST(ChainMethods, BadInputIsRefusedWithItsReason) {
  const ChainTask good = chainTasks(2).front().task;
  ChainTask wrongSize = good;
  wrongSize.start.u.resize(2);
  ChainTask pastTheStop = good;
  pastTheStop.start.u(2) = 2 * good.chain.gap;
  ChainTask noHorizon = good;
  noHorizon.tEnd = -1;
  ChainTask badChain = good;
  badChain.chain.masses[1] = -1;
  for (const auto& [task, word] : {std::pair{wrongSize, "displacements"}, std::pair{pastTheStop, "past the stop"},
                                   std::pair{noHorizon, "t-end"}, std::pair{badChain, "m"}}) {
    for (MethodKind kind : kAllMethods) {
      const ChainMethodRun run = runMethod(task, {kind, 1e-3});
      SCOPED_TRACE(std::string(methodName(kind)) + ": " + run.reason);
      EXPECT_EQ(run.status, RunStatus::Refused);
      EXPECT_NE(run.reason.find(word), std::string::npos);
    }
    EXPECT_EQ(makeReference(task).run.status, RunStatus::Refused);
  }
}

TEST(ChainMethods, EveryMethodHonoursItsStopToken) {
  const ChainTask task = chainTasks(50).back().task;
  std::stop_source source;
  source.request_stop();
  for (MethodKind kind : kAllMethods) {
    const ChainMethodRun run = runMethod(task, {kind, 1e-4}, {}, source.get_token());
    SCOPED_TRACE(std::string(methodName(kind)));
    EXPECT_EQ(run.status, RunStatus::Cancelled);
  }
}

TEST(ChainCompare, CountsMissedAndExtraContactsOnTheStoppedMass) {
  // a reference with contacts at 1, 2, 3, 4 (T2 = 4); the method misses 2, finds 3 late and
  // invents one at 3.4: its speeds read on the stopped mass (the second of three)
  ChainReference reference;
  reference.period = 4;
  reference.positionScale = 1;
  reference.velocityScale = 1;
  reference.stop = 1;
  auto event = [](double t, double speed) {
    return ChainEvent{t, EventType::Impact, Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(9, speed, 9), -speed};
  };
  for (double t : {1.0, 2.0, 3.0, 4.0}) reference.run.result.events.push_back(event(t, 1.0));
  reference.run.result.tFinal = 5;
  reference.run.result.final = stateOf({0, 0, 0}, {0, 0, 0});
  ChainMethodRun run;
  run.result.events = {event(1.0, 1.0), event(3.01, 1.5), event(3.4, 1.0), event(4.0, 1.0)};
  run.result.tFinal = 5;
  run.result.final = stateOf({0, 0.25, 0}, {0, 0, 0});
  const Errors e = compare(reference, run);
  EXPECT_EQ(e.matched, 3);
  EXPECT_EQ(e.missed, 1);
  EXPECT_EQ(e.extra, 1);
  EXPECT_NEAR(e.contactTime, 0.01 / 4, 1e-12);
  EXPECT_NEAR(e.impactSpeed, 0.5, 1e-12);
  EXPECT_NEAR(e.state, 0.25, 1e-15);
}

}  // namespace
}  // namespace grazelab::core::methods
