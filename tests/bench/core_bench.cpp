// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Throughput of the exact solver, in contacts per second (items/s), on the canonical cases.
// Run: ./build/tests/bench/grazelab_core_bench
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "core/model/two_mass_form.h"
#include "core/solver/contact.h"
#include "core/experiments/bar.h"
#include "core/experiments/chain_series.h"
#include "core/experiments/run.h"
#include "core/model/linear_modes.h"
#include "core/model/chain_design.h"
#include "core/model/mass_chain.h"
#include "core/solver/chain_run.h"
#include "core/orbits/chain_monodromy.h"
#include "core/orbits/chain_onepp.h"
#include "core/orbits/chain_atlas.h"
#include "core/orbits/modes_atlas.h"
#include "core/orbits/periodic_orbit.h"
#include "core/orbits/starts.h"
#include "core/solver/free_flight.h"
#include "core/orbits/special_orbits.h"
#include "core/solver/simulate.h"
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
  const core::TwoMassForm<double> chain = *core::makeTwoMassForm(model).chain;
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

// Dense display samples of one flight (the explorer's animation samples a whole run, 48 per
// fast period): Arg(0) a state at a time (Flight::at, a sine and a cosine each), Arg(1) the
// grid by rotation (Flight::statesOnGrid); items are samples.
void FlightSamples(benchmark::State& state) {
  const core::Model model = testing::resonantChain(0.5);
  const core::TwoMassForm<double> chain = *core::makeTwoMassForm(model).chain;
  const core::State start = testing::nearGrazingStart(model, 0.5, 0.05);
  const core::Scale<double> scale = core::chooseScale(chain, start);
  const core::Flight<double> flight(chain, scale.gap, scale.toScaled(start));
  const double step = 2 * M_PI / chain.ratio / 48;
  std::vector<core::BasicState<double>> samples(96);
  for (auto _ : state) {
    if (state.range(0) == 0) {
      for (std::size_t k = 0; k < samples.size(); ++k) {
        samples[k] = flight.at(core::FlightTime<double>::nearest(double(k) * step));
      }
    } else {
      flight.statesOnGrid(0.0, step, samples);
    }
    benchmark::DoNotOptimize(samples.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(samples.size()));
}
BENCHMARK(FlightSamples)->Arg(0)->Arg(1);

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

// The explorer's Near grazing scene (GLO(0.5) data, v2 pushed by -0.01, 20 000 contacts): the
// run as the worker computes it, up to the report that carries the whole run (what the plots
// wait for; the error estimate after it is not timed). Arg 0: the bare run keeping only the
// cost; 1: with what the scene keeps (events over 30 T2, points on H, free flights, samples).
void NearGrazingSceneRun(benchmark::State& state) {
  core::experiments::Spec spec;
  spec.model = testing::resonantChain(0.5);
  const core::Modes modes = core::computeModes(spec.model);
  spec.run.initial = core::gloData(spec.model, modes, 0.5);
  spec.run.initial.v2 -= 0.01;
  spec.run.maxContacts = 20'000;
  spec.run.needs.events = state.range(0) == 1;
  spec.run.needs.poincare = state.range(0) == 1;
  spec.run.needs.freeFlights = state.range(0) == 1;
  if (state.range(0) == 1) {
    spec.run.needs.eventsUntil = 30 * modes.T2;
    spec.run.needs.samples.spacing = modes.T1 / 48;
    spec.run.needs.samples.tEnd = 30 * modes.T2;
  }
  double runSeconds = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    core::experiments::run(spec, {}, core::experiments::Options{}, [&](const auto& update) {
      if (update.runDone && update.trustPending) {
        runSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }
    });
  }
  state.counters["ms_to_whole_run"] = 1e3 * runSeconds / double(state.iterations());
}
BENCHMARK(NearGrazingSceneRun)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The modes of an N-mass chain (binary128 eigen-solve, then rounded to double): the cost a
// chain editor pays on each edit. Masses and springs from 0.5 to 2, a right wall.
void ChainModes(benchmark::State& state) {
  core::MassChain chain;
  for (int i = 0; i < state.range(0); ++i) {
    chain.masses.push_back(1.0 + 0.5 * std::sin(i));
    chain.springs.push_back(1.0 + 0.5 * std::cos(i));
  }
  chain.rightSpring = 1.0;
  for (auto _ : state) benchmark::DoNotOptimize(core::chainModes(chain));
}
BENCHMARK(ChainModes)->Arg(2)->Arg(8)->Arg(32)->Unit(benchmark::kMicrosecond);

