// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The typed atlas (commands/modes_atlas_command.h), as the command line and the Python module
// call it: its tables are its document's families row for row, every flip with a family born
// there names a family of twice the impacts, double and long double place the flips alike, and
// the refusals are lines.
#include <gtest/gtest.h>

#include <QString>

#include <cmath>
#include <memory>
#include <numbers>
#include <utility>
#include <vector>

#include "commands/modes_atlas_command.h"
#include "commands/orbit_command.h"
#include "io/option_values.h"
#include "io/prepared_chain.h"

namespace grazelab::cli {
namespace {

using Options = std::vector<std::pair<QString, QString>>;

ModesOutcome atlasOf(const Options& options, PrecisionChoice precision, int maxImpacts = 2) {
  const auto chain = twoMassChainOf(OptionValues(options));
  EXPECT_TRUE(chain.value) << chain.error.toStdString();
  ModesRequest request;
  request.maxImpacts = maxImpacts;
  request.precision = precision;
  return modesAtlas(**chain.value, request);
}

// the energies of the flips of every family, in the document's order
std::vector<double> flipEnergies(const JsonValue& document) {
  std::vector<double> energies;
  for (const JsonValue& family : document.find("families")->items) {
    for (const JsonValue& point : family.find("bifurcations")->items) {
      if (point.find("kind")->text == "period-doubling") energies.push_back(point.find("energy")->toDouble());
    }
  }
  return energies;
}

TEST(TypedModes, TablesAreTheDocumentsFamiliesAndFlipsNameTheirFamilies) {
  for (const Options& chain : {Options{}, Options{{"m2", "0.3"}, {"branch", "lower"}}}) {
    const ModesOutcome outcome = atlasOf(chain, PrecisionChoice::Double);
    int bornChecked = 0;
    ASSERT_EQ(outcome.status, ModesStatus::Computed) << outcome.problem;
    const JsonValue document = modesDocument(outcome, std::nullopt);
    const auto& families = document.find("families")->items;
    ASSERT_EQ(families.size(), modesFamilyCount(outcome));
    ASSERT_FALSE(families.empty());
    for (std::size_t i = 0; i < families.size(); ++i) {
      EXPECT_EQ(families[i].find("file"), nullptr);  // (no files written, none named)
      const std::vector<double> table = modesTable(outcome, i);
      const std::size_t columns = kModesColumns.size();
      ASSERT_EQ(table.size(), std::size_t(families[i].find("rows")->integer) * columns);
      for (std::size_t at = 0; at < table.size(); at += columns) {
        EXPECT_DOUBLE_EQ(table[at + 2], 2 * std::numbers::pi / table[at + 1]);  // omega = 2 pi / T
        EXPECT_GE(table[at + 4], 0);
        EXPECT_LE(table[at + 4], 3);
      }
      for (const JsonValue& point : families[i].find("bifurcations")->items) {
        const JsonValue* born = point.find("born_family");
        if (!born || born->kind != JsonValue::Kind::Integer) continue;
        // the family born at a flip has twice the impacts of the one it is born from
        for (const JsonValue& other : families) {
          if (other.find("id")->integer != born->integer) continue;
          EXPECT_EQ(other.find("impacts")->integer, 2 * families[i].find("impacts")->integer);
          ++bornChecked;
        }
      }
    }
    EXPECT_GT(bornChecked, 0);  // (a flip of the 1IPP family gives a family of 2 impacts)
  }
}

TEST(TypedModes, DoubleAndLongDoublePlaceTheFlipsAlike) {
  const ModesOutcome inDouble = atlasOf({}, PrecisionChoice::Double, 1);
  const ModesOutcome inLong = atlasOf({}, PrecisionChoice::Long, 1);
  ASSERT_EQ(inDouble.status, ModesStatus::Computed) << inDouble.problem;
  ASSERT_EQ(inLong.status, ModesStatus::Computed) << inLong.problem;
  EXPECT_EQ(inLong.precision, core::Precision::Long);
  const std::vector<double> a = flipEnergies(modesDocument(inDouble, std::nullopt));
  const std::vector<double> b = flipEnergies(modesDocument(inLong, "m"));
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-9 * b[i]) << i;
  EXPECT_EQ(modesDocument(inLong, "m").find("families")->items.front().find("file")->text.rfind("m-family-", 0), 0u);
}

TEST(TypedModes, RefusalsAreLines) {
  EXPECT_NE(atlasOf({{"k2", "0.3"}}, PrecisionChoice::Double).problem.find("1:2 resonant chain"), std::string::npos);
  const auto chain = twoMassChainOf(OptionValues(Options{}));
  ASSERT_TRUE(chain.value);
  ModesRequest request;
  request.energyRange = "3:1";
  EXPECT_NE(modesAtlas(**chain.value, request).problem.find("0 < A < B"), std::string::npos);
  request.energyRange.reset();
  request.maxImpacts = 65;
  const ModesOutcome refused = modesAtlas(**chain.value, request);
  EXPECT_EQ(refused.status, ModesStatus::Refused);
  EXPECT_EQ(modesFamilyCount(refused), 0u);
}

}  // namespace
}  // namespace grazelab::cli
