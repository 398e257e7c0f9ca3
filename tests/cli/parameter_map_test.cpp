// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The typed map (commands/parameter_map.h), as the command line and the Python module call it:
// its points are the core's, point by point, however many threads and stripes; the note's chain
// written with --masses is the note's map; a chain of N masses its own; refusals are lines and a
// stop is a status.
#include <gtest/gtest.h>

#include <QString>

#include <cstring>
#include <optional>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "commands/map_command.h"
#include "commands/parameter_map.h"
#include "core/experiments/chain_map.h"
#include "core/experiments/maps.h"
#include "io/option_values.h"

namespace grazelab::cli {
namespace {

using Options = std::vector<std::pair<QString, QString>>;

std::optional<MapRequest> requestOf(const Options& options, QString& error) {
  bool stopped = false;
  const OptionValues values(options);
  std::optional<MapRequest> request = readMapRequest(values, {}, error, stopped);
  EXPECT_FALSE(stopped);
  return request;
}

MapRequest requestOf(const Options& options) {
  QString error;
  std::optional<MapRequest> request = requestOf(options, error);
  EXPECT_TRUE(request) << error.toStdString();
  return request ? *request : MapRequest{};
}

// the same bits, NaN included (PointSummary's == says NaN != NaN)
bool sameBits(const core::PointSummary& a, const core::PointSummary& b) {
  const auto bits = [](double x) {
    std::uint64_t u = 0;
    std::memcpy(&u, &x, sizeof u);
    return u;
  };
  return bits(a.fftFirst) == bits(b.fftFirst) && bits(a.fftMin) == bits(b.fftMin) && bits(a.fftMax) == bits(b.fftMax) &&
         bits(a.fftMean) == bits(b.fftMean) && a.impacts == b.impacts && a.grazings == b.grazings &&
         a.sticks == b.sticks && bits(a.firstImpactTime) == bits(b.firstImpactTime) &&
         bits(a.horizon) == bits(b.horizon) && a.valid == b.valid;
}

// the point (column, row) as the core computes it alone
core::PointSummary corePoint(const MapRequest& request, std::int64_t column, std::int64_t row) {
  if (const auto* spec = std::get_if<core::MapSpec>(&request.spec)) return core::mapPoint(*spec, column, row);
  return core::chainMapPoint(std::get<core::ChainMapSpec>(request.spec), column, row);
}

void expectTheCoresPoints(const MapRequest& request, const MapOutcome& outcome) {
  ASSERT_EQ(outcome.status, MapStatus::Computed);
  const map::StoredMap& stored = outcome.map;
  // runs that met the stop, not a map of empty points
  std::int64_t impacting = 0;
  for (const core::PointSummary& point : stored.points) impacting += point.valid && point.impacts > 0;
  EXPECT_GT(impacting, 0);
  ASSERT_EQ(stored.columns, request.columns());
  ASSERT_EQ(std::int64_t(stored.points.size()), (stored.rows.rowEnd - stored.rows.rowBegin) * stored.columns);
  for (std::int64_t row = stored.rows.rowBegin; row < stored.rows.rowEnd; ++row) {
    for (std::int64_t column = 0; column < stored.columns; ++column) {
      const auto& point = stored.points[std::size_t((row - stored.rows.rowBegin) * stored.columns + column)];
      EXPECT_TRUE(sameBits(point, corePoint(request, column, row))) << "column " << column << ", row " << row;
    }
  }
}

TEST(TypedMap, ItsPointsAreTheCoresOnAnyThreadsAndItsStripesJoinToTheWhole) {
  // the note's chain near grazing (a push below the grazing-start plane), with each point's horizon
  const Options base{{"x", "u1:-1.5:1.5:7"}, {"y", "v1:-1:1:5"}, {"contacts", "6"}, {"perturb", "0,0,0,-0.05"},
                     {"trust", "auto"}, {"m2", "0.3"}};
  Options onTwo = base;
  onTwo.emplace_back("threads", "2");
  const MapRequest request = requestOf(onTwo);
  ASSERT_TRUE(std::holds_alternative<core::MapSpec>(request.spec));
  const MapOutcome whole = parameterMap(request);
  expectTheCoresPoints(request, whole);
  EXPECT_EQ(whole.map.totalRows, 5);
  EXPECT_EQ(whole.map.description.run.find("threads")->toDouble(), 2);
  EXPECT_EQ(whole.map.description.spec.find("picture")->text, "fft_first");
  // three stripes of one thread each: the rows of each, joined, the whole map's points
  std::vector<core::PointSummary> joined;
  for (int k = 1; k <= 3; ++k) {
    Options stripe = base;
    stripe.emplace_back("shard", QStringLiteral("%1/3").arg(k));
    stripe.emplace_back("threads", "1");
    const MapRequest part = requestOf(stripe);
    const MapOutcome outcome = parameterMap(part);
    expectTheCoresPoints(part, outcome);
    EXPECT_EQ(outcome.map.description.run.find("shard")->text, std::to_string(k) + "/3");
    EXPECT_EQ(outcome.map.description.spec, whole.map.description.spec);  // one map's identity
    joined.insert(joined.end(), outcome.map.points.begin(), outcome.map.points.end());
  }
  ASSERT_EQ(joined.size(), whole.map.points.size());
  for (std::size_t i = 0; i < joined.size(); ++i) EXPECT_TRUE(sameBits(joined[i], whole.map.points[i])) << i;
}

TEST(TypedMap, TheNotesChainWrittenWithMassesIsTheNotesMapAndAChainOfNMassesItsOwn) {
  const Options axes{{"x", "u1:-1:1:6"}, {"y", "v2:-0.8:0.4:4"}, {"contacts", "5"}, {"state", "0,1,0,0"}};
  const MapOutcome notes = parameterMap(requestOf(axes));
  Options written = axes;
  written.emplace_back("masses", "1,0.5");
  written.emplace_back("frequencies", "2:1");
  const MapRequest asMasses = requestOf(written);
  ASSERT_TRUE(std::holds_alternative<core::MapSpec>(asMasses.spec));  // the note's engine
  const MapOutcome same = parameterMap(asMasses);
  ASSERT_EQ(same.map.points.size(), notes.map.points.size());
  for (std::size_t i = 0; i < same.map.points.size(); ++i) {
    EXPECT_TRUE(sameBits(same.map.points[i], notes.map.points[i])) << i;
  }
  // three masses, a 3:2:1 design, the middle mass stopped: a chain map, point by point the core's
  const MapRequest three = requestOf({{"masses", "1,0.2,0.05"}, {"frequencies", "3:2:1"}, {"stop-mass", "2"},
                                      {"x", "u1:-0.5:0.5:4"}, {"y", "v2:-1:-0.2:3"}, {"contacts", "4"}});
  ASSERT_TRUE(std::holds_alternative<core::ChainMapSpec>(three.spec));
  const MapOutcome chain = parameterMap(three);
  expectTheCoresPoints(three, chain);
  EXPECT_EQ(chain.map.description.spec.find("x")->find("variable")->text, "u1");
  EXPECT_TRUE(chain.map.description.spec.find("chain"));
}

TEST(TypedMap, RefusalsAreLinesAndAStopEndsItWithoutAMap) {
  const auto refusal = [](const Options& options) {
    QString error;
    EXPECT_FALSE(requestOf(options, error));
    return error.toStdString();
  };
  const Options axes{{"x", "u1:-1:1:4"}, {"y", "v1:-1:1:3"}};
  const auto with = [&](const char* name, const char* value) {
    Options options = axes;
    options.emplace_back(name, value);
    return options;
  };
  EXPECT_NE(refusal(with("precision", "quad")).find("--precision"), std::string::npos);
  EXPECT_NE(refusal(with("shard", "3/2")).find("--shard"), std::string::npos);
  EXPECT_NE(refusal(with("threads", "0")).find("--threads"), std::string::npos);
  EXPECT_NE(refusal(with("picture", "colour")).find("--picture"), std::string::npos);
  EXPECT_NE(refusal(with("springs", "1,1")).find("--masses"), std::string::npos);
  EXPECT_NE(refusal({{"x", "u1:-1:1:20000"}, {"y", "v1:-1:1:20000"}}).find("--shard K/N"), std::string::npos);
  EXPECT_NE(refusal({{"x", "u1:-1:1:4"}}).find("--y"), std::string::npos);
  // a stop asked for before the first point: interrupted, no points
  std::stop_source stop;
  stop.request_stop();
  const MapOutcome stopped = parameterMap(requestOf(axes), stop.get_token());
  EXPECT_EQ(stopped.status, MapStatus::Interrupted);
  EXPECT_TRUE(stopped.map.points.empty());
}

}  // namespace
}  // namespace grazelab::cli