// Springs designed for the ratios N : N-1 : ... : 1 of masses 1, 0.6, 0.36, ...: N! paths
// followed (counter designs: how many positive ones).
void DesignSprings(benchmark::State& state) {
  std::vector<double> masses;
  std::vector<int> harmonics;
  for (int i = 0; i < state.range(0); ++i) {
    masses.push_back(std::pow(0.6, i));
    harmonics.push_back(int(state.range(0)) - i);
  }
  std::size_t designs = 0;
  for (auto _ : state) designs = core::designSprings(masses, 1.0, harmonics).designs.size();
  state.counters["designs"] = double(designs);
}
BENCHMARK(DesignSprings)->DenseRange(2, 6)->Unit(benchmark::kMillisecond);

// The chains ChainRunContacts and ChainContactsReady run: Arg(0) the designed 3:2:1 chain of
// masses 1, 0.2, 0.05 (commensurate: one period searched a flight); Arg(N > 0) a uniform chain
// of N masses (not commensurate: the search runs to the contact); each with a start that reaches
// the stop.
std::pair<core::MassChain, core::ChainState> contactsBenchChain(std::int64_t arg) {
  core::MassChain chain;
  if (arg == 0) {
    chain.masses = {1.0, 0.2, 0.05};
    chain.springs = core::designSprings(chain.masses, 1.0, {3, 2, 1}).designs.at(0).springs;
  } else {
    chain.masses.assign(std::size_t(arg), 1.0);
    chain.springs.assign(std::size_t(arg), 1.0);
  }
  const Eigen::Index n = chain.size();
  core::ChainState start{Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
  for (Eigen::Index i = 0; i < n; ++i) start.v[i] = 0.3 * std::cos(double(i));
  start.v[n - 1] = 1.5 / std::sqrt(chain.masses.back());  // enough energy to reach the stop
  return {chain, start};
}

// Contacts of a chain of N masses (core/solver/chain_run.h), the chain made ready in each run,
// items = contacts, 2000 contacts.
void ChainRunContacts(benchmark::State& state) {
  const auto [chain, start] = contactsBenchChain(state.range(0));
  std::int64_t contacts = 0;
  for (auto _ : state) contacts += std::int64_t(core::runChain(chain, start, 2000).events.size());
  state.SetItemsProcessed(contacts);
}
BENCHMARK(ChainRunContacts)->Arg(0)->Arg(3)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);

// The same chains made ready once, outside the timing (their modes: a binary128 eigensolve, half
// of ChainRunContacts/100's time): the contacts alone, so that issue 50's rates (N = 100: 3e4
// contacts/s) are read without the set-up.
void ChainContactsReady(benchmark::State& state) {
  const auto [chain, start] = contactsBenchChain(state.range(0));
  const core::ReadyChain ready = core::readyChain(chain);
  std::int64_t contacts = 0;
  for (auto _ : state) contacts += std::int64_t(core::runChain(ready, start, 2000).events.size());
  state.SetItemsProcessed(contacts);
}
BENCHMARK(ChainContactsReady)->Arg(3)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);

// A steel bar of N masses thrown at a wall (core/experiments/bar.h): its whole burst of impacts
// (about 0.87 N), the chain made ready once outside the timing (its closed-form modes), the
// events streamed, items = contacts: issue 50's rates are N = 100 >= 3e4 and N = 1000 >= 1e3
// contacts/s. (BarThrown: the same through throwBar, set-up included.)
void BarBurst(benchmark::State& state) {
  const int n = int(state.range(0));
  const core::ReadyChain ready = core::readyChain(core::barChain(core::Bar{}, n));
  const core::ChainState start = core::barStart(core::Bar{}, n);
  std::int64_t contacts = 0;
  for (auto _ : state) {
    contacts += core::runChain(ready, start, 100L * n, 0.0, {}, [](const core::ChainEvent&) {}).contacts;
  }
  state.SetItemsProcessed(contacts);
}
BENCHMARK(BarBurst)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

