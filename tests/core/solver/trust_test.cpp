// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The trust estimate (core/solver/trust.h), on the note's chain and on chains of N masses: it tracks
// the true error, which a binary128 run of the same start measures here, and it names a chaotic
// run past its horizon, and the horizon means what it says: the run's events agree with a
// binary128 run of the same start to 1e-6 of their scales before it, not after; the same run gets
// the same estimate; off is unchecked.
#include <gtest/gtest.h>

#include <cmath>

#include "core/model/chain_design.h"
#include "core/model/linear_modes.h"
#include "core/orbits/chain_glo.h"
#include "core/orbits/special_orbits.h"
#include "core/solver/simulate.h"
#include "core/solver/trust.h"
#include "support/cases.h"

namespace grazelab::core {
namespace {

struct Checked {
  Trust trust;
  ChainRun run;
};

// the note's chain read in long double, and the shadow of its double runs (which points into it)
struct NotesShadow {
  explicit NotesShadow(const Model& model)
      : input(readyChain(convertModel<long double>(model))), shadow(chainShadow<double>(input)) {}
  NotesShadow(const NotesShadow&) = delete;
  NotesShadow& operator=(const NotesShadow&) = delete;
  BasicReadyChain<long double> input;
  ChainShadow<double> shadow;
};

// the one run of the note's chain with its estimate, made event by event
Checked runWithTrust(const Model& model, const State& start, long contacts, TrustMode mode) {
  const NotesShadow notes(model);
  TrustMonitor<double> monitor(notes.shadow, chainStateOf(convertState<long double>(start)), contacts, 0, mode);
  Checked checked;
  checked.run = runChain(readyChain(model), chainStateOf(start), contacts, 0, {},
                         [&monitor](const ChainEvent& event) { monitor.observe(event); });
  checked.trust = monitor.finish(checked.run);
  return checked;
}

// the error of a double run's final state against the same run in binary128, each component
// against its largest size at the events (as the estimate defines it)
double trueStateError(const Model& model, const State& start, std::int64_t contacts) {
  Request request;
  request.initial = start;
  request.maxContacts = contacts;
  const Result run = simulate(model, request);
  BasicRequest<Quad> wide;
  wide.initial = convertState<Quad>(start);
  wide.maxContacts = contacts;
  const BasicResult<Quad> exact = simulate(convertModel<Quad>(model), wide);
  double scale[4] = {0, std::abs(model.gap), 0, 0};
  for (const auto& event : exact.events) {
    for (const auto& x : {event.before, event.after}) {
      const double values[4] = {toDouble(x.u1), toDouble(x.u2), toDouble(x.v1), toDouble(x.v2)};
      for (int i = 0; i < 4; ++i) scale[i] = std::max(scale[i], std::abs(values[i]));
    }
  }
  const double positions = std::max(scale[0], scale[1]);
  const double velocities = std::max(scale[2], scale[3]);
  const double difference[4] = {
      std::abs(run.final.u1 - toDouble(exact.final.u1)), std::abs(run.final.u2 - toDouble(exact.final.u2)),
      std::abs(run.final.v1 - toDouble(exact.final.v1)), std::abs(run.final.v2 - toDouble(exact.final.v2))};
  double worst = 0;
  for (int i = 0; i < 4; ++i) {
    const double floor = (i < 2 ? positions : velocities) / 1000;
    worst = std::max(worst, difference[i] / std::max(scale[i], floor));
  }
  return worst;
}

TEST(Trust, TracksTheTrueErrorOfRegularRuns) {
  const Model model = testing::resonantChain(0.5);
  const State start = testing::nearGrazingStart(model, 0.5, 0.05);
  const Checked checked = runWithTrust(model, start, 2000, TrustMode::Full);
  const double truth = trueStateError(model, start, 2000);
  EXPECT_EQ(checked.trust.verdict, Verdict::Ok) << checked.trust.reason;
  EXPECT_LE(truth, 10 * checked.trust.stateError);
  EXPECT_LE(checked.trust.stateError, 1000 * std::max(truth, 1e-16));
  // the contact times drift by rounding: about eps per period, never zero
  EXPECT_GT(checked.trust.timeError, 1e-14);
  EXPECT_LT(checked.trust.timeError, 1e-9);
  EXPECT_FALSE(checked.trust.horizonObserved);
  EXPECT_GT(checked.trust.horizon, checked.run.tFinal);
}

TEST(Trust, NamesAChaoticRunPastItsHorizon) {
  // the sticking start GLO_1.5 is chaotic: 1000 contacts are far beyond its horizon
  const Model model = testing::resonantChain(0.5);
  const State start = gloData(model, computeModes(model), 1.5);
  const Checked checked = runWithTrust(model, start, 1000, TrustMode::Full);
  EXPECT_EQ(checked.trust.verdict, Verdict::Unreliable) << checked.trust.reason;
  EXPECT_TRUE(checked.trust.horizonObserved);
  EXPECT_GT(checked.trust.horizon, 0);
  EXPECT_LT(checked.trust.horizon, checked.run.tFinal);
  EXPECT_GT(checked.trust.stateError, kHorizonTolerance);
  // and its first 30 contacts are still fine
  const Checked early = runWithTrust(model, start, 30, TrustMode::Full);
  EXPECT_NE(early.trust.verdict, Verdict::Unreliable) << early.trust.reason;
  const double truth = trueStateError(model, start, 30);
  EXPECT_LE(truth, 10 * early.trust.stateError);
}

TEST(Trust, AnExtrapolatedHorizonIsConservativeAndTheSameForTheSameRun) {
  // GLO(0.5) pushed by (0, 0, 0.05, -0.05): double and binary128 part by 1e-6 near t = 8.3e3
  // (1000 contacts); the horizon extrapolated from 100 or 300 contacts must not lie beyond
  // where that really happens (a power law once gave 4.55e7 from 300 contacts)
  const Model model = testing::resonantChain(0.5);
  State start = gloData(model, computeModes(model), 0.5);
  start.v1 += 0.05;
  start.v2 -= 0.05;
  const Checked long_ = runWithTrust(model, start, 1000, TrustMode::Full);
  ASSERT_TRUE(long_.trust.horizonObserved) << long_.trust.reason;
  const double observed = long_.trust.horizon;
  for (const std::int64_t contacts : {100, 300, 600}) {
    const Checked checked = runWithTrust(model, start, contacts, TrustMode::Full);
    EXPECT_FALSE(checked.trust.horizonObserved) << contacts;
    EXPECT_LE(checked.trust.horizon, observed) << contacts << " contacts: " << checked.trust.horizonMethod;
    EXPECT_GE(checked.trust.horizon, checked.run.tFinal) << contacts;  // it held over what it saw
  }
  // auto shadows a fixed number of events: the same run, the same estimate, bit for bit
  const Checked first = runWithTrust(model, start, 20000, TrustMode::Auto);
  const Checked second = runWithTrust(model, start, 20000, TrustMode::Auto);
  EXPECT_EQ(first.trust.horizon, second.trust.horizon);
  EXPECT_EQ(first.trust.stateError, second.trust.stateError);
  EXPECT_EQ(first.trust.reason, second.trust.reason);
}

TEST(Trust, AShadowThatLeavesThePathOnItsOwnRoundingIsNoAlarm) {
  // a stick, a release, then contacts with v2 ~ 1e-30: the long double shadow chatters through
  // one of them (three impacts at t = 17.77) while the double run follows binary128 to 1e-15;
  // it once said "unreliable, estimated time error 2.0"
  const Model model = testing::resonantChain(0.5);
  const State start{1.0, 1.0, 1e-10, 0.0};
  const Checked checked = runWithTrust(model, start, 6, TrustMode::Auto);
  EXPECT_NE(checked.trust.verdict, Verdict::Unreliable) << checked.trust.reason;
  EXPECT_LT(std::max(checked.trust.stateError, checked.trust.timeError), 1e-12) << checked.trust.reason;
  EXPECT_NE(checked.trust.reason.find("false alarm"), std::string::npos) << checked.trust.reason;
}

TEST(Trust, AnInterruptStopsTheShadowAndTheEstimateSaysSo) {
  // the shadow watches the run's stop token: once it is requested the shadow does not march on
  // (a long detuned search in the shadow ignored it for minutes), and the estimate covers what
  // was compared, not "another path"
  const Model model = testing::resonantChain(0.5);
  const State start = testing::nearGrazingStart(model, 0.5, 0.05);
  std::stop_source source;
  const NotesShadow notes(model);
  TrustMonitor<double> monitor(notes.shadow, chainStateOf(convertState<long double>(start)), 1000, 0, TrustMode::Full,
                               source.get_token());
  long seen = 0;
  const ChainRun run = runChain(readyChain(model), chainStateOf(start), 1000, 0, {}, [&](const ChainEvent& event) {
    if (++seen == 10) source.request_stop();
    monitor.observe(event);
  });
  ASSERT_EQ(run.contacts, 1000);  // the run itself did not watch this token
  const Trust trust = monitor.finish(run);
  EXPECT_NE(trust.verdict, Verdict::Unreliable) << trust.reason;
  EXPECT_NE(trust.reason.find("interrupted at event 10"), std::string::npos) << trust.reason;
}

TEST(Trust, OffEstimatesNothing) {
  const Model model = testing::resonantChain(0.5);
  const Checked checked =
      runWithTrust(model, testing::nearGrazingStart(model, 0.5, 0.05), 10, TrustMode::Off);
  EXPECT_EQ(checked.trust.verdict, Verdict::Unchecked);
}

MassChain threeMasses() { return MassChain{{1.0, 0.7, 0.4}, {1.0, 0.8, 0.6}, 0, 2, 1.0}; }

ChainState pressedStart() {
  return {Eigen::Vector3d(1.4, 1.0, 1.3), Eigen::Vector3d(0.1, 0.0, -0.2)};
}

TEST(Trust, AShortRunAgreesWithItsShadow) {
  const MassChain chain = threeMasses();
  const ChainRun run = runChain(chain, pressedStart(), 6);
  const Trust trust = trustOf(readyChain(chain), pressedStart(), run, 6, 0.0, TrustMode::Auto);
  EXPECT_EQ(trust.verdict, Verdict::Ok) << trust.reason;
  EXPECT_LT(trust.stateError, 1e-9);
  EXPECT_GT(trust.horizon, run.tFinal);
  EXPECT_FALSE(trust.horizonObserved);
  EXPECT_EQ(trustOf(readyChain(chain), pressedStart(), run, 6, 0.0, TrustMode::Off).verdict, Verdict::Unchecked);
}

TEST(Trust, TheHorizonOfAChaoticRunIsWhereItPartsFromBinary128) {
  const MassChain chain = threeMasses();
  const ChainRun run = runChain(chain, pressedStart(), 100);
  const Trust trust = trustOf(readyChain(chain), pressedStart(), run, 100, 0.0, TrustMode::Full);
  ASSERT_EQ(trust.verdict, Verdict::Unreliable) << trust.reason;
  EXPECT_TRUE(trust.horizonObserved);
  EXPECT_LT(trust.horizon, run.tFinal);
  const Trust again = trustOf(readyChain(chain), pressedStart(), run, 100, 0.0, TrustMode::Full);
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
TEST(Trust, ARunThatCannotDecideItsFirstContactIsNotConfirmed) {
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

TEST(Trust, AGrazingOrbitMeetsTheStopAtRestAndIsOk) {
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
      const Trust trust = trustOf(readyChain(chain), start, run, 20, 0.0, TrustMode::Full);
      EXPECT_EQ(trust.verdict, Verdict::Ok) << masses.size() << " masses: " << trust.reason;
      EXPECT_LT(trust.stateError, 1e-12) << trust.reason;
    }
  }
}

TEST(Trust, AStiffLightMassIsJudgedAtAGivenTimeNotOnlyAtItsEvents) {
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
  const Trust trust = trustOf(readyChain(light), start, run, 1000000, tEnd, TrustMode::Full);
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

TEST(Trust, AutoShadowsTheFirstContactsOfALongRun) {
  // one mass bouncing on its stop: periodic, its errors grow slowly
  const BasicMassChain<long double> chain{{2.0L}, {3.0L}, 0, 0, 0.5L};
  const BasicChainState<long double> start{Eigen::Matrix<long double, 1, 1>(0.1L),
                                           Eigen::Matrix<long double, 1, 1>(1.7L)};
  const long contacts = long(autoShadowEvents<long double>()) + 300;
  const BasicChainRun<long double> run = runChain(chain, start, contacts);
  ASSERT_EQ(run.contacts, contacts);
  const Trust automatic = trustOf(readyChain(chain), start, run, contacts, 0.0L, TrustMode::Auto);
  // (the budget is looked at every 64 events)
  EXPECT_GE(automatic.shadowEvents, autoShadowEvents<long double>());
  EXPECT_LT(automatic.shadowEvents, autoShadowEvents<long double>() + 64);
  EXPECT_NE(automatic.reason.find("the first"), std::string::npos) << automatic.reason;
  EXPECT_NE(automatic.verdict, Verdict::Unchecked);
  const double compared = double(run.events[std::size_t(automatic.shadowEvents) - 1].t);
  EXPECT_LE(automatic.horizon, 2 * compared * (1 + 1e-15));
  EXPECT_EQ(automatic.verdict == Verdict::Unreliable, automatic.horizon < double(run.tFinal)) << automatic.reason;
  const Trust full = trustOf(readyChain(chain), start, run, contacts, 0.0L, TrustMode::Full);
  EXPECT_EQ(full.shadowEvents, contacts);
  EXPECT_EQ(full.reason.find("the first"), std::string::npos) << full.reason;
  // auto extrapolates what full measures: never optimistic by more than the honesty bound
  EXPECT_GE(automatic.stateError * 10, full.stateError) << automatic.reason << " against " << full.reason;
  const Trust again = trustOf(readyChain(chain), start, run, contacts, 0.0L, TrustMode::Auto);
  EXPECT_EQ(again.horizon, automatic.horizon);
}

TEST(Trust, ModesRoundTrip) {
  for (TrustMode mode : {TrustMode::Off, TrustMode::Auto, TrustMode::Full}) {
    EXPECT_EQ(parseTrustMode(toString(mode)), mode);
  }
  EXPECT_FALSE(parseTrustMode("sometimes"));
}

}  // namespace
}  // namespace grazelab::core
