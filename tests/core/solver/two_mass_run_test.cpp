// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/solver/two_mass_run.cpp: the note's chain's run kept as its two-mass views draw
// it, made by the one run of the chain. Against that run's own events (BasicChainSimulator, bit
// for bit), and each view against what it must be: a Poincaré point is its contact's state after
// it, a free flight the time between a departure from the stop and the next contact (and T2 less
// it), a sample on the grid the closed-form flight from the event before it (tests/support), the
// contacts' corners in the samples; over both design branches and several mass ratios, grazing,
// perturbed, pressed and sticking starts, a detuned chain, a time limit, in double and binary128;
// and a start that names a mode still (GLO_0 left unpushed).
#include "core/solver/two_mass_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/model/linear_modes.h"
#include "core/orbits/starts.h"
#include "core/solver/simulate.h"
#include "support/physical_flight.h"

namespace grazelab::core {
namespace {

template <typename S>
BasicRequest<S> viewRequest(const BasicModel<S>& model, const BasicState<S>& start, std::int64_t contacts, S tEnd) {
  BasicRequest<S> request;
  request.initial = start;
  request.maxContacts = contacts;
  if (tEnd > 0) request.tEnd = tEnd;
  request.needs.events = true;
  request.needs.poincare = true;
  request.needs.freeFlights = true;
  const double T1 = computeModes(convertModel<double>(model)).T1;
  request.needs.samples.spacing = T1 / 48;
  request.needs.samples.tEnd = 40 * T1;
  return request;
}

template <typename S>
void expectTheViewsOfTheRun(const BasicModel<S>& model, const BasicState<S>& start, std::int64_t contacts, S tEnd,
                            const std::string& name) {
  const BasicRequest<S> request = viewRequest(model, start, contacts, tEnd);
  TwoMassRun<S> run(model, request);
  // in pieces, as the explorer runs it
  while (!run.advance(7)) {
  }
  const BasicResult<S>& view = run.result();
  // the one run, whole
  const BasicReadyChain<S> ready = readyChain(model);
  BasicChainSimulator<S> one(ready, chainStateOf(start), long(contacts), tEnd);
  one.advance(long(contacts));
  const BasicChainRun<S>& raw = one.run();
  ASSERT_EQ(view.stop, raw.stop) << name;
  EXPECT_TRUE(view.tFinal == raw.tFinal && view.final == twoMassStateOf(raw.final)) << name;
  EXPECT_EQ(view.cost.contacts, raw.contacts) << name;
  EXPECT_EQ(view.cost.impacts, raw.impacts) << name;
  EXPECT_EQ(view.cost.grazings, raw.grazings) << name;
  EXPECT_EQ(view.cost.sticks, raw.sticks) << name;
  ASSERT_EQ(view.events.size(), raw.events.size()) << name;
  for (std::size_t k = 0; k < raw.events.size(); ++k) {
    ASSERT_TRUE(view.events[k] == twoMassEventOf(raw.events[k])) << name << ": event " << k;
  }
  const std::vector<Event> events = toDoubleResult(view).events;
  const double T2 = computeModes(convertModel<double>(model)).T2;
  // a Poincaré point per contact, its state after it; a free flight per contact that ends a
  // flight from the stop (the start on it, or an impact or graze before), its length the time
  // between the two to rounding, and T2 less that
  std::size_t point = 0, flight = 0;
  std::int64_t contact = 0;
  bool fromStop = start.u2 == model.gap && start.v2 <= 0;
  double leftStop = 0;
  for (const Event& event : events) {
    if (!isContact(event.type)) {
      fromStop = true;  // a release leaves the stop
      leftStop = event.t;
      continue;
    }
    ASSERT_LT(point, view.poincare.size()) << name;
    const PoincarePoint& p = view.poincare[point++];
    EXPECT_TRUE(p.t == event.t && p.u1 == event.after.u1 && p.v1 == event.after.v1 && p.v2 == event.after.v2 &&
                p.type == event.type)
        << name << ": point " << point - 1;
    if (fromStop && event.t > leftStop) {
      ASSERT_LT(flight, view.freeFlights.size()) << name;
      const FreeFlight& f = view.freeFlights[flight++];
      EXPECT_EQ(f.contactIndex, contact) << name;
      EXPECT_NEAR(f.duration, event.t - leftStop, 1e-12 * event.t) << name << ": flight " << flight - 1;
      EXPECT_NEAR(f.shortfall, T2 - f.duration, 1e-12 * T2) << name << ": flight " << flight - 1;
    }
    ++contact;
    fromStop = event.type != EventType::Stick;
    leftStop = event.t;
  }
  EXPECT_EQ(point, view.poincare.size()) << name;
  EXPECT_EQ(flight, view.freeFlights.size()) << name;
  // the samples: the grid, each the closed-form flight from the event before it (or the event's
  // state after it, on its time; a stuck phase has its own motion: not checked here), then with
  // each contact's two corners (before it, and after it when that differs) merged in
  BasicRequest<S> gridOnly = request;
  gridOnly.needs.samples.includeContacts = false;
  const std::vector<Sample> grid = simulate(model, gridOnly).samples;
  ASSERT_GT(grid.size(), 100u) << name;
  const double spacing = request.needs.samples.spacing;
  std::size_t next = 0;  // the first event not before the sample
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const Sample& sample = grid[k];
    EXPECT_NEAR(sample.t, double(k) * spacing, 1e-9 * spacing) << name << ": sample " << k;
    while (next < events.size() && events[next].t < sample.t) ++next;
    State expected = next < events.size() && events[next].t == sample.t ? events[next].after : State{};
    if (!(next < events.size() && events[next].t == sample.t)) {
      if (next > 0 && events[next - 1].type == EventType::Stick) continue;
      const State from = next == 0 ? convertState<double>(start) : events[next - 1].after;
      const double since = sample.t - (next == 0 ? 0.0 : events[next - 1].t);
      expected = testing::PhysicalFlight(convertModel<double>(model), from).at(since);
    }
    const double scale = std::max({std::abs(expected.u1), std::abs(expected.u2), std::abs(expected.v1),
                                   std::abs(expected.v2), 1.0});
    const double apart = std::max({std::abs(sample.state.u1 - expected.u1), std::abs(sample.state.u2 - expected.u2),
                                   std::abs(sample.state.v1 - expected.v1), std::abs(sample.state.v2 - expected.v2)});
    EXPECT_LE(apart, 1e-12 * scale) << name << ": sample " << k << " at t = " << sample.t;
  }
  std::vector<Sample> merged;
  std::size_t g = 0;
  const double windowEnd = request.needs.samples.tEnd;
  for (const Event& event : events) {
    if (!isContact(event.type) || event.t > windowEnd) continue;
    while (g < grid.size() && grid[g].t < event.t) merged.push_back(grid[g++]);
    merged.push_back({event.t, event.before});
    if (!(event.after == event.before)) merged.push_back({event.t, event.after});
  }
  while (g < grid.size()) merged.push_back(grid[g++]);
  ASSERT_EQ(view.samples.size(), merged.size()) << name;
  for (std::size_t k = 0; k < merged.size(); ++k) {
    EXPECT_TRUE(view.samples[k].t == merged[k].t && view.samples[k].state == merged[k].state)
        << name << ": sample " << k << " at t = " << merged[k].t;
  }
  EXPECT_EQ(view.initialEnergy, raw.energyInitial) << name;
}

template <typename S>
BasicState<S> gloPlus(const BasicModel<S>& model, double lambda, const State& push) {
  StartSpec<S> spec;
  spec.lambda = S(lambda);
  spec.perturbation = convertState<S>(push);
  return makeStart(*makeTwoMassForm(model).chain, spec).start->state;
}

TEST(TwoMassRun, KeepsEveryViewOfTheOneRun) {
  for (const Branch branch : {Branch::Upper, Branch::Lower}) {
    for (const double m2 : {0.1, 0.3, 0.5}) {
      const Model model = *designedModel(1.0, m2, 1.0, 1.0, branch);
      const std::string chain = std::string(toString(branch)) + " m2 " + std::to_string(m2);
      expectTheViewsOfTheRun(model, gloPlus(model, 0.5, {0, 0, 0, -0.05}), 300, 0.0, chain + " near grazing");
      expectTheViewsOfTheRun(model, gloPlus(model, 0.3, {0, 0, 0.02, -1e-3}), 300, 0.0, chain + " pushed");
      expectTheViewsOfTheRun(model, gloPlus(model, 1.2, {0, 0, 0, 0}), 200, 0.0, chain + " GLO 1.2");
      expectTheViewsOfTheRun(model, gloPlus(model, 0.5, {0, 0, 0, -0.05}), 100000, 150.0, chain + " time limit");
    }
  }
  // pressed on the stop: sticks and releases
  const Model model = *designedModel(1.0, 0.5, 1.0, 1.0, Branch::Upper);
  expectTheViewsOfTheRun(model, State{1.5, 1.0, 0.0, 0.0}, 40, 0.0, "pressed");
  // detuned: no common period, the certified search
  Model detuned = model;
  detuned.design.reset();
  detuned.k2 *= 1.05;
  expectTheViewsOfTheRun(detuned, gloPlus(detuned, 0.5, {0, 0, 0, -0.05}), 100, 0.0, "detuned");
  // binary128
  const BasicModel<Quad> wide = convertModel<Quad>(model);
  expectTheViewsOfTheRun(wide, gloPlus(wide, 0.5, {0, 0, 0, -0.05}), 60, Quad(0), "binary128");
}

TEST(TwoMassRun, KeepsAModeStillAndDecidesGloZero) {
  // GLO_0, the fast mode alone, left unpushed: its touches at T1 = T2 / 2 are grazings decided
  // in double (the note's kernel, without the slow mode named still, cannot decide them)
  const Model model = *designedModel(1.0, 0.3, 1.0, 1.0, Branch::Upper);
  const TwoMassForm<double> form = *makeTwoMassForm(model).chain;
  StartSpec<double> spec;
  spec.lambda = 0;
  const StartOrProblem<double> made = makeStart(form, spec);
  ASSERT_TRUE(made.start);
  ASSERT_EQ(made.start->stillModes, (std::vector<bool>{false, true}));
  Request request;
  request.initial = made.start->state;
  request.maxContacts = 10;
  EXPECT_EQ(simulate(model, request).stop, StopReason::Undecided);
  TwoMassRun<double> run(model, request, made.start->stillModes);
  run.advance(100);
  const Result& result = run.result();
  ASSERT_EQ(result.stop, StopReason::ContactLimit) << result.message;
  ASSERT_EQ(result.cost.grazings, 10);
  const double T1 = computeModes(model).T1;
  for (std::size_t k = 0; k < result.events.size(); ++k) {
    EXPECT_NEAR(result.events[k].t, double(k + 1) * T1, 1e-12 * T1 * double(k + 1)) << k;
  }
}

TEST(TwoMassRun, RefusesBadInputAtOnce) {
  const Model model = *designedModel(1.0, 0.5, 1.0, 1.0, Branch::Upper);
  Request request;
  request.initial = State{0, 1.5, 0, 0};  // past the stop
  TwoMassRun<double> run(model, request);
  EXPECT_TRUE(run.done());
  EXPECT_EQ(run.result().stop, StopReason::InvalidInput);
  EXPECT_NE(run.result().message.find("initial.u2"), std::string::npos) << run.result().message;
  EXPECT_EQ(run.result().cost.contacts, 0);
}

}  // namespace
}  // namespace grazelab::core
