// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The comparison methods of issue 8: each converges to the exact solution at its order, each
// stops with a reason on a budget, a stop token or an input it cannot take, and the errors are
// measured against a reference that is itself right.
#include <gtest/gtest.h>

#include <cmath>
#include <stop_token>

#include "core/methods/compare.h"
#include "core/methods/stress_matrix.h"
#include "core/methods/work_precision.h"
#include "core/solver/simulate.h"
#include "support/cases.h"

namespace grazelab::core::methods {
namespace {

/// The report's default problem, over `periods` slow periods.
Task defaultTask(double periods) {
  const Model model = testing::resonantChain(0.5);
  const TwoMassForm<double> chain = *makeTwoMassForm(model).chain;
  StartSpec<double> spec;
  spec.lambda = 0.5;
  spec.perturbation = State{0, 0, 0.05, -0.05};
  Task task{model, makeStart(chain, spec).start->state, periods * twoPi<double>() / chain.omegaSlow, {}};
  task.needs.events = true;
  return task;
}

double period(const Task& task) { return twoPi<double>() / makeTwoMassForm(task.model).chain->omegaSlow; }

TEST(Methods, NamesRoundTrip) {
  for (MethodKind kind : kAllMethods) {
    EXPECT_EQ(parseMethod(methodName(kind)), kind);
  }
  EXPECT_FALSE(parseMethod("runge-kutta"));
}

TEST(Methods, TheReferenceAgreesWithThePlainBinary128Run) {
  // the reference runs a rescaled chain; scale-free physics gives the same motion
  const Task task = defaultTask(20);
  const Reference reference = makeReference(task);
  ASSERT_EQ(reference.run.status, RunStatus::Completed);
  const MethodRun quad = runMethod(task, {MethodKind::Exact, 0, Precision::Quad});
  ASSERT_EQ(quad.status, RunStatus::Completed);
  const Errors errors = compare(reference, quad);
  EXPECT_LT(errors.state, 1e-15);  // the comparison is in double: this is its resolution
  EXPECT_EQ(errors.missed, 0);
  EXPECT_EQ(errors.extra, 0);
  EXPECT_EQ(errors.matched, 20);
}

TEST(Methods, ExactThroughTheInterfaceIsTheRun) {
  const Task task = defaultTask(20);
  Request request;
  request.initial = task.start;
  request.tEnd = task.tEnd;
  request.maxContacts = std::numeric_limits<std::int64_t>::max();
  const Result direct = simulate(task.model, request);
  const MethodRun run = runMethod(task, {MethodKind::Exact, 0, Precision::Double});
  EXPECT_EQ(run.result.final, direct.final);
  EXPECT_EQ(run.result.cost.contacts, direct.cost.contacts);
  EXPECT_EQ(run.status, RunStatus::Completed);
}

/// The order of a fixed-step method from h, h/4, h/16 on a short, non-sensitive stretch.
double observedOrder(MethodKind kind, const Task& task, double h) {
  const Reference reference = makeReference(task);
  double errors[3];
  for (int i = 0; i < 3; ++i) {
    const MethodRun run = runMethod(task, {kind, h / std::pow(4.0, i)});
    EXPECT_EQ(run.status, RunStatus::Completed) << run.reason;
    const Errors e = compare(reference, run);
    EXPECT_EQ(e.missed, 0);
    EXPECT_EQ(e.extra, 0);
    errors[i] = e.contactTime;
  }
  return std::log(errors[0] / errors[2]) / std::log(16.0);
}

TEST(Methods, MoreauJeanIsFirstOrderInTheContactTimes) {
  const Task task = defaultTask(5);
  const double order = observedOrder(MethodKind::MoreauJean, task, period(task) * 1e-4);
  EXPECT_GT(order, 0.8);
  EXPECT_LT(order, 1.3);
}

TEST(Methods, SchatzmanPaoliIsFirstOrderInTheContactTimes) {
  const Task task = defaultTask(5);
  const double order = observedOrder(MethodKind::SchatzmanPaoli, task, period(task) * 1e-4);
  EXPECT_GT(order, 0.8);
  EXPECT_LT(order, 1.3);
}

TEST(Methods, EventDrivenMethodsFollowTheirTolerance) {
  const Task task = defaultTask(5);
  const Reference reference = makeReference(task);
  for (MethodKind kind : {MethodKind::Dopri5Events, MethodKind::CvodeAdams, MethodKind::CvodeBdf}) {
    const Errors loose = compare(reference, runMethod(task, {kind, 1e-6}));
    const Errors tight = compare(reference, runMethod(task, {kind, 1e-11}));
    SCOPED_TRACE(std::string(methodName(kind)));
    EXPECT_EQ(tight.missed + tight.extra, 0);
    // CVODE's global error is some 1e5 times its tolerance here, Dormand-Prince's 1e3 times
    EXPECT_LT(tight.state, 1e-5);
    EXPECT_LT(tight.state, loose.state / 50);
  }
}

TEST(Methods, PenaltyErrorFallsWithTheStiffness) {
  const Task task = defaultTask(5);
  const Reference reference = makeReference(task);
  double previous = 1e300;
  for (double kc : {1e6, 1e8, 1e10}) {
    const MethodRun run = runMethod(task, {MethodKind::Penalty, kc, Precision::Double, 1e-12});
    ASSERT_EQ(run.status, RunStatus::Completed) << run.reason;
    const Errors e = compare(reference, run);
    EXPECT_EQ(e.missed + e.extra, 0);
    EXPECT_LT(e.contactTime, previous);
    previous = e.contactTime;
  }
}

TEST(Methods, ThetaHalfKeepsTheEnergyAndThetaOneDissipatesIt) {
  const Task task = defaultTask(20);
  const MethodRun half = runMethod(task, {MethodKind::MoreauJean, period(task) * 1e-3});
  const MethodRun one = runMethod(task, {MethodKind::MoreauJeanTheta1, period(task) * 1e-3});
  EXPECT_LT(half.maxEnergyDrift, 1e-9);  // trapezoidal in flight, e = 1 at impacts
  EXPECT_GT(one.maxEnergyDrift, 1e-2);   // implicit Euler damps
}

TEST(Methods, ScaleFreeAsThePhysics) {
  // a chain 2^20 times larger, start with it: the same nondimensional run, bit for bit
  Task small = defaultTask(5);
  Task large = small;
  const double factor = std::ldexp(1.0, 20);
  large.model = testing::resonantChain(0.5, factor);
  large.start = factor * small.start;
  for (MethodKind kind : {MethodKind::MoreauJean, MethodKind::SchatzmanPaoli, MethodKind::Dopri5Events,
                          MethodKind::CvodeBdf}) {
    const double value = kind == MethodKind::Dopri5Events || kind == MethodKind::CvodeBdf ? 1e-8 : period(small) * 1e-3;
    const MethodRun a = runMethod(small, {kind, value});
    const MethodRun b = runMethod(large, {kind, value});
    SCOPED_TRACE(std::string(methodName(kind)));
    EXPECT_EQ(factor * a.result.final, b.result.final);
    EXPECT_EQ(a.result.events.size(), b.result.events.size());
  }
}

TEST(Methods, EveryMethodStopsOnItsBudgetWithAReason) {
  Task task = defaultTask(1e6);  // far beyond any budget
  task.needs.events = false;
  WorkBudget budget;
  budget.maxSeconds = 0.05;
  for (MethodKind kind : kAllMethods) {
    const MethodSetting setting = standardSetting(kind, period(task), 1.0);
    const MethodRun run = runMethod(task, setting, budget);
    SCOPED_TRACE(std::string(methodName(kind)));
    EXPECT_EQ(run.status, RunStatus::Budget);
    EXPECT_FALSE(run.reason.empty());
    EXPECT_LT(run.seconds, 1.0);
  }
}

TEST(Methods, EveryMethodHonoursItsStopToken) {
  const Task task = defaultTask(1e5);
  std::stop_source source;
  source.request_stop();
  for (MethodKind kind : kAllMethods) {
    const MethodRun run = runMethod(task, standardSetting(kind, period(task), 1.0), {}, source.get_token());
    SCOPED_TRACE(std::string(methodName(kind)));
    EXPECT_EQ(run.status, RunStatus::Cancelled);
  }
}

TEST(Methods, BadInputIsRefusedWithItsReason) {
  Task task = defaultTask(1);
  task.model.m1 = -1;
  for (MethodKind kind : kAllMethods) {
    const MethodRun run = runMethod(task, standardSetting(kind, 8.9, 1.0));
    EXPECT_EQ(run.status, RunStatus::Refused);
    EXPECT_NE(run.reason.find("m1"), std::string::npos) << run.reason;
  }
  const MethodRun zeroStep = runMethod(defaultTask(1), {MethodKind::MoreauJean, 0.0});
  EXPECT_EQ(zeroStep.status, RunStatus::Refused);
}

TEST(Methods, AStartPressedOnTheStopSticksInMoreauJeanAndStopsTheEventDrivenOnes) {
  Task task = defaultTask(1);
  task.start = State{1.5, 1, 0, 0};  // the spring pushes mass 2 into the stop
  const MethodRun mj = runMethod(task, standardSetting(MethodKind::MoreauJean, period(task), 1.0));
  ASSERT_EQ(mj.status, RunStatus::Completed);
  ASSERT_FALSE(mj.result.events.empty());
  EXPECT_EQ(mj.result.events.front().type, EventType::Stick);
  EXPECT_LE(mj.result.final.u2, 1.0 + 1e-9);
  for (MethodKind kind : {MethodKind::Dopri5Events, MethodKind::CvodeAdams, MethodKind::CvodeBdf}) {
    const MethodRun run = runMethod(task, standardSetting(kind, period(task), 1.0));
    SCOPED_TRACE(std::string(methodName(kind)));
    // never a silent pass through the stop: the run fails and says why
    EXPECT_EQ(run.status, RunStatus::Failed);
    EXPECT_FALSE(run.reason.empty());
  }
}

TEST(Methods, AnUnstableExplicitSchemeDivergesLoudly) {
  // k2/k1 = 1e6: w1 h = 2 pi 1000 / 1000 >> 2, beyond central differences' stability limit
  Model model;
  model.k2 = 1e6;
  model.design.reset();
  const TwoMassForm<double> chain = *makeTwoMassForm(model).chain;
  StartSpec<double> spec;
  spec.perturbation = State{0, 0, 0.05, -0.05};
  Task task{model, makeStart(chain, spec).start->state, 20 * twoPi<double>() / chain.omegaSlow, {}};
  const MethodRun run = runMethod(task, standardSetting(MethodKind::SchatzmanPaoli, period(task), 1.0));
  EXPECT_EQ(run.status, RunStatus::Failed);
  EXPECT_NE(run.reason.find("diverged"), std::string::npos) << run.reason;
}

TEST(Compare, CountsMissedAndExtraContacts) {
  Reference reference;
  reference.period = 10;
  reference.positionScale = 1;
  reference.velocityScale = 1;
  reference.run.result.tFinal = 100;
  for (double t : {10.0, 20.0, 30.0}) {
    reference.run.result.events.push_back({t, EventType::Impact, {0, 1, 0, 1}, {0, 1, 0, -1}});
  }
  MethodRun run;
  run.result.tFinal = 100;
  run.result.events.push_back({10.1, EventType::Impact, {0, 1, 0, 1.5}, {0, 1, 0, -1.5}});
  run.result.events.push_back({25.0, EventType::Impact, {0, 1, 0, 1}, {0, 1, 0, -1}});
  run.result.events.push_back({30.0, EventType::Impact, {0, 1, 0, 1}, {0, 1, 0, -1}});
  const Errors e = compare(reference, run);
  EXPECT_EQ(e.matched, 2);
  EXPECT_EQ(e.missed, 1);  // 20 has no counterpart within its window (5 on either side / 2)
  EXPECT_EQ(e.extra, 1);   // 25
  EXPECT_NEAR(e.contactTime, 0.01, 1e-12);
  EXPECT_NEAR(e.impactSpeed, 0.5, 1e-12);
}

TEST(WorkPrecision, SlopeOfAFirstOrderLaw) {
  std::vector<WorkPrecisionPoint> points;
  for (double h : {1e-3, 1e-4, 1e-5, 1e-6}) {
    WorkPrecisionPoint p;
    p.setting = {MethodKind::MoreauJean, h};
    p.secondsMin = 1e-3 / h;
    p.errors.state = p.errors.contactTime = 3 * h;
    points.push_back(p);
  }
  const auto slope = fittedSlope(points, ErrorMeasure::ContactTime);
  ASSERT_TRUE(slope);
  EXPECT_NEAR(slope->value, 1.0, 1e-12);
  EXPECT_EQ(slope->points, 4);
  const auto reach = secondsToReach(points, 3e-5);
  ASSERT_TRUE(reach);
  EXPECT_NEAR(*reach, 100.0, 1e-9);
}

TEST(Stability, QuickMatrixEndsEveryCellWithAVerdictAndAReason) {
  std::vector<StressCell> cells;
  WorkBudget budget;
  budget.maxSeconds = 0.5;
  const std::vector<MethodKind> methods(std::begin(kAllMethods), std::end(kAllMethods));
  for (const StressCase& row : stressCases(true)) {
    if (row.longRunContacts > 0) continue;  // the long run is the command's, not a unit test's
    runStressCase(row, methods, budget, [&cells](const StressCell& c) { cells.push_back(c); }, nullptr);
  }
  ASSERT_FALSE(cells.empty());
  int ok = 0;
  for (const StressCell& cell : cells) {
    SCOPED_TRACE(cell.caseName + " / " + std::string(methodName(cell.method)));
    if (cell.verdict == CellVerdict::Ok) {
      ++ok;
      EXPECT_TRUE(std::isfinite(cell.errors.state));
      EXPECT_TRUE(cell.reason.empty());
    } else {
      EXPECT_FALSE(cell.reason.empty());
    }
    if (cell.method == MethodKind::Exact && cell.caseName != "penalty-kc-1e+12") {
      EXPECT_EQ(cell.verdict, CellVerdict::Ok) << cell.reason;
    }
  }
  EXPECT_GT(ok, 0);
}

}  // namespace
}  // namespace grazelab::core::methods
