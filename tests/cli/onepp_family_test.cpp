// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The typed family (commands/onepp_family.h), as the command line and the Python module call it:
// the note's chain gives the same table however it is written; every admissible row's class is
// its trace's; a chain of N masses tends to its grazing limit (V -> 0, weights summing to 1); the
// refusals come before any of it is computed; the document names its files only when written.
#include <gtest/gtest.h>

#include <QString>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <memory>
#include <numeric>
#include <utility>
#include <variant>
#include <vector>

#include "commands/onepp_family.h"
#include "commands/simulate_command.h"
#include "core/orbits/chain_monodromy.h"
#include "core/orbits/periodic_orbit.h"
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

FamilyOutcome familyOf(const Options& options, std::int64_t count, PrecisionChoice precision = PrecisionChoice::Auto) {
  FamilyRequest request;
  request.count = count;
  request.precision = precision;
  return onePeriodicFamily(*chainOf(options), request);
}

double at(const FamilyOutcome& outcome, std::size_t row, const std::string& column) {
  const auto found = std::find(outcome.columns.begin(), outcome.columns.end(), column);
  return outcome.table[row * outcome.columns.size() + std::size_t(found - outcome.columns.begin())];
}

TEST(TypedFamily, TheNotesChainHoweverWrittenGivesOneTableWhoseClassesAreItsTraces) {
  const FamilyOutcome byNotes = familyOf({{"m2", "0.125"}}, 300);
  ASSERT_EQ(byNotes.status, FamilyStatus::Computed) << byNotes.problem;
  ASSERT_TRUE(std::holds_alternative<NotesFamily>(byNotes.of));
  const FamilyOutcome byMasses = familyOf({{"masses", "1,0.125"}, {"frequencies", "2:1"}}, 300);
  ASSERT_EQ(byMasses.status, FamilyStatus::Computed) << byMasses.problem;
  EXPECT_EQ(byNotes.columns, byMasses.columns);
  ASSERT_EQ(byNotes.table.size(), byMasses.table.size());
  for (std::size_t i = 0; i < byNotes.table.size(); ++i) {
    const double a = byNotes.table[i], b = byMasses.table[i];
    ASSERT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << i << ": " << a << " " << b;
  }
  std::int64_t admissible = 0;
  for (std::size_t row = 0; row < byNotes.rows(); ++row) {
    const double trace = at(byNotes, row, "trace"), code = at(byNotes, row, "stability");
    if (at(byNotes, row, "admissible") == 0) {
      EXPECT_TRUE(std::isnan(trace) && std::isnan(code)) << row;
      continue;
    }
    ++admissible;
    ASSERT_TRUE(std::isfinite(trace)) << row;
    const auto stability = core::Stability(int(code));
    const core::Stability expected = std::abs(trace) < 2 - 1e-9 ? core::Stability::Elliptic
                                     : trace > 2 + 1e-9        ? core::Stability::Hyperbolic
                                     : trace < -2 - 1e-9       ? core::Stability::FlipHyperbolic
                                                               : stability;  // (parabolic within rounding)
    EXPECT_EQ(stability, expected) << row << " tr " << trace;
  }
  EXPECT_EQ(admissible, byNotes.admissible);
  EXPECT_GT(admissible, 100);
  // the document: its rows, and the files only when written
  const JsonValue unwritten = familyDocument(byNotes, std::nullopt);
  EXPECT_EQ(unwritten.find("rows")->integer, std::int64_t(byNotes.rows()));
  EXPECT_EQ(unwritten.find("files"), nullptr);
  EXPECT_EQ(familyDocument(byNotes, "f").find("files")->find("csv")->text, "f.csv");
}

TEST(TypedFamily, AChainOfThreeMassesTendsToItsGrazingLimit) {
  const FamilyOutcome outcome = familyOf({{"masses", "1,0.2,0.05"}, {"frequencies", "3:2:1"}}, 400);
  ASSERT_EQ(outcome.status, FamilyStatus::Computed) << outcome.problem;
  const auto& family = std::get<ChainFamily>(outcome.of);
  // T, omega, V, energy, admissible, u1..u3, the class, and re, im, Krein of 2N - 2 = 4 multipliers
  EXPECT_EQ(outcome.columns.size(), 5u + 3u + 1u + 3u * 4u);
  // each admissible row's class and multipliers (its exact monodromy): an elliptic row's on the
  // circle, a hyperbolic one's product of reciprocals 1; the family's end (3:2:1, near grazing)
  // has both kinds
  int elliptic = 0, other = 0;
  for (std::size_t row = 0; row < outcome.rows(); ++row) {
    if (at(outcome, row, "admissible") == 0) {
      EXPECT_TRUE(std::isnan(at(outcome, row, "class")));
      continue;
    }
    const auto cls = core::ChainStability(int(at(outcome, row, "class")));
    std::complex<double> product = 1;
    double farthest = 0;
    for (int k = 1; k <= 4; ++k) {
      const std::complex<double> mu(at(outcome, row, "mu" + std::to_string(k) + "_re"),
                                    at(outcome, row, "mu" + std::to_string(k) + "_im"));
      product *= mu;
      farthest = std::max(farthest, std::abs(std::abs(mu) - 1));
    }
    EXPECT_NEAR(std::abs(product - 1.0), 0.0, 1e-8) << "T " << at(outcome, row, "T");
    if (cls == core::ChainStability::Elliptic) {
      EXPECT_LT(farthest, 1e-8);
      ++elliptic;
    } else if (cls != core::ChainStability::Undecided) {
      EXPECT_GT(farthest, 1e-10);
      ++other;
    }
  }
  EXPECT_GT(elliptic, 0);
  EXPECT_GT(other, 0);
  EXPECT_NEAR(std::accumulate(family.weights.begin(), family.weights.end(), 0.0), 1.0, 1e-12);
  // the admissible rows nearest T_max have the smallest impact speeds
  double lastV = 0, lastT = 0;
  for (std::size_t row = 0; row < outcome.rows(); ++row) {
    if (at(outcome, row, "admissible") == 0) continue;
    lastV = at(outcome, row, "V");
    lastT = at(outcome, row, "T");
  }
  ASSERT_GT(lastT, 0.99 * family.tMax);
  EXPECT_LT(std::abs(lastV), 1e-2);
  // the picture's points are the rows with data (none at a multiple of a mode's period)
  std::size_t withData = 0;
  for (std::size_t row = 0; row < outcome.rows(); ++row) withData += std::isfinite(at(outcome, row, "V")) ? 1 : 0;
  EXPECT_EQ(outcome.points.size(), withData);
}

