// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/solver/contact.cpp: contact times against independent computations (a dense scan of
// the plain closed form, and the detuned march run on a resonant chain), and the precise
// handling of near-grazing returns.
#include "core/solver/contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/solver/simulate.h"

#include "support/cases.h"
#include "support/physical_flight.h"

namespace grazelab::core {
namespace {

// u2(t) - gap from the textbook modal formula, written independently of Flight
double naiveGap(const Model& model, const Modes& modes, const State& start, double t) {
  const Eigen::Vector2d q = modes.Pinv * Eigen::Vector2d(start.u1, start.u2);
  const Eigen::Vector2d qDot = modes.Pinv * Eigen::Vector2d(start.v1, start.v2);
  const double omega[2] = {modes.omegaFast, modes.omegaSlow};
  double u2 = 0;
  for (int j = 0; j < 2; ++j) {
    u2 += modes.P(1, j) * (q(j) * std::cos(omega[j] * t) + qDot(j) / omega[j] * std::sin(omega[j] * t));
  }
  return u2 - model.gap;
}

// first sign change of the naive gap on a fine grid, refined by bisection; -1 if none
double scanFirstContact(const Model& model, const Modes& modes, const State& start, double horizon) {
  const int samples = 200000;
  double previousT = 0;
  double previous = naiveGap(model, modes, start, 0.0);
  for (int i = 1; i <= samples; ++i) {
    const double t = horizon * i / samples;
    const double value = naiveGap(model, modes, start, t);
    if (previous < 0 && value >= 0) {
      double a = previousT;
      double b = t;
      for (int k = 0; k < 80; ++k) {
        const double mid = 0.5 * (a + b);
        (naiveGap(model, modes, start, mid) < 0 ? a : b) = mid;
      }
      return 0.5 * (a + b);
    }
    previousT = t;
    previous = value;
  }
  return -1;
}

// states strictly below the stop whose flight crosses it transversally
std::vector<State> randomStarts(const Model& model, int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<State> starts;
  while (static_cast<int>(starts.size()) < count) {
    State s{uniform(random), uniform(random), uniform(random), uniform(random)};
    s = model.gap * s;
    s.u2 = std::min(s.u2, 0.9 * model.gap);
    starts.push_back(s);
  }
  return starts;
}

TEST(Contact, ResonantTimesMatchADenseScan) {
  for (const auto& chain : testing::resonantChains()) {
    const Model& model = chain.model;
    const Modes modes = computeModes(model);
    int compared = 0;
    for (const State& start : randomStarts(model, 60, 7)) {
      const testing::PhysicalFlight flight(model, start);
      const auto contact = flight.nextContact(kInfinity);
      const double scanned = scanFirstContact(model, modes, start, modes.T2);
      if (scanned < 0) {
        EXPECT_NE(contact.kind, ContactKind::Crossing) << chain.name;
        continue;
      }
      // a transversal crossing: the scan is reliable there
      if (std::abs(flight.at(scanned).v2) < 1e-3 * modes.omegaSlow * model.gap) continue;
      ASSERT_EQ(contact.kind, ContactKind::Crossing) << chain.name;
      EXPECT_NEAR(contact.time, scanned, 1e-10 * modes.T2) << chain.name;
      ++compared;
    }
    EXPECT_GT(compared, 10) << chain.name;
  }
}

TEST(Contact, DetunedTimesMatchADenseScan) {
  const Model model = testing::detunedChain();
  const Modes modes = computeModes(model);
  int compared = 0;
  for (const State& start : randomStarts(model, 60, 11)) {
    const testing::PhysicalFlight flight(model, start);
    const double horizon = 3 * modes.T2;
    const auto contact = flight.nextContact(horizon);
    const double scanned = scanFirstContact(model, modes, start, horizon);
    if (scanned < 0 || std::abs(flight.at(scanned).v2) < 1e-3 * modes.omegaSlow) continue;
    ASSERT_EQ(contact.kind, ContactKind::Crossing);
    EXPECT_NEAR(contact.time, scanned, 1e-10 * modes.T2);
    ++compared;
  }
  EXPECT_GT(compared, 10);
}

TEST(Contact, QuarticSearchAndSafeMarchAgreeOnResonantFlights) {
  // the march knows nothing of polynomials: run it on the same resonant chain
  const Model model = testing::resonantChain(0.5);
  const Modes modes = computeModes(model);
  int compared = 0;
  for (const State& start : randomStarts(model, 200, 3)) {
    const auto quartic = testing::PhysicalFlight(model, start).nextContact(kInfinity);
    const auto march = testing::PhysicalFlight(model, start, true).nextContact(1.01 * modes.T2);
    ASSERT_EQ(quartic.kind == ContactKind::None, march.kind == ContactKind::None);
    if (quartic.kind != ContactKind::Crossing) continue;
    EXPECT_NEAR(quartic.time, march.time, 1e-11 * modes.T2);
    ++compared;
  }
  EXPECT_GT(compared, 50);
}

TEST(Contact, GapPolynomialIsTheGapInTheHalfAngleTangent) {
  // (1 + x^2)^2 (x2 - delta) at theta = 2 atan x, from the quartic and from the flight itself;
  // its low coefficients are the start's own: c0 = x2 - delta, c1 = 2 y2 (exactly)
  const Model model = testing::resonantChain(0.5, 1.0, Branch::Lower);
  for (const State& start : randomStarts(model, 50, 5)) {
    const testing::PhysicalFlight flight(model, start);
    const Flight<double>& scaled = flight.scaled();
    const std::array<double, 5> c = resonantGapPolynomial(scaled);
    EXPECT_EQ(c[0], scaled.start().u2 - scaled.gapLevel());
    EXPECT_EQ(c[1], 2 * scaled.start().v2);
    double size = 0;
    for (double x : {-7.0, -1.0, -0.3, 0.01, 0.5, 2.0, 11.0}) {
      const double theta = 2 * std::atan(x);
      const FlightTime<double> time = FlightTime<double>::nearest(theta);
      const double square = 1 + x * x;
      const double expected = square * square * scaled.gapAndRate(time).first;
      double value = 0;
      size = 0;
      for (int i = 4; i >= 0; --i) {
        value = value * x + c[i];
        size = size * std::abs(x) + std::abs(c[i]);
      }
      EXPECT_NEAR(value, expected, 1e-14 * size) << x;
    }
  }
}

TEST(Contact, CrossingNearHalfPeriodIsFoundInTheFarChart) {
  // GLOM1 peaks at 0 and T2 / 2. Started a little after a peak with its amplitude raised by
  // 1 + eps, the flight crosses just before the next peak, near theta = pi, where tan(theta/2)
  // runs off to infinity: the far chart must find it, as the march does
  const Model model = testing::resonantChain(0.5);
  const Modes modes = computeModes(model);
  const testing::PhysicalFlight glom1(model, gloData(model, modes, 0.0));
  const double delay = 0.01 / modes.omegaSlow;
  for (double eps : {1e-5, 1e-8, 1e-11, 1e-14}) {
    const State start = (1 + eps) * glom1.at(delay);
    ASSERT_LT(start.u2, model.gap);
    const auto contact = testing::PhysicalFlight(model, start).nextContact(kInfinity);
    const auto march = testing::PhysicalFlight(model, start, true).nextContact(modes.T2);
    ASSERT_EQ(contact.kind, ContactKind::Crossing) << eps;
    ASSERT_EQ(march.kind, ContactKind::Crossing) << eps;
    EXPECT_NEAR(contact.time, march.time, 1e-11 * modes.T2) << eps;
    // the crossing lies sqrt(2 eps) / 2 before the peak (in slow phase), to leading order
    const double peak = modes.T2 / 2 - delay;
    EXPECT_NEAR((peak - contact.time) * modes.omegaSlow / std::sqrt(2 * eps), 0.5, 0.05) << eps;
  }
}

TEST(Contact, NearGrazingReturnIsResolvedToRelativePrecision) {
  // GLO_0.5 data with v2 = -eps: it hits at T2 - s*, s* = -2 v2 / acc2 (1 + O(eps)), arriving
  // with exactly the speed it left with; plain evaluation of u2 - gap would call it a grazing
  const Model model = testing::resonantChain(0.5);
  const Modes modes = computeModes(model);
  for (double eps : {1e-4, 1e-8, 1e-12, 1e-16, 1e-30, 1e-100, 1e-300}) {
    State start = gloData(model, modes, 0.5);
    start.v2 = -eps;
    const testing::PhysicalFlight flight(model, start);
    const auto contact = flight.nextContact(kInfinity);
    ASSERT_EQ(contact.kind, ContactKind::Crossing) << eps;
    ASSERT_TRUE(contact.fromReturn) << eps;
    const double acc2 = model.k2 * (start.u1 - model.gap) / model.m2;
    const double predicted = -2 * start.v2 / acc2;
    EXPECT_NEAR(contact.offsetFromT2 / predicted, 1.0, eps < 1e-6 ? 1e-10 : 1e-2) << eps;
    EXPECT_NEAR(flight.at(contact).v2 / eps, 1.0, eps < 1e-6 ? 1e-10 : 1e-6) << eps;
  }
}

TEST(Contact, GrazingOrbitsTouchOnceAtT2) {
  const Model model = testing::resonantChain(0.5);
  const Modes modes = computeModes(model);
  for (double lambda : {0.01, 0.25, 0.5, 1.0, 1.2, 4.0 / 3.0}) {
    const testing::PhysicalFlight flight(model, gloData(model, modes, lambda));
    const auto contact = flight.nextContact(kInfinity);
    EXPECT_EQ(contact.kind, ContactKind::Tangent) << lambda;
    EXPECT_EQ(contact.time, modes.T2) << lambda;
  }
  // GLOM1 alone touches twice per slow period: at T1 = T2 / 2
  const testing::PhysicalFlight fast(model, gloData(model, modes, 0.0));
  const auto contact = fast.nextContact(kInfinity);
  EXPECT_EQ(contact.kind, ContactKind::Tangent);
  EXPECT_NEAR(contact.time, modes.T1, 1e-12 * modes.T2);
}

TEST(Contact, NegativeLambdaCrossesBeforeTheReturn) {
  const Model model = testing::resonantChain(0.5);
  const Modes modes = computeModes(model);
  const testing::PhysicalFlight flight(model, gloData(model, modes, -0.3));
  const auto contact = flight.nextContact(kInfinity);
  EXPECT_EQ(contact.kind, ContactKind::Crossing);
  EXPECT_LT(contact.time, modes.T2);
  EXPECT_GT(flight.at(contact).v2, 0);
}

TEST(Contact, SmallMotionBelowTheStopNeverArrives) {
  const Model model = testing::resonantChain(0.5);
  const testing::PhysicalFlight flight(model, {0.1, 0.2, 0.0, 0.1});
  EXPECT_EQ(flight.nextContact(kInfinity).kind, ContactKind::None);
  const Model detuned = testing::detunedChain();
  const testing::PhysicalFlight detunedFlight(detuned, {0.1, 0.2, 0.0, 0.1});
  EXPECT_EQ(detunedFlight.nextContact(50.0).kind, ContactKind::None);
}

}  // namespace
}  // namespace grazelab::core
