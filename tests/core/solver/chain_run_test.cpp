// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/solver/chain_flight.cpp, chain_stick.cpp and chain_run.cpp: exact runs of
// chains of N masses. Against the two-mass solver (N = 2 is the note's chain, sticks included),
// against brute force in long double (no contact missed, near-grazing pushes included), and the
// theorems that hold for any N: every flight of a fully resonant chain returns by T (< T after
// an impact), energy is conserved (a stick and its release happen at rest), a held mass is
// pressed on the stop until its release, and the run scales with the chain.
#include "core/solver/chain_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "core/model/chain_design.h"
#include "core/model/model.h"
#include "core/orbits/chain_glo.h"
#include "core/solver/chain_stick.h"
#include "core/solver/trust.h"
#include "core/solver/simulate.h"

namespace grazelab::core {
namespace {

MassChain designed(const std::vector<double>& masses, const std::vector<int>& ratios, int design = 0) {
  const ChainDesigns designs = designSprings(masses, 1.0, ratios);
  EXPECT_GT(int(designs.designs.size()), design);
  return MassChain{masses, designs.designs.at(std::size_t(design)).springs, 0, 0, 1.0};
}

// a random start below the stop with energy of order one
ChainState randomStart(const MassChain& chain, std::mt19937& random) {
  std::uniform_real_distribution<double> value(-0.6, 0.6);
  const Eigen::Index n = chain.size();
  ChainState start{Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    start.u[i] = value(random);
    start.v[i] = value(random);
  }
  return start;
}

// u_s(t) - d along a flight, in long double, straight from the modes (no bounds, no windows)
long double stopDistance(const ChainDynamics& dynamics, const ChainFlight& flight, long double t) {
  long double f = -dynamics.gap;
  for (Eigen::Index j = 0; j < flight.q.size(); ++j) {
    const long double w = dynamics.omega[j];
    f += dynamics.P(dynamics.stop, j) * (flight.q[j] * std::cos(w * t) + flight.qdot[j] / w * std::sin(w * t));
  }
  return f;
}

TEST(ChainRun, TwoMassesByTheModalKernelAreTheNotesSolver) {
  // the note's designed chain run by the modal kernel (two algorithms): near-grazing starts (60
  // contacts), and starts pressed on the stop (a stick at once, its release, the flights after;
  // 20 contacts: these runs are chaotic, the two solvers' roundings part by 1e-10 after some 25):
  // the same events as the two-mass solver
  const auto model = designedModel<double>(1.0, 0.5, 1.0, 1.0, Branch::Upper);
  ASSERT_TRUE(model);
  const MassChain chain{{1.0, 0.5}, {1.0, model->k2}, 0, 0, 1.0};
  for (const auto& [u1, u2, v1, v2] : {std::tuple{0.5, 0.9, 0.8, 0.6}, std::tuple{-1.2, 0.95, 0.3, 0.9},
                                       std::tuple{0.0, 1.0, 0.3, -0.2}, std::tuple{0.7, 0.99, 0.1, 0.3},
                                       std::tuple{1.5, 1.0, 0.2, 0.0}, std::tuple{2.5, 1.0, -0.7, 0.0},
                                       std::tuple{1.0 + 1e-6, 1.0, 0.0, 0.0}, std::tuple{0.5, 1.0, 0.0, 0.3}}) {
    Request request;
    request.initial = {u1, u2, v1, v2};
    const long contacts = v2 == 0 ? 20 : 60;
    request.maxContacts = contacts;
    const Result two = simulate(*model, request);
    ChainState start{Eigen::Vector2d(u1, u2), Eigen::Vector2d(v1, v2)};
    const ChainRun n = runChain(readyChain(chain, Kernel::Modal), start, contacts);
    ASSERT_EQ(n.contacts, contacts) << u1 << ": " << int(n.stop);
    ASSERT_EQ(n.events.size(), two.events.size()) << u1 << ": " << toString(two.stop) << " " << two.message;
    for (std::size_t k = 0; k < n.events.size(); ++k) {
      EXPECT_NEAR(n.events[k].t, two.events[k].t, 1e-12 * (1 + two.events[k].t)) << "event " << k;
      EXPECT_EQ(n.events[k].type, two.events[k].type) << "event " << k;
      EXPECT_NEAR(n.events[k].u[0], two.events[k].after.u1, 1e-9) << "event " << k;
      EXPECT_NEAR(n.events[k].vAfter, two.events[k].after.v2, 1e-9) << "event " << k;
    }
  }
}

// The note's chain however it is given to the one run (its model, its form, or its numbers with
// the 1:2 design's springs or detuned ones) is run by the note's kernel: the events, the end and
// the energies of its model's run (simulate) to the last bit, in every precision, on chains the
// note does not name (both branches, other masses, a chain scaled by 2^-40 and 3e7, detuned
// springs), from starts near grazing, pressed on the stop, on it moving in, and in pieces; with a
// time limit too.
template <typename S>
void expectTheNotesBits(const BasicModel<S>& model, const BasicReadyChain<S>& ready, const BasicState<S>& initial,
                        long contacts, const S& tEnd, const std::string& label) {
  ASSERT_TRUE(ready.notes) << label;
  BasicRequest<S> request;
  request.initial = initial;
  request.maxContacts = contacts;
  request.needs.freeFlights = true;
  if (tEnd > 0) request.tEnd = tEnd;
  const BasicResult<S> two = simulate(model, request);
  BasicChainSimulator<S> simulator(ready, chainStateOf(initial), contacts, tEnd);
  while (!simulator.advance(7)) {
  }
  const BasicChainRun<S>& one = simulator.run();
  ASSERT_EQ(one.events.size(), two.events.size()) << label << ": " << toString(two.stop) << " / " << toString(one.stop);
  for (std::size_t k = 0; k < one.events.size(); ++k) {
    const BasicEvent<S>& e = two.events[k];
    ASSERT_TRUE(one.events[k].t == e.t && one.events[k].type == e.type) << label << ", event " << k;
    ASSERT_TRUE(one.events[k].u[0] == e.after.u1 && one.events[k].u[1] == e.after.u2) << label << ", event " << k;
    ASSERT_TRUE(one.events[k].vBefore[0] == e.before.v1 && one.events[k].vBefore[1] == e.before.v2)
        << label << ", event " << k;
    ASSERT_TRUE(one.events[k].vAfter == e.after.v2) << label << ", event " << k;
  }
  // the flights from the stop the note's recorder keeps are the one run's, length and shortfall
  // to the bit (a flight from the stop: after a contact or a release, or from a start on it)
  std::vector<std::pair<double, double>> flights;
  bool fromStop = initial.u2 == model.gap && initial.v2 <= 0;
  for (const BasicChainEvent<S>& event : one.events) {
    if (fromStop && event.flight > 0) flights.emplace_back(toDouble(event.flight), toDouble(event.shortfall));
    fromStop = event.type != EventType::Stick;
  }
  ASSERT_EQ(flights.size(), two.freeFlights.size()) << label;
  for (std::size_t k = 0; k < flights.size(); ++k) {
    EXPECT_EQ(flights[k].first, two.freeFlights[k].duration) << label << ", flight " << k;
    EXPECT_EQ(flights[k].second, two.freeFlights[k].shortfall) << label << ", flight " << k;
  }
  EXPECT_EQ(one.stop, two.stop) << label;
  EXPECT_TRUE(one.tFinal == two.tFinal) << label;
  EXPECT_TRUE(twoMassStateOf(one.final) == two.final) << label;
  EXPECT_TRUE(one.energyInitial == two.initialEnergy) << label;
  // its accuracy as the note's recorder measures it: the same residuals; the energy drift over
  // the physical states, not the scaled ones (rounding apart)
  EXPECT_EQ(one.maxContactResidual, two.cost.maxContactResidual) << label;
  EXPECT_NEAR(one.maxEnergyDrift, two.cost.maxRelEnergyDrift, 16 * toDouble(std::numeric_limits<S>::epsilon()))
      << label;
}

template <typename S>
void notesChainsInThePrecision() {
  const std::vector<std::tuple<double, double, double, double>> starts{
      {0.5, 0.9, 0.8, 0.6}, {-1.2, 0.95, 0.3, 0.9}, {0.0, 1.0, 0.3, -0.2}, {0.7, 0.99, 0.1, 0.3},
      {1.5, 1.0, 0.2, 0.0}, {2.5, 1.0, -0.7, 0.0}, {0.5, 1.0, 0.0, 0.3},   {-0.25, 1.0, 0.0, -1e-7}};
  struct Given {
    double m1, m2, k1, gap;
    std::optional<Branch> branch;  ///< none: detuned, k2 = 0.37 k1
  };
  for (const Given& given : {Given{1, 0.5, 1, 1, Branch::Upper}, Given{2, 0.3, 1.5, 0.7, Branch::Lower},
                             Given{1, 0.3, 1, 1, Branch::Upper}, Given{0x1p-40, 0x1p-41, 3e7, 0x1p-40, Branch::Upper},
                             Given{1, 0.4, 1.2, 1, std::nullopt}}) {
    const S m1(given.m1), m2(given.m2), k1(given.k1), gap(given.gap);
    const BasicModel<S> model = given.branch ? *designedModel<S>(m1, m2, k1, gap, *given.branch)
                                             : BasicModel<S>{m1, m2, k1, S(0.37) * k1, gap, std::nullopt};
    // the same chain by its numbers: the design branch found from its springs
    const BasicMassChain<S> numbers{{m1, m2}, {k1, model.k2}, S(0), 0, gap};
    for (const auto& [u1, u2, v1, v2] : starts) {
      using std::sqrt;
      const S length = gap;
      const S speed = gap * sqrt(k1 / m1);
      const BasicState<S> initial{S(u1) * length, S(u2) * length, S(v1) * speed, S(v2) * speed};
      std::ostringstream label;
      label << toString(precisionOf<S>()) << " m2 " << given.m2 << " start " << u1 << "," << u2;
      const long contacts = v2 == 0 ? 20 : 60;
      expectTheNotesBits(model, readyChain(numbers), initial, contacts, S(0), label.str() + " (numbers)");
      expectTheNotesBits(model, readyChain(*makeTwoMassForm(model).chain), initial, contacts, S(0),
                         label.str() + " (form)");
      const S tEnd = S(37.5) / sqrt(k1 / m1);
      expectTheNotesBits(model, readyChain(numbers), initial, 1000, tEnd, label.str() + " (time limit)");
    }
  }
}

TEST(ChainRun, TheNotesChainIsRunByTheNotesKernelBitForBit) {
  notesChainsInThePrecision<double>();
  notesChainsInThePrecision<long double>();
  notesChainsInThePrecision<Quad>();
}

// A run measures its own accuracy as it goes: the largest energy drift over its events' states
// (at least the final state's, when it ends on an event) and the largest |u_s - d| of its
// contacts as the flights reached them, both at the rounding of the run's precision, and far
// smaller one precision up: chains of 3 to 6 masses, resonant and not, a wall, interior stops.
template <typename S>
void measuresItsAccuracyIn(double bound, double& largestResidual) {
  std::mt19937 random(20261130);
  long contacts = 0;
  const std::vector<MassChain> chains{MassChain{{1.0, 0.2, 0.05}, {}, 0, 0, 1.0},  // 3:2:1, designed in S below
                                      MassChain{{1.0, 0.7, 1.3, 0.5}, {1.0, 0.8, 1.4, 0.6}, 0.3, 2, 1.0},
                                      MassChain{{1.0, 1.0, 1.0, 1.0, 1.0}, {1, 1, 1, 1, 1}, 0, 3, 0.5},
                                      MassChain{{0.4, 1.0, 0.8, 1.1, 0.6, 1.0}, {1.2, 1, 0.7, 1.3, 0.9, 1.1}, 0, 0, 1.0}};
  for (const MassChain& given : chains) {
    BasicMassChain<S> chain = chainCast<S>(given);
    if (given.springs.empty()) {
      // a design in S's own numbers: double's rounding of it, run in binary128 as exactly 3:2:1,
      // drifts by 1e-17 (what the measure is for)
      const DesignChoice design = chooseDesign(given.masses, 1.0, 0.0, {3, 2, 1}, 1);
      chain.springs = *designedSpringsIn<S>(chain.masses, S(1), S(0), design);
    }
    const BasicReadyChain<S> ready = readyChain(chain);
    for (int trial = 0; trial < 4; ++trial) {
      ChainState start = randomStart(given, random);
      start.u[given.stopped() - 1] = std::min(start.u[given.stopped() - 1], 0.9 * given.gap);  // below the stop
      const BasicChainState<S> state{start.u.template cast<S>(), start.v.template cast<S>()};
      const BasicChainRun<S> run = runChain(ready, state, 200);
      contacts += run.contacts;
      EXPECT_LE(run.maxEnergyDrift, bound) << given.size() << " masses, trial " << trial;
      EXPECT_LE(run.maxContactResidual, bound * toDouble(chain.gap)) << given.size() << " masses, trial " << trial;
      if (run.stop == StopReason::ContactLimit) {
        using std::abs;
        EXPECT_GE(run.maxEnergyDrift, toDouble(S(abs(run.energyFinal / run.energyInitial - 1))));
      }
      largestResidual = std::max(largestResidual, run.maxContactResidual);
    }
  }
  EXPECT_GT(contacts, 2000);  // (a start may stay below the stop for good)
}

TEST(ChainRun, ARunMeasuresItsOwnAccuracy) {
  double inDouble = 0, inQuad = 0;
  measuresItsAccuracyIn<double>(1e-12, inDouble);
  measuresItsAccuracyIn<Quad>(1e-28, inQuad);
  // the residuals are measured, not the stop's own value put back: some contact of double's
  // runs lands off it by rounding, and binary128's land far closer
  EXPECT_GT(inDouble, 0.0);
  EXPECT_LT(inQuad, 1e-6 * inDouble);
}

// Each contact carries the flight it ends, as the kernel computed it: the time since the event
// before to rounding, its shortfall the period less it; and on a commensurate chain every flight
// from the stop ends within the common period T (docs/model.md section 11), its shortfall >= 0.
// Chains of 3 to 6 masses (the modal kernel), resonant and not, a wall, interior stops.
TEST(ChainRun, EachContactCarriesTheFlightItEnds) {
  std::mt19937 random(20261201);
  const std::vector<MassChain> chains{MassChain{{1.0, 0.2, 0.05}, {}, 0, 0, 1.0},  // 3:2:1
                                      MassChain{{1.0, 0.7, 1.3, 0.5}, {1.0, 0.8, 1.4, 0.6}, 0.3, 2, 1.0},
                                      MassChain{{1.0, 1.0, 1.0, 1.0, 1.0}, {1, 1, 1, 1, 1}, 0, 3, 0.5},
                                      MassChain{{0.4, 1.0, 0.8, 1.1, 0.6, 1.0}, {1.2, 1, 0.7, 1.3, 0.9, 1.1}, 0, 0, 1.0}};
  long fromStop = 0;
  for (MassChain chain : chains) {
    if (chain.springs.empty()) {
      chain.springs = *designedSpringsIn<double>(chain.masses, 1.0, 0.0, chooseDesign(chain.masses, 1.0, 0.0, {3, 2, 1}, 1));
    }
    const ReadyChain ready = readyChain(chain);
    const double period = ready.dynamics.period > 0 ? ready.dynamics.period : twoPi<double>() / ready.dynamics.omega.minCoeff();
    for (int trial = 0; trial < 4; ++trial) {
      ChainState start = randomStart(chain, random);
      start.u[chain.stopped() - 1] = std::min(start.u[chain.stopped() - 1], 0.9 * chain.gap);
      const ChainRun run = runChain(ready, start, 200);
      double before = 0;
      bool onStop = false;
      for (const ChainEvent& event : run.events) {
        const std::string where = std::to_string(chain.size()) + " masses, t = " + std::to_string(event.t);
        if (event.type == EventType::Impact || event.type == EventType::Grazing) {
          EXPECT_NEAR(event.flight, event.t - before, 1e-12 * (1 + event.t)) << where;
          EXPECT_EQ(event.shortfall, period - event.flight) << where;
          if (onStop && ready.dynamics.period > 0) {
            EXPECT_GE(event.shortfall, -1e-12 * period) << where;
            ++fromStop;
          }
        } else {
          EXPECT_EQ(event.flight, 0.0) << where;  // a stick or a release ends no flight
        }
        onStop = event.type != EventType::Stick;
        before = event.t;
      }
    }
  }
  EXPECT_GT(fromStop, 200);
}

// The sum over the modes of the stopped mass's amplitudes in a flight from `start`: u_s never
// exceeds it, and on a chain whose frequencies are not commensurate it comes as near as one likes
double stopReach(const ChainDynamics& dynamics, const ChainState& start) {
  const ChainFlight flight = flightFrom(dynamics, start);
  double reach = 0;
  for (Eigen::Index j = 0; j < flight.q.size(); ++j) {
    reach += std::abs(dynamics.P(dynamics.stop, j)) * std::hypot(flight.q[j], flight.qdot[j] / dynamics.omega[j]);
  }
  return reach;
}

TEST(ChainRun, AFlightWhoseModesCannotReachTheStopEndsTheRunWhateverTheFrequencies) {
  // a chain not commensurate searched its budget out (1000 slowest periods) and said so, where
  // the modes' amplitudes decide at once that it never meets the stop: on random chains of two
  // to six masses (walls, stops on any mass), and the note's kernel on a detuned two-mass chain;
  // a start whose amplitudes reach a little past the stop is not said to miss it
  std::mt19937 random(20261203);
  std::uniform_real_distribution<double> logUniform(-0.5, 0.5);
  int never = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const int n = 2 + trial % 5;
    MassChain chain;
    for (int i = 0; i < n; ++i) {
      chain.masses.push_back(std::pow(10.0, logUniform(random)));
      chain.springs.push_back(std::pow(10.0, logUniform(random)));
    }
    chain.rightSpring = trial % 3 == 0 ? std::pow(10.0, logUniform(random)) : 0.0;
    chain.stopMass = int(random() % unsigned(n)) + 1;
    chain.gap = 0.5 + double(random() % 1000) / 1000.0;
    const bool notes = trial == 23;
    const ReadyChain ready = notes ? readyChain(Model{1.0, 0.5, 1.0, 0.37, chain.gap, std::nullopt})
                                   : readyChain(chain, Kernel::Modal);
    ASSERT_EQ(ready.dynamics.period, 0.0) << "trial " << trial << ": not commensurate";
    ASSERT_EQ(bool(ready.notes), notes);
    ChainState start = randomStart(notes ? MassChain{{1.0, 0.5}, {1.0, 0.37}, 0, 0, chain.gap} : chain, random);
    const double reach = stopReach(ready.dynamics, start);
    for (const double fraction : {0.999, 1.001}) {
      const ChainState scaled{start.u * (fraction * ready.dynamics.gap / reach),
                              start.v * (fraction * ready.dynamics.gap / reach)};
      const ChainRun run = runChain(ready, scaled, 10);
      if (fraction < 1) {
        EXPECT_EQ(run.stop, StopReason::NoFurtherContact) << "trial " << trial << ": " << toString(run.stop);
        EXPECT_EQ(run.contacts, 0);
        EXPECT_EQ(run.tFinal, 0.0);
        never += run.stop == StopReason::NoFurtherContact;
        // with an end time, the run goes on to it
        EXPECT_EQ(runChain(ready, scaled, 10, 50.0).stop, StopReason::TimeLimit) << "trial " << trial;
      } else {
        // (contacts, or a search out of its budget: the modes come as near the stop as one likes)
        EXPECT_TRUE(run.stop == StopReason::ContactLimit || run.stop == StopReason::SearchBudget)
            << "trial " << trial << ": " << toString(run.stop);
      }
    }
  }
  EXPECT_EQ(never, 24);
}

// The note's kernel takes the note's budget of march steps for a detuned flight's search: out of
// it, the run ends search-budget where simulate does, and goes on to the contact with the default
// budget
TEST(ChainRun, TheNotesKernelsSearchTakesItsStepBudget) {
  // (its first contact comes after 65 time units, about 8 slow periods)
  const Model model{1.0, 0.5, 1.0, 0.37, 1.0, std::nullopt};
  const State initial{0.5, 0.8, 0.0, 0.0};
  Request request;
  request.initial = initial;
  request.maxContacts = 1;
  request.flightSearchSteps = 10;
  const Result two = simulate(model, request);
  ASSERT_EQ(two.stop, StopReason::SearchBudget);
  const ReadyChain ready = readyChain(model);
  ASSERT_TRUE(ready.notes && ready.notesModel);
  const ChainRun budgeted = runChain(ready, chainStateOf(initial), 1, 0.0, {}, {}, {}, 10);
  EXPECT_EQ(budgeted.stop, StopReason::SearchBudget);
  EXPECT_EQ(budgeted.contacts, 0);
  const ChainRun whole = runChain(ready, chainStateOf(initial), 1);
  EXPECT_EQ(whole.contacts, 1) << toString(whole.stop);
  // the contact the search finds with its default budget: the modal kernel's (two algorithms)
  const ChainRun modal = runChain(readyChain(MassChain{{1.0, 0.5}, {1.0, 0.37}, 0, 0, 1.0}, Kernel::Modal),
                                  chainStateOf(initial), 1);
  ASSERT_EQ(modal.contacts, 1);
  EXPECT_NEAR(whole.events.at(0).t, modal.events.at(0).t, 1e-10 * modal.events.at(0).t);
}

// The note's chain made ready from its form (the closed forms: what a periodic orbit's check run
// takes) has the dynamics of the chain's binary128 eigensolve: frequencies and M-orthonormal
// mode shapes to rounding, the same common period and harmonics when resonant, none when not;
// on both branches, light and heavy second masses, a scaled chain and a detuned one
TEST(ChainRun, AFormMadeReadyHasTheChainsModes) {
  std::vector<Model> models;
  for (const Branch branch : {Branch::Upper, Branch::Lower}) {
    for (const double m2 : {1e-3, 0.1, 0.3, 0.5}) models.push_back(*designedModel(1.0, m2, 1.0, 1.0, branch));
  }
  models.push_back(*designedModel(3e7, 0x1p-20 * 3e7, 2e-5, 0x1p-40, Branch::Upper));
  models.push_back(Model{1.0, 0.4, 1.2, 0.37, 1.0, std::nullopt});
  for (const Model& model : models) {
    const ReadyChain fromForm = readyChain(*makeTwoMassForm(model).chain);
    const ReadyChain fromModel = readyChain(model);
    ASSERT_TRUE(fromForm.notes && fromForm.notesModel);
    const ChainDynamics& a = fromForm.dynamics;
    const ChainDynamics& b = fromModel.dynamics;
    const std::string label = "m2/m1 " + std::to_string(model.m2 / model.m1) + (model.design ? " designed" : " detuned");
    for (Eigen::Index j = 0; j < 2; ++j) {
      EXPECT_NEAR(a.omega[j] / b.omega[j], 1.0, 1e-14) << label;
      // a shape's sign is free: compare |P|, and P^T M P = I
      for (Eigen::Index i = 0; i < 2; ++i) {
        EXPECT_NEAR(std::abs(a.P(i, j)), std::abs(b.P(i, j)), 1e-13 * b.P.cwiseAbs().maxCoeff()) << label;
      }
    }
    const Eigen::Matrix2d orthonormal = a.P.transpose() * a.mass.asDiagonal() * a.P;
    EXPECT_LT((orthonormal - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff(), 1e-14) << label;
    EXPECT_EQ(a.harmonics, b.harmonics) << label;
    EXPECT_NEAR(a.period, b.period, 1e-14 * b.period) << label;
    EXPECT_EQ(a.stop, b.stop);
    EXPECT_EQ(a.gap, b.gap);
  }
}

TEST(ChainRun, TheNotesKernelSamplesTheModalKernelsMotion) {
  // samples of a run by the note's kernel (its grid a batch at a time: through flights, a stick
  // and its release) are the states the modal kernel samples at those times on the same chain
  // (two algorithms), to where their roundings part
  const Model model = *designedModel<double>(1.0, 0.3, 1.0, 1.0, Branch::Lower);
  const MassChain numbers{{1.0, 0.3}, {1.0, model.k2}, 0, 0, 1.0};
  for (const State& initial : {State{0.5, 0.9, 0.8, 0.6}, State{1.5, 1.0, 0.2, 0.0}}) {
    std::array<std::vector<std::pair<double, ChainState>>, 2> samples;
    for (int kernel = 0; kernel < 2; ++kernel) {
      ChainSampling<double> sampling;
      sampling.spacing = 0.173;
      sampling.sink = [&](double t, const ChainState& state) { samples[kernel].emplace_back(t, state); };
      const ReadyChain ready = kernel == 0 ? readyChain(model) : readyChain(numbers, Kernel::Modal);
      ASSERT_EQ(bool(ready.notes), kernel == 0);
      const ChainRun run = runChain(ready, chainStateOf(initial), 30, 0.0, {}, {}, sampling);
      ASSERT_EQ(run.contacts, 30);
    }
    ASSERT_EQ(samples[0].size(), samples[1].size());
    ASSERT_GT(samples[0].size(), 100u);
    for (std::size_t k = 0; k < samples[0].size(); ++k) {
      EXPECT_EQ(samples[0][k].first, samples[1][k].first);
      const ChainState& notes = samples[0][k].second;
      const ChainState& modal = samples[1][k].second;
      EXPECT_LT((notes.u - modal.u).norm() + (notes.v - modal.v).norm(), 1e-8)
          << "sample " << k << " at t = " << samples[0][k].first;
    }
  }
}

// Where the two kernels could part on the same chain (the modal one forced): a flight that
// cannot reach the stop ends the run at its start; the last contact asked for being a stick ends
// the run held there; an event at the end time gives the sample due there. And near the merge
// point m2/m1 = 9/16, springs near 1:2 but off the design keep their own k2 (the modal kernel).
TEST(ChainRun, TheTwoKernelsEndAlike) {
  const auto both = [](const MassChain& chain, const ChainState& start, long contacts, double tEnd,
                       const std::vector<double>& times) {
    std::array<std::pair<ChainRun, std::vector<double>>, 2> runs;
    for (int k = 0; k < 2; ++k) {
      ChainSampling<double> sampling;
      sampling.times = times;
      sampling.sink = [&runs, k](double t, const ChainState&) { runs[std::size_t(k)].second.push_back(t); };
      const ReadyChain ready = readyChain(chain, k == 0 ? Kernel::Best : Kernel::Modal);
      EXPECT_EQ(bool(ready.notes), k == 0);
      runs[std::size_t(k)].first = runChain(ready, start, contacts, tEnd, {}, {}, sampling);
    }
    return runs;
  };
  // detuned, never reaching the stop (its modes' amplitudes short of it): said at once, at the
  // start; the same start scaled until they pass the stop by 1e-9: its phases do not line up
  // within the search's 1000 slowest periods, which both search out, ending at the start
  {
    const MassChain chain{{1.0, 0.4}, {1.2, 0.444}, 0, 0, 1.0};
    const ChainState start{Eigen::Vector2d(0.1, 0.1), Eigen::Vector2d::Zero()};
    const auto runs = both(chain, start, 10, 0, {});
    for (const auto& [run, samples] : runs) {
      EXPECT_EQ(run.stop, StopReason::NoFurtherContact);
      EXPECT_EQ(run.tFinal, 0.0);
      EXPECT_EQ(run.final.u, start.u);
    }
    const double past = (1 + 1e-9) * chain.gap / stopReach(readyChain(chain, Kernel::Modal).dynamics, start);
    const ChainState late{start.u * past, start.v * past};
    for (const auto& [run, samples] : both(chain, late, 10, 0, {})) {
      EXPECT_EQ(run.stop, StopReason::SearchBudget);
      EXPECT_EQ(run.tFinal, 0.0);
      EXPECT_EQ(run.final.u, late.u);
    }
  }
  // pressed on the stop: the one contact asked for is the stick at 0
  const auto model = designedModel<double>(1.0, 0.5, 1.0, 1.0, Branch::Upper);
  const MassChain note{{1.0, 0.5}, {1.0, model->k2}, 0, 0, 1.0};
  {
    const ChainState pressed{Eigen::Vector2d(1.5, 1.0), Eigen::Vector2d(0.2, 0.0)};
    const auto runs = both(note, pressed, 1, 0, {0.0});
    for (const auto& [run, samples] : runs) {
      ASSERT_EQ(run.events.size(), 1u);
      EXPECT_EQ(run.events[0].type, EventType::Stick);
      EXPECT_EQ(run.stop, StopReason::ContactLimit);
      EXPECT_EQ(run.tFinal, 0.0);
      EXPECT_EQ(samples, std::vector<double>{0.0});
    }
  }
  // an impact exactly at the end time: the sample there is given, by both
  {
    const ChainState start{Eigen::Vector2d(0.5, 1.0), Eigen::Vector2d(0.0, 0.3)};
    const ChainRun first = runChain(readyChain(note), start, 3);
    ASSERT_EQ(first.events.size(), 3u);
    const double tEnd = first.events[1].t;
    const auto runs = both(note, start, 10, tEnd, {1.0, tEnd});
    for (const auto& [run, samples] : runs) {
      EXPECT_EQ(run.stop, StopReason::TimeLimit);
      EXPECT_EQ(run.tFinal, tEnd);
      EXPECT_EQ(samples, (std::vector<double>{1.0, tEnd}));
    }
  }
  // near the merge point: within the ratio tolerance of 1:2, 1e-5 off the design's k2
  const MassChain nearMerge{{1.0, 0.5625}, {1.0, 0.3600036}, 0, 0, 1.0};
  EXPECT_FALSE(readyChain(nearMerge).notes);
  EXPECT_TRUE(readyChain(MassChain{{1.0, 0.5625}, {1.0, 0.36}, 0, 0, 1.0}).notes);
}

TEST(ChainRun, OtherTwoMassChainsTakeTheModalKernel) {
  // a 3:1 chain (the note's kernel knows 1:2 and the chains not commensurate), a right wall, the
  // stop on the first mass: the modal kernel
  const MassChain threeToOne = designed({1.0, 0.5}, {3, 1});
  EXPECT_FALSE(readyChain(threeToOne).notes);
  EXPECT_TRUE(readyChain(designed({1.0, 0.5}, {2, 1})).notes);
  EXPECT_FALSE(readyChain(MassChain{{1.0, 0.5}, {1.0, 0.37}, 0.2, 0, 1.0}).notes);
  EXPECT_FALSE(readyChain(MassChain{{1.0, 0.5}, {1.0, 0.37}, 0, 1, 1.0}).notes);
  EXPECT_FALSE(readyChain(designed({1.0, 0.5}, {2, 1}), Kernel::Modal).notes);
}

// The springs' force on the stopped mass, straight from the displacements
double forceOn(const MassChain& chain, const ChainState& state) {
  return -(stiffnessMatrix(chain).row(chain.stopped() - 1) * state.u)(0);
}

TEST(ChainRun, AHeldMassIsPressedOnTheStopUntilItsRelease) {
  // stops on the first, an interior and the last mass, with and without a right wall: every
  // stuck phase keeps F_s > 0 until its release, where F_s = 0 and the released flight leaves;
  // the masses beside the clamp move as the chain with u_s = d held (checked by the equations
  // of motion: M u'' = -K u on them, by central differences of the phase's closed form); the
  // energy is the same at every event
  std::mt19937 random(17);
  std::uniform_real_distribution<double> value(0.3, 3.0);
  int phases = 0;
  for (int trial = 0; trial < 24; ++trial) {
    MassChain chain;
    const int n = 1 + trial % 5;
    for (int i = 0; i < n; ++i) {
      chain.masses.push_back(value(random));
      chain.springs.push_back(value(random));
    }
    chain.rightSpring = trial % 2 == 0 ? value(random) : 0.0;
    chain.stopMass = 1 + trial % n;
    chain.gap = value(random);
    if (n == 1) continue;  // one mass is never pressed: its springs pull it off the stop
    const int s = chain.stopped() - 1;
    ChainState start = randomStart(chain, random);
    start.u *= chain.gap;
    start.u[s] = chain.gap;
    start.v[s] = 0;
    // pressed: a neighbour pushed past the stop far enough
    const int neighbour = s > 0 ? s - 1 : s + 1;
    if (neighbour >= n) continue;
    start.u[neighbour] = 3 * chain.gap + 1;
    ASSERT_GT(forceOn(chain, start), 0);
    const ChainRun run = runChain(chain, start, 40, 0);
    ASSERT_FALSE(run.events.empty());
    EXPECT_EQ(run.events[0].type, EventType::Stick);
    EXPECT_EQ(run.events[0].t, 0);
    const Eigen::MatrixXd K = stiffnessMatrix(chain);
    for (std::size_t k = 0; k + 1 < run.events.size(); ++k) {
      if (run.events[k].type != EventType::Stick) continue;
      ASSERT_EQ(run.events[k + 1].type, EventType::Release) << "event " << k;
      ++phases;
      ChainState held{run.events[k].u, run.events[k].vBefore};
      held.v[s] = 0;
      const ChainStuckPhase phase = stuckPhase(chain, held);
      const double length = run.events[k + 1].t - run.events[k].t;
      ASSERT_GT(length, 0);
      for (int i = 1; i < 40; ++i) {
        const double t = length * i / 40;
        const ChainState at = stuckStateAt(phase, t);
        EXPECT_GT(forceOn(chain, at), -1e-12) << "event " << k << ", " << i << "/40 of the phase";
        // M u'' = -K u for every mass but s, by a central difference of the velocities
        const double h = 1e-5 * length;
        const Eigen::VectorXd acceleration = (stuckStateAt(phase, t + h).v - stuckStateAt(phase, t - h).v) / (2 * h);
        const Eigen::VectorXd force = -K * at.u;
        for (int m = 0; m < n; ++m) {
          if (m == s) continue;
          EXPECT_NEAR(chain.masses[std::size_t(m)] * acceleration[m], force[m], 1e-6 * (1 + force.cwiseAbs().maxCoeff()))
              << "mass " << m + 1;
        }
      }
      const ChainState released{run.events[k + 1].u, run.events[k + 1].vBefore};
      EXPECT_NEAR(forceOn(chain, released), 0.0, 1e-12 * (1 + K.cwiseAbs().maxCoeff() * chain.gap));
      EXPECT_NEAR(chainEnergy(chain, released), run.energyInitial, 1e-12 * run.energyInitial);
    }
    EXPECT_NEAR(run.energyFinal, run.energyInitial, 1e-11 * run.energyInitial);
  }
  EXPECT_GT(phases, 15);
}

TEST(ChainRun, ResonantFlightsReturnByTheirPeriodAndKeepTheEnergy) {
  // Theorem 2.3 for any N: in a fully resonant chain every flight after an impact ends before T
  std::mt19937 random(5);
  for (const auto& [masses, ratios] : std::vector<std::pair<std::vector<double>, std::vector<int>>>{
           {{1.0, 0.2, 0.05}, {3, 2, 1}}, {{1.0, 1.0, 0.2}, {4, 3, 1}}, {{1.0, 0.4, 0.2}, {5, 3, 1}},
           {{1.0, 0.6, 0.36, 0.216}, {4, 3, 2, 1}}}) {
    const MassChain chain = designed(masses, ratios);
    const ChainDynamics dynamics = chainDynamics(chain);
    ASSERT_GT(dynamics.period, 0);
    for (int trial = 0; trial < 5; ++trial) {
      const ChainState start = randomStart(chain, random);
      if (start.u[chain.size() - 1] > chain.gap) continue;
      const ChainRun run = runChain(chain, start, 300);
      if (run.stop == StopReason::NoFurtherContact) continue;
      ASSERT_EQ(run.stop, StopReason::ContactLimit);
      for (std::size_t k = 1; k < run.events.size(); ++k) {
        const double flight = run.events[k].t - run.events[k - 1].t;
        if (run.events[k].type == EventType::Release) continue;  // a stuck phase, not a flight
        EXPECT_GT(flight, 0);
        if (run.events[k - 1].type == EventType::Impact) {
          EXPECT_LT(flight, dynamics.period);
        }
        EXPECT_LE(flight, dynamics.period * (1 + 1e-12));
      }
      EXPECT_NEAR(run.energyFinal / run.energyInitial, 1.0, 1e-11);
    }
  }
}

// Brute force, in long double: f sampled 4000 times per fastest period before each contact the
// run found, and each sampled local maximum refined; none may reach the stop before it.
void expectNoContactMissed(const MassChain& chain, const ChainState& start, long contacts, double tEnd = 0) {
  const ChainDynamics dynamics = chainDynamics(chain);
  const ChainRun run = runChain(chain, start, contacts, tEnd);
  ChainState state = start;
  double t = 0;
  const double step = 2 * std::numbers::pi / dynamics.omega.maxCoeff() / 4000;
  for (const ChainEvent& event : run.events) {
    if (event.type == EventType::Release) {
      // a stuck phase ends: the next flight starts from its release
      state.u = event.u;
      state.v = event.vBefore;
      t = event.t;
      continue;
    }
    const ChainFlight flight = flightFrom(dynamics, state);
    const double length = event.t - t;
    long double previous = stopDistance(dynamics, flight, 0);
    long double before = previous;
    for (double s = step; s < length - 1e-9 * (1 + length); s += step) {
      const long double now = stopDistance(dynamics, flight, s);
      EXPECT_LT(now, 1e-12L) << "a contact at t = " << t + s << " before the one found at " << event.t;
      if (previous > before && previous >= now) {
        // a local maximum near s - step: golden-section refine, it must stay below the stop
        long double a = s - 2 * step, b = s;
        for (int i = 0; i < 80; ++i) {
          const long double m1 = a + (b - a) * 0.382L, m2 = a + (b - a) * 0.618L;
          (stopDistance(dynamics, flight, m1) < stopDistance(dynamics, flight, m2) ? a : b) = (stopDistance(dynamics, flight, m1) < stopDistance(dynamics, flight, m2) ? m1 : m2);
        }
        const long double peak = stopDistance(dynamics, flight, (a + b) / 2);
        if ((a + b) / 2 < length * (1 - 1e-9)) {
          EXPECT_LT(peak, 1e-12L) << "a touch at t = " << t + double((a + b) / 2) << " missed (found " << event.t << ")";
        }
      }
      before = previous;
      previous = now;
    }
    // the contact itself is on the stop
    EXPECT_NEAR(double(stopDistance(dynamics, flight, length)), 0.0, 1e-9);
    state.u = event.u;
    state.v = event.vBefore;
    state.v[dynamics.stop] = event.vAfter;
    t = event.t;
  }
}

TEST(ChainRun, NoContactIsMissedOnResonantAndDetunedChains) {
  std::mt19937 random(9);
  const MassChain resonant = designed({1.0, 0.2, 0.05}, {3, 2, 1});
  MassChain detuned = resonant;
  detuned.springs[1] *= std::sqrt(2.0);  // frequencies no longer in any small ratio
  ASSERT_EQ(chainDynamics(detuned).period, 0);
  MassChain interior = designed({1.0, 1.0, 0.2}, {4, 3, 1});
  interior.stopMass = 2;  // a stop on an interior mass
  for (const MassChain* chain : std::initializer_list<const MassChain*>{&resonant, &detuned, &interior}) {
    for (int trial = 0; trial < 3; ++trial) {
      ChainState start = randomStart(*chain, random);
      start.u[chain->stopped() - 1] = std::min(start.u[chain->stopped() - 1], 0.5);
      expectNoContactMissed(*chain, start, 25, 400);
    }
  }
}

TEST(ChainRun, NearGrazingPushesAreImpactsUnresolvedOrNothing) {
  // GLOM_j of a resonant chain (a pure mode whose top just touches the stop) started at its
  // rest position: pushed out by eps the flight crosses, pushed in it never reaches (a pure mode
  // is periodic); at eps = 0 its top is the stop within rounding, where double cannot tell a
  // touch from a slow impact or a miss: unresolved, never taken for a grazing
  const MassChain chain = designed({1.0, 0.2, 0.05}, {3, 2, 1});
  const ChainDynamics dynamics = chainDynamics(chain);
  const int s = dynamics.stop;
  for (Eigen::Index j = 0; j < dynamics.P.cols(); ++j) {
    const double w = dynamics.omega[j];
    const Eigen::VectorXd shape = dynamics.P.col(j) / dynamics.P(s, j);  // unit at the stop
    for (double push : {1e-3, 1e-6, 1e-9, 0.0, -1e-9, -1e-3}) {
      // u = 0, v = (1 + push) d w shape: amplitude (1 + push) d at mass s, a quarter period on
      ChainState start{Eigen::VectorXd::Zero(chain.size()), (1 + push) * chain.gap * w * shape};
      const ChainContact contact = firstContact(dynamics, flightFrom(dynamics, start));
      const double quarter = std::numbers::pi / (2 * w);
      if (push > 1e-12) {
        EXPECT_EQ(contact.kind, ChainContactKind::Impact) << "mode " << j + 1 << ", push " << push;
        // the first crossing, sqrt(2 push) / w before the top
        EXPECT_NEAR(contact.t, quarter - std::acos(1 / (1 + push)) / w, 1e-9 * quarter) << push;
      } else if (push == 0) {
        EXPECT_EQ(contact.kind, ChainContactKind::Unresolved) << "mode " << j + 1;
        EXPECT_NEAR(contact.t, quarter, 1e-6 * quarter);
      } else {
        EXPECT_EQ(contact.kind, ChainContactKind::None) << "mode " << j + 1 << ", push " << push;
      }
    }
  }
}

// The chain and a start in a wider precision, exactly (every double is a long double and a
// binary128).
template <typename To>
BasicChainState<To> stateCast(const ChainState& state) {
  return {state.u.cast<To>(), state.v.cast<To>()};
}

// Whether a run's events are a prefix of the reference's, type for type, as long as their times
// agree to 1e-6 of the slowest period: a grazing taken for an impact, or a contact missed or
// added, is caught there; past it the runs part as near-grazing runs do (the error estimate's
// business, not this test's)
template <typename S>
void expectAPrefixOf(const BasicChainRun<S>& run, const BasicChainRun<Quad>& reference, double slowest,
                     const std::string& what) {
  for (std::size_t k = 0; k < run.events.size(); ++k) {
    ASSERT_LT(k, reference.events.size()) << what << ": more events than the reference decides";
    if (std::abs(double(run.events[k].t) - double(reference.events[k].t)) > 1e-6 * slowest) return;
    EXPECT_EQ(run.events[k].type, reference.events[k].type) << what << ", event " << k << " at t = " << double(run.events[k].t);
  }
}

TEST(ChainRun, AGrazingIsRecordedOnlyWhereItIsExact) {
  // Found by the stability matrix: the grazing orbit of a mode pushed off the stop by a few ulps
  // of its speed returns each period with its top within rounding of the stop; double recorded
  // a grazing there each time (19 over 20 periods) where binary128 finds 6 impacts. Each mode's
  // GLOM, pushed by 0 to 1e-11 d w_N, on a chain with no ratios, a designed 3:2:1 chain and one
  // stopped inside: every event decided in double or long double is the binary128 run's, and a
  // run stops undecided rather than decide what its precision cannot (an exact periodic return
  // in a resonant chain stays a grazing).
  MassChain uneven{{1.0, 0.6, 1.4, 0.9}, {1.0, 2.0, 0.8, 1.1}, 0, 2, 0.5};
  const MassChain resonant = designed({1.0, 0.2, 0.05}, {3, 2, 1});
  MassChain interior = designed({1.0, 1.0, 0.2}, {4, 3, 1});
  interior.stopMass = 2;
  long grazingsKept = 0;
  for (const MassChain* chain : std::initializer_list<const MassChain*>{&uneven, &resonant, &interior}) {
    const ChainModes modes = chainModes(*chain);
    const Eigen::Index n = chain->size();
    const double slowestOmega = modes.omega[n - 1];
    const double slowest = 2 * std::numbers::pi / slowestOmega;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (modes.nodeAtStop[std::size_t(j)]) continue;
      std::vector<double> weights(std::size_t(n), 0.0);
      weights[std::size_t(j)] = 1;
      const ChainGloStart glo = chainGloStart(*chain, weights);
      ASSERT_EQ(glo.problem, GloStartProblem::None);
      for (double eps : {0.0, 1e-15, 1e-13, 1e-11}) {
        ChainState start = glo.state;
        start.v[chain->stopped() - 1] -= eps * chain->gap * slowestOmega;
        const double tEnd = 19.5 * slowest;  // not at a return, where the precisions' ends may differ
        const BasicChainRun<Quad> reference = runChain(chainCast<Quad>(*chain), stateCast<Quad>(start), 200, Quad(tEnd));
        const std::string what = std::to_string(n) + " masses, mode " + std::to_string(j + 1) + ", push " +
                                 std::to_string(eps);
        const ChainRun inDouble = runChain(*chain, start, 200, tEnd);
        expectAPrefixOf(inDouble, reference, slowest, what + ", double");
        const BasicChainRun<long double> inLong =
            runChain(chainCast<long double>(*chain), stateCast<long double>(start), 200, (long double)tEnd);
        expectAPrefixOf(inLong, reference, slowest, what + ", long double");
        if (inDouble.stop != StopReason::Undecided) grazingsKept += inDouble.grazings;
      }
    }
  }
  // the resonant chains' unpushed GLOMs graze at each period, decided in double
  EXPECT_GT(grazingsKept, 0);
}

// A GLO start's run in S: every event a grazing after u_s's own period T/g, at k T/g, in the
// start's state to the last bit (the flight goes on through each touch unchanged).
template <typename S>
void expectGrazesAtItsOwnPeriod(const MassChain& chain, const std::vector<double>& weights, int repeats,
                                const std::string& what) {
  const BasicMassChain<S> inS = chainCast<S>(chain);
  std::vector<S> weightsInS;
  for (double w : weights) weightsInS.push_back(S(w));
  const BasicChainGloStart<S> glo = chainGloStartIn<S>(inS, weightsInS);
  ASSERT_EQ(glo.problem, GloStartProblem::None) << what;
  const BasicReadyChain<S> ready = readyChain(inS);
  const S period = ready.dynamics.period / S(repeats);
  ASSERT_GT(period, S(0)) << what;
  const BasicChainRun<S> run = runChain(ready, glo.start(), 50);
  ASSERT_EQ(run.stop, StopReason::ContactLimit) << what;
  ASSERT_EQ(run.grazings, 50) << what;
  for (std::size_t k = 0; k < run.events.size(); ++k) {
    const BasicChainEvent<S>& e = run.events[k];
    EXPECT_NEAR(toDouble(S(e.t / period)), double(k + 1), 1e-12 * double(k + 1)) << what << ", event " << k;
    EXPECT_TRUE(e.u == glo.state.u && e.vBefore == glo.state.v) << what << ", event " << k;
  }
  // its state alone holds ~1e-17 of the still modes (their amplitudes from P^T M u), which its
  // numbers cannot tell from a motion: undecided, or the same grazings where they round to 0
  const BasicChainRun<S> alone = runChain(ready, glo.state, 50);
  if (alone.stop == StopReason::Undecided) {
    EXPECT_TRUE(alone.events.empty()) << what << ", its state alone";
  } else {
    EXPECT_EQ(alone.grazings, 50) << what << ", its state alone";
  }
}

TEST(ChainRun, AGlomOfAFastModeGrazesAtItsOwnPeriod) {
  // GLOM_1 of a 3:2:1 chain alone (u_s = d cos 3 w0 t) returns to the stop after T/3, and GLOM_2
  // after T/2; with 4:2:1, GLO of the two fast modes after T/2. Both were undecided at t = 0 in
  // every precision: the touch was called exact only at T. Designed chains of several mass
  // ratios, both designs where two exist, a stop inside the chain; double, long double, binary128.
  struct Case {
    std::vector<double> masses;
    std::vector<int> ratios;
    int stop;
    std::vector<double> weights;
    int repeats;
  };
  const std::vector<Case> cases = {
      {{1.0, 0.2, 0.05}, {3, 2, 1}, 0, {1, 0, 0}, 3},
      {{1.0, 0.2, 0.05}, {3, 2, 1}, 0, {0, 1, 0}, 2},
      {{1.0, 0.5, 0.1}, {3, 2, 1}, 0, {1, 0, 0}, 3},
      {{2.0, 0.3, 0.02}, {3, 2, 1}, 0, {0, 1, 0}, 2},
      {{1.0, 0.2, 0.05}, {4, 2, 1}, 0, {0.5, 0.5, 0}, 2},
      {{1.0, 0.2, 0.05}, {4, 2, 1}, 0, {1, 0, 0}, 4},
      {{1.0, 1.0, 0.2}, {4, 3, 1}, 2, {0, 1, 0}, 3},
      {{1.0, 0.3}, {2, 1}, 0, {1, 0}, 2},
  };
  int tried = 0;
  for (const Case& c : cases) {
    const ChainDesigns designs = designSprings(c.masses, 1.0, c.ratios);
    for (std::size_t d = 0; d < designs.designs.size(); ++d) {
      MassChain chain{c.masses, designs.designs[d].springs, 0, c.stop, 1.0};
      std::ostringstream words;
      words << c.masses.size() << " masses, design " << d << ", ratios";
      for (int n : c.ratios) words << ' ' << n;
      const std::string what = words.str();
      expectGrazesAtItsOwnPeriod<double>(chain, c.weights, c.repeats, what + ", double");
      expectGrazesAtItsOwnPeriod<long double>(chain, c.weights, c.repeats, what + ", long double");
      expectGrazesAtItsOwnPeriod<Quad>(chain, c.weights, c.repeats, what + ", binary128");
      ++tried;
    }
  }
  EXPECT_GE(tried, int(cases.size()));
}

TEST(ChainRun, AfterItsStopPeriodAFlightIsItsClosedFormThere) {
  // u_s's period T/g and the flight after it: the modes that move the stopped mass exactly as they
  // were, a mode with a node at the stop turned by 2 pi n_j / g as its closed form says, a still
  // one still. The 3:2:1 chain's mode 2 is given a node at the stop here (P[s][1] = 0), which
  // no designed chain in the tests has.
  ChainDynamics dynamics = chainDynamics(designed({1.0, 0.2, 0.05}, {3, 2, 1}));
  ASSERT_EQ(dynamics.harmonics, (std::vector<int>{3, 2, 1}));
  dynamics.P(dynamics.stop, 1) = 0;
  ChainFlight flight;
  flight.q = Eigen::Vector3d(0.5, 0.3, 0.0);
  flight.qdot = Eigen::Vector3d(0.0, 0.1, 0.0);
  EXPECT_EQ(stopRepeats(dynamics, flight), 3);  // mode 1 alone moves the stopped mass
  const ChainFlight before = flight;
  EXPECT_TRUE(afterStopPeriod(dynamics, 3, flight));
  EXPECT_EQ(flight.q[0], before.q[0]);
  EXPECT_EQ(flight.qdot[0], before.qdot[0]);
  EXPECT_EQ(flight.q[2], 0.0);
  EXPECT_EQ(flight.qdot[2], 0.0);
  const double w = dynamics.omega[1], angle = w * dynamics.period / 3;  // 4 pi / 3
  EXPECT_NEAR(angle, 4 * std::numbers::pi / 3, 1e-14);
  EXPECT_NEAR(flight.q[1], before.q[1] * std::cos(angle) + before.qdot[1] / w * std::sin(angle), 1e-15);
  EXPECT_NEAR(flight.qdot[1], -before.q[1] * w * std::sin(angle) + before.qdot[1] * std::cos(angle), 1e-15);
  // with every moving mode a whole number of its periods on, nothing turns
  flight = before;
  flight.q[1] = flight.qdot[1] = 0;
  EXPECT_FALSE(afterStopPeriod(dynamics, 3, flight));
  // every mode moving the stopped mass (g = 1): the flight is its start again, bit for bit
  const ChainDynamics plain = chainDynamics(designed({1.0, 0.2, 0.05}, {3, 2, 1}));
  flight = before;
  EXPECT_EQ(stopRepeats(plain, flight), 1);
  EXPECT_FALSE(afterStopPeriod(plain, 1, flight));
  EXPECT_EQ(flight.q, before.q);
}

TEST(ChainRun, AGlomPushedOffItsModeIsDecidedAsAnyStart) {
  // GLOM_1 of 3:2:1 with the slow mode's velocity pushed by 1e-9: no mode is still any more, every
  // mode moves the stopped mass (g = 1); its events agree with binary128's where double decides
  const MassChain chain = designed({1.0, 0.2, 0.05}, {3, 2, 1});
  const ChainGloStart glo = chainGloStart(chain, {1, 0, 0});
  ChainState pushed = glo.state;
  pushed.v += 1e-9 * chainModes(chain).P.col(2);
  const ChainRun run = runChain(chain, pushed, 40);
  const BasicChainRun<Quad> reference = runChain(chainCast<Quad>(chain), stateCast<Quad>(pushed), 40);
  const double period = chainDynamics(chain).period;
  expectAPrefixOf(run, reference, period, "GLOM_1 pushed");
  EXPECT_GT(reference.contacts, 0);
}

TEST(ChainRun, AStartAtRestOnTheStopLeavesItOrSticks) {
  // mass 2 of the 1:2 chain at rest on the stop with mass 1 at rest at 0: pulled away by its
  // spring it leaves, and (both modes at their tops at once) grazes the stop again after each
  // period T; pushed into the stop (mass 1 at rest at 3) it sticks at once, never a loop of
  // touches at t = 0, while mass 1 swings alone about c = k2 d / (k1 + k2) at W^2 = (k1 + k2)
  // / m1, and is released when u1 falls back to d
  const MassChain chain = designed({1.0, 0.5}, {2, 1});
  const double period = chainDynamics(chain).period;
  const ChainRun pulled = runChain(chain, ChainState{Eigen::Vector2d(0.0, 1.0), Eigen::Vector2d::Zero()}, 3);
  ASSERT_EQ(pulled.events.size(), 3u) << int(pulled.stop);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(pulled.events[k].type, EventType::Grazing);
    EXPECT_NEAR(pulled.events[k].t, double(k + 1) * period, 1e-6 * period);
  }
  const ChainRun pressed = runChain(chain, ChainState{Eigen::Vector2d(3.0, 1.0), Eigen::Vector2d::Zero()}, 5);
  ASSERT_GE(pressed.events.size(), 2u);
  EXPECT_EQ(pressed.events[0].type, EventType::Stick);
  EXPECT_EQ(pressed.events[0].t, 0);
  EXPECT_EQ(pressed.events[1].type, EventType::Release);
  const double k1 = chain.springs[0], k2 = chain.springs[1];
  const double centre = k2 * chain.gap / (k1 + k2), swing = std::sqrt((k1 + k2) / chain.masses[0]);
  EXPECT_NEAR(pressed.events[1].t, std::acos((chain.gap - centre) / (3.0 - centre)) / swing, 1e-13);
  EXPECT_NEAR(pressed.events[1].vBefore[0], -swing * std::sqrt(std::pow(3.0 - centre, 2) - std::pow(chain.gap - centre, 2)),
              1e-13);
  EXPECT_EQ(pressed.contacts, 5);
}

