// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/solver/simulate.cpp: requests, limits, cancellation, outputs, invalid input.
#include "core/solver/simulate.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "core/solver/free_flight.h"
#include "core/model/linear_modes.h"
#include "core/solver/sticking.h"
#include "support/cases.h"
#include "support/physical_flight.h"
#include "core/solver/two_mass_run.h"

namespace grazelab::core {
namespace {

Request nearGrazingRequest(const Model& model, std::int64_t contacts) {
  Request request;
  request.initial = testing::nearGrazingStart(model, 0.5, 0.05);
  request.maxContacts = contacts;
  return request;
}

TEST(Simulate, InvalidInputIsReportedNotRun) {
  const Model good = testing::resonantChain(0.5);
  struct Case {
    Model model;
    State initial;
    const char* field;
  };
  const Case cases[] = {
      {{0, 0.5, 1, 0.5, 1, {}}, {}, "m1"},
      {{1, -0.5, 1, 0.5, 1, {}}, {}, "m2"},
      {{1, 0.5, std::nan(""), 0.5, 1, {}}, {}, "k1"},
      {{1, 0.5, 1, INFINITY, 1, {}}, {}, "k2"},
      {{1, 0.5, 1, 0.5, 0, {}}, {}, "gap"},
      {good, {0, 1.5, 0, 0}, "initial.u2"},
      {good, {0, 0, std::nan(""), 0}, "initial.v1"},
  };
  for (const Case& c : cases) {
    Request request;
    request.initial = c.initial;
    const Result result = simulate(c.model, request);
    EXPECT_EQ(result.stop, StopReason::InvalidInput) << c.field;
    EXPECT_NE(result.message.find(c.field), std::string::npos) << result.message;
    EXPECT_EQ(result.cost.contacts, 0);
  }
  Request negative = nearGrazingRequest(good, -1);
  EXPECT_EQ(simulate(good, negative).stop, StopReason::InvalidInput);
}

TEST(Simulate, StopsAtTheContactLimit) {
  const Model model = testing::resonantChain(0.5);
  const Result result = simulate(model, nearGrazingRequest(model, 37));
  EXPECT_EQ(result.stop, StopReason::ContactLimit);
  EXPECT_EQ(result.cost.contacts, 37);
  ASSERT_EQ(result.events.size(), 37u);
  EXPECT_EQ(result.tFinal, result.events.back().t);
  EXPECT_EQ(result.final, result.events.back().after);
}

TEST(Simulate, StopsAtTheTimeLimitOnTheFlight) {
  const Model model = testing::resonantChain(0.5);
  Request request = nearGrazingRequest(model, 1'000'000);
  request.tEnd = 100.0;
  const Result result = simulate(model, request);
  EXPECT_EQ(result.stop, StopReason::TimeLimit);
  EXPECT_EQ(result.tFinal, 100.0);
  EXPECT_LE(result.events.back().t, 100.0);
  const testing::PhysicalFlight flight(model, result.events.back().after);
  const State expected = flight.at(100.0 - result.events.back().t);
  EXPECT_NEAR(result.final.u1, expected.u1, 1e-12);
  EXPECT_NEAR(result.final.v2, expected.v2, 1e-12);
}

TEST(Simulate, AFlightFromTheStopIsNeverRecordedAgainWhateverTheHorizon) {
  // GLO data on detuned chains leave the stop at t = 0; a horizon below the contact search's
  // resolution (1e-300, 3.7e-262) once recorded the start as a grazing again and again at t = 0
  for (const Model& model : {Model{1.0, 0.5, 1.0, 0.6, 1.0, {}}, Model{1.0, 0.5, 1.0, 1.0, 1.0, {}}, testing::detunedChain()}) {
    for (const double tEnd : {1e-300, 3.7e-262, 1e-100, 1e-20, 1e-8}) {
      Request request;
      request.initial = {-0.16666666666666680, 1.0, 0.0, 0.0};  // u1 below the gap: it leaves
      request.maxContacts = 1000;
      request.tEnd = tEnd;
      request.needs.events = true;
      const Result result = simulate(model, request);
      EXPECT_EQ(result.stop, StopReason::TimeLimit) << "t_end = " << tEnd;
      EXPECT_TRUE(result.events.empty()) << "t_end = " << tEnd << ": " << result.events.size() << " events";
      EXPECT_EQ(result.tFinal, tEnd);
    }
  }
}

TEST(Simulate, ChunkedRunEqualsOneShotRun) {
  const Model model = testing::resonantChain(0.5, 1.0, Branch::Lower);
  const Request request = nearGrazingRequest(model, 500);
  const Result whole = simulate(model, request);
  TwoMassRun<double> run(model, request);
  int chunks = 0;
  while (!run.advance(7)) ++chunks;
  EXPECT_GT(chunks, 50);
  EXPECT_EQ(run.result().events, whole.events);
  EXPECT_EQ(run.progress(), 1.0);
}

TEST(Simulate, CancelFromAnotherThreadStopsPromptly) {
  const Model model = testing::resonantChain(0.5);
  Request request = nearGrazingRequest(model, std::numeric_limits<std::int64_t>::max());
  request.needs.events = false;
  std::stop_source source;
  std::jthread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    source.request_stop();
  });
  const Result result = simulate(model, request, source.get_token());
  EXPECT_EQ(result.stop, StopReason::Cancelled);
  EXPECT_GT(result.cost.contacts, 0);
  EXPECT_LT(result.cost.wallSeconds, 5.0);
}

