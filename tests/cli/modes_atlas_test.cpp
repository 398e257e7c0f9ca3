// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The typed atlas (commands/modes_atlas_command.h), as the command line and the Python module
// call it: its tables are its document's families row for row, every flip with a family born
// there names a family of twice the impacts, double and long double place the flips alike, the
// refusals are lines, and every other chain, of any N, takes the atlas of any chain.
#include <gtest/gtest.h>

#include <QString>

#include <cmath>
#include <memory>
#include <numbers>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "commands/modes_atlas_command.h"
#include "commands/orbit_command.h"
#include "commands/simulate_command.h"
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

ModesOutcome chainAtlasOf(const Options& options, int maxImpacts, std::stop_token stop = {}) {
  const auto chain = recentChain(OptionValues(options));
  EXPECT_TRUE(chain.value) << chain.error.toStdString();
  ModesRequest request;
  request.maxImpacts = maxImpacts;
  return modesAtlas(**chain.value, request, {}, stop);
}

// Every chain that is not the note's 1:2 two-mass chain takes the atlas of any chain: its document
// names the chain (not the note's model), each table is its family's rows over the columns of N
// masses, the first and last rows are the orbits the ends name, every multiplier's Krein signature
// is +-1 on the circle off the real axis and 0 off it, an elliptic row has every multiplier on the
// circle, and each family born at a doubling names that doubling, whose branch names it back.
TEST(TypedModes, AnyOtherChainTakesTheAtlasOfAnyChain) {
  const std::vector<std::pair<Options, int>> chains = {
      {{{"masses", "1,0.7,0.4"}, {"frequencies", "3:2:1"}}, 3},
      {{{"masses", "1,0.7,0.4"}, {"springs", "1,1.3,0.8"}, {"stop-mass", "2"}}, 3},
      {{{"m2", "0.4"}, {"k2", "0.37"}}, 2},  // two masses off the 1:2 design
      {{{"masses", "1,0.5"}, {"springs", "1,0.5"}, {"stop-mass", "1"}}, 2},
  };
  for (const auto& [options, n] : chains) {
    SCOPED_TRACE(n);
    const ModesOutcome outcome = chainAtlasOf(options, 2);
    ASSERT_EQ(outcome.status, ModesStatus::Computed) << outcome.problem;
    const JsonValue document = modesDocument(outcome, "x");
    EXPECT_EQ(document.find("model"), nullptr);
    ASSERT_NE(document.find("chain"), nullptr);
    const std::vector<std::string> columns = modesColumns(outcome);
    const std::size_t width = columns.size();
    ASSERT_EQ(width, std::size_t(5 + 2 * n + 3 * (2 * n - 2)));
    EXPECT_EQ(columns[5], "u1");
    EXPECT_EQ(columns.back(), "mu" + std::to_string(2 * n - 2) + "_krein");
    const auto& families = document.find("families")->items;
    ASSERT_EQ(families.size(), modesFamilyCount(outcome));
    ASSERT_FALSE(families.empty());
    const double low = document.find("energy_range")->items[0].toDouble();
    const double high = document.find("energy_range")->items[1].toDouble();
    for (std::size_t i = 0; i < families.size(); ++i) {
      const JsonValue& family = families[i];
      EXPECT_EQ(family.find("file")->text, "x-family-" + std::to_string(family.find("id")->integer) + ".csv");
      const std::vector<double> table = modesTable(outcome, i);
      const std::size_t rows = std::size_t(family.find("rows")->integer);
      ASSERT_EQ(table.size(), rows * width);
      ASSERT_GT(rows, 0u);
      for (std::size_t at = 0; at < table.size(); at += width) {
        EXPECT_GE(table[at], low * (1 - 1e-9));
        EXPECT_LE(table[at], high * (1 + 1e-9));
        EXPECT_DOUBLE_EQ(table[at + 2], 2 * std::numbers::pi / table[at + 1]);
        const int cls = int(table[at + 3]);
        ASSERT_GE(cls, 0);
        ASSERT_LE(cls, 4);
        EXPECT_GT(table[at + 4], 0);  // every impact of an admissible orbit has a speed
        for (int k = 0; k < 2 * n - 2; ++k) {
          const std::size_t mu = at + 5 + 2 * n + 3 * k;
          const double modulus = std::hypot(table[mu], table[mu + 1]);
          const double krein = table[mu + 2];
          if (krein != 0) {
            EXPECT_NEAR(modulus, 1, 1e-6);
          }
          if (std::abs(modulus - 1) > 1e-6 || std::abs(table[mu + 1]) < 1e-12) {
            EXPECT_EQ(krein, 0);
          }
          if (cls == int(core::ChainStability::Elliptic)) {
            EXPECT_NEAR(modulus, 1, 1e-6);
          }
        }
      }
      // the ends are the first and last rows
      EXPECT_EQ(family.find("end")->find("orbit")->find("energy")->toDouble(), table[(rows - 1) * width]);
      if (family.find("start")->kind != JsonValue::Kind::Null) {
        EXPECT_EQ(family.find("start")->find("orbit")->find("energy")->toDouble(), table[0]);
      }
      const JsonValue* born = family.find("born_at");
      if (born->find("kind")->text != "period-doubling") continue;
      const JsonValue* parent = nullptr;
      for (const JsonValue& other : families) {
        if (other.find("id")->integer == born->find("family")->integer) parent = &other;
      }
      ASSERT_NE(parent, nullptr);
      EXPECT_EQ(family.find("impacts")->integer, 2 * parent->find("impacts")->integer);
      const JsonValue& doubling = parent->find("bifurcations")->items.at(std::size_t(born->find("bifurcation")->integer));
      EXPECT_EQ(doubling.find("kind")->text, "period-doubling");
      EXPECT_EQ(doubling.find("branch")->text, "born");
      EXPECT_EQ(doubling.find("family")->integer, family.find("id")->integer);
    }
  }
}

TEST(TypedModes, AChainsAtlasStopsWhenAsked) {
  std::stop_source source;
  source.request_stop();
  const ModesOutcome outcome = chainAtlasOf({{"masses", "1,0.7,0.4"}, {"frequencies", "3:2:1"}}, 2, source.get_token());
  EXPECT_EQ(outcome.status, ModesStatus::Interrupted);
  EXPECT_EQ(modesFamilyCount(outcome), 0u);
}

}  // namespace
}  // namespace grazelab::cli