// A flat start: mass s at rest on the stop with no force (its neighbour at d too) and no jerk
// (everything at rest). Its fourth derivative, (k_s a_(s-1)) / m_s with a the neighbour's
// acceleration, decides: pulled off (mass 1 behind d) it leaves as t^4, and on a resonant chain
// comes back just so at every period T (a grazing with no force, leaving the same way again),
// in double and in binary128; pushed on (mass 1 beyond d) it is held at once and released
// later. Until the fourth derivative was taken, both were undecided at t = 0.
TEST(ChainRun, AFlatStartLeavesByItsFourthDerivativeOrIsHeld) {
  const MassChain chain = designed({1.0, 0.2, 0.05}, {3, 2, 1});
  const double period = chainDynamics(chain).period;
  const ChainState pulled{Eigen::Vector3d(0.3, 1.0, 1.0), Eigen::Vector3d::Zero()};
  const ChainRun run = runChain(chain, pulled, 4);
  ASSERT_EQ(run.events.size(), 4u) << int(run.stop);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(run.events[k].type, EventType::Grazing) << k;
    EXPECT_NEAR(run.events[k].t, double(k + 1) * period, 1e-12 * period) << k;
    EXPECT_NEAR(run.events[k].u[0], 0.3, 1e-12) << k;  // the start again
  }
  BasicChainState<Quad> pulledQuad{ChainVector<Quad>(3), ChainVector<Quad>::Zero(3)};
  pulledQuad.u << Quad(0.3), Quad(1), Quad(1);
  const BasicChainRun<Quad> quad = runChain(chainCast<Quad>(chain), pulledQuad, 2);
  ASSERT_EQ(quad.events.size(), 2u) << int(quad.stop);
  EXPECT_EQ(quad.events[1].type, EventType::Grazing);
  EXPECT_NEAR(double(quad.events[1].t), 2 * period, 1e-12 * period);

  const ChainRun pushed = runChain(chain, ChainState{Eigen::Vector3d(1.7, 1.0, 1.0), Eigen::Vector3d::Zero()}, 3);
  ASSERT_GE(pushed.events.size(), 2u) << int(pushed.stop);
  EXPECT_EQ(pushed.events[0].type, EventType::Stick);
  EXPECT_EQ(pushed.events[0].t, 0);
  EXPECT_EQ(pushed.events[1].type, EventType::Release);
  EXPECT_GT(pushed.events[1].t, 0);

  // N = 2 (the stop on mass 2, mass 1 at rest on d), detuned: the modal kernel's events are the
  // note's kernel's
  const Model model{1.0, 0.3, 1.0, 0.7, 1.0, std::nullopt};
  const MassChain two{{1.0, 0.3}, {1.0, 0.7}, 0, 0, 1.0};
  Request request;
  request.initial = {1.0, 1.0, 0.0, 0.0};
  request.maxContacts = 6;
  const Result reference = simulate(model, request);
  const ChainRun flat =
      runChain(readyChain(two, Kernel::Modal), ChainState{Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d::Zero()}, 6);
  ASSERT_EQ(flat.events.size(), reference.events.size()) << int(flat.stop);
  for (std::size_t k = 0; k < flat.events.size(); ++k) {
    EXPECT_EQ(flat.events[k].type, reference.events[k].type) << k;
    EXPECT_NEAR(flat.events[k].t, reference.events[k].t, 1e-12 * (1 + reference.events[k].t)) << k;
  }
}