TEST(Simulate, AlreadyCancelledDoesNothing) {
  const Model model = testing::resonantChain(0.5);
  std::stop_source source;
  source.request_stop();
  const Result result = simulate(model, nearGrazingRequest(model, 10), source.get_token());
  EXPECT_EQ(result.stop, StopReason::Cancelled);
  EXPECT_EQ(result.cost.contacts, 0);
}

TEST(Simulate, OnlyWhatIsNeededIsKept) {
  const Model model = testing::resonantChain(0.5);
  Request request = nearGrazingRequest(model, 50);
  request.needs = {};
  request.needs.events = false;
  const Result bare = simulate(model, request);
  EXPECT_TRUE(bare.events.empty());
  EXPECT_TRUE(bare.poincare.empty());
  EXPECT_TRUE(bare.freeFlights.empty());
  EXPECT_TRUE(bare.samples.empty());
  EXPECT_EQ(bare.cost.contacts, 50);

  request.needs.poincare = true;
  request.needs.freeFlights = true;
  const Result rich = simulate(model, request);
  EXPECT_EQ(rich.poincare.size(), 50u);
  EXPECT_EQ(rich.freeFlights.size(), 50u);
  EXPECT_EQ(rich.final, bare.final);
}

TEST(Simulate, EventsAreKeptOnlyInTheirWindow) {
  const Model model = testing::resonantChain(0.5);
  Request request = nearGrazingRequest(model, 200);
  request.needs.eventsUntil = 50.0;
  const Result result = simulate(model, request);
  EXPECT_EQ(result.cost.contacts, 200);
  ASSERT_FALSE(result.events.empty());
  EXPECT_LT(result.events.size(), 10u);
  for (const Event& event : result.events) EXPECT_LE(event.t, 50.0);
}

TEST(Simulate, SamplesAreEvenlySpacedAndBelowTheStop) {
  const Model model = testing::resonantChain(0.5);
  Request request = nearGrazingRequest(model, 20);
  request.needs.samples.spacing = 0.05;
  request.needs.samples.includeContacts = false;
  const Result result = simulate(model, request);
  ASSERT_GT(result.samples.size(), 100u);
  for (std::size_t i = 0; i < result.samples.size(); ++i) {
    EXPECT_NEAR(result.samples[i].t, 0.05 * double(i), 1e-9);
    EXPECT_LE(result.samples[i].state.u2, model.gap + 1e-12);
  }
  EXPECT_LE(result.samples.back().t, result.tFinal);
}

TEST(Simulate, SampleCountIsCapped) {
  const Model model = testing::resonantChain(0.5);
  Request request = nearGrazingRequest(model, 20);
  request.needs.samples.spacing = 1e-3;
  request.needs.samples.maxCount = 1000;
  const Result result = simulate(model, request);
  EXPECT_EQ(result.samples.size(), 1000u);
  EXPECT_TRUE(result.samplesTruncated);
}

