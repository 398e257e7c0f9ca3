// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// What a short `simulate` costs around the core's own run, piece by piece: the Python module's
// direct call (python/native_module.cpp) is these pieces plus the document's Python objects.
//   ./build/tests/bench/grazelab_commands_bench
#include <benchmark/benchmark.h>

#include <cstdio>
#include <stop_token>
#include <vector>

#include "commands/simulate_command.h"
#include "commands/simulation_document.h"
#include "commands/simulation.h"
#include "core/solver/trust.h"
#include "core/solver/chain_run.h"
#include "io/cli_input.h"
#include "io/cli_io.h"
#include "io/json_value.h"
#include "io/prepared_chain.h"

namespace {

using grazelab::cli::GivenOption;
using grazelab::cli::OptionValues;

// gl.simulate(glo=0.5, perturb=(0, 0, 0, -0.05), contacts=10, trust="off") as the module hands it over
OptionValues shortRun() {
  auto number = [](const char* name, std::initializer_list<double> values) {
    GivenOption option{name, {}, {}, true};
    option.numbers.assign(values);
    return option;
  };
  return OptionValues(std::vector<GivenOption>{
      number("m1", {1}), number("m2", {0.5}), number("k1", {1}), number("gap", {1}),
      {"precision", "auto", {}, false}, number("glo", {0.5}), number("perturb", {0, 0, 0, -0.05}),
      number("contacts", {10}), {"trust", "off", {}, false}});
}

// the options read: the chain designed, the start made
void BM_ReadOptions(benchmark::State& state) {
  const OptionValues options = shortRun();
  for (auto _ : state) benchmark::DoNotOptimize(grazelab::cli::parseRun<double>(options));
}
BENCHMARK(BM_ReadOptions);

// the core's run alone (the one run, the note's kernel), from the read options
void BM_CoreRun(benchmark::State& state) {
  const auto run = *grazelab::cli::parseRun<double>(shortRun()).value;
  const grazelab::core::ReadyChain ready = grazelab::core::readyChain(run.model.model);
  const grazelab::core::ChainState start = grazelab::core::chainStateOf(run.request.initial);
  for (auto _ : state) {
    benchmark::DoNotOptimize(grazelab::core::runChain(ready, start, long(run.request.maxContacts)).tFinal);
  }
}
BENCHMARK(BM_CoreRun);

// The typed command as the Python module calls it: the request read from the options, the run
// with its events into a table, its document as values
std::size_t typedRun(const grazelab::cli::PreparedMassChain& chain, const OptionValues& options, bool notesStarts) {
  QString error;
  auto request = grazelab::cli::readSimulateRequest(options, grazelab::cli::Format::Json, error);
  request->notesStarts = notesStarts;
  grazelab::cli::ChainEventTable table;
  grazelab::cli::EventTableSink sink(table);
  const grazelab::cli::SimulateOutcome outcome = grazelab::cli::simulate(chain, *request, sink);
  return grazelab::cli::simulationDocument<grazelab::cli::JsonValue>(outcome, *request).fields.size() + table.count;
}

// the whole command with its document as values and its events in a table (what the module
// calls), the chain found among those read last
void BM_SimulateToDocument(benchmark::State& state) {
  const OptionValues options = shortRun();
  for (auto _ : state) {
    const auto chain = grazelab::cli::recentChain(options);
    benchmark::DoNotOptimize(typedRun(**chain.value, options, true));
  }
}
BENCHMARK(BM_SimulateToDocument);

// `simulate --glo 0.5 --perturb 0,0,0,-0.05 --contacts N --format summary --trust off`: the
// command's streamed run against the core's run of the same request (issue 47: within 1.2x)
OptionValues summaryRun(double contacts) {
  return OptionValues(std::vector<std::pair<QString, QString>>{
      {"glo", "0.5"}, {"perturb", "0,0,0,-0.05"}, {"contacts", QString::number(contacts, 'f', 0)},
      {"format", "summary"}, {"trust", "off"}});
}

void BM_CoreRunSummaryStart(benchmark::State& state) {
  auto run = *grazelab::cli::parseRun<double>(summaryRun(double(state.range(0)))).value;
  const grazelab::core::ReadyChain ready = grazelab::core::readyChain(run.model.model);
  const grazelab::core::ChainState start = grazelab::core::chainStateOf(run.request.initial);
  // (a summary looks at no event: the run hands them to a sink that keeps none)
  const grazelab::core::ChainEventSink<double> none = [](const grazelab::core::ChainEvent&) {};
  for (auto _ : state) {
    benchmark::DoNotOptimize(grazelab::core::runChain(ready, start, long(run.request.maxContacts), 0.0, {}, none).tFinal);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_CoreRunSummaryStart)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void BM_SimulateSummary(benchmark::State& state) {
  const OptionValues options = summaryRun(double(state.range(0)));
  std::FILE* sink = std::fopen("/dev/null", "w");
  for (auto _ : state) {
    grazelab::cli::Io io;
    io.out = sink;
    io.messages = sink;
    QString error;
    benchmark::DoNotOptimize(grazelab::cli::runSimulate(options, io, std::stop_token{}, error));
  }
  std::fclose(sink);
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_SimulateSummary)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

// A chain of three masses made once, as grazelab.Chain holds it: Arg(0) the designed 3:2:1
// chain of masses 1, 0.2, 0.05, Arg(1) the same masses on springs 1, 1, 1 (not commensurate)
grazelab::cli::PreparedMassChain const& preparedThreeMasses(bool designed) {
  static const auto make = [](bool withDesign) {
    std::vector<std::pair<QString, QString>> options{{"masses", "1,0.2,0.05"}};
    if (withDesign) options.emplace_back("frequencies", "3:2:1");
    else options.emplace_back("springs", "1,1,1");
    return *grazelab::cli::PreparedMassChain::make(OptionValues(std::move(options))).value;
  };
  static const auto designedChain = make(true);
  static const auto givenChain = make(false);
  return designed ? *designedChain : *givenChain;
}

// Chain.simulate(state=[0, 0, 0, 0, 0, 6.7], contacts=10, trust=...) as the module hands it over
OptionValues threeMassRun(const char* trust) {
  GivenOption state{"state", {}, {}, true};
  state.numbers.assign({0, 0, 0, 0, 0, 6.7});
  GivenOption contacts{"contacts", {}, {}, true};
  contacts.numbers.assign({10});
  return OptionValues(std::vector<GivenOption>{{"precision", "auto", {}, false}, state, contacts,
                                               {"trust", trust, {}, false}});
}

// The one-off set-up of grazelab.Chain(masses=[1, 0.2, 0.05], frequencies=[3, 2, 1]): read,
// designed, made ready in double (its modes) with its shadow (trust auto's chain in long double)
void BM_PrepareDesignedChain(benchmark::State& state) {
  const OptionValues options(std::vector<std::pair<QString, QString>>{{"masses", "1,0.2,0.05"}, {"frequencies", "3:2:1"}});
  for (auto _ : state) {
    const auto chain = grazelab::cli::PreparedMassChain::make(options);
    benchmark::DoNotOptimize(chain.value.value()->ready<double>().value->dynamics.period);
    benchmark::DoNotOptimize(chain.value.value()->shadow<double>().usable());
  }
}
BENCHMARK(BM_PrepareDesignedChain)->Unit(benchmark::kMicrosecond);

// The core's own work in a 10-contact run of a prepared chain: the run, and with Arg(1) its
// shadow run and comparison (trust auto)
void BM_PreparedChainCoreRun(benchmark::State& state) {
  const auto& chain = preparedThreeMasses(true);
  const auto& ready = *chain.ready<double>().value;
  const grazelab::core::ChainState start{Eigen::VectorXd::Zero(3), (Eigen::VectorXd(3) << 0, 0, 6.7).finished()};
  const auto mode = state.range(0) ? grazelab::core::TrustMode::Auto : grazelab::core::TrustMode::Off;
  for (auto _ : state) {
    const auto run = grazelab::core::runChain(ready, start, 10);
    if (mode != grazelab::core::TrustMode::Off) {
      grazelab::core::TrustMonitor<double> monitor(chain.shadow<double>(),
                                                   {{start.u.cast<long double>(), start.v.cast<long double>()}}, 10,
                                                   0.0L, mode);
      for (const auto& event : run.events) monitor.observe(event);
      benchmark::DoNotOptimize(monitor.finish(run).stateError);
    }
    benchmark::DoNotOptimize(run.tFinal);
  }
}
BENCHMARK(BM_PreparedChainCoreRun)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// The whole command on a prepared chain, its document as values (what Chain.simulate calls):
// Arg(0) trust off, Arg(1) trust auto
void BM_PreparedChainSimulate(benchmark::State& state) {
  const auto& chain = preparedThreeMasses(true);
  const OptionValues options = threeMassRun(state.range(0) ? "auto" : "off");
  for (auto _ : state) benchmark::DoNotOptimize(typedRun(chain, options, false));
}
BENCHMARK(BM_PreparedChainSimulate)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