TEST(ChainRun, ScalesWithTheChain) {
  // masses x 1000, springs x 10, gap x 7: times x 10, displacements x 7
  std::mt19937 random(3);
  const MassChain chain = designed({1.0, 0.4, 0.2}, {5, 3, 1});
  MassChain scaled = chain;
  for (double& m : scaled.masses) m *= 1000;
  for (double& k : scaled.springs) k *= 10;
  scaled.gap *= 7;
  const ChainState start = randomStart(chain, random);
  const ChainState bigger{7 * start.u, 0.7 * start.v};
  const ChainRun a = runChain(chain, start, 40);
  const ChainRun b = runChain(scaled, bigger, 40);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t k = 0; k < a.events.size(); ++k) {
    EXPECT_NEAR(b.events[k].t / (10 * a.events[k].t), 1.0, 1e-9) << k;
    EXPECT_EQ(a.events[k].type, b.events[k].type);
  }
}

// a run that streams its events (a sink) makes the same run as one that keeps them, holds none,
// and counts them by type; its error estimate, compared event by event as they come, is the one
// of the kept run (sticks and releases included: a pressed start)
TEST(ChainRun, AStreamedRunIsTheKeptRun) {
  const MassChain chain{{1.0, 0.7, 0.4}, {1.0, 0.8, 0.6}, 0, 2, 1.0};
  const ChainState start{Eigen::Vector3d(1.4, 1.0, 1.3), Eigen::Vector3d(0.1, 0.0, -0.2)};
  const ChainRun kept = runChain(chain, start, 40);
  std::vector<ChainEvent> streamed;
  const ReadyChain ready = readyChain(chain);
  std::optional<BasicReadyChain<long double>> widened;
  const ChainShadow<double> shadow = widenedShadow(ready, widened);
  TrustMonitor<double> check(shadow, {{start.u.cast<long double>(), start.v.cast<long double>()}}, 40, 0.0L,
                             TrustMode::Full);
  const ChainRun run = runChain(chain, start, 40, 0.0, {}, [&](const ChainEvent& event) {
    streamed.push_back(event);
    check.observe(event);
  });
  EXPECT_TRUE(run.events.empty());
  ASSERT_EQ(streamed.size(), kept.events.size());
  long byType[4] = {0, 0, 0, 0};
  for (std::size_t k = 0; k < streamed.size(); ++k) {
    EXPECT_EQ(streamed[k].t, kept.events[k].t);
    EXPECT_EQ(streamed[k].type, kept.events[k].type);
    EXPECT_EQ(streamed[k].u, kept.events[k].u);
    ++byType[int(streamed[k].type)];
  }
  EXPECT_GT(kept.sticks, 0);
  EXPECT_GT(kept.releases, 0);
  EXPECT_EQ(run.impacts, byType[int(EventType::Impact)]);
  EXPECT_EQ(run.grazings, byType[int(EventType::Grazing)]);
  EXPECT_EQ(run.sticks, byType[int(EventType::Stick)]);
  EXPECT_EQ(run.releases, byType[int(EventType::Release)]);
  EXPECT_EQ(run.contacts, run.impacts + run.grazings + run.sticks);
  EXPECT_EQ(run.final.u, kept.final.u);
  const Trust whole = trustOf(ready, start, kept, 40, 0.0, TrustMode::Full);
  const Trust online = check.finish(run);
  EXPECT_EQ(online.verdict, whole.verdict);
  EXPECT_EQ(online.horizon, whole.horizon);
  EXPECT_EQ(online.stateError, whole.stateError);
}

