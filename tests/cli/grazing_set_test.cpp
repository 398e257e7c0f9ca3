// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The typed glo-set (commands/grazing_set.h), as the command line and the Python module call it:
// the note's chain however written has the note's interval [0, 4/3]; each end of every interval
// grazes and its outer point does not (checked here by a dense scan, another algorithm than the
// certified search); refusals and an interrupt are statuses with their line, not text to parse.
#include <gtest/gtest.h>

#include <QString>

#include <cmath>
#include <numbers>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "commands/glo_set_command.h"
#include "commands/grazing_set.h"
#include "io/option_values.h"

namespace grazelab::cli {
namespace {

using Options = std::vector<std::pair<QString, QString>>;

core::MassChain chainOf(const Options& options) {
  const Parsed<core::MassChain> made = gloSetChainOf(OptionValues(options), {});
  EXPECT_TRUE(made.value) << made.error.toStdString();
  return made.value ? *made.value : core::MassChain{};
}

// max over theta of sum_j w_j cos(n_j theta), by a scan of the period refined by golden sections
// around its best sample: what "grazes" means (the maximum is 1)
double top(const std::vector<int>& n, const std::vector<double>& w) {
  const auto f = [&](double theta) {
    double sum = 0;
    for (std::size_t j = 0; j < n.size(); ++j) sum += w[j] * std::cos(n[j] * theta);
    return sum;
  };
  const int samples = 20000;
  const double step = 2 * std::numbers::pi / samples;
  double best = -10, at = 0;
  for (int i = 0; i < samples; ++i) {
    if (f(i * step) > best) best = f(i * step), at = i * step;
  }
  double a = at - step, b = at + step;
  for (int i = 0; i < 200; ++i) {
    const double c = b - (b - a) / std::numbers::phi, d = a + (b - a) / std::numbers::phi;
    (f(c) > f(d) ? b : a) = (f(c) > f(d) ? d : c);
  }
  return std::max(best, f((a + b) / 2));
}

double top(int n1, int n2, double lambda) { return top({n1, n2}, {1 - lambda, lambda}); }

TEST(TypedGloSet, TheNotesChainHoweverWrittenIsTheIntervalZeroToFourThirds) {
  for (const Options& written : {Options{}, Options{{"masses", "1,0.5"}, {"frequencies", "2:1"}}}) {
    const GloSetOutcome outcome = grazingSet(chainOf(written), GloSetRequest{});
    ASSERT_EQ(outcome.status, GloSetStatus::Computed) << outcome.problem;
    EXPECT_EQ(outcome.modes, (std::vector<int>{0, 1}));
    EXPECT_EQ(outcome.harmonics, (std::vector<int>{2, 1}));
    ASSERT_TRUE(outcome.interval);
    EXPECT_NEAR(outcome.interval->low, 0, 1e-12);
    EXPECT_NEAR(outcome.interval->high, 4.0 / 3, 1e-12);
    EXPECT_NEAR(outcome.period, 8.885765876316732, 1e-12);  // T2, the slow mode's period
    const JsonValue document = gloSetDocument(outcome);
    EXPECT_EQ(document.find("grazing_set")->find("kind")->text, "interval");
  }
}

TEST(TypedGloSet, EachEndOfEveryIntervalGrazesAndItsOuterPointDoesNot) {
  // resonances the issues do not name, both orders of the stopped mass's modes, a scaled chain
  for (const Options& written : {Options{{"masses", "1,0.3"}, {"frequencies", "3:1"}},
                                 Options{{"masses", "2,0.2"}, {"frequencies", "3:2"}, {"springs", "5"}, {"gap", "0.01"}},
                                 Options{{"masses", "1,0.4"}, {"frequencies", "5:2"}}}) {
    const GloSetOutcome outcome = grazingSet(chainOf(written), GloSetRequest{});
    ASSERT_EQ(outcome.status, GloSetStatus::Computed) << outcome.problem;
    ASSERT_TRUE(outcome.interval);
    const int n1 = outcome.harmonics[0], n2 = outcome.harmonics[1];
    const core::GrazingInterval& set = *outcome.interval;
    EXPECT_LT(set.lowOut, set.low);
    EXPECT_GT(set.highOut, set.high);
    for (double lambda : {set.low, set.high, (set.low + set.high) / 2}) {
      EXPECT_NEAR(top(n1, n2, lambda), 1, 1e-9) << n1 << ":" << n2 << " " << lambda;
    }
    // outside by the bracket's width (at least 1e-6, where a scan sees the excess)
    EXPECT_GT(top(n1, n2, set.low - std::max(1e-6, set.low - set.lowOut)), 1 + 1e-13) << n1 << ":" << n2;
    if (set.high != set.flatPoint) {
      EXPECT_GT(top(n1, n2, set.high + std::max(1e-6, set.highOut - set.high)), 1 + 1e-13) << n1 << ":" << n2;
    }
  }
}

TEST(TypedGloSet, ThreeModesGiveARegionWhoseRaysGrazeInsideAndNotOutside) {
  const GloSetOutcome outcome =
      grazingSet(chainOf({{"masses", "1,0.6,0.3"}, {"frequencies", "3:2:1"}}), GloSetRequest{12});
  ASSERT_EQ(outcome.status, GloSetStatus::Computed) << outcome.problem;
  ASSERT_EQ(outcome.boundary.size(), 12u);
  const std::vector<int>& n = outcome.harmonics;
  for (const core::GrazingRegionPoint& point : outcome.boundary) {
    EXPECT_LT(point.radius, point.radiusOut);
    EXPECT_NEAR(top(n, {1 - point.lambda2 - point.lambda3, point.lambda2, point.lambda3}), 1, 1e-9) << point.angle;
    // the ray's point beyond, by at least 1e-6 (a scan sees the excess there)
    const double out = std::max(point.radiusOut, point.radius + 1e-6);
    const double l2 = 1.0 / 3 + out * std::cos(point.angle), l3 = 1.0 / 3 + out * std::sin(point.angle);
    EXPECT_GT(top(n, {1 - l2 - l3, l2, l3}), 1 + 1e-13) << point.angle;
  }
  EXPECT_EQ(gloSetDocument(outcome).find("grazing_set")->find("kind")->text, "region");
}

TEST(TypedGloSet, RefusalsAndAnInterruptAreStatusesWithTheirLine) {
  // four modes move the stopped mass
  const GloSetOutcome four = grazingSet(chainOf({{"masses", "1,0.7,0.5,0.3"}, {"frequencies", "4:3:2:1"}}), {});
  EXPECT_EQ(four.status, GloSetStatus::Refused);
  EXPECT_NE(four.problem.find("two or three modes"), std::string::npos) << four.problem;
  // frequencies that are not commensurate
  const GloSetOutcome detuned = grazingSet(chainOf({{"masses", "1,1"}, {"springs", "1,1"}}), {});
  EXPECT_EQ(detuned.status, GloSetStatus::Refused);
  EXPECT_NE(detuned.problem.find("commensurate"), std::string::npos) << detuned.problem;
  // the region's search stopped
  std::stop_source stop;
  stop.request_stop();
  const GloSetOutcome stopped =
      grazingSet(chainOf({{"masses", "1,0.6,0.3"}, {"frequencies", "3:2:1"}}), GloSetRequest{}, stop.get_token());
  EXPECT_EQ(stopped.status, GloSetStatus::Interrupted);
  // the request's reader: a bad --directions changes nothing and says why
  QString error;
  EXPECT_FALSE(readGloSetRequest(OptionValues(Options{{"directions", "2"}}), error));
  EXPECT_TRUE(error.contains("--directions")) << error.toStdString();
}

}  // namespace
}  // namespace grazelab::cli