void BarThrown(benchmark::State& state) {
  std::int64_t contacts = 0;
  for (auto _ : state) contacts += core::throwBar(core::Bar{}, int(state.range(0))).impacts;
  state.SetItemsProcessed(contacts);
}
BENCHMARK(BarThrown)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

// The note's near-grazing run (NearGrazingUpper's start) through the one run of every chain,
// its events streamed to a sink (nothing kept), items = contacts: Arg(0) by the modal kernel,
// Arg(1) by the note's kernel that the run picks for this chain (the same events as simulate).
void NotesChainOneRun(benchmark::State& state) {
  const core::Model model = testing::resonantChain(0.5);
  const core::State start = testing::nearGrazingStart(model, 0.5, 0.05);
  const core::ReadyChain ready = state.range(0) == 0 ? core::readyChain(core::massChainOf(model), core::Kernel::Modal)
                                                     : core::readyChain(model);
  const long contacts = 100'000;
  long seen = 0;
  const core::ChainEventSink<double> sink = [&](const core::ChainEvent&) { ++seen; };
  for (auto _ : state) {
    const core::ChainRun run = core::runChain(ready, core::chainStateOf(start), contacts, 0.0, {}, sink);
    benchmark::DoNotOptimize(run.final);
  }
  state.SetItemsProcessed(seen);
}
BENCHMARK(NotesChainOneRun)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The explorer's scene "A string of eight masses" as its job computes it: eight equal masses on
// equal springs, the stop on mass 5, the slowest mode with its top on the stop pushed by 1e-4;
// 100 contacts with the trace's grid of 1500 points over four slowest periods, no estimate
// (core::experiments::chainSeries, items = contacts)
void EightMassesScene(benchmark::State& state) {
  core::experiments::ChainSeriesSpec spec;
  spec.chain = core::MassChain{std::vector<double>(8, 1.0), std::vector<double>(8, 1.0), 0, 5, 1.0};
  const core::ChainModes modes = core::chainModes(spec.chain);
  spec.start = core::ChainState{modes.P.col(7) / modes.P(4, 7), Eigen::VectorXd::Zero(8)};
  spec.start.v[4] = -1e-4;
  spec.contacts = 100;
  spec.window = 4 * 2 * std::numbers::pi / modes.omega.minCoeff();
  spec.trust = core::TrustMode::Off;
  for (auto _ : state) benchmark::DoNotOptimize(core::experiments::chainSeries(spec).run.tFinal);
  state.SetItemsProcessed(state.iterations() * spec.contacts);
}
BENCHMARK(EightMassesScene)->Unit(benchmark::kMillisecond);

