// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Stiff and extreme inputs (issue 7): each class of silent wrong answer found there, checked
// against the same algorithm in binary128 or against exact scale invariance.
#include <gtest/gtest.h>

#include <cmath>

#include "core/orbits/special_orbits.h"
#include "core/orbits/starts.h"
#include "core/solver/simulate.h"
#include "support/cases.h"

namespace grazelab::core {
namespace {

template <typename S>
std::vector<BasicEvent<S>> run(const BasicModel<S>& model, const BasicState<S>& start,
                               std::int64_t contacts) {
  BasicRequest<S> request;
  request.initial = start;
  request.maxContacts = contacts;
  return simulate(model, request).events;
}

// the double run against the binary128 run of the same numbers: type, time to 1e-10 T2,
// state to `tolerance` of the scales (positions by `length`, velocities by w2 length)
void expectAgreesWithQuad(const Model& model, const State& start, int contacts, double tolerance) {
  const auto fine = run(convertModel<Quad>(model), convertState<Quad>(start), contacts);
  const auto coarse = run(model, start, contacts);
  ASSERT_EQ(coarse.size(), fine.size());
  const Modes modes = computeModes(model);
  double length = model.gap;
  for (const auto& event : fine) length = std::max({length, std::abs(toDouble(event.before.u1))});
  const double speed = modes.omegaSlow * length;
  for (std::size_t i = 0; i < fine.size(); ++i) {
    ASSERT_EQ(coarse[i].type, fine[i].type) << "event " << i;
    EXPECT_NEAR(coarse[i].t / modes.T2, toDouble(fine[i].t) / modes.T2, 1e-10) << "event " << i;
    EXPECT_NEAR(coarse[i].before.u1 / length, toDouble(fine[i].before.u1) / length, tolerance);
    EXPECT_NEAR(coarse[i].before.v1 / speed, toDouble(fine[i].before.v1) / speed, tolerance);
    const double v2 = toDouble(fine[i].before.v2);
    if (v2 != 0) { EXPECT_NEAR(coarse[i].before.v2 / v2, 1.0, 1e-8) << "event " << i; }
  }
}

TEST(Extremes, ScalingGapMassesAndStiffnessesLeavesTheEventsUnchanged) {
  const Model unit = testing::resonantChain(0.5);
  const State start = testing::nearGrazingStart(unit, 0.5, 0.01);
  const auto reference = run(unit, start, 20);
  ASSERT_EQ(reference.size(), 20u);
  for (double length : {1e-300, 1e-150, 1e-9, 1e6, 1e150, 1e300}) {
    for (double stiffness : {1e-200, 1e-78, 1.0, 1e78, 1e200}) {
      for (double mass : {1e-80, 1.0, 1e80}) {
        // w2 scales by sqrt(stiffness / mass): times by its inverse, speeds by it
        const double rate = std::sqrt(stiffness) / std::sqrt(mass);
        // the start's speeds must be representable numbers themselves (not 1e-400)
        const double speedScale = std::log10(length) + std::log10(rate);
        if (std::abs(speedScale) > 290) continue;
        const Model scaled = *designedModel(mass, 0.5 * mass, stiffness, length, Branch::Upper);
        const State scaledStart{start.u1 * length, start.u2 * length, start.v1 * length * rate,
                                start.v2 * length * rate};
        const auto events = run(scaled, scaledStart, 20);
        ASSERT_EQ(events.size(), reference.size()) << length << " " << stiffness << " " << mass;
        for (std::size_t i = 0; i < events.size(); ++i) {
          EXPECT_EQ(events[i].type, reference[i].type);
          EXPECT_NEAR(events[i].t * rate, reference[i].t, 1e-12 * reference[i].t);
          EXPECT_NEAR(events[i].before.u1 / length, reference[i].before.u1, 1e-13);
          EXPECT_NEAR(events[i].before.v2 / (length * rate), reference[i].before.v2,
                      1e-13 * std::abs(reference[i].before.v2));
          EXPECT_TRUE(std::isfinite(events[i].before.v1));
        }
      }
    }
  }
}

TEST(Extremes, TinyGapNextToTheMotionStillImpacts) {
  // the motion 1e9 times the gap: impacts, not grazings at multiples of T2 (class 1)
  for (double gap : {1e-9, 1e-12}) {
    const Model model = testing::resonantChain(0.5, gap);
    State start = gloData(model, computeModes(model), 0.5);
    start.v2 = -1.0;
    const auto events = run(model, start, 10);
    ASSERT_EQ(events.size(), 10u);
    for (const auto& event : events) {
      EXPECT_EQ(event.type, EventType::Impact);
      EXPECT_GT(event.before.v2, 1e-3);
    }
    expectAgreesWithQuad(model, start, 10, 1e-9);
  }
}

TEST(Extremes, ExtremeMassRatiosKeepTheirModeShapes) {
  // class 2: m2/m1 down to 1e-40, both branches
  for (double beta : {1e-20, 1e-32, 1e-40}) {
    for (Branch branch : {Branch::Upper, Branch::Lower}) {
      const Model model = *designedModel(1.0, beta, 1.0, 1.0, branch);
      const Modes modes = computeModes(model);
      EXPECT_GT(modes.P(1, 1), 0) << beta;
      EXPECT_GT(modes.P(1, 0), 0) << beta;
      const State start = testing::nearGrazingStart(model, 0.5, 1e-3);
      EXPECT_TRUE(std::isfinite(start.u1)) << beta;
      const auto events = run(model, start, 5);
      ASSERT_EQ(events.size(), 5u) << beta;
      EXPECT_EQ(events.front().type, EventType::Impact) << beta;
      expectAgreesWithQuad(model, start, 5, 1e-9);
    }
  }
}

TEST(Extremes, TinyPushFromAFourthOrderTouchScalesWithThePush) {
  // class 4: u1 = d, v1 = 0 on the stop, v2 = -eps: the impact speed is proportional to eps
  const Model model = testing::resonantChain(0.5);
  double ratio = 0;
  double swing = 0;  // v1 at the impact over eps^(1/3)
  // down to the subnormal edge: the root is found to its relative precision (Newton that stops
  // at rounding noise, exponent bisection toward the zero end); v1 at the impact ~ eps^(1/3)
  for (double eps : {1e-20, 1e-100, 1e-150, 1e-200, 1e-290}) {
    const auto events = run(model, State{1.0, 1.0, 0.0, -eps}, 1);
    ASSERT_EQ(events.size(), 1u) << eps;
    ASSERT_EQ(events[0].type, EventType::Impact) << eps;
    const double speedOverPush = events[0].before.v2 / eps;
    if (ratio == 0) ratio = speedOverPush;
    EXPECT_NEAR(speedOverPush / ratio, 1.0, 1e-10) << eps;
    const double swingOverRoot = events[0].before.v1 / std::cbrt(eps);
    if (swing == 0) swing = swingOverRoot;
    EXPECT_NEAR(swingOverRoot / swing, 1.0, 1e-9) << eps;
  }
  EXPECT_GT(ratio, 0);
}

TEST(Extremes, ShortStickKeepsTheRelativePrecisionOfItsRelease) {
  // class 5: pressed by 1e-10 and moving off: release after ~1e-10, the next impact exact
  const Model model = testing::resonantChain(0.5);
  for (double excess : {1e-7, 1e-10, 1e-13}) {
    const State start{1.0 + excess, 1.0, -0.3, 0.0};
    const auto fine = run(convertModel<Quad>(model), convertState<Quad>(start), 3);
    const auto coarse = run(model, start, 3);
    ASSERT_GE(coarse.size(), 2u);
    ASSERT_EQ(coarse[1].type, EventType::Release);
    EXPECT_NEAR(coarse[1].t / toDouble(fine[1].t), 1.0, 1e-12) << excess;
    EXPECT_NEAR(coarse[1].after.v1 / toDouble(fine[1].after.v1), 1.0, 1e-12) << excess;
    expectAgreesWithQuad(model, start, 4, 1e-9);
  }
}

TEST(Extremes, StiffDetunedChainsHoldTheirAccuracy) {
  // class 6: k2/k1 = 1e4 and 1e6, detuned
  for (double stiffness : {1e4, 1e6}) {
    const Model model{1.0, 0.5, 1.0, stiffness, 1.0, {}};
    const State start{0.2, 0.5, 0.1, 0.8};
    expectAgreesWithQuad(model, start, 5, 1e-9);
  }
}

TEST(Extremes, LambdaNearFourThirdsKeepsItsClass) {
  // class 8: the class follows lambda, the data follows the class
  for (const Model& model : {testing::resonantChain(1e-12), testing::resonantChain(1e-4, 1.0, Branch::Lower),
                             testing::resonantChain(0.5)}) {
    const TwoMassForm<double> chain = *makeTwoMassForm(model).chain;
    const double below = 4.0 / 3.0;  // the double nearest 4/3 lies below it
    const double above = std::nextafter(below, 2.0);
    EXPECT_EQ(classifyGlo(below), GloKind::Grazing);
    EXPECT_EQ(classifyGlo(above), GloKind::StickingStart);
    EXPECT_LE(gloData(chain, below).u1, model.gap);
    EXPECT_GT(gloData(chain, above).u1, model.gap);
  }
}

TEST(Extremes, AnEndTimeSetsTheDetunedSearchHorizon) {
  // class 9: no search-budget stop before an explicit end time
  const Model model{1.0, 0.5, 1.0, 0.45, 1.0, {}};
  Request request;
  request.initial = {0.01, 0.02, 0.0, 0.01};  // stays far below the stop
  request.maxContacts = 10;
  request.tEnd = 3000 * computeModes(model).T2;
  const Result result = simulate(model, request);
  EXPECT_EQ(result.stop, StopReason::TimeLimit);
  EXPECT_EQ(result.tFinal, request.tEnd);
}

}  // namespace
}  // namespace grazelab::core