// a run advanced in pieces (the explorer's worker shows each) is the run made at once, bit for
// bit, events and samples alike: pieces of 1, 3 and 17 contacts on a designed 3:2:1 chain near
// grazing, a chain that sticks and releases (stop on an interior mass), eight masses on a
// string stopped inside it, a right wall, binary128; a run that ends before its contacts
// (a time limit) ends the same way
template <typename S>
void expectPiecesAreTheWhole(const BasicMassChain<S>& chain, const BasicChainState<S>& start, long contacts, S tEnd,
                             const std::string& name) {
  using Sampled = std::vector<std::pair<double, BasicChainState<S>>>;
  const auto samplingInto = [](Sampled& into) {
    return ChainSampling<S>{0.05, {}, [&into](double t, const BasicChainState<S>& state) { into.emplace_back(t, state); }};
  };
  Sampled wholeSamples;
  const BasicChainRun<S> whole = runChain(chain, start, contacts, tEnd, {}, {}, samplingInto(wholeSamples));
  for (long piece : {1L, 3L, 17L}) {
    Sampled samples;
    BasicChainSimulator<S> simulator(chain, start, contacts, tEnd, {}, samplingInto(samples));
    long pieces = 0;
    while (!simulator.advance(piece)) {
      ++pieces;
      ASSERT_EQ(simulator.run().contacts, piece * pieces) << name;
      ASSERT_FALSE(simulator.done());
    }
    const BasicChainRun<S>& run = simulator.run();
    ASSERT_EQ(run.events.size(), whole.events.size()) << name << ", pieces of " << piece;
    for (std::size_t k = 0; k < run.events.size(); ++k) {
      ASSERT_TRUE(run.events[k].t == whole.events[k].t && run.events[k].type == whole.events[k].type &&
                  run.events[k].u == whole.events[k].u && run.events[k].vBefore == whole.events[k].vBefore &&
                  run.events[k].vAfter == whole.events[k].vAfter)
          << name << ", pieces of " << piece << ": event " << k;
    }
    EXPECT_EQ(run.stop, whole.stop) << name;
    EXPECT_TRUE(run.tFinal == whole.tFinal && run.final.u == whole.final.u && run.final.v == whole.final.v) << name;
    EXPECT_TRUE(run.energyFinal == whole.energyFinal) << name;
    ASSERT_EQ(samples.size(), wholeSamples.size()) << name;
    for (std::size_t k = 0; k < samples.size(); ++k) {
      ASSERT_TRUE(samples[k].first == wholeSamples[k].first && samples[k].second.u == wholeSamples[k].second.u &&
                  samples[k].second.v == wholeSamples[k].second.v)
          << name << ", sample " << k;
    }
    EXPECT_TRUE(simulator.advance(5)) << "a run over stays over";
    EXPECT_EQ(simulator.run().events.size(), whole.events.size());
  }
}