TEST(Simulate, MotionBelowTheStopEndsWithNoFurtherContact) {
  const Model model = testing::resonantChain(0.5);
  Request request;
  request.initial = {0.1, 0.2, 0.0, 0.1};
  const Result result = simulate(model, request);
  EXPECT_EQ(result.stop, StopReason::NoFurtherContact);
  EXPECT_EQ(result.cost.contacts, 0);
  EXPECT_FALSE(result.message.empty());
  // detuned: no period bounds the search, but this start's modes' amplitudes together fall short
  // of the stop: no further contact, said at once, at the flight's start
  const Model detuned = testing::detunedChain();
  const Result never = simulate(detuned, request);
  EXPECT_EQ(never.stop, StopReason::NoFurtherContact) << never.message;
  EXPECT_EQ(never.tFinal, 0.0);
  EXPECT_EQ(never.final, request.initial);
  // (a search that runs out of its budget: Decisions.AnExhaustedSearchIsItsOwnStopNeverNoContact)
}

// A motion that never reaches the stop is still a motion: the plots draw its free orbit over
// the sample window (an explorer run pushed below the stop showed nothing but its start dot).
TEST(Simulate, MotionBelowTheStopIsSampledOverTheWindow) {
  const Model model = testing::resonantChain(0.5);
  const Modes modes = computeModes(model);
  Request request;
  request.initial = {0.1, 0.2, 0.0, 0.1};
  request.needs.samples.spacing = modes.T1 / 48;
  request.needs.samples.tEnd = 3 * modes.T2;
  Result result = simulate(model, request);
  ASSERT_EQ(result.stop, StopReason::NoFurtherContact);
  ASSERT_GT(result.samples.size(), 100u);
  EXPECT_NEAR(result.samples.back().t, 3 * modes.T2, modes.T1 / 48);
  // the free motion repeats after T2 and stays below the stop
  const auto period = std::ptrdiff_t(std::llround(modes.T2 / (modes.T1 / 48)));
  EXPECT_NEAR(result.samples[std::size_t(period)].state.u2, request.initial.u2, 1e-12);
  for (const Sample& sample : result.samples) EXPECT_LT(sample.state.u2, model.gap);
  // an open-ended window gets one slow period
  request.needs.samples.tEnd = kInfinity;
  result = simulate(model, request);
  EXPECT_NEAR(result.samples.back().t, modes.T2, modes.T1 / 48);
}

TEST(Simulate, StartMovingIntoTheStopImpactsAtOnce) {
  const Model model = testing::resonantChain(0.5);
  Request request;
  request.initial = {0.0, model.gap, 0.0, 0.7};
  request.maxContacts = 2;
  const Result result = simulate(model, request);
  ASSERT_EQ(result.events.size(), 2u);
  EXPECT_EQ(result.events[0].type, EventType::Impact);
  EXPECT_EQ(result.events[0].t, 0.0);
  EXPECT_EQ(result.events[0].after.v2, -0.7);
}

TEST(Simulate, PinnedReferenceSequence) {
  // GLO_0.5 data of the upper chain pushed to v2 = -0.05: event times from the 40-digit
  // reference of tools/reference (reference_sim.py --state=-0.25000000000000017,1,0,-0.05
  // --double-inputs --contacts 4), which the exact solver matched to 1e-15 when pinned
  const Model model = testing::resonantChain(0.5);
  Request request;
  request.initial = {-0.25000000000000017, 1.0, 0.0, -0.05};
  request.maxContacts = 4;
  const Result result = simulate(model, request);
  ASSERT_EQ(result.events.size(), 4u);
  for (const Event& event : result.events) EXPECT_EQ(event.type, EventType::Impact);
  const double times[] = {8.80577867244994, 17.61131761650285, 26.416371092866047, 35.22068092771523};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(result.events[i].t, times[i], 1e-12) << i;
}

}  // namespace
}  // namespace grazelab::core
