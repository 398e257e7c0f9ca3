// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/model.cpp.
#include "core/model/model.h"

#include "core/model/two_mass_form.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace grazelab::core {
namespace {

TEST(Model, DefaultIsValid) { EXPECT_TRUE(validate(Model{}).empty()); }

TEST(Model, EveryBadParameterIsNamedWithItsReason) {
  const double bad[] = {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()};
  double Model::*fields[] = {&Model::m1, &Model::m2, &Model::k1, &Model::k2, &Model::gap};
  const char* names[] = {"m1", "m2", "k1", "k2", "gap"};
  for (int f = 0; f < 5; ++f) {
    for (double value : bad) {
      Model model;
      model.*fields[f] = value;
      const auto problems = validate(model);
      ASSERT_EQ(problems.size(), 1u) << names[f] << " = " << value;
      EXPECT_EQ(problems[0].field, names[f]);
      const bool finite = std::isfinite(value);
      EXPECT_NE(problems[0].reason.find(finite ? "positive" : "finite"), std::string::npos)
          << problems[0].reason;
    }
  }
}

TEST(Model, DescribeJoinsProblemsOnOneLine) {
  Model model;
  model.m1 = 0;
  model.gap = -2;
  const std::string line = describe(validate(model));
  EXPECT_NE(line.find("m1 must be positive"), std::string::npos) << line;
  EXPECT_NE(line.find("gap must be positive"), std::string::npos) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos);
}

TEST(Model, StatePastTheStopIsRejected) {
  const Model model;
  EXPECT_TRUE(validateState(model, {0, model.gap, 0, 0}, "initial").empty());
  const auto problems = validateState(model, {0, std::nextafter(model.gap, 2.0), 0, 0}, "initial");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].field, "initial.u2");
  EXPECT_NE(problems[0].reason.find("past the stop"), std::string::npos);
  EXPECT_EQ(validateState(model, {std::nan(""), 0, 0, 0}, "s").at(0).field, "s.u1");
}

TEST(Model, EnergyMatchesTheQuadraticForms) {
  const Model model{1.3, 0.4, 2.1, 0.7, 1.0, {}};
  const State state{0.3, -0.8, 1.1, -0.25};
  Eigen::Matrix2d mass;
  mass << model.m1, 0, 0, model.m2;
  Eigen::Matrix2d stiffness;
  stiffness << model.k1 + model.k2, -model.k2, -model.k2, model.k2;
  const Eigen::Vector2d u(state.u1, state.u2);
  const Eigen::Vector2d v(state.v1, state.v2);
  const double expected = 0.5 * v.dot(mass * v) + 0.5 * u.dot(stiffness * u);
  EXPECT_NEAR(energy(model, state), expected, 1e-15 * expected);
}

// a state at infinity (the 1IPP data where g2(T) = 0) has infinite energy, one with a NaN a NaN
// energy: not the overflow of a scale taken from ilogb's sentinels (UBSan saw 2 * INT_MAX)
TEST(Model, EnergyOfAStateNotFiniteIsNotFinite) {
  const Model model{1.3, 0.4, 2.1, 0.7, 1.0, {}};
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(energy(model, State{0.3, 1.0, 0, -inf}), inf);
  EXPECT_EQ(energy(model, State{-inf, 1.0, 0, 0}), inf);
  EXPECT_TRUE(std::isnan(energy(model, State{std::nan(""), 1.0, 0, 0})));
  const TwoMassForm<long double> chain = *makeTwoMassForm(convertModel<long double>(model)).chain;
  EXPECT_EQ(physicalEnergy(chain, BasicState<long double>{0, 1, 0, -INFINITY}), INFINITY);
}

}  // namespace
}  // namespace grazelab::core
