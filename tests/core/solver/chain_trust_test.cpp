// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/solver/chain_trust.cpp: the error estimate of an N-mass run. A short run agrees
// with its shadow ("ok"); a long chaotic one passes its horizon ("unreliable"), and the horizon
// means what it says: the run's events agree with a binary128 run of the same start to 1e-6 of
// their scales before it, not after; the same run gets the same estimate; off is unchecked.
#include "core/solver/chain_trust.h"

#include "core/model/chain_design.h"
#include "core/orbits/chain_glo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

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
      runChain(chainCast<Quad>(chain), BasicChainState<Quad>{pressedStart().u.cast<Quad>(), pressedStart().v.cast<Quad>()}, 100);
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

// auto shadows a long run's first contacts only (a number fixed by the precision), full all of
// them; both agree on a periodic run, and auto's horizon stays within twice the time it compared
TEST(ChainTrust, ARunThatCannotDecideItsFirstContactIsNotConfirmed) {
  // four masses stopped on the second, on the grazing orbit of their slowest mode pushed off the
  // stop by 1.8e-16 (1e-15 d w_4): its top comes back within rounding of the stop each period,
  // which binary128 finds to be impacts. Double once decided grazings there and read "ok" (its
  // shadow in long double, undecided at once, compared nothing); it now stops undecided at the
  // first such return, at that flight's start, having claimed nothing past it
  MassChain chain;
  chain.masses = {1.0, 0.6, 1.4, 0.9};
  chain.springs = {1.0, 2.0, 0.8, 1.1};
  chain.stopMass = 2;
  chain.gap = 0.5;
  ChainState start = chainGloStart(chain, {0, 0, 0, 1}).state;
  start.v[1] -= 1e-15 * chain.gap * chainModes(chain).omega.minCoeff();
  const ChainRun run = runChain(chain, start, 100000, 346.0);
  EXPECT_EQ(run.stop, StopReason::Undecided);
  EXPECT_EQ(run.events.size(), 0u);
  EXPECT_EQ(run.tFinal, 0.0);
  EXPECT_EQ(run.final.v, start.v);
  // and binary128 decides impacts
  const BasicChainRun<Quad> exact =
      runChain(chainCast<Quad>(chain), BasicChainState<Quad>{start.u.cast<Quad>(), start.v.cast<Quad>()}, 100000, Quad(346));
  EXPECT_EQ(exact.stop, StopReason::TimeLimit);
  EXPECT_GT(exact.impacts, 0);
  EXPECT_EQ(exact.grazings, 0);
}

TEST(ChainTrust, AGrazingOrbitMeetsTheStopAtRestAndIsOk) {
  // GLO_lambda of a designed chain grazes at every period T, exactly: its velocities at the
  // events are zero but for rounding, and were the scale the shadow's differences were measured
  // against, so the estimate read "unreliable" (by 1e14) on an exactly periodic orbit. The speed
  // the energy allows is the scale at least: ok, to the precision's rounding
  for (const auto& [masses, ratios] : {std::pair{std::vector<double>{1.0, 0.2, 0.05}, std::vector<int>{3, 2, 1}},
                                       std::pair{std::vector<double>{1.0, 0.6, 0.36, 0.216}, std::vector<int>{4, 3, 2, 1}}}) {
    const ChainDesigns designs = designSprings(masses, 1.0, ratios);
    ASSERT_FALSE(designs.designs.empty());
    const MassChain chain{masses, designs.designs.front().springs, 0, 0, 0.7};
    std::vector<double> weights(masses.size(), 0.0);
    weights.front() = 0.5;
    weights[1] = 0.5;  // harmonics n_1, n_2 with no common factor: the first return is at T
    for (std::vector<double> w : {weights, std::vector<double>(masses.size(), 1.0 / double(masses.size()))}) {
      const ChainState start = chainGloStart(chain, w).state;
      const ChainRun run = runChain(chain, start, 20);
      ASSERT_EQ(run.grazings, 20) << int(run.stop);
      const Trust trust = chainTrust(chain, start, run, 20, 0.0, TrustMode::Full);
      EXPECT_EQ(trust.verdict, Verdict::Ok) << masses.size() << " masses: " << trust.reason;
      EXPECT_LT(trust.stateError, 1e-12) << trust.reason;
    }
  }
}