// Periodic orbits (issue 22): one orbit with its monodromy and checks; the continuation of
// the 1IPP family (items = orbits); the atlas up to K impacts (the budgets: K = 2 under 10 s,
// K = 4 under 60 s on two cores).
template <typename S>
void OnePeriodicOrbitWithStability(benchmark::State& state) {
  const core::TwoMassForm<S> chain = *core::makeTwoMassForm(*core::designedModel<S>(S(1), S(0.5), S(1), S(1), core::Branch::Upper)).chain;
  const S T = S(0.8) * core::twoPi<S>() / chain.omegaSlow;
  for (auto _ : state) benchmark::DoNotOptimize(core::onePeriodicOrbitStability(chain, T).orbit->trace);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(OnePeriodicOrbitWithStability<double>);
BENCHMARK(OnePeriodicOrbitWithStability<core::Quad>);

void TwoImpactOrbitByNewton(benchmark::State& state) {
  const core::TwoMassForm<double> chain = *core::makeTwoMassForm(testing::resonantChain(0.5)).chain;
  for (auto _ : state) {
    benchmark::DoNotOptimize(core::findOrbit(chain, 1.99998, 0.8, 0.05, 2).orbit->period);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(TwoImpactOrbitByNewton);

void ContinueOnePeriodicFamily(benchmark::State& state) {
  const core::TwoMassForm<double> chain = *core::makeTwoMassForm(testing::resonantChain(0.5)).chain;
  const double T2 = core::twoPi<double>() / chain.omegaSlow;
  const core::PeriodicOrbit<double> start = *core::onePeriodicOrbitStability(chain, 0.9 * T2).orbit;
  core::ContinuationOptions<double> options;
  options.energyLow = 1e-3;
  options.energyHigh = 1e3;
  std::size_t orbits = 0;
  for (auto _ : state) {
    const core::ContinuedFamily<double> family = core::continueFamily(chain, start, 1, options);
    orbits += family.orbits.size();
  }
  state.SetItemsProcessed(std::int64_t(orbits));
}
BENCHMARK(ContinueOnePeriodicFamily)->Unit(benchmark::kMillisecond);

void ModesAtlas(benchmark::State& state) {
  const core::TwoMassForm<double> chain = *core::makeTwoMassForm(testing::resonantChain(0.5)).chain;
  const double grazing = core::physicalEnergy(chain, core::gloData(chain, core::lambdaStar(chain)));
  for (auto _ : state) {
    const core::ModesAtlas<double> atlas =
        core::computeModesAtlas(chain, int(state.range(0)), grazing / 100, grazing * 1e4);
    benchmark::DoNotOptimize(atlas.families.size());
  }
}
BENCHMARK(ModesAtlas)->Arg(2)->Arg(4)->Unit(benchmark::kMillisecond);

// Periodic orbits of N masses (issue 49): the 1IPP family of a 10-mass chain over 1000 periods,
// each admissible row with its exact 20 x 20 monodromy, multipliers, Krein signatures and class
// (the budget: under 1 s); items = rows.
void ChainOnePeriodicFamilyWithMultipliers(benchmark::State& state) {
  const core::MassChain chain{{1, 0.9, 0.8, 0.7, 0.6, 0.5, 0.6, 0.7, 0.8, 0.9},
                              {1, 1.1, 0.9, 1.2, 1, 0.8, 1.3, 1, 0.9, 1.1}, 0, 0, 1};
  const core::ReadyChain ready = core::readyChain(chain);
  const double end = core::chainOnePeriodicEnd(chain);
  std::int64_t rows = 0;
  for (auto _ : state) {
    for (int k = 1; k <= 1000; ++k) {
      const double T = end * k / 1001.0;
      const core::ChainOnePeriodicOrbit data = core::chainOnePeriodicOrbitIn<double>(chain, ready.dynamics, T);
      if (data.admissible()) benchmark::DoNotOptimize(core::chainOnePeriodicStability(ready, T).orbit.monodromy.stability);
      ++rows;
    }
  }
  state.SetItemsProcessed(rows);
}
BENCHMARK(ChainOnePeriodicFamilyWithMultipliers)->Unit(benchmark::kMillisecond);

// The atlas of a chain of three masses to K impacts (issue 49's budget for K = 2: under 10 s):
// the 3:2:1 design of masses 1, 0.7, 0.4 (stop on the third; its resonance holds a sheet of
// period-2T orbits, one family of which runs to the 2000-orbit limit) and the same masses with
// springs 1, 1.3, 0.8 (not commensurate); the default energy range.
void ChainAtlasThreeMasses(benchmark::State& state) {
  core::MassChain chain;
  chain.masses = {1, 0.7, 0.4};
  chain.stopMass = 3;
  chain.gap = 1;
  chain.springs = state.range(1) == 0
                      ? core::designSprings(chain.masses, 1.0, std::vector<int>{3, 2, 1}).designs.at(0).springs
                      : std::vector<double>{1, 1.3, 0.8};
  const core::ReadyChain ready = core::readyChain(chain);
  const core::AtlasEnergyRange<double> range = core::defaultChainAtlasEnergyRange(ready);
  core::ChainAtlasOptions<double> options;
  options.maxImpacts = int(state.range(0));
  options.energyLow = range.low;
  options.energyHigh = range.high;
  std::size_t families = 0;
  for (auto _ : state) {
    const core::ChainAtlas<double> atlas = core::computeChainAtlas(ready, options);
    families = atlas.families.size();
    benchmark::DoNotOptimize(families);
  }
  state.counters["families"] = double(families);
}
BENCHMARK(ChainAtlasThreeMasses)->Args({2, 0})->Args({2, 1})->Args({4, 0})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace grazelab

BENCHMARK_MAIN();