TEST(ChainRun, ARunInPiecesIsTheWholeRun) {
  {
    const MassChain chain = designed({1.0, 0.2, 0.05}, {3, 2, 1});
    ChainState start{Eigen::Vector3d(0.2, 0.3, 0.999), Eigen::Vector3d(0.0, 0.0, -1e-3)};
    expectPiecesAreTheWhole(chain, start, 60, 0.0, "3:2:1 near grazing");
  }
  {
    const MassChain chain{{1.0, 0.7, 0.4}, {1.0, 0.8, 0.6}, 0, 2, 1.0};
    const ChainState start{Eigen::Vector3d(1.4, 1.0, 1.3), Eigen::Vector3d(0.1, 0.0, -0.2)};
    const ChainRun run = runChain(chain, start, 40);
    ASSERT_GT(run.sticks, 0);
    ASSERT_GT(run.releases, 0);
    expectPiecesAreTheWhole(chain, start, 40, 0.0, "sticks on mass 2");
    expectPiecesAreTheWhole(chain, start, 40, run.events[20].t, "sticks, ended by time");
    expectPiecesAreTheWhole(chainCast<Quad>(chain), BasicChainState<Quad>{start.u.cast<Quad>(), start.v.cast<Quad>()},
                            12, Quad(0), "sticks, binary128");
  }
  {
    MassChain chain{std::vector<double>(8, 1.0), std::vector<double>(8, 1.0), 0, 5, 1.0};
    ChainState start{Eigen::VectorXd::Zero(8), Eigen::VectorXd::Zero(8)};
    const ChainModes modes = chainModes(chain);
    start.u = modes.P.col(7) / modes.P(4, 7);  // the slowest mode with its top on the stop
    start.v[4] = -1e-4;
    expectPiecesAreTheWhole(chain, start, 40, 0.0, "eight masses, stop on 5");
  }
  {
    const MassChain chain{{1.0, 2.0}, {1.5, 0.7}, 0.9, 1, 0.5};
    const ChainState start{Eigen::Vector2d(0.1, -0.3), Eigen::Vector2d(0.8, 0.2)};
    expectPiecesAreTheWhole(chain, start, 50, 0.0, "right wall, stop on 1");
  }
}

