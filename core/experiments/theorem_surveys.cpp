// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/experiments/theorem_surveys.h"

#include <algorithm>
#include <optional>
#include <random>
#include <vector>

#include "core/orbits/special_orbits.h"
#include "core/solver/chain_run.h"

namespace grazelab::core::experiments {

double gloHighestReach(double lambda) {
  // with c = cos s the expression is the quadratic 2 (1 - lambda) c^2 + lambda c - (1 - lambda)
  // on [-1, 1]: its ends give 1 and 1 - 2 lambda, its vertex (a maximum inside when
  // 1 - lambda < 0) -(1 - lambda) - lambda^2 / (8 (1 - lambda))
  double best = std::max(1.0, 1 - 2 * lambda);
  const double a = 1 - lambda;
  if (a < 0) {
    const double vertex = -lambda / (4 * a);
    if (vertex > -1 && vertex < 1) best = std::max(best, -a - lambda * lambda / (8 * a));
  }
  return best;
}

namespace {

// One flight from the stop: the contact that ends it (0-based) and its shortfall 1 - FFT / T2
// (exact near T2, where FFT / T2 itself would round to 1).
struct FlightFromStop {
  long contact = 0;
  double shortfall = 0;
  double fraction() const { return 1.0 - shortfall; }
};

// The flights from the stop of a run (from a contact or a release, or from a start on the stop,
// to the next contact), its contacts and how it ended.
struct Flights {
  std::vector<FlightFromStop> list;
  long contacts = 0;
  StopReason stop = StopReason::ContactLimit;
};

template <typename S>
Flights flightsIn(const BasicReadyChain<S>& chain, const State& start, std::int64_t contacts, double T2,
                  std::stop_token stop) {
  Flights flights;
  bool fromStop = start.u2 == toDouble(chain.numbers.gap) && start.v2 <= 0;
  const BasicChainState<S> first{chainStateOf(start).u.template cast<S>(), chainStateOf(start).v.template cast<S>()};
  const BasicChainRun<S> run =
      runChain(chain, first, long(contacts), S(0), stop, [&](const BasicChainEvent<S>& event) {
        if (isContact(event.type) && fromStop && event.flight > 0) {
          flights.list.push_back({flights.contacts, toDouble(event.shortfall) / T2});
        }
        if (isContact(event.type)) ++flights.contacts;
        fromStop = event.type != EventType::Stick;
      });
  flights.stop = run.stop;
  return flights;
}

// The note's chain made ready in each precision, the wider ones when first needed.
struct ReadyChains {
  const Model& model;
  ReadyChain inDouble = readyChain(model);
  std::optional<BasicReadyChain<long double>> inLong = {};
  std::optional<BasicReadyChain<Quad>> inQuad = {};
};

// The run from `start` in double, and again from its start in long double, then binary128, when
// a contact is one its precision cannot decide (simulate's --precision auto): the flights of the
// run that decided, or of binary128's up to the contact it cannot decide either.
Flights runFlights(ReadyChains& chains, const State& start, std::int64_t contacts, double T2, std::stop_token stop) {
  Flights flights = flightsIn(chains.inDouble, start, contacts, T2, stop);
  if (flights.stop != StopReason::Undecided) return flights;
  if (!chains.inLong) chains.inLong = readyChain(convertModel<long double>(chains.model));
  flights = flightsIn(*chains.inLong, start, contacts, T2, stop);
  if (flights.stop != StopReason::Undecided) return flights;
  if (!chains.inQuad) chains.inQuad = readyChain(convertModel<Quad>(chains.model));
  return flightsIn(*chains.inQuad, start, contacts, T2, stop);
}

}  // namespace

FlightSurvey surveyRandomStarts(const Model& model, int starts, std::int64_t contacts,
                                std::uint64_t seed, int bins, double binWidth,
                                std::stop_token stop) {
  FlightSurvey survey;
  survey.counts.assign(std::size_t(std::max(1, bins)), 0);
  survey.binWidth = binWidth;
  const Modes modes = computeModes(model);
  ReadyChains chains{model};
  std::mt19937_64 generator(seed);
  const double d = model.gap;
  const double speed = 1.5 * modes.omegaSlow * d;
  std::uniform_real_distribution<double> position(-1.5 * d, 1.5 * d);
  std::uniform_real_distribution<double> below(-1.5 * d, d);
  std::uniform_real_distribution<double> velocity(-speed, speed);
  for (int start = 0; start < starts; ++start) {
    if (stop.stop_requested()) return survey;
    const State initial{position(generator), below(generator), velocity(generator), velocity(generator)};
    const Flights run = runFlights(chains, initial, contacts, modes.T2, stop);
    for (const FlightFromStop& flight : run.list) {
      ++survey.flights;
      survey.longest = std::max(survey.longest, flight.fraction());
      const int bin = std::clamp(int(flight.fraction() / binWidth), 0, int(survey.counts.size()) - 1);
      ++survey.counts[std::size_t(bin)];
    }
    if (run.contacts == 0 && run.stop != StopReason::Undecided) {
      ++survey.neverTouch;
    } else if (run.contacts >= contacts) {
      ++survey.reachedLimit;
      if (!survey.firstTouching) survey.firstTouching = initial;
    } else {
      ++survey.other;
    }
  }
  survey.complete = !stop.stop_requested();
  return survey;
}

std::optional<double> largestShortfall(const Model& model, const State& start,
                                       std::int64_t contacts, std::stop_token stop) {
  ReadyChains chains{model};
  const Flights run = runFlights(chains, start, contacts, computeModes(model).T2, stop);
  if (stop.stop_requested()) return std::nullopt;
  double shortfall = 0;
  for (const FlightFromStop& flight : run.list) shortfall = std::max(shortfall, flight.shortfall);
  return shortfall;
}

std::vector<OnePeriodicOrbit<double>> onePeriodicFamilySamples(const Model& model, const Modes& modes,
                                                               double lowEnd, int points,
                                                               std::stop_token stop) {
  std::vector<OnePeriodicOrbit<double>> samples;
  const double T2 = modes.T2;
  for (int i = points; i >= 1 && !stop.stop_requested(); --i) {
    // squared spacing: the points crowd towards T2; 1e-6 keeps the first clear of the low end
    const double s = double(i) / points;
    const double T = T2 - (T2 - lowEnd) * (1 - 1e-6) * s * s;
    OnePeriodicOrbit orbit = onePeriodicOrbit(model, modes, T);
    if (orbit.admissible) samples.push_back(std::move(orbit));
  }
  return samples;
}

}  // namespace grazelab::core::experiments
