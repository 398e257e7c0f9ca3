// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The typed info (commands/chain_info.h), as the command line and the Python module call it: the
// note's chain in each precision gives its closed forms (T2 = 2 pi sqrt(2), lambda* = 8/9) to
// that precision's digits, scaled chains scale them, a chain of N masses its modes; refusals
// are statuses with their line.
#include <gtest/gtest.h>

#include <QString>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "commands/chain_info.h"
#include "core/numbers/scalar.h"
#include "io/option_values.h"

namespace grazelab::cli {
namespace {

using Options = std::vector<std::pair<QString, QString>>;

InfoOutcome infoOf(const Options& options) {
  QString error;
  const OptionValues values(options);
  const std::optional<InfoRequest> request = readInfoRequest(values, error);
  EXPECT_TRUE(request) << error.toStdString();
  return request ? describeChain(values, *request) : InfoOutcome{};
}

// a number of the note's model, as its text (binary128's digits where wider than double)
long double numberOf(const InfoOutcome& outcome, const char* name) {
  const JsonValue* value = outcome.document.find("model")->find(name);
  return std::stold(value->numberText());
}

TEST(TypedInfo, TheNotesChainHasItsClosedFormsToEachPrecisionsDigitsAndScales) {
  // T2 = 2 pi / omega2 with omega2 = 1 / sqrt(2) (m1 = k1 = 1, m2 = 1/2): 2 pi sqrt(2); lambda* = 8/9
  const long double T2 = 2 * std::numbers::pi_v<long double> * std::sqrt(2.0L);
  for (const char* precision : {"double", "long", "quad"}) {
    const InfoOutcome outcome = infoOf({{"precision", precision}});
    ASSERT_EQ(outcome.status, InfoStatus::Described) << outcome.problem;
    EXPECT_TRUE(outcome.notesModel);
    const long double ulps = std::string(precision) == "double" ? 4e-16L : 4e-19L;
    EXPECT_NEAR(numberOf(outcome, "T2"), T2, ulps * T2) << precision;
    EXPECT_NEAR(numberOf(outcome, "lambda_star"), 8.0L / 9, ulps) << precision;
    EXPECT_NEAR(numberOf(outcome, "T1"), T2 / 2, ulps * T2) << precision;
  }
  // binary128's digits, read as binary128: 2 pi sqrt(2) to its rounding
  const InfoOutcome quad = infoOf({{"precision", "quad"}});
  const auto quadT2 = core::parseScalar<core::Quad>(quad.document.find("model")->find("T2")->numberText());
  ASSERT_TRUE(quadT2.value);
  const core::Quad exactT2 = core::twoPi<core::Quad>() * sqrt(core::Quad(2));
  EXPECT_LT(core::toDouble(abs(*quadT2.value / exactT2 - 1)), 1e-33);
  // masses and springs scaled by 4 and 9: periods by sqrt(4 / 9); lambda* unchanged
  const InfoOutcome scaled = infoOf({{"m1", "4"}, {"m2", "2"}, {"k1", "9"}});
  ASSERT_EQ(scaled.status, InfoStatus::Described) << scaled.problem;
  EXPECT_NEAR(numberOf(scaled, "T2"), T2 * 2 / 3, 4e-16 * T2);
  EXPECT_NEAR(numberOf(scaled, "lambda_star"), 8.0L / 9, 4e-16);
}

TEST(TypedInfo, AChainOfNMassesHasItsModesAndTheCommandLinesText) {
  const InfoOutcome three = infoOf({{"masses", "1,0.6,0.3"}, {"frequencies", "3:2:1"}});
  ASSERT_EQ(three.status, InfoStatus::Described) << three.problem;
  EXPECT_FALSE(three.notesModel);
  const JsonValue* modes = three.document.find("modes");
  ASSERT_TRUE(modes);
  ASSERT_EQ(modes->items.size(), 3u);
  // designed 3:2:1: each mode's frequency its harmonic times the slowest's
  const double slowest = modes->items[2].find("omega")->value;
  for (const JsonValue& mode : modes->items) {
    EXPECT_NEAR(mode.find("omega")->value, double(mode.find("harmonic")->integer) * slowest, 1e-12 * slowest);
  }
  EXPECT_EQ(infoText(three).front(), '{');
  EXPECT_EQ(infoText(three).back(), '\n');
}

TEST(TypedInfo, RefusalsAreStatusesWithTheirLine) {
  const InfoOutcome quadChain = infoOf({{"masses", "1,0.5,0.2"}, {"precision", "quad"}});
  EXPECT_EQ(quadChain.status, InfoStatus::Refused);
  EXPECT_NE(quadChain.problem.find("in double for now"), std::string::npos) << quadChain.problem;
  const InfoOutcome springsAlone = infoOf({{"springs", "1,2"}});
  EXPECT_EQ(springsAlone.status, InfoStatus::Refused);
  EXPECT_NE(springsAlone.problem.find("--masses"), std::string::npos) << springsAlone.problem;
  const InfoOutcome negative = infoOf({{"m2", "-1"}});
  EXPECT_EQ(negative.status, InfoStatus::Refused);
  EXPECT_NE(negative.problem.find("m2"), std::string::npos) << negative.problem;
  QString error;
  EXPECT_FALSE(readInfoRequest(OptionValues(Options{{"precision", "half"}}), error));
  EXPECT_TRUE(error.contains("--precision")) << error.toStdString();
}

}  // namespace
}  // namespace grazelab::cli
