// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The typed simulate (commands/simulation.h): the run a raised request ends with is the run of
// its chain in that precision, event for event; the command line's csv and the Python module's
// table are the same events; a refusal begins nothing; a stop ends the run unestimated.
#include <gtest/gtest.h>

#include <QString>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "commands/simulate_command.h"
#include "commands/simulation.h"
#include "io/cli_io.h"
#include "io/option_values.h"
#include "io/prepared_chain.h"

namespace grazelab::cli {
namespace {

using Options = std::vector<std::pair<QString, QString>>;

std::shared_ptr<const PreparedMassChain> chainOf(const Options& options) {
  auto made = PreparedMassChain::make(OptionValues(options));
  EXPECT_TRUE(made.value) << made.error.toStdString();
  return *made.value;
}

SimulateRequest requestOf(const Options& options, Format format = Format::Json) {
  QString error;
  auto request = readSimulateRequest(OptionValues(options), format, error);
  EXPECT_TRUE(request) << error.toStdString();
  return *request;
}

// Counts what a run reports
struct CountingSink final : SimulateSink {
  int begins = 0;
  long events = 0;
  void begin(const AnyRun&, const std::vector<std::string>&) override {
    ++begins;
    events = 0;
  }
  void event(const core::BasicChainEvent<double>&) override { ++events; }
  void event(const core::BasicChainEvent<long double>&) override { ++events; }
  void event(const core::BasicChainEvent<core::Quad>&) override { ++events; }
};

// a row of a table: t and the 2N + 1 numbers after the type
std::vector<double> rowOf(const ChainEventTable& table, std::size_t row) {
  const char* at = table.rows.data() + row * table.rowBytes();
  std::vector<double> numbers(2 * table.masses + 2);
  std::memcpy(numbers.data(), at, sizeof(double));
  std::memcpy(numbers.data() + 1, at + sizeof(double) + 8 * sizeof(char32_t), (numbers.size() - 1) * sizeof(double));
  return numbers;
}

// Three masses designed 3:2:1, pushed 1e-15 below GLO_lambda: double cannot decide its grazings
const Options kNearGrazing{{"masses", "1,0.2,0.05"}, {"frequencies", "3:2:1"}, {"glo-weights", "0.2,0.3,0.5"},
                           {"perturb", "0,0,0,0,0,-1e-15"}, {"contacts", "200"}};

TEST(Simulation, ARaisedRequestEndsWithTheRunOfItsChainInThatPrecision) {
  const auto chain = chainOf(kNearGrazing);
  const SimulateRequest request = requestOf(kNearGrazing);
  ChainEventTable table;
  EventTableSink sink(table);
  const SimulateOutcome outcome = simulate(*chain, request, sink);
  ASSERT_EQ(outcome.status, SimulateStatus::Ran) << outcome.problem;
  // double was left: each run left says why, and the head is double's (the start as read first)
  ASSERT_FALSE(outcome.raised.empty());
  EXPECT_EQ(outcome.raised.size(), outcome.escalations.size());
  EXPECT_EQ(outcome.raised.front().precision, core::Precision::Double);
  EXPECT_NE(outcome.precision, core::Precision::Double);
  EXPECT_TRUE(std::holds_alternative<RunIn<double>>(outcome.head()));
  // the table holds the last run alone, event for event the chain's own run in that precision
  std::visit(
      [&]<typename S>(const RunIn<S>& ran) {
        EXPECT_EQ(core::precisionOf<S>(), outcome.precision);
        EXPECT_NE(ran.run.stop, core::StopReason::Undecided);
        const core::BasicChainRun<S> alone = core::runChain(*ran.ready, ran.start, request.contacts);
        ASSERT_EQ(table.count, alone.events.size());
        EXPECT_EQ(long(table.count), ran.run.contacts + ran.run.releases);
        for (std::size_t i = 0; i < table.count; ++i) {
          const core::BasicChainEvent<S>& event = alone.events[i];
          const std::vector<double> row = rowOf(table, i);
          EXPECT_EQ(row[0], core::toDouble(event.t)) << "event " << i;
          for (Eigen::Index j = 0; j < event.u.size(); ++j) EXPECT_EQ(row[1 + j], core::toDouble(event.u[j]));
          // (wider than double: each number's decimal text too)
          if constexpr (!std::is_same_v<S, double>) {
            EXPECT_EQ(table.decimals[i * row.size()], core::formatScalar(event.t));
          }
        }
      },
      *outcome.last);
}

TEST(Simulation, TheCommandLinesCsvAndTheModulesTableAreTheSameEvents) {
  for (const Options& options :
       {Options{{"glo", "0.3"}, {"perturb", "0,0,0,-0.05"}, {"contacts", "40"}},
        Options{{"m2", "0.2"}, {"branch", "lower"}, {"contacts", "40"}},
        Options{{"masses", "1,2,1"}, {"springs", "1,1,1"}, {"right-spring", "2"}, {"stop-mass", "2"},
                {"state", "0,0,0,0,3,0"}, {"contacts", "40"}}}) {
    SCOPED_TRACE(OptionValues(options).value("masses").toStdString());
    Options csv = options;
    csv.emplace_back("format", "csv");
    char* text = nullptr;
    std::size_t size = 0;
    std::FILE* out = open_memstream(&text, &size);
    Io io;
    io.out = out;
    io.messages = stderr;
    QString error;
    ASSERT_EQ(runSimulate(OptionValues(csv), io, {}, error), 0) << error.toStdString();
    std::fclose(out);
    std::istringstream lines(std::string(text, size));
    std::free(text);

    const auto chain = chainOf(options);
    SimulateRequest request = requestOf(options);
    request.notesStarts = !OptionValues(options).isSet("masses");
    ChainEventTable table;
    EventTableSink sink(table);
    ASSERT_EQ(simulate(*chain, request, sink).status, SimulateStatus::Ran);

    std::string line;
    std::getline(lines, line);  // (the header)
    std::size_t row = 0;
    while (std::getline(lines, line)) {
      ASSERT_LT(row, table.count);
      std::vector<double> numbers;
      std::istringstream fields(line);
      std::string field;
      for (int column = 0; std::getline(fields, field, ','); ++column) {
        if (column != 1) numbers.push_back(std::strtod(field.c_str(), nullptr));  // (column 1: the type)
      }
      EXPECT_EQ(numbers, rowOf(table, row)) << "row " << row;  // (the csv's shortest texts read back)
      ++row;
    }
    EXPECT_EQ(row, table.count);
    EXPECT_GT(row, 10u);
  }
}

TEST(Simulation, ARefusalBeginsNothing) {
  const Options options{{"masses", "1,1,1"}, {"springs", "1,1,1"}, {"state", "0,0,2,0,0,0"}};
  const auto chain = chainOf(options);
  CountingSink sink;
  const SimulateOutcome outcome = simulate(*chain, requestOf(options), sink);
  EXPECT_EQ(outcome.status, SimulateStatus::Refused);
  EXPECT_NE(outcome.problem.find("past the stop"), std::string::npos) << outcome.problem;
  EXPECT_EQ(sink.begins, 0);
  EXPECT_FALSE(outcome.last);
}

TEST(Simulation, AStopEndsTheRunUnestimated) {
  const Options options{{"glo", "0.5"}, {"perturb", "0,0,0,-0.05"}, {"contacts", "100000"}};
  const auto chain = chainOf(options);
  SimulateRequest request = requestOf(options);
  request.notesStarts = true;
  std::stop_source stop;
  stop.request_stop();
  CountingSink sink;
  const SimulateOutcome outcome = simulate(*chain, request, sink, stop.get_token());
  ASSERT_EQ(outcome.status, SimulateStatus::Ran);
  EXPECT_EQ(std::visit([](const auto& ran) { return ran.run.stop; }, *outcome.last), core::StopReason::Cancelled);
  EXPECT_EQ(outcome.trust.verdict, core::Verdict::Unchecked);
  EXPECT_LT(sink.events, 100000);
}

TEST(Simulation, TheCsvRunsNoEstimateAndAnEndTimeLiftsTheContactBound) {
  EXPECT_EQ(requestOf({{"glo", "0.5"}}, Format::Csv).trust, core::TrustMode::Off);
  EXPECT_EQ(requestOf({{"glo", "0.5"}}, Format::Json).trust, core::TrustMode::Auto);
  EXPECT_EQ(requestOf({{"glo", "0.5"}}).contacts, 100);
  EXPECT_GT(requestOf({{"glo", "0.5"}, {"t-end", "3"}}).contacts, 1'000'000'000L);
  EXPECT_EQ(requestOf({{"glo", "0.5"}, {"t-end", "3"}, {"contacts", "7"}}).contacts, 7);
  QString error;
  EXPECT_FALSE(readSimulateRequest(OptionValues(Options{{"precision", "octuple"}}), Format::Json, error));
  EXPECT_TRUE(error.contains("--precision"));
}

}  // namespace
}  // namespace grazelab::cli
