// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The statements of docs/model.md section 5, checked numerically on every canonical resonant chain:
// energy conservation, FFT <= T2 (< T2 after an impact, = T2 on GLO_lambda), 1IPP periodicity,
// the lambda* limit, scaling with the gap, sticking starts, and a detuned chain for contrast.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/orbits/special_orbits.h"
#include "core/solver/exact_stepper.h"
#include "core/solver/simulate.h"
#include "core/solver/two_mass_run.h"
#include "support/cases.h"

namespace grazelab::core {
namespace {

// The largest relative energy error of one computed flight of the note's stepper over `contacts`
// contacts, before its end state is put back on its energy level: the raw accuracy of the
// closed-form flight. Also the number of flights it saw.
std::pair<double, int> largestFlightEnergyError(const Model& model, const State& start, int contacts) {
  const TwoMassForm<double> form = *makeTwoMassForm(model).chain;
  const Scale<double> scale = chooseScale(form, start);
  IntegrationState<double> state;
  state.x = scale.toScaled(start);
  ExactStepper<double> stepper(form, scale.gap);
  double largest = 0;
  int flights = 0;
  for (int i = 0; i < contacts; ++i) {
    const Step<double> step = stepper.advance(state, kInfinity, 1000 * twoPi<double>());
    if (step.kind != Step<double>::Kind::Event) break;
    if (!step.endsFlight) continue;
    largest = std::max(largest, step.flightEnergyError);
    ++flights;
  }
  return {largest, flights};
}

class Theorems : public ::testing::TestWithParam<testing::Chain> {
 protected:
  const Model& model() const { return GetParam().model; }
  Modes modes() const { return computeModes(model()); }
};

TEST_P(Theorems, EnergyIsConservedOverOneHundredThousandContacts) {
  for (double push : {0.05, 1e-6}) {
    Request request;
    request.initial = testing::nearGrazingStart(model(), 0.5, push);
    request.maxContacts = 100'000;
    request.needs.events = false;
    const Result result = simulate(model(), request);
    EXPECT_EQ(result.cost.contacts, 100'000);
    EXPECT_LT(result.cost.maxRelEnergyDrift, testing::tolerance(1e-10, 1.0)) << push;
    // each computed flight, before its end state is put back on its energy level, is exact to
    // rounding: a wrong frequency or mode shape shows up here at once
    const auto [flightError, flights] = largestFlightEnergyError(model(), request.initial, 100'000);
    EXPECT_EQ(flights, 100'000) << push;
    EXPECT_LT(flightError, testing::tolerance(1e-13, 1.0)) << push;
  }
}

TEST_P(Theorems, FreeFlightNeverExceedsT2AndIsShorterAfterAnImpact) {
  for (double lambda : {-0.2, 0.3, 0.5, 1.1, 1.5}) {
    Request request;
    request.initial = testing::nearGrazingStart(model(), lambda, 1e-3);
    request.maxContacts = 2000;
    request.needs.freeFlights = true;
    const Result result = simulate(model(), request);
    ASSERT_FALSE(result.freeFlights.empty());
    for (const FreeFlight& flight : result.freeFlights) {
      EXPECT_LE(flight.duration, modes().T2) << lambda;
      const Event& end = result.events[flight.contactIndex];
      // a flight that follows an impact ends strictly before T2
      const std::int64_t index = flight.contactIndex;
      if (index > 0 && result.events[index - 1].type == EventType::Impact) {
        EXPECT_GT(flight.shortfall, 0) << lambda << " at contact " << index;
      }
      EXPECT_NE(end.type, EventType::Release);
    }
  }
}

TEST_P(Theorems, GrazingLinearOrbitsReturnEveryT2) {
  // FFT = T2 exactly on GLO_lambda for lambda in (0, 4/3]; no impact, no micro-contact
  // (4/3 itself sits on the sticking threshold up to rounding: see FourthOrderTouchAtFourThirds)
  for (double lambda : {0.02, 0.25, 0.5, 0.75, 1.0, 1.1, 1.25, 1.33}) {
    Request request;
    request.initial = gloData(model(), modes(), lambda);
    request.maxContacts = 200;
    request.needs.freeFlights = true;
    const Result result = simulate(model(), request);
    EXPECT_EQ(result.cost.grazings, 200) << lambda;
    for (const FreeFlight& flight : result.freeFlights) {
      EXPECT_EQ(flight.duration, modes().T2) << lambda;
      EXPECT_EQ(flight.shortfall, 0) << lambda;
    }
  }
}

TEST_P(Theorems, FastModeGrazesEveryT1) {
  Request request;
  request.initial = gloData(model(), modes(), 0.0);
  request.maxContacts = 50;
  request.needs.freeFlights = true;
  // the start with its slow mode named exactly still (as GLO_0 is made): decided in double
  TwoMassRun<double> run(model(), request, {false, true});
  run.advance(request.maxContacts);
  const Result& result = run.result();
  EXPECT_EQ(result.cost.grazings, 50) << result.message;
  for (const FreeFlight& flight : result.freeFlights) {
    EXPECT_NEAR(flight.duration, modes().T1, 1e-12 * modes().T2);
  }
}

TEST_P(Theorems, OneImpactPerPeriodOrbitsRepeat) {
  for (double fraction : {0.55, 0.7, 0.9, 0.99, 0.999}) {
    const double period = fraction * modes().T2;
    const OnePeriodicOrbit orbit = onePeriodicOrbit(model(), modes(), period);
    if (!orbit.admissible) continue;
    Request request;
    request.initial = orbit.postImpact;
    request.maxContacts = 20;
    const Result result = simulate(model(), request);
    ASSERT_EQ(result.events.size(), 20u);
    const double velocity = std::abs(orbit.V);
    for (std::size_t k = 0; k < result.events.size(); ++k) {
      const Event& event = result.events[k];
      EXPECT_EQ(event.type, EventType::Impact);
      EXPECT_NEAR(event.t, double(k + 1) * period, 1e-10 * double(k + 1) * modes().T2)
          << fraction;
      EXPECT_NEAR(event.after.u1, orbit.postImpact.u1, 1e-9 * model().gap) << fraction;
      EXPECT_NEAR(event.after.v1, 0.0, 1e-9 * velocity + 1e-12 * modes().omegaSlow * model().gap)
          << fraction;
      EXPECT_NEAR(event.after.v2 / orbit.V, 1.0, 1e-8) << fraction;
    }
  }
}

TEST_P(Theorems, OneImpactPerPeriodDataTendToLambdaStar) {
  const double target = gloData(model(), modes(), lambdaStar(modes())).u1;
  double previousError = INFINITY;
  double previousSpeed = INFINITY;
  for (double below : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5}) {
    const OnePeriodicOrbit orbit = onePeriodicOrbit(model(), modes(), (1 - below) * modes().T2);
    ASSERT_LT(orbit.V, 0) << below;
    const double error = std::abs(orbit.postImpact.u1 - target);
    EXPECT_LT(error, previousError) << below;
    previousError = error;
    // the impact speed vanishes linearly in T2 - T
    if (std::isfinite(previousSpeed)) {
      EXPECT_NEAR(std::abs(orbit.V) / previousSpeed, 0.1, 0.03) << below;
    }
    previousSpeed = std::abs(orbit.V);
  }
  EXPECT_LT(previousError, 1e-4 * model().gap);
}

TEST_P(Theorems, ContactTimesAreUnchangedWhenGapAndStateScaleTogether) {
  const State start = testing::nearGrazingStart(model(), 0.5, 0.05);
  Request request;
  request.initial = start;
  request.maxContacts = 40;
  const Result reference = simulate(model(), request);
  // impacting motions amplify round-off (docs/model.md section 6): measure how far a one-ulp nudge
  // of the start drifts, and allow a hundred times that (and never less than 1e-11)
  request.initial.u1 = std::nextafter(start.u1, 1.0);
  const Result nudged = simulate(model(), request);
  ASSERT_EQ(nudged.events.size(), reference.events.size());
  std::vector<double> allowance;
  for (std::size_t k = 0; k < reference.events.size(); ++k) {
    const double drift = std::max(std::abs(nudged.events[k].t - reference.events[k].t) / modes().T2,
                                  std::abs(nudged.events[k].after.u1 - reference.events[k].after.u1) /
                                      model().gap);
    allowance.push_back(std::max(1e-11, 100 * drift));
  }
  for (double scale : {1e-9, 1e-5, 1e3, 1e9}) {
    Model scaled = model();
    scaled.gap *= scale;
    request.initial = scale * start;
    request.initial.u2 = scaled.gap;  // on the stop exactly, as the unscaled start
    const Result result = simulate(scaled, request);
    ASSERT_EQ(result.events.size(), reference.events.size()) << scale;
    for (std::size_t k = 0; k < result.events.size(); ++k) {
      EXPECT_EQ(result.events[k].type, reference.events[k].type) << scale;
      EXPECT_NEAR(result.events[k].t, reference.events[k].t, allowance[k] * modes().T2)
          << scale << " at " << k;
      EXPECT_NEAR(result.events[k].after.u1 / scale, reference.events[k].after.u1,
                  allowance[k] * model().gap)
          << scale << " at " << k;
    }
  }
}

TEST_P(Theorems, StickingStartReleasesThenImpacts) {
  // lambda > 4/3: the data are pressed on the stop
  Request request;
  request.initial = gloData(model(), modes(), 1.5);
  request.maxContacts = 20;
  const Result result = simulate(model(), request);
  ASSERT_GE(result.events.size(), 3u);
  EXPECT_EQ(result.events[0].type, EventType::Stick);
  EXPECT_EQ(result.events[0].t, 0.0);
  EXPECT_EQ(result.events[1].type, EventType::Release);
  EXPECT_EQ(result.events[1].after.u1, model().gap);
  EXPECT_LT(result.events[1].after.v1, 0);
  EXPECT_GT(result.cost.impacts, 0);
  EXPECT_LT(result.cost.maxRelEnergyDrift, 1e-12);
}

TEST_P(Theorems, FourthOrderTouchAtFourThirdsIsAGrazing) {
  Request request;
  request.initial = gloData(model(), modes(), 4.0 / 3.0);
  request.initial.u1 = model().gap;  // exactly: no force on mass 2
  request.maxContacts = 5;
  request.needs.freeFlights = true;
  const Result result = simulate(model(), request);
  EXPECT_EQ(result.cost.grazings, 5);
  EXPECT_EQ(result.cost.sticks, 0);
  for (const FreeFlight& flight : result.freeFlights) EXPECT_EQ(flight.duration, modes().T2);
}

INSTANTIATE_TEST_SUITE_P(Chains, Theorems, ::testing::ValuesIn(testing::resonantChains()),
                         [](const auto& info) { return info.param.name; });

TEST(TheoremsContrast, DetunedChainConservesEnergyAndKeepsContacting) {
  const Model model = testing::detunedChain();
  Request request;
  request.initial = {-0.25, 1.0, 0.0, -0.05};
  request.maxContacts = 2000;
  request.needs.freeFlights = true;
  const Result result = simulate(model, request);
  EXPECT_EQ(result.cost.contacts, 2000);
  EXPECT_LT(result.cost.maxRelEnergyDrift, 1e-11);
  for (const Event& event : result.events) {
    if (event.type == EventType::Impact) { EXPECT_GT(event.before.v2, 0); }
  }
  // without resonance some free flights outlast T2 (the FFT is not bounded by it)
  double longest = 0;
  for (const FreeFlight& flight : result.freeFlights) longest = std::max(longest, flight.duration);
  EXPECT_GT(longest, computeModes(model).T2);
}

}  // namespace
}  // namespace grazelab::core
