// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The computations behind the explorer's theorem scenes (core/experiments/theorem_surveys.h), checked against
// the statements they illustrate (docs/model.md section 5).
#include <gtest/gtest.h>

#include <numeric>
#include <stop_token>

#include "core/experiments/theorem_surveys.h"
#include "core/orbits/special_orbits.h"
#include "tests/support/cases.h"

namespace grazelab::core::experiments {
namespace {

using testing::nearGrazingStart;
using testing::resonantChain;

// Lemma 2.1: GLO(lambda) just touches the stop (its top is the gap) for lambda in [0, 4/3] and
// passes it outside; the closed form agrees with a dense sampling of the orbit's u2.
TEST(ExperimentsTest, theGrazingFamilyTouchesTheStopExactlyOnZeroToFourThirds) {
  for (double lambda = 0; lambda <= 4.0 / 3.0; lambda += 1.0 / 96) EXPECT_EQ(gloHighestReach(lambda), 1.0) << lambda;
  for (double lambda : {-0.5, -0.1, 1.34, 1.5, 2.0}) {
    EXPECT_GT(gloHighestReach(lambda), 1.0) << lambda;
    double sampled = -1e300;
    for (int i = 0; i <= 200'000; ++i) {
      const double s = 2 * 3.141592653589793 * i / 200'000;
      sampled = std::max(sampled, (1 - lambda) * std::cos(2 * s) + lambda * std::cos(s));
    }
    EXPECT_NEAR(gloHighestReach(lambda), sampled, 1e-9) << lambda;
  }
}

// Theorem 2.3: whatever the start, no flight from the stop lasts longer than T2; every flight
// is counted once, every start once.
TEST(ExperimentsTest, noRandomStartFliesLongerThanT2) {
  for (const Model& model : {resonantChain(0.5), resonantChain(0.2, 2.0, Branch::Lower)}) {
    const FlightSurvey survey = surveyRandomStarts(model, 120, 40, 7, 44, 0.025);
    ASSERT_TRUE(survey.complete);
    EXPECT_LE(survey.longest, 1.0);
    EXPECT_GT(survey.flights, 100);
    EXPECT_EQ(std::accumulate(survey.counts.begin(), survey.counts.end(), 0), survey.flights);
    EXPECT_EQ(survey.neverTouch + survey.reachedLimit + survey.other, 120);
    ASSERT_TRUE(survey.firstTouching);
    EXPECT_LE(survey.firstTouching->u2, model.gap);
  }
}

// The same seed, the same survey: the scene shows the same histogram for a chain every time.
TEST(ExperimentsTest, aSurveyIsReproducibleAndStops) {
  const Model model = resonantChain(0.5);
  const FlightSurvey a = surveyRandomStarts(model, 30, 20, 11, 44, 0.025);
  const FlightSurvey b = surveyRandomStarts(model, 30, 20, 11, 44, 0.025);
  EXPECT_EQ(a.counts, b.counts);
  EXPECT_EQ(a.longest, b.longest);
  std::stop_source source;
  source.request_stop();
  const FlightSurvey stopped = surveyRandomStarts(model, 30, 20, 11, 44, 0.025, source.get_token());
  EXPECT_FALSE(stopped.complete);
  EXPECT_FALSE(largestShortfall(model, nearGrazingStart(model, 0.5, 1e-3), 50, source.get_token()));
}

// Theorem 2.2: near a grazing orbit every flight lasts almost T2: the largest shortfall
// shrinks with the push (GLOM1, lambda = 0, excepted), and is never negative.
TEST(ExperimentsTest, theShortfallShrinksWithThePush) {
  const Model model = resonantChain(0.5);
  double previous = 1.0;
  for (double push : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5}) {
    const std::optional<double> shortfall = largestShortfall(model, nearGrazingStart(model, 0.5, push), 200);
    ASSERT_TRUE(shortfall);
    EXPECT_GE(*shortfall, 0.0);
    EXPECT_LT(*shortfall, previous) << push;
    previous = *shortfall;
  }
  EXPECT_LT(previous, 1e-2);
}

}  // namespace
}  // namespace grazelab::core::experiments
