// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/modes.cpp.
#include "core/model/linear_modes.h"

#include <gtest/gtest.h>

#include <numbers>

#include "support/cases.h"

namespace grazelab::core {
namespace {

class ModesOf : public ::testing::TestWithParam<testing::Chain> {};

TEST_P(ModesOf, AreMassOrthonormalAndDiagonaliseTheStiffness) {
  const Model& model = GetParam().model;
  const Modes modes = computeModes(model);
  Eigen::Matrix2d mass;
  mass << model.m1, 0, 0, model.m2;
  Eigen::Matrix2d stiffness;
  stiffness << model.k1 + model.k2, -model.k2, -model.k2, model.k2;

  const Eigen::Matrix2d identity = modes.P.transpose() * mass * modes.P;
  EXPECT_LT((identity - Eigen::Matrix2d::Identity()).norm(), 1e-13);
  const Eigen::Matrix2d diagonal = modes.P.transpose() * stiffness * modes.P;
  const double scale = modes.omegaFast * modes.omegaFast;
  EXPECT_NEAR(diagonal(0, 0), modes.omegaFast * modes.omegaFast, 1e-12 * scale);
  EXPECT_NEAR(diagonal(1, 1), modes.omegaSlow * modes.omegaSlow, 1e-12 * scale);
  EXPECT_NEAR(diagonal(0, 1), 0.0, 1e-12 * scale);
  EXPECT_LT((modes.Pinv * modes.P - Eigen::Matrix2d::Identity()).norm(), 1e-13);
}

TEST_P(ModesOf, AreLabelledFastFirstWithMass2RowPositive) {
  const Modes modes = computeModes(GetParam().model);
  EXPECT_GT(modes.omegaFast, modes.omegaSlow);
  EXPECT_GT(modes.P(1, 0), 0);
  EXPECT_GT(modes.P(1, 1), 0);
  EXPECT_TRUE(modes.resonant);
  EXPECT_EQ(modes.omegaFast, 2 * modes.omegaSlow);
  EXPECT_EQ(modes.T2, 2 * std::numbers::pi / modes.omegaSlow);
  EXPECT_NEAR(modes.T2, 2 * modes.T1, 1e-15 * modes.T2);
}

INSTANTIATE_TEST_SUITE_P(Chains, ModesOf, ::testing::ValuesIn(testing::resonantChains()),
                         [](const auto& info) { return info.param.name; });

TEST(Modes, ClosedFormsForHalfMass) {
  // m1 = k1 = 1, m2 = 1/2: upper k2 = 1/2 gives w^2 = {2, 1/2}; lower k2 = 2/9 gives {4/3, 1/3}
  const Modes upper = computeModes({1, 0.5, 1, 0.5, 1, {}});
  EXPECT_NEAR(upper.omegaFast * upper.omegaFast, 2.0, 1e-14);
  EXPECT_NEAR(upper.omegaSlow * upper.omegaSlow, 0.5, 1e-14);
  const Modes lower = computeModes({1, 0.5, 1, 2.0 / 9.0, 1, {}});
  EXPECT_NEAR(lower.omegaFast * lower.omegaFast, 4.0 / 3.0, 1e-14);
  EXPECT_NEAR(lower.omegaSlow * lower.omegaSlow, 1.0 / 3.0, 1e-14);
  // the upper-branch shapes: fast (-1, 1)/sqrt(1.5) in mass-1 units, slow (1, 2)/sqrt(3)
  EXPECT_NEAR(upper.P(0, 0) / upper.P(1, 0), -1.0, 1e-14);
  EXPECT_NEAR(upper.P(0, 1) / upper.P(1, 1), 0.5, 1e-14);
}

TEST(Modes, DetunedChainIsNotSnapped) {
  const Modes modes = computeModes(testing::detunedChain());
  EXPECT_FALSE(modes.resonant);
  EXPECT_GT(std::abs(modes.detuning), 1e-3);
  EXPECT_NE(modes.omegaFast, 2 * modes.omegaSlow);
}

}  // namespace
}  // namespace grazelab::core
