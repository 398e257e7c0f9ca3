// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/resonance.cpp.
#include "core/model/resonance.h"

#include "core/model/two_mass_form.h"
#include "core/orbits/starts.h"

#include <gtest/gtest.h>

#include <cmath>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "core/model/linear_modes.h"

namespace grazelab::core {
namespace {

TEST(Resonance, HalfMassGivesTheKnownStiffnesses) {
  EXPECT_NEAR(*resonantK2(1, 0.5, 1, Branch::Upper), 0.5, 1e-15);
  EXPECT_NEAR(*resonantK2(1, 0.5, 1, Branch::Lower), 2.0 / 9.0, 1e-15);
}

TEST(Resonance, StiffnessScalesWithK1AndDependsOnlyOnTheMassRatio) {
  EXPECT_NEAR(*resonantK2(3, 1.5, 7, Branch::Upper), 3.5, 1e-14);
  EXPECT_NEAR(*resonantK2(3, 1.5, 7, Branch::Lower), 7 * 2.0 / 9.0, 1e-14);
}

TEST(Resonance, BranchesMergeAtNineSixteenths) {
  const double upper = *resonantK2(1, 9.0 / 16.0, 1, Branch::Upper);
  const double lower = *resonantK2(1, 9.0 / 16.0, 1, Branch::Lower);
  EXPECT_NEAR(upper, 0.36, 1e-15);
  EXPECT_NEAR(lower, 0.36, 1e-15);
  const Modes modes = computeModes({1, 9.0 / 16.0, 1, upper, 1, {}});
  EXPECT_NEAR(modes.omegaFast * modes.omegaFast, 1.6, 1e-13);
  EXPECT_NEAR(modes.omegaSlow * modes.omegaSlow, 0.4, 1e-13);
}

TEST(Resonance, NoChainBeyondNineSixteenths) {
  EXPECT_FALSE(resonantK2(1, std::nextafter(9.0 / 16.0, 1.0), 1, Branch::Upper));
  EXPECT_FALSE(resonantK2(1, 0.6, 1, Branch::Lower));
  EXPECT_FALSE(resonantK2(1, 5, 1, Branch::Upper));
}

TEST(Resonance, BadInputGivesNothing) {
  EXPECT_FALSE(resonantK2(0, 0.5, 1, Branch::Upper));
  EXPECT_FALSE(resonantK2(1, -0.5, 1, Branch::Upper));
  EXPECT_FALSE(resonantK2(1, std::nan(""), 1, Branch::Upper));
  EXPECT_FALSE(resonantK2(1, 0.5, INFINITY, Branch::Upper));
}

TEST(Resonance, EveryFeasibleRatioGivesOneToTwoOnBothBranches) {
  for (double beta = 1e-6; beta <= 9.0 / 16.0; beta *= 1.37) {
    for (Branch branch : {Branch::Upper, Branch::Lower}) {
      // the design chain is exactly resonant...
      const Model designed = *designedModel(1.0, beta, 1.0, 1.0, branch);
      EXPECT_TRUE(computeModes(designed).resonant) << "beta " << beta << " " << toString(branch);
      // ...while its k2 rounded to double and given as such is a chain detuned by rounding,
      // solved as what it is (issue 7, class 3); the detuning is exact to relative precision
      Model given = designed;
      given.design.reset();
      const Modes modes = computeModes(given);
      const TwoMassForm<long double> wide = *makeTwoMassForm(convertModel<long double>(given)).chain;
      if (!modes.resonant) {
        EXPECT_LT(std::abs(modes.detuning), 1e-13) << "beta " << beta;
        EXPECT_NEAR(modes.detuning / double(wide.detuning), 1.0, 1e-12) << "beta " << beta;
      }
    }
  }
}

// The detuned-contrast scene's chains: the asked frequency ratio, and the 1:2 design at 2.
TEST(Resonance, StiffnessForAFrequencyRatioGivesThatRatio) {
  for (const double beta : {0.05, 0.3, 0.5, 0.5625}) {
    for (const Branch branch : {Branch::Upper, Branch::Lower}) {
      const auto designed = resonantK2(1.0, beta, 1.0, branch);
      const auto atTwo = k2ForFrequencyRatio(1.0, beta, 1.0, 2.0, branch);
      ASSERT_TRUE(designed && atTwo);
      EXPECT_NEAR(*atTwo, *designed, 1e-12 * *designed) << beta;
      for (const double ratio : {1.9, 1.97, 2.03, 2.2, 3.0}) {
        const auto k2 = k2ForFrequencyRatio(2.0, 2.0 * beta, 3.0, ratio, branch);
        if (!k2) continue;  // this mass ratio reaches no such frequency ratio
        const Modes modes = computeModes(Model{2.0, 2.0 * beta, 3.0, *k2, 1.0, std::nullopt});
        EXPECT_NEAR(modes.omegaFast / modes.omegaSlow, ratio, 1e-12) << beta << " " << ratio;
      }
    }
  }
  EXPECT_FALSE(k2ForFrequencyRatio(1.0, 0.5, 1.0, 1.0, Branch::Upper));
  EXPECT_FALSE(k2ForFrequencyRatio(1.0, -0.5, 1.0, 2.0, Branch::Upper));
  // 1 + beta small: a ratio below ~ the chain's least reachable one has no stiffness
  EXPECT_FALSE(k2ForFrequencyRatio(1.0, 0.5625, 1.0, 1.5, Branch::Upper));
}

TEST(Resonance, TheDefectIsBinary128sRoundingOfTheExactValue) {
  // the defect comes from exact rationals, rounded once: checked against 400-bit arithmetic on
  // the same binary128 inputs (a chunked rounding counted some bits twice: 7e-30 off, and every
  // detuned binary128 run lost four digits)
  using Wide = boost::multiprecision::number<
      boost::multiprecision::cpp_bin_float<400, boost::multiprecision::digit_base_2>>;
  for (const char* text : {"0.37", "0.1", "1e-3", "0.4999", "3.7"}) {
    const Quad k2 = parseScalar<Quad>(text).value.value();
    const Quad beta = Quad(0.5);
    const Wide b(beta), k(k2);
    const Wide exact = (4 * (1 + b) * (1 + b) * k * k - b * (17 - 8 * b) * k + 4 * b * b) / (b * b);
    const Quad defect = resonanceDefect(Quad(1), beta, Quad(1), k2);
    const Wide error = abs(Wide(defect) - exact) / abs(exact);
    EXPECT_LE(error.convert_to<double>(), std::numeric_limits<Quad>::epsilon().convert_to<double>())
        << text;
  }
}

TEST(Resonance, BranchNamesRoundTrip) {
  EXPECT_EQ(parseBranch(toString(Branch::Upper)), Branch::Upper);
  EXPECT_EQ(parseBranch(toString(Branch::Lower)), Branch::Lower);
  EXPECT_FALSE(parseBranch("middle"));
}

}  // namespace
}  // namespace grazelab::core
