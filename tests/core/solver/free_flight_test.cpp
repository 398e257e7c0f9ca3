// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/solver/free_flight.cpp: the closed form against an ODE integration, the two
// evaluations against each other, and the exact periodicity of resonant flights.
#include "core/solver/free_flight.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/cases.h"
#include "support/physical_flight.h"

namespace grazelab::core {
namespace {

// classical RK4 on M u'' + K u = 0, independent of the modal solution
State integrate(const Model& model, State state, double t, int steps) {
  auto rate = [&](const Eigen::Vector4d& y) {
    const double a1 = (-(model.k1 + model.k2) * y(0) + model.k2 * y(1)) / model.m1;
    const double a2 = (model.k2 * y(0) - model.k2 * y(1)) / model.m2;
    return Eigen::Vector4d(y(2), y(3), a1, a2);
  };
  Eigen::Vector4d y(state.u1, state.u2, state.v1, state.v2);
  const double h = t / steps;
  for (int i = 0; i < steps; ++i) {
    const Eigen::Vector4d k1 = rate(y);
    const Eigen::Vector4d k2 = rate(y + 0.5 * h * k1);
    const Eigen::Vector4d k3 = rate(y + 0.5 * h * k2);
    const Eigen::Vector4d k4 = rate(y + h * k3);
    y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return {y(0), y(1), y(2), y(3)};
}

// largest difference, positions relative to `length`, velocities to `length * omega`
double distance(const State& a, const State& b, double omega, double length = 1.0) {
  const double velocity = omega * length;
  return std::max({std::abs(a.u1 - b.u1) / length, std::abs(a.u2 - b.u2) / length,
                   std::abs(a.v1 - b.v1) / velocity, std::abs(a.v2 - b.v2) / velocity});
}

TEST(FreeFlight, MatchesAnOdeIntegration) {
  for (const Model& model : {testing::resonantChain(0.5), testing::detunedChain()}) {
    const Modes modes = computeModes(model);
    const State start{0.3, -0.7, 0.4, 0.9};
    const testing::PhysicalFlight flight(model, start);
    for (double fraction : {0.01, 0.3, 0.77, 1.0, 2.6}) {
      const double t = fraction * modes.T2;
      const State exact = flight.at(t);
      const State numeric = integrate(model, start, t, 40000);
      EXPECT_LT(distance(exact, numeric, modes.omegaSlow), 1e-10) << "t = " << t;
    }
  }
}

TEST(FreeFlight, TaylorAndModalFormsAgreeAtTheSwitch) {
  const Model model = testing::resonantChain(0.5);
  const Modes modes = computeModes(model);
  const testing::PhysicalFlight flight(model, {0.3, -0.7, 0.4, 0.9});
  const double edge = flight.taylorRadius();
  const State inside = flight.at(std::nextafter(edge, 0.0));
  const State outside = flight.at(std::nextafter(edge, 1.0));
  EXPECT_LT(distance(inside, outside, modes.omegaFast), 1e-14);
}

TEST(FreeFlight, ResonantFlightRepeatsExactlyAfterT2) {
  for (const auto& chain : testing::resonantChains()) {
    const Model& model = chain.model;
    const Modes modes = computeModes(model);
    const State start = model.gap * State{0.3, -0.7, 0.4, -0.2};
    const testing::PhysicalFlight flight(model, start);
    // one slow period on, in scaled time (2 pi exactly): the same state
    const State back = flight.scaled().at(FlightTime<double>{1, 0.0});
    EXPECT_LT(distance(back, flight.scaled().start(), 1.0), 1e-15);
    EXPECT_LT(distance(flight.at(0.3 * modes.T2), flight.at(7.3 * modes.T2), modes.omegaSlow,
                       model.gap),
              1e-13)
        << chain.name;
  }
}

// the display samples' rotation against the exact evaluation at every sample: a wrong turn
// direction, a lost cos - 1 term or a stale restart shows at once; resonant and detuned chains,
// a flight from the stop (the Taylor window) and one over several slow periods
TEST(FreeFlight, GridSamplesAgreeWithTheExactStates) {
  for (const Model& model : {testing::resonantChain(0.5), testing::resonantChain(0.2),
                             testing::detunedChain()}) {
    for (const State& start : {State{0.3, -0.7, 0.4, 0.9}, State{0.2, model.gap, 0.0, -0.4}}) {
      const testing::PhysicalFlight flight(model, start);
      const Flight<double>& scaled = flight.scaled();
      const double size = std::max({std::abs(scaled.start().u1), std::abs(scaled.start().u2),
                                    std::abs(scaled.start().v1), std::abs(scaled.start().v2)});
      for (const double step : {0.0131, 2 * M_PI / 96, 0.7}) {
        const double first = -0.05;
        // more than two slow periods
        std::vector<BasicState<double>> grid(std::size_t(4 * M_PI / step) + 20);
        scaled.statesOnGrid(first, step, grid);
        for (std::size_t k = 0; k < grid.size(); ++k) {
          const double s = first + double(k) * step;
          const BasicState<double> exact = scaled.at(FlightTime<double>::nearest(s));
          // a detuned flight's phase carries the rounding of s itself
          const double bound = flight.chain().resonant ? 2e-14 : 2e-14 + 4e-16 * s;
          ASSERT_LT(distance(grid[k], exact, 1.0, size), bound) << "step " << step << ", s " << s;
        }
      }
    }
  }
}

TEST(FreeFlight, GapFunctionIsTheStatesU2MinusTheGap) {
  const Model model = testing::resonantChain(0.5);
  const testing::PhysicalFlight flight(model, {-0.25, 1.0, 0.1, -0.3});
  for (double t : {1e-9, 0.1, 1.0, 4.0, 8.0}) {
    const auto [gap, rate] = flight.gapAndRate(t);
    const State state = flight.at(t);
    EXPECT_NEAR(gap, state.u2 - model.gap, 1e-15);
    EXPECT_NEAR(rate, state.v2, 1e-15);
  }
}

TEST(FreeFlight, ReducedGapRemovesTheZeroAtTheStart) {
  const Model model = testing::resonantChain(0.5);
  // leaving the stop with v2 < 0: simple zero; at rest with u1 < gap: double zero
  const testing::PhysicalFlight leaving(model, {-0.25, 1.0, 0.0, -0.3});
  const testing::PhysicalFlight resting(model, {-0.25, 1.0, 0.0, 0.0});
  EXPECT_EQ(leaving.contactOrder(), 1);
  EXPECT_EQ(resting.contactOrder(), 2);
  for (double x : {1e-12, 1e-3, 0.2, 0.9, 3.0, -2.0}) {
    EXPECT_NEAR(leaving.reducedGapAndRate(x, 1).first * x, leaving.gap(x), 1e-15 + 1e-14 * std::abs(x));
    EXPECT_NEAR(resting.reducedGapAndRate(x, 2).first * x * x, resting.gap(x),
                1e-15 + 1e-14 * x * x);
  }
  // g(0) is the first nonzero derivative over its factorial: v2, then acc2 / 2
  EXPECT_NEAR(leaving.reducedGapAndRate(0.0, 1).first, -0.3, 1e-15);
  const double halfAcceleration = 0.5 * model.k2 * (-0.25 - 1.0) / model.m2;
  EXPECT_NEAR(resting.reducedGapAndRate(0.0, 2).first, halfAcceleration,
              1e-15 * std::abs(halfAcceleration));
}

TEST(FreeFlight, TinyDepartureSpeedKeepsFullRelativePrecision) {
  // the leading Taylor coefficient is v2 itself: a speed 1e-200 is not lost in the modal sum
  const Model model = testing::resonantChain(0.5);
  const testing::PhysicalFlight flight(model, {-0.25, 1.0, 0.0, -1e-200});
  const double s = 1e-201;
  const double expected = -1e-200 * s + 0.5 * model.k2 * (-1.25) / model.m2 * s * s;
  EXPECT_NEAR(flight.gap(s), expected, 1e-15 * std::abs(expected));
}

}  // namespace
}  // namespace grazelab::core
