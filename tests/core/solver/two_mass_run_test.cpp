// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/solver/two_mass_run.cpp: the note's chain's run kept as its two-mass views draw
// it, made by the one run of the chain. Against the note's own simulator (simulate.h), item by
// item and bit for bit: events, Poincaré points, free flights, end and stop (dense samples with
// their contacts' corners to 1e-13), over both design branches and several mass ratios, grazing, perturbed,
// pressed and sticking starts, a detuned chain, a time limit, in double and binary128; and a
// start that names a mode still (GLO_0 left unpushed), which the note's simulator cannot keep so.
#include "core/solver/two_mass_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/model/linear_modes.h"
#include "core/orbits/starts.h"
#include "core/solver/simulate.h"

namespace grazelab::core {
namespace {

template <typename S>
BasicRequest<S> viewRequest(const BasicModel<S>& model, const BasicState<S>& start, std::int64_t contacts, S tEnd) {
  BasicRequest<S> request;
  request.initial = start;
  request.maxContacts = contacts;
  if (tEnd > 0) request.tEnd = tEnd;
  request.stopAtUndecided = true;
  request.needs.events = true;
  request.needs.poincare = true;
  request.needs.freeFlights = true;
  const double T1 = computeModes(convertModel<double>(model)).T1;
  request.needs.samples.spacing = T1 / 48;
  request.needs.samples.tEnd = 40 * T1;
  return request;
}

template <typename S>
void expectTheNotesRun(const BasicModel<S>& model, const BasicState<S>& start, std::int64_t contacts, S tEnd,
                       const std::string& name) {
  const BasicRequest<S> request = viewRequest(model, start, contacts, tEnd);
  const BasicResult<S> notes = simulate(model, request);
  TwoMassRun<S> run(model, request);
  // in pieces, as the explorer runs it
  while (!run.advance(7)) {
  }
  const BasicResult<S>& view = run.result();
  const StopReason expected = notes.stop == StopReason::SearchLimit ? StopReason::SearchBudget : notes.stop;
  ASSERT_EQ(view.stop, expected) << name;
  ASSERT_EQ(view.events.size(), notes.events.size()) << name;
  for (std::size_t k = 0; k < notes.events.size(); ++k) {
    ASSERT_TRUE(view.events[k] == notes.events[k]) << name << ": event " << k;
  }
  ASSERT_EQ(view.poincare.size(), notes.poincare.size()) << name;
  for (std::size_t k = 0; k < notes.poincare.size(); ++k) {
    const PoincarePoint& a = view.poincare[k];
    const PoincarePoint& b = notes.poincare[k];
    ASSERT_TRUE(a.t == b.t && a.u1 == b.u1 && a.v1 == b.v1 && a.v2 == b.v2 && a.type == b.type) << name << ": point " << k;
  }
  ASSERT_EQ(view.freeFlights.size(), notes.freeFlights.size()) << name;
  for (std::size_t k = 0; k < notes.freeFlights.size(); ++k) {
    const FreeFlight& a = view.freeFlights[k];
    const FreeFlight& b = notes.freeFlights[k];
    ASSERT_TRUE(a.contactIndex == b.contactIndex && a.duration == b.duration && a.shortfall == b.shortfall)
        << name << ": flight " << k;
  }
  // the samples at the same times, the same states but where a grid time falls on an event
  // exactly (GLO_lambda grazes at T2 = 96 T1 / 48): the one run samples it after the event, in
  // the flight after it, whose grid batch then starts a sample earlier (each batch rotates its
  // flight's phase from its first sample: 1e-14 apart)
  ASSERT_EQ(view.samples.size(), notes.samples.size()) << name;
  for (std::size_t k = 0; k < notes.samples.size(); ++k) {
    const State& a = view.samples[k].state;
    const State& b = notes.samples[k].state;
    const double scale = std::max({std::abs(b.u1), std::abs(b.u2), std::abs(b.v1), std::abs(b.v2), 1.0});
    const double apart = std::max({std::abs(a.u1 - b.u1), std::abs(a.u2 - b.u2), std::abs(a.v1 - b.v1), std::abs(a.v2 - b.v2)});
    ASSERT_TRUE(view.samples[k].t == notes.samples[k].t && apart <= 1e-13 * scale)
        << name << ": sample " << k << " at t = " << notes.samples[k].t << ", " << apart << " apart";
  }
  EXPECT_EQ(view.cost.contacts, notes.cost.contacts) << name;
  EXPECT_EQ(view.cost.impacts, notes.cost.impacts) << name;
  EXPECT_EQ(view.cost.grazings, notes.cost.grazings) << name;
  EXPECT_EQ(view.cost.sticks, notes.cost.sticks) << name;
  if (expected != StopReason::SearchBudget) {
    EXPECT_TRUE(view.tFinal == notes.tFinal && view.final == notes.final) << name;
  }
  EXPECT_EQ(view.initialEnergy, notes.initialEnergy) << name;
}

template <typename S>
BasicState<S> gloPlus(const BasicModel<S>& model, double lambda, const State& push) {
  StartSpec<S> spec;
  spec.lambda = S(lambda);
  spec.perturbation = convertState<S>(push);
  return makeStart(*makeTwoMassForm(model).chain, spec).start->state;
}

TEST(TwoMassRun, IsTheNotesRunItemByItem) {
  for (const Branch branch : {Branch::Upper, Branch::Lower}) {
    for (const double m2 : {0.1, 0.3, 0.5}) {
      const Model model = *designedModel(1.0, m2, 1.0, 1.0, branch);
      const std::string chain = std::string(toString(branch)) + " m2 " + std::to_string(m2);
      expectTheNotesRun(model, gloPlus(model, 0.5, {0, 0, 0, -0.05}), 300, 0.0, chain + " near grazing");
      expectTheNotesRun(model, gloPlus(model, 0.3, {0, 0, 0.02, -1e-3}), 300, 0.0, chain + " pushed");
      expectTheNotesRun(model, gloPlus(model, 1.2, {0, 0, 0, 0}), 200, 0.0, chain + " GLO 1.2");
      expectTheNotesRun(model, gloPlus(model, 0.5, {0, 0, 0, -0.05}), 100000, 150.0, chain + " time limit");
    }
  }
  // pressed on the stop: sticks and releases
  const Model model = *designedModel(1.0, 0.5, 1.0, 1.0, Branch::Upper);
  expectTheNotesRun(model, State{1.5, 1.0, 0.0, 0.0}, 40, 0.0, "pressed");
  // detuned: no common period, the certified search
  Model detuned = model;
  detuned.design.reset();
  detuned.k2 *= 1.05;
  expectTheNotesRun(detuned, gloPlus(detuned, 0.5, {0, 0, 0, -0.05}), 100, 0.0, "detuned");
  // binary128
  const BasicModel<Quad> wide = convertModel<Quad>(model);
  expectTheNotesRun(wide, gloPlus(wide, 0.5, {0, 0, 0, -0.05}), 60, Quad(0), "binary128");
}

TEST(TwoMassRun, KeepsAModeStillAndDecidesGloZero) {
  // GLO_0, the fast mode alone, left unpushed: its touches at T1 = T2 / 2 are grazings decided
  // in double (the note's simulator, without the slow mode named still, cannot decide them)
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
  request.stopAtUndecided = true;
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

TEST(TwoMassRun, RefusesBadInputAsTheNotesSimulatorDoes) {
  const Model model = *designedModel(1.0, 0.5, 1.0, 1.0, Branch::Upper);
  Request request;
  request.initial = State{0, 1.5, 0, 0};  // past the stop
  TwoMassRun<double> run(model, request);
  EXPECT_TRUE(run.done());
  EXPECT_EQ(run.result().stop, StopReason::InvalidInput);
  EXPECT_EQ(run.result().message, simulate(model, request).message);
}

}  // namespace
}  // namespace grazelab::core