TEST(TypedFamily, AChainOfThreeMassesLocatesWhereItsStabilityChanges) {
  // (a chain whose 1IPP family has period doublings, folds and Krein collisions)
  const FamilyOutcome outcome = familyOf(
      {{"masses", "0.6865,1.9630,0.8236"}, {"springs", "0.8423,1.0745,0.7486"}, {"stop-mass", "2"}}, 300);
  ASSERT_EQ(outcome.status, FamilyStatus::Computed) << outcome.problem;
  const auto& family = std::get<ChainFamily>(outcome.of);
  int kinds[4] = {};
  double last = 0;
  for (const core::ChainBifurcation<double>& b : family.bifurcations.changes) {
    ++kinds[int(b.kind)];
    EXPECT_GT(b.T, last) << "in increasing T";
    EXPECT_LT(b.periodError, 1e-11 * b.T);
    last = b.T;
    // the class of the rows on either side differs: the change is between them
    double before = NAN, after = NAN;
    for (std::size_t row = 0; row < outcome.rows(); ++row) {
      const double cls = at(outcome, row, "class");
      if (std::isnan(cls)) continue;
      if (at(outcome, row, "T") < b.T) before = cls;
      if (at(outcome, row, "T") > b.T && std::isnan(after)) after = cls;
    }
    EXPECT_FALSE(std::isnan(before) || std::isnan(after)) << "T " << b.T;
  }
  EXPECT_GT(kinds[int(core::ChainBifurcationKind::PeriodDoubling)], 0);
  EXPECT_GT(kinds[int(core::ChainBifurcationKind::Fold)], 0);
  EXPECT_GT(kinds[int(core::ChainBifurcationKind::KreinCollision)], 0);
  // and the document lists them
  const JsonValue document = familyDocument(outcome, std::nullopt);
  EXPECT_EQ(document.find("bifurcations")->items.size(), family.bifurcations.changes.size());
  EXPECT_EQ(document.find("unsearched")->items.size(), family.bifurcations.unsearched.size());
  for (const JsonValue& point : document.find("bifurcations")->items) {
    const double energy = point.find("energy")->value, error = point.find("energy_error")->value;
    EXPECT_GT(error, 0.0);
    EXPECT_LT(error, 1e-9 * energy);
  }
}

TEST(TypedFamily, RefusalsComeBeforeAnyOfItIsComputed) {
  // what the request alone decides, before a chain is read or designed
  FamilyRequest request;
  request.count = 0;
  EXPECT_NE(familyRequestRefusal(request, true)->find("from 1 to 10000000"), std::string::npos);
  request.count = 2'000'000;
  EXPECT_FALSE(familyRequestRefusal(request, true));
  EXPECT_NE(familyRequestRefusal(request, false)->find("from 1 to 1000000"), std::string::npos);
  request.count = 10;
  request.precision = PrecisionChoice::Long;
  EXPECT_EQ(*familyRequestRefusal(request, false), kFamilyOfNMassesInDouble);
  request.precision = PrecisionChoice::Auto;
  request.count = 0;
  EXPECT_NE(familyRefusal(*chainOf({}), request)->find("not a count"), std::string::npos);
  request.count = 10;
  EXPECT_NE(familyRefusal(*chainOf({{"k2", "0.3"}}), request)->find("1:2 resonant chain"), std::string::npos);
  request.precision = PrecisionChoice::Quad;
  EXPECT_FALSE(familyRefusal(*chainOf({}), request));
  const auto three = chainOf({{"masses", "1,0.2,0.05"}, {"frequencies", "3:2:1"}});
  EXPECT_NE(familyRefusal(*three, request)->find("computed in double"), std::string::npos);
  const FamilyOutcome refused = onePeriodicFamily(*three, request);
  EXPECT_EQ(refused.status, FamilyStatus::Refused);
  EXPECT_TRUE(refused.table.empty());
}

}  // namespace
}  // namespace grazelab::cli
