// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The trust estimate (core/solver/trust.h): it tracks the true error, which a binary128 run of the
// same start measures here, and it names a chaotic run past its horizon.
#include <gtest/gtest.h>

#include <cmath>

#include "core/model/linear_modes.h"
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

// the one run of the note's chain with its estimate, made event by event
Checked runWithTrust(const Model& model, const State& start, long contacts, TrustMode mode) {
  TrustMonitor<double> monitor(convertModel<long double>(model), chainStateOf(convertState<long double>(start)),
                               contacts, 0, mode);
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
  TrustMonitor<double> monitor(convertModel<long double>(model), chainStateOf(convertState<long double>(start)), 1000, 0,
                               TrustMode::Full, source.get_token());
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

TEST(Trust, ModesRoundTrip) {
  for (TrustMode mode : {TrustMode::Off, TrustMode::Auto, TrustMode::Full}) {
    EXPECT_EQ(parseTrustMode(toString(mode)), mode);
  }
  EXPECT_FALSE(parseTrustMode("sometimes"));
}

}  // namespace
}  // namespace grazelab::core