// A chain made ready once runs as the chain itself, however many runs share it: the same events,
// final state and error estimate to the bit, each run from another start in turn (a run that
// changed the ready chain, or a shadow kept from the run before, would show here); in double,
// long double and binary128, resonant or not, an interior stop, a right wall
template <typename S>
void expectReadyRunsAsTheChain(const BasicMassChain<S>& chain, const std::vector<ChainState>& starts, long contacts,
                               const char* name) {
  const BasicReadyChain<S> ready = readyChain(chain);
  std::optional<BasicReadyChain<ShadowScalar<S>>> widened;
  const ChainShadow<S> shadow = widenedShadow(ready, widened);
  for (int pass = 0; pass < 2; ++pass) {
    for (const ChainState& given : starts) {
      const BasicChainState<S> start{given.u.cast<S>(), given.v.cast<S>()};
      const BasicChainRun<S> once = runChain(chain, start, contacts);
      const BasicChainRun<S> shared = runChain(ready, start, contacts);
      ASSERT_EQ(once.events.size(), shared.events.size()) << name;
      for (std::size_t k = 0; k < once.events.size(); ++k) {
        ASSERT_TRUE(once.events[k].t == shared.events[k].t && once.events[k].type == shared.events[k].type &&
                    once.events[k].u == shared.events[k].u && once.events[k].vBefore == shared.events[k].vBefore &&
                    once.events[k].vAfter == shared.events[k].vAfter)
            << name << " event " << k;
      }
      EXPECT_TRUE(once.final.u == shared.final.u && once.final.v == shared.final.v && once.stop == shared.stop) << name;
      const Trust made = trustOf(readyChain(chain), start, once, contacts, S(0), TrustMode::Full);
      using H = ShadowScalar<S>;
      TrustMonitor<S> monitor(shadow, {{start.u.template cast<H>(), start.v.template cast<H>()}}, contacts, H(0),
                              TrustMode::Full);
      for (const BasicChainEvent<S>& event : shared.events) monitor.observe(event);
      const Trust kept = monitor.finish(shared);
      EXPECT_TRUE(made.verdict == kept.verdict && made.stateError == kept.stateError &&
                  made.timeError == kept.timeError && made.horizon == kept.horizon && made.reason == kept.reason)
          << name << ": " << made.reason << " against " << kept.reason;
    }
  }
}