TEST(ChainTrust, AStiffLightMassIsJudgedAtAGivenTimeNotOnlyAtItsEvents) {
  // the designed 3:2:1 chain with its stopped mass a million times lighter (springs as designed),
  // from its grazing orbit: the light mass hits the stop thousands of times at speeds of ~1e3. At
  // each event u_s = d exactly and the contact times agree to 1e-11 of the slowest period, so
  // event by event the shadow agreed to 2.6e-9, while the state at the end time was off by 2e-7
  // (an event time error dt moves a mass at speed V by V dt). The estimate must be the error of
  // the state at a given time: here within a factor 3 of the true one, binary128's
  const std::vector<double> masses{1.0, 0.2, 0.05};
  const ChainDesigns designs = designSprings(masses, 1.0, {3, 2, 1});
  ASSERT_FALSE(designs.designs.empty());
  const MassChain designed{masses, designs.designs.front().springs, 0, 0, 1.0};
  const ChainState start = chainGloStart(designed, {0.5, 0.5, 0.0}).state;
  MassChain light = designed;
  light.masses.back() *= 1e-6;
  const double tEnd = 40;
  const ChainRun run = runChain(light, start, 1000000, tEnd);
  ASSERT_EQ(run.stop, StopReason::TimeLimit);
  ASSERT_GT(run.impacts, 1000);
  const Trust trust = chainTrust(light, start, run, 1000000, tEnd, TrustMode::Full);
  const BasicChainRun<Quad> exact = runChain(chainCast<Quad>(light),
                                             BasicChainState<Quad>{start.u.cast<Quad>(), start.v.cast<Quad>()},
                                             1000000, Quad(tEnd));
  ASSERT_EQ(exact.stop, StopReason::TimeLimit);
  double actual = 0;
  for (Eigen::Index i = 0; i < 3; ++i) {
    actual = std::max(actual, std::abs(run.final.u[i] - double(exact.final.u[i])) / light.gap);
  }
  EXPECT_GT(actual, 1e-12);  // the case is one where double's rounding shows
  EXPECT_GE(trust.stateError, actual / 3) << trust.reason;
  EXPECT_LE(trust.stateError, actual * 100) << trust.reason;
}

TEST(ChainTrust, AutoShadowsTheFirstContactsOfALongRun) {
  // one mass bouncing on its stop: periodic, its errors grow slowly
  const BasicMassChain<long double> chain{{2.0L}, {3.0L}, 0, 0, 0.5L};
  const BasicChainState<long double> start{Eigen::Matrix<long double, 1, 1>(0.1L),
                                           Eigen::Matrix<long double, 1, 1>(1.7L)};
  const long contacts = chainShadowContacts<long double>() + 300;
  const BasicChainRun<long double> run = runChain(chain, start, contacts);
  ASSERT_EQ(run.contacts, contacts);
  const Trust automatic = chainTrust(chain, start, run, contacts, 0.0L, TrustMode::Auto);
  EXPECT_EQ(automatic.shadowEvents, chainShadowContacts<long double>());
  EXPECT_NE(automatic.horizonMethod.find("the first"), std::string::npos) << automatic.horizonMethod;
  EXPECT_NE(automatic.verdict, Verdict::Unchecked);
  const double compared = double(run.events[std::size_t(automatic.shadowEvents) - 1].t);
  EXPECT_LE(automatic.horizon, 2 * compared * (1 + 1e-15));
  EXPECT_EQ(automatic.verdict == Verdict::Unreliable, automatic.horizon < double(run.tFinal)) << automatic.reason;
  const Trust full = chainTrust(chain, start, run, contacts, 0.0L, TrustMode::Full);
  EXPECT_EQ(full.shadowEvents, contacts);
  EXPECT_EQ(full.horizonMethod.find("the first"), std::string::npos);
  EXPECT_LE(automatic.stateError, full.stateError);  // a part of the same comparison
  const Trust again = chainTrust(chain, start, run, contacts, 0.0L, TrustMode::Auto);
  EXPECT_EQ(again.horizon, automatic.horizon);
}

}  // namespace
}  // namespace grazelab::core
