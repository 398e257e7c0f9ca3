// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Cost per step of each comparison method and per contact of the exact solver, and the default
// problem of the work-precision report run by each at (about) the same accuracy.
// Run: ./build/tests/bench/grazelab_methods_bench
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/methods/compare.h"
#include "core/methods/stress_matrix.h"
#include "support/cases.h"

namespace grazelab {
namespace {

using core::methods::MethodKind;

/// The report's default problem over `periods` slow periods.
core::methods::Task defaultTask(double periods) {
  const core::Model model = testing::resonantChain(0.5);
  const core::Chain<double> chain = *core::makeChain(model).chain;
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
  const double period = core::twoPi<double>() / core::makeChain(task.model).chain->omegaSlow;
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

}  // namespace
}  // namespace grazelab

BENCHMARK_MAIN();