TEST(ChainRun, AChainMadeReadyOnceRunsAsTheChain) {
  std::mt19937 random(29);
  const MassChain resonant = designed({1.0, 0.2, 0.05}, {3, 2, 1});
  const MassChain interior{{1.0, 0.7, 0.4}, {1.0, 0.8, 0.6}, 0.5, 2, 0.8};
  const MassChain four = designed({1.0, 0.6, 0.36, 0.216}, {4, 3, 2, 1});
  for (const auto& [chain, name] : {std::pair{resonant, "3:2:1"}, std::pair{interior, "interior stop, right wall"},
                                    std::pair{four, "4:3:2:1"}}) {
    std::vector<ChainState> starts;
    for (int k = 0; k < 3; ++k) starts.push_back(randomStart(chain, random));
    expectReadyRunsAsTheChain(chain, starts, 25, name);
    expectReadyRunsAsTheChain(chainCast<long double>(chain), starts, 10, name);
    expectReadyRunsAsTheChain(chainCast<Quad>(chain), starts, 4, name);
  }
}

// dense samples: on the grid asked for, up to the run's end; each keeps the energy; on the
// stop during a stuck phase and never past it; the samples obey M u'' = -K u away from the
// events (a central difference of samples h apart, the stopped mass included, where it flies);
// a sample at an event's time is the state just after it
TEST(ChainRun, SamplesFollowTheMotionBetweenEvents) {
  const MassChain chain{{1.0, 0.7, 0.4}, {1.0, 0.8, 0.6}, 0, 2, 1.0};
  const ChainState start{Eigen::Vector3d(1.4, 1.0, 1.3), Eigen::Vector3d(0.1, 0.0, -0.2)};
  const Eigen::MatrixXd K = stiffnessMatrix(chain);
  const ChainRun run = runChain(chain, start, 12);
  std::vector<std::pair<double, ChainState>> samples;
  ChainSampling<double> sampling{0.01, {}, [&](double t, const ChainState& state) { samples.emplace_back(t, state); }};
  const ChainRun sampled = runChain(chain, start, 12, 0.0, {}, {}, sampling);
  ASSERT_EQ(sampled.events.size(), run.events.size());  // sampling changes nothing
  EXPECT_EQ(sampled.final.u, run.final.u);
  ASSERT_EQ(samples.size(), std::size_t(std::floor(run.tFinal / 0.01)) + 1);
  int checked = 0, stuck = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const auto& [t, state] = samples[k];
    EXPECT_EQ(t, 0.01 * double(k));
    EXPECT_NEAR(chainEnergy(chain, state), run.energyInitial, 1e-12 * run.energyInitial) << "t = " << t;
    EXPECT_LE(state.u[1], chain.gap + 1e-12) << "t = " << t;
    // where the event before it is a stick, mass 2 is held on the stop
    std::size_t before = 0;
    while (before + 1 < run.events.size() && run.events[before + 1].t <= t) ++before;
    if (run.events[before].type == EventType::Stick && run.events[before].t <= t &&
        (before + 1 >= run.events.size() || t < run.events[before + 1].t)) {
      EXPECT_EQ(state.u[1], chain.gap) << "t = " << t;
      ++stuck;
    }
    // away from every event by two samples: the equations of motion by central differences
    if (k == 0 || k + 1 >= samples.size()) continue;
    bool nearEvent = false;
    for (const ChainEvent& event : run.events) nearEvent |= std::abs(event.t - t) < 0.025;
    if (nearEvent || state.u[1] == chain.gap) continue;
    const Eigen::VectorXd acceleration = (samples[k + 1].second.u - 2 * state.u + samples[k - 1].second.u) / (0.01 * 0.01);
    const Eigen::VectorXd force = -K * state.u;
    for (int m = 0; m < 3; ++m) {
      EXPECT_NEAR(chain.masses[std::size_t(m)] * acceleration[m], force[m], 1e-3 * (1 + force.cwiseAbs().maxCoeff()))
          << "t = " << t << ", mass " << m + 1;
    }
    ++checked;
  }
  EXPECT_GT(checked, 100);
  EXPECT_GT(stuck, 10);
  // at the events' own times: the state just after each
  std::vector<double> times;
  for (const ChainEvent& event : run.events) {
    if (times.empty() || event.t > times.back()) times.push_back(event.t);
  }
  std::vector<std::pair<double, ChainState>> atEvents;
  runChain(chain, start, 12, 0.0, {}, {},
           ChainSampling<double>{0, times, [&](double t, const ChainState& state) { atEvents.emplace_back(t, state); }});
  ASSERT_EQ(atEvents.size(), times.size());
  for (std::size_t k = 0; k < atEvents.size(); ++k) {
    const auto last = std::find_if(run.events.rbegin(), run.events.rend(),
                                   [&](const ChainEvent& event) { return event.t == atEvents[k].first; });
    ASSERT_NE(last, run.events.rend());
    EXPECT_LT((atEvents[k].second.u - last->u).cwiseAbs().maxCoeff(), 1e-12) << "t = " << atEvents[k].first;
    EXPECT_NEAR(atEvents[k].second.v[1], last->vAfter, 1e-12) << "t = " << atEvents[k].first;
  }
}

}  // namespace
}  // namespace grazelab::core
