// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The typed stability matrix (commands/stability_matrix.h), as the command line and the Python
// module call it: a cell per case and method, the exact solver ok on a chain's own start, its
// table and text made from the outcome; refusals are lines and a stop ends it without a matrix.
#include <gtest/gtest.h>

#include <QString>

#include <optional>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "commands/stability_command.h"
#include "commands/stability_matrix.h"
#include "io/option_values.h"

namespace grazelab::cli {
namespace {

using Options = std::vector<std::pair<QString, QString>>;
using core::methods::CellVerdict;
using core::methods::MethodKind;

std::optional<StabilityRequest> requestOf(const Options& options, QString& error) {
  bool stopped = false;
  std::optional<StabilityRequest> request = readStabilityRequest(OptionValues(options), {}, error, stopped);
  EXPECT_FALSE(stopped);
  return request;
}

TEST(TypedStability, AChainsMatrixHasACellPerCaseAndMethodAndTheExactSolverHoldsOnItsStart) {
  // three masses stopped on the last, a start that leaves the stop (and comes back to it)
  QString error;
  const auto request = requestOf({{"quick", ""}, {"methods", "exact,moreau-jean"}, {"masses", "1,0.3,0.6"},
                                  {"springs", "1,0.7,1.3"}, {"stop-mass", "3"}, {"gap", "0.4"},
                                  {"state", "0.1,0,0.4,0,0.2,-0.3"}}, error);
  ASSERT_TRUE(request) << error.toStdString();
  ASSERT_EQ(request->methods, (std::vector<MethodKind>{MethodKind::Exact, MethodKind::MoreauJean}));
  ASSERT_GE(request->cases.size(), 2u);
  EXPECT_EQ(request->cases.front().name, "given");
  const StabilityOutcome outcome = stabilityMatrix(*request);
  ASSERT_EQ(outcome.status, StabilityStatus::Computed);
  ASSERT_EQ(outcome.cells.size(), request->cases.size() * request->methods.size());
  EXPECT_EQ(outcome.horizons.size(), request->cases.size());
  for (std::size_t i = 0; i < outcome.cells.size(); ++i) {
    EXPECT_EQ(outcome.cells[i].caseName, request->cases[i / 2].name);
    EXPECT_EQ(outcome.cells[i].method, request->methods[i % 2]);
    // a cell not ok says why
    EXPECT_EQ(outcome.cells[i].verdict == CellVerdict::Ok, outcome.cells[i].reason.empty()) << i;
  }
  // the exact solver on the chain as given: every contact, within its own error estimate; the
  // fixed-step scheme misses some
  EXPECT_EQ(outcome.cells[0].verdict, CellVerdict::Ok);
  EXPECT_LT(outcome.cells[0].errors.state, 1e-6);
  EXPECT_EQ(outcome.cells[0].errors.missed, 0);
  EXPECT_GT(outcome.cells[1].errors.missed, 0);
  // the table: a header and a line per cell; the text: a row per case
  const QByteArray csv = stabilityCsv(outcome);
  EXPECT_EQ(csv.count('\n'), qsizetype(outcome.cells.size()) + 1);
  const QString markdown = stabilityMarkdown(*request, outcome);
  for (const auto& row : request->cases) EXPECT_TRUE(markdown.contains("| " + QString::fromStdString(row.name) + " |"));
}

TEST(TypedStability, RefusalsAreLinesAndAStopEndsItWithoutAMatrix) {
  const auto refusal = [](const Options& options) {
    QString error;
    EXPECT_FALSE(requestOf(options, error));
    return error.toStdString();
  };
  EXPECT_NE(refusal({{"methods", "nope"}}).find("--methods"), std::string::npos);
  EXPECT_NE(refusal({{"springs", "1,1"}}).find("--masses"), std::string::npos);
  EXPECT_NE(refusal({{"masses", "1,0.5"}, {"springs", "1,1"}, {"state", "1,2"}}).find("--state"), std::string::npos);
  QString error;
  const auto request = requestOf({{"quick", ""}, {"methods", "exact"}}, error);
  ASSERT_TRUE(request) << error.toStdString();
  std::stop_source stop;
  stop.request_stop();
  const StabilityOutcome stopped = stabilityMatrix(*request, stop.get_token());
  EXPECT_EQ(stopped.status, StabilityStatus::Interrupted);
  EXPECT_TRUE(stopped.cells.empty());
}

}  // namespace
}  // namespace grazelab::cli
