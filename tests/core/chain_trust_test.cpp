// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/solver/chain_trust.cpp: the error estimate of an N-mass run. A short run agrees
// with its shadow ("ok"); a long chaotic one passes its horizon ("unreliable"), and the horizon
// means what it says: the run's events agree with a binary128 run of the same start to 1e-6 of
// their scales before it, not after; the same run gets the same estimate; off is unchecked.
#include "core/solver/chain_trust.h"

#include <gtest/gtest.h>

#include <cmath>

namespace grazelab::core {
namespace {

MassChain threeMasses() { return MassChain{{1.0, 0.7, 0.4}, {1.0, 0.8, 0.6}, 0, 2, 1.0}; }

ChainState pressedStart() {
  return {Eigen::Vector3d(1.4, 1.0, 1.3), Eigen::Vector3d(0.1, 0.0, -0.2)};
}

TEST(ChainTrust, AShortRunAgreesWithItsShadow) {
  const MassChain chain = threeMasses();
  const ChainRun run = runChain(chain, pressedStart(), 6);
  const Trust trust = chainTrust(chain, pressedStart(), run, 6, 0.0, TrustMode::Auto);
  EXPECT_EQ(trust.verdict, Verdict::Ok) << trust.reason;
  EXPECT_LT(trust.stateError, 1e-9);
  EXPECT_GT(trust.horizon, run.tFinal);
  EXPECT_FALSE(trust.horizonObserved);
  EXPECT_EQ(chainTrust(chain, pressedStart(), run, 6, 0.0, TrustMode::Off).verdict, Verdict::Unchecked);
}

TEST(ChainTrust, TheHorizonOfAChaoticRunIsWhereItPartsFromBinary128) {
  const MassChain chain = threeMasses();
  const ChainRun run = runChain(chain, pressedStart(), 100);
  const Trust trust = chainTrust(chain, pressedStart(), run, 100, 0.0, TrustMode::Full);
  ASSERT_EQ(trust.verdict, Verdict::Unreliable) << trust.reason;
  EXPECT_TRUE(trust.horizonObserved);
  EXPECT_LT(trust.horizon, run.tFinal);
  const Trust again = chainTrust(chain, pressedStart(), run, 100, 0.0, TrustMode::Full);
  EXPECT_EQ(again.horizon, trust.horizon);
  EXPECT_EQ(again.stateError, trust.stateError);
  // against binary128: within 1e-6 of the scales up to a little before the horizon, not by the end
  const BasicChainRun<Quad> exact =
      runChain(chain, BasicChainState<Quad>{pressedStart().u.cast<Quad>(), pressedStart().v.cast<Quad>()}, 100);
  double before = 0, after = 0;
  for (std::size_t k = 0; k < std::min(run.events.size(), exact.events.size()); ++k) {
    const double t = run.events[k].t;
    double error = 0;
    for (Eigen::Index i = 0; i < 3; ++i) {
      error = std::max(error, std::abs(run.events[k].u[i] - double(exact.events[k].u[i])));
    }
    (t < 0.9 * trust.horizon ? before : after) = std::max(t < 0.9 * trust.horizon ? before : after, error);
  }
  EXPECT_LT(before, 1e-5);
  EXPECT_GT(after, 1e-6);
}

}  // namespace
}  // namespace grazelab::core
