// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/sticking.cpp.
#include "core/solver/sticking.h"

#include "core/solver/impact_law.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/model/linear_modes.h"
#include "core/orbits/special_orbits.h"
#include "core/solver/simulate.h"
#include "support/cases.h"

namespace grazelab::core {
namespace {

TEST(Sticking, PressedOnlyWhenTheSpringPushesIntoTheStop) {
  const Model model = testing::resonantChain(0.5);
  EXPECT_TRUE(pressedOnStop<double>({1.2, 1.0, 0.0, 0.0}, model.gap));
  EXPECT_TRUE(pressedOnStop<double>({1.0, 1.0, 0.3, 0.0}, model.gap));
  EXPECT_FALSE(pressedOnStop<double>({1.0, 1.0, -0.3, 0.0}, model.gap));
  EXPECT_FALSE(pressedOnStop<double>({1.0, 1.0, 0.0, 0.0}, model.gap));  // no force, no push: grazing
  EXPECT_FALSE(pressedOnStop<double>({0.8, 1.0, 0.0, 0.0}, model.gap));
  EXPECT_FALSE(pressedOnStop<double>({1.2, 1.0, 0.0, -0.1}, model.gap));
  EXPECT_FALSE(pressedOnStop<double>({1.2, 0.9, 0.0, 0.0}, model.gap));
}

// A start pressed on the stop sticks at t = 0, a step that takes no time. Its dense samples
// must be the motion (mass 2 on the stop, mass 1 moving), not zeros: the explorer drew a line
// from the origin to the start.
TEST(Sticking, SamplesOfAStuckStartStayOnTheStop) {
  const Model model = testing::resonantChain(0.5);
  const Modes modes = computeModes(model);
  Request request;
  request.initial = gloData(model, modes, 1.6);
  request.maxContacts = 3;
  request.needs.samples.spacing = modes.T1 / 48;
  request.needs.samples.tEnd = 5 * modes.T2;
  const Result result = simulate(model, request);
  ASSERT_EQ(result.events.front().type, EventType::Stick);
  ASSERT_FALSE(result.samples.empty());
  EXPECT_EQ(result.samples.front().t, 0.0);
  EXPECT_EQ(result.samples.front().state.u1, request.initial.u1);
  EXPECT_EQ(result.samples.front().state.u2, model.gap);
  // until the release, mass 2 is on the stop
  const double release = result.events[1].t;
  for (const Sample& sample : result.samples) {
    if (sample.t < release) { EXPECT_NEAR(sample.state.u2, model.gap, 1e-12 * model.gap); }
    EXPECT_LE(sample.state.u2, model.gap * (1 + 1e-12));
  }
}

TEST(Sticking, ReleaseWhenTheReactionVanishes) {
  const Model model = testing::resonantChain(0.5);
  for (const State start : {State{1.25, 1.0, 0.0, 0.0}, State{1.0, 1.0, 0.4, 0.0},
                            State{1.0000001, 1.0, -0.2, 0.0}, State{3.0, 1.0, 2.0, 0.0}}) {
    // the stuck motion runs in scaled units (lengths by the gap, time by 1/w2)
    const TwoMassForm<double> chain = *makeTwoMassForm(model).chain;
    const Scale<double> scale = chooseScale(chain, start);
    const StuckMotion<double> motion(chain, scale.gap, scale.toScaled(start));
    const double release = motion.releaseTime() / chain.omegaSlow;
    ASSERT_GT(release, 0);
    // independent check: bisection on the closed-form u1(t) - gap over a fine scan
    const double omega = std::sqrt((model.k1 + model.k2) / model.m1);
    const double centre = model.k2 * model.gap / (model.k1 + model.k2);
    auto u1 = [&](double t) {
      return centre + (start.u1 - centre) * std::cos(omega * t) + start.v1 / omega * std::sin(omega * t);
    };
    double a = 0;
    double b = 0;
    for (int i = 1; i <= 100000; ++i) {
      b = i * (2 * M_PI / omega) / 100000;
      if (u1(b) < model.gap) break;
      a = b;
    }
    for (int k = 0; k < 80; ++k) {
      const double mid = 0.5 * (a + b);
      (u1(mid) >= model.gap ? a : b) = mid;
    }
    EXPECT_NEAR(release, 0.5 * (a + b), 1e-12 * (2 * M_PI / omega));
    // reaction -k2 (u1 - gap) <= 0 all along the stuck phase
    for (int i = 0; i <= 100; ++i) {
      const State state = scale.toPhysical(motion.at(chain.omegaSlow * release * i / 100));
      EXPECT_GE(state.u1 - model.gap, -1e-14);
      EXPECT_EQ(state.u2, model.gap);
      EXPECT_EQ(state.v2, 0);
    }
    const State released = scale.toPhysical(motion.releaseState());
    EXPECT_EQ(released.u1, model.gap);
    EXPECT_LE(released.v1, 0);
  }
}

}  // namespace
}  // namespace grazelab::core
