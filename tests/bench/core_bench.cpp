// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Throughput of the exact solver, in contacts per second (items/s), on the canonical cases.
// Run: ./build/tests/bench/grazelab_core_bench
#include <benchmark/benchmark.h>

#include "core/chain.h"
#include "core/contact.h"
#include "core/experiment_run.h"
#include "core/modes.h"
#include "core/free_flight.h"
#include "core/orbits.h"
#include "core/simulate.h"
#include "support/cases.h"

namespace grazelab {
namespace {

// a run of `contacts` contacts keeping nothing but the cost (the CLI's summary format)
void runContacts(benchmark::State& state, const core::Model& model, const core::State& initial,
                 bool poincare) {
  core::Request request;
  request.initial = initial;
  request.maxContacts = state.range(0);
  request.needs.events = false;
  request.needs.poincare = poincare;
  core::simulate(model, request);  // warm-up outside the timed loop
  double drift = 0;
  for (auto _ : state) {
    const core::Result result = core::simulate(model, request);
    benchmark::DoNotOptimize(result.final);
    drift = std::max(drift, result.cost.maxRelEnergyDrift);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.counters["energy_drift"] = drift;
}

void NearGrazingUpper(benchmark::State& state) {
  const core::Model model = testing::resonantChain(0.5);
  runContacts(state, model, testing::nearGrazingStart(model, 0.5, 0.05), false);
}
BENCHMARK(NearGrazingUpper)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void NearGrazingLower(benchmark::State& state) {
  const core::Model model = testing::resonantChain(0.5, 1.0, core::Branch::Lower);
  runContacts(state, model, testing::nearGrazingStart(model, 0.5, 0.05), false);
}
BENCHMARK(NearGrazingLower)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void StickingStartUpper(benchmark::State& state) {
  const core::Model model = testing::resonantChain(0.5);
  const core::Modes modes = core::computeModes(model);
  runContacts(state, model, core::gloData(model, modes, 1.5), false);
}
BENCHMARK(StickingStartUpper)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void PoincareSectionUpper(benchmark::State& state) {
  const core::Model model = testing::resonantChain(0.5);
  runContacts(state, model, testing::nearGrazingStart(model, 0.5, 0.05), true);
}
BENCHMARK(PoincareSectionUpper)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void Detuned(benchmark::State& state) {
  runContacts(state, testing::detunedChain(), {-0.25, 1.0, 0.0, -0.05}, false);
}
BENCHMARK(Detuned)->Arg(100'000)->Unit(benchmark::kMillisecond);

// one contact search from a fixed state: the cost of the quartic path alone
void NextContactResonant(benchmark::State& state) {
  const core::Model model = testing::resonantChain(0.5);
  const core::Chain<double> chain = *core::makeChain(model).chain;
  const core::State start = testing::nearGrazingStart(model, 0.5, 0.05);
  const core::Scale<double> scale = core::chooseScale(chain, start);
  const core::State scaled = scale.toScaled(start);
  for (auto _ : state) {
    const core::Flight<double> flight(chain, scale.gap, scaled);
    benchmark::DoNotOptimize(core::nextContact(flight, core::kInfinity));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(NextContactResonant);

// The explorer's default experiment as its worker computes it (core::experiments::run): the
// run in pieces of 30 ms with its trace samples over 400 T2, then its error estimate; against
// NearGrazingUpper, the cost of the pieces and the estimate.
void DefaultSceneExperiment(benchmark::State& state) {
  core::experiments::Spec spec;
  spec.model = testing::resonantChain(0.5);
  spec.run.initial = testing::nearGrazingStart(spec.model, 0.5, 0.05);
  spec.run.maxContacts = state.range(0);
  spec.run.needs.events = true;
  spec.run.needs.poincare = true;
  const core::Modes modes = core::computeModes(spec.model);
  spec.run.needs.samples.spacing = modes.T1 / 48;
  spec.run.needs.samples.tEnd = 400 * modes.T2;
  for (auto _ : state) {
    const core::experiments::Update last =
        core::experiments::run(spec, {}, core::experiments::Options{}, [](const auto&) {});
    benchmark::DoNotOptimize(last.trust);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(DefaultSceneExperiment)->Arg(20'000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace grazelab

BENCHMARK_MAIN();
