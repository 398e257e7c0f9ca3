// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Cost per step of each comparison method and per contact of the exact solver, and the default
// problem of the work-precision report run by each at (about) the same accuracy.
// Run: ./build/tests/bench/grazelab_methods_bench
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/methods/compare.h"
#include "core/methods/stress_matrix.h"
#include "core/model/mass_chain.h"
#include "support/cases.h"

namespace grazelab {
namespace {

using core::methods::MethodKind;

/// The report's default problem over `periods` slow periods.
core::methods::Task defaultTask(double periods) {
  const core::Model model = testing::resonantChain(0.5);
  const core::TwoMassForm<double> chain = *core::makeTwoMassForm(model).chain;
  core::StartSpec<double> spec;
  spec.lambda = 0.5;
  spec.perturbation = core::State{0, 0, 0.05, -0.05};
  core::methods::Task task{model, core::makeStart(chain, spec).start->state,
                           periods * core::twoPi<double>() / chain.omegaSlow, {}};
  task.needs.events = true;
  return task;
}

void runSetting(benchmark::State& state, const core::methods::Task& task,
                const core::methods::MethodSetting& setting) {
  const core::methods::Reference reference = core::methods::makeReference(task);
  const core::methods::MethodRun first = core::methods::runMethod(task, setting);
  std::int64_t steps = 0;
  for (auto _ : state) {
    const core::methods::MethodRun run = core::methods::runMethod(task, setting);
    benchmark::DoNotOptimize(run.result.final);
    steps += run.steps;
  }
  // items: time steps (contacts for the exact solver)
  state.SetItemsProcessed(steps);
  state.counters["state_error"] = core::methods::compare(reference, first).state;
}

/// Each method at its standard setting of the stability matrix, 20 T2: the cost per step.
void PerStep(benchmark::State& state) {
  const MethodKind kind = core::methods::kAllMethods[state.range(0)];
  const core::methods::Task task = defaultTask(20);
  const double period = core::twoPi<double>() / core::makeTwoMassForm(task.model).chain->omegaSlow;
  state.SetLabel(std::string(core::methods::methodName(kind)));
  runSetting(state, task, core::methods::standardSetting(kind, period, 1.0));
}
BENCHMARK(PerStep)->DenseRange(0, 7)->Unit(benchmark::kMicrosecond);

/// The report's default problem (200 T2) at a state error of about 1e-8: the exact solver in
/// double, and Dormand-Prince at the tolerance that reaches it (the fastest other method there).
void EqualAccuracyExact(benchmark::State& state) {
  runSetting(state, defaultTask(200), {MethodKind::Exact, 0, core::Precision::Double});
}
BENCHMARK(EqualAccuracyExact)->Unit(benchmark::kMicrosecond);

void EqualAccuracyDopri5(benchmark::State& state) {
  runSetting(state, defaultTask(200), {MethodKind::Dopri5Events, 2e-13});
}
BENCHMARK(EqualAccuracyDopri5)->Unit(benchmark::kMicrosecond);

/// Each method at its standard setting on chains of N = 3 and 10 masses (the first N of the
/// unequal masses 1, 2, 0.5, 1.5, ... and springs 1, 0.7, 1.3, ..., the last mass stopped at
/// d = 0.8, started moving into the stop), 20 of its slowest periods: the cost per step as the
/// chain grows. Arguments: the method, N.
void ChainPerStep(benchmark::State& state) {
  const MethodKind kind = core::methods::kAllMethods[state.range(0)];
  const int n = int(state.range(1));
  core::MassChain chain;
  for (int i = 0; i < n; ++i) {
    chain.masses.push_back(i % 3 == 0 ? 1.0 + 0.5 * (i / 3) : i % 3 == 1 ? 2.0 : 0.5);
    chain.springs.push_back(i % 3 == 0 ? 1.0 : i % 3 == 1 ? 0.7 : 1.3);
  }
  chain.gap = 0.8;
  core::ChainState start{Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
  start.u(n - 1) = 0.5;
  start.v(n - 1) = 1.5;
  start.v(0) = -0.4;
  const double period = core::twoPi<double>() / core::chainModes(chain).omega.minCoeff();
  const core::methods::ChainTask task = core::methods::prepared({chain, start, 20 * period, {}, {}});
  const core::methods::MethodSetting setting = core::methods::standardSetting(kind, period, chain.springs[0]);
  const core::methods::ChainReference reference = core::methods::makeReference(task);
  const core::methods::ChainMethodRun first = core::methods::runMethod(task, setting);
  std::int64_t steps = 0;
  for (auto _ : state) {
    const core::methods::ChainMethodRun run = core::methods::runMethod(task, setting);
    benchmark::DoNotOptimize(run.result.final.u.data());
    steps += run.steps;
  }
  state.SetLabel(std::string(core::methods::methodName(kind)) + ", N = " + std::to_string(n));
  state.SetItemsProcessed(steps);
  const core::methods::Errors errors = core::methods::compare(reference, first);
  state.counters["state_error"] = errors.state;
  state.counters["missed"] = double(errors.missed);
}
BENCHMARK(ChainPerStep)->ArgsProduct({benchmark::CreateDenseRange(0, 7, 1), {3, 10}})->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace grazelab

BENCHMARK_MAIN();
