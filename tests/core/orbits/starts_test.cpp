// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/orbits/starts.cpp's starts chosen with the mouse: on two masses the chain's
// section start is the two-mass one, on N masses it keeps the energy and the coordinates given,
// and what cannot be a start is said (a coordinate H fixes, an energy too low).
#include "core/orbits/starts.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/model/chain_design.h"
#include "core/solver/chain_run.h"

namespace grazelab::core {
namespace {

TEST(Starts, ATwoMassSectionStartIsTheChainsOfTwo) {
  const Model model = *designedModel(1.0, 0.5, 1.0, 1.0, Branch::Upper);
  const MassChain chain{{model.m1, model.m2}, {model.k1, model.k2}, 0.0, 2, model.gap};
  const State shown{0.1, model.gap, 0.2, -1.0};
  const double level = energy(model, shown);
  for (const auto& [u1, v1] : {std::pair{0.0, 0.0}, std::pair{-0.1, 0.25}, std::pair{0.2, -0.4}}) {
    const std::optional<State> two = sectionStateAtEnergy(model, level, u1, v1);
    const ChainSectionStart many = chainSectionStateAtEnergy(chain, level, chainStateOf(shown), 0, u1, 2, v1);
    ASSERT_TRUE(two);
    ASSERT_EQ(many.problem, ChainSectionProblem::None);
    const State back = twoMassStateOf(many.state);
    EXPECT_EQ(back.u1, two->u1);
    EXPECT_EQ(back.u2, two->u2);
    EXPECT_EQ(back.v1, two->v1);
    EXPECT_NEAR(back.v2, two->v2, 1e-14);  // (the energies summed in another order)
  }
}

TEST(Starts, AnNMassSectionStartKeepsTheEnergyAndSaysWhatCannotBe) {
  MassChain chain;
  chain.masses = {1.0, 0.2, 0.05, 0.7};
  chain.springs = {1.0, 0.8, 0.3, 0.5};
  chain.stopMass = 3;
  ChainState base{ChainVector<double>(4), ChainVector<double>(4)};
  base.u << 0.2, 0.5, 1.0, 0.4;
  base.v << 0.1, -0.2, -0.3, 0.05;
  const double level = chainEnergy(chain, base);
  // (u1, v4) chosen: the others as given, mass 3 on the stop leaving it, the energy kept
  const ChainSectionStart start = chainSectionStateAtEnergy(chain, level, base, 0, 0.25, 7, -0.02);
  ASSERT_EQ(start.problem, ChainSectionProblem::None);
  EXPECT_EQ(start.state.u[0], 0.25);
  EXPECT_EQ(start.state.v[3], -0.02);
  EXPECT_EQ(start.state.u[1], base.u[1]);
  EXPECT_EQ(start.state.v[1], base.v[1]);
  EXPECT_EQ(start.state.u[2], chain.gap);
  EXPECT_LT(start.state.v[2], 0);
  EXPECT_NEAR(chainEnergy(chain, start.state), level, 1e-14 * level);
  // the stopped mass's own coordinates are H's and the energy's
  EXPECT_EQ(chainSectionStateAtEnergy(chain, level, base, 2, 1.0, 4, 0.0).problem,
            ChainSectionProblem::StoppedMassCoordinate);
  EXPECT_EQ(chainSectionStateAtEnergy(chain, level, base, 0, 0.0, 6, 0.0).problem,
            ChainSectionProblem::StoppedMassCoordinate);
  // a displacement the springs alone hold more than the energy for
  EXPECT_EQ(chainSectionStateAtEnergy(chain, level, base, 0, 50.0, 4, 0.0).problem, ChainSectionProblem::EnergyTooLow);
  // the stop line: mass 3 on the stop leaving at the speed given, whatever its sign
  const ChainState line = chainStopLineState(chain, base, 0.7);
  EXPECT_EQ(line.u[2], chain.gap);
  EXPECT_EQ(line.v[2], -0.7);
  EXPECT_EQ(chainStopLineState(chain, base, -0.7).v[2], -0.7);
  EXPECT_EQ(line.u[0], base.u[0]);
}

}  // namespace
}  // namespace grazelab::core
