// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Map throughput (issue 10): runs per second (items/s) of a first-flight landscape on the
// grazing-start plane and of 100-contact runs, on 1 and 2 threads in one run.
// Run: ./build/tests/bench/grazelab_map_bench
#include <benchmark/benchmark.h>

#include "core/experiments/maps.h"
#include "parallel/tbb_parallel_for.h"

namespace grazelab {
namespace {

void mapOfGrazingPlane(benchmark::State& state, std::int64_t side, std::int64_t contacts) {
  core::MapSpec spec;
  spec.model.design = core::Branch::Upper;
  spec.x = {core::MapVariable::U1, -1.0, 2.0, side};
  spec.y = {core::MapVariable::V1, -1.5, 1.5, side};
  spec.contacts = contacts;
  const core::ParallelFor executor = parallel::tbbParallelFor(int(state.range(0)));
  for (auto _ : state) {
    const core::MapRows map = core::computeMap(spec, {0, side}, executor);
    benchmark::DoNotOptimize(map.points.data());
  }
  state.SetItemsProcessed(state.iterations() * side * side);
}

void FirstFlights512(benchmark::State& state) { mapOfGrazingPlane(state, 512, 1); }
BENCHMARK(FirstFlights512)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

void HundredContacts128(benchmark::State& state) { mapOfGrazingPlane(state, 128, 100); }
BENCHMARK(HundredContacts128)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace grazelab

BENCHMARK_MAIN();
