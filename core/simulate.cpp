// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/simulate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "core/contact.h"
#include "core/free_flight.h"
#include "core/sticking.h"

namespace grazelab::core {
namespace {

std::vector<Problem> validateRequest(const Request& request) {
  std::vector<Problem> problems;
  auto add = [&](const char* field, const std::string& reason, double value) {
    std::ostringstream text;
    text.precision(17);
    text << reason << " (got " << value << ")";
    problems.push_back({field, text.str()});
  };
  if (request.maxContacts < 0) add("contacts", "must not be negative", double(request.maxContacts));
  if (std::isnan(request.tEnd) || request.tEnd < 0) add("t-end", "must be >= 0", request.tEnd);
  if (!std::isfinite(request.flightSearchPeriods) || request.flightSearchPeriods <= 0) {
    add("flightSearchPeriods", "must be positive and finite", request.flightSearchPeriods);
  }
  const SampleSpec& samples = request.needs.samples;
  if (!std::isfinite(samples.spacing) || samples.spacing < 0) {
    add("samples.spacing", "must be >= 0 and finite", samples.spacing);
  }
  if (!std::isfinite(samples.tBegin) || samples.tBegin < 0) {
    add("samples.tBegin", "must be >= 0 and finite", samples.tBegin);
  }
  return problems;
}

// Free flight is exact and conserves the energy, but its computed end state carries rounding
// that the rounded modal basis (P, w1, w2 in double) biases the same way at every contact: left
// alone, the energy drifts linearly, about 1e-16 per flight. The end state is therefore moved
// back onto the energy level of the flight's start, along the energy gradient with u2 held on
// the stop: a correction of rounding size that leaves only unbiased round-off. Returns the
// relative energy error the flight had before the correction.
double restoreEnergy(const Model& model, State& state, double target) {
  const double error = energy(model, state) - target;
  const double gradientU1 = (model.k1 + model.k2) * state.u1 - model.k2 * state.u2;
  const double gradientV1 = model.m1 * state.v1;
  const double gradientV2 = model.m2 * state.v2;
  const double norm = gradientU1 * gradientU1 + gradientV1 * gradientV1 + gradientV2 * gradientV2;
  if (norm > 0) {
    const double step = -error / norm;
    state.u1 += step * gradientU1;
    state.v1 += step * gradientV1;
    state.v2 += step * gradientV2;
  }
  return std::abs(error) / (target > 0 ? target : 1.0);
}

}  // namespace

std::string_view toString(StopReason reason) {
  switch (reason) {
    case StopReason::ContactLimit:
      return "contact-limit";
    case StopReason::TimeLimit:
      return "time-limit";
    case StopReason::NoFurtherContact:
      return "no-further-contact";
    case StopReason::SearchLimit:
      return "search-limit";
    case StopReason::Cancelled:
      return "cancelled";
    case StopReason::InvalidInput:
      return "invalid-input";
  }
  return "unknown";
}

Simulator::Simulator(const Model& model, const Request& request)
    : m_model(model), m_request(request), m_state(request.initial) {
  std::vector<Problem> problems = validate(model);
  for (Problem& problem : validateState(model, request.initial, "initial")) {
    problems.push_back(std::move(problem));
  }
  for (Problem& problem : validateRequest(request)) problems.push_back(std::move(problem));
  m_result.initialEnergy = energy(model, request.initial);
  m_result.final = request.initial;
  if (!problems.empty()) {
    m_result.stop = StopReason::InvalidInput;
    m_result.message = describe(problems);
    m_done = true;
    return;
  }
  m_result.modes = computeModes(model);
  m_nextSampleTime = request.needs.samples.tBegin;
  // one entry per contact: reserve up front (capped) rather than regrow a long section
  const std::size_t expected = std::size_t(std::clamp<std::int64_t>(request.maxContacts, 0, 4'000'000));
  if (request.needs.events && !std::isfinite(request.needs.eventsUntil)) {
    m_result.events.reserve(expected);
  }
  if (request.needs.poincare) m_result.poincare.reserve(expected);
  if (request.needs.freeFlights) m_result.freeFlights.reserve(expected);
}

double Simulator::progress() const {
  if (m_done) return 1.0;
  double fraction = 0;
  if (m_request.maxContacts > 0) {
    fraction = double(m_result.cost.contacts) / double(m_request.maxContacts);
  }
  if (std::isfinite(m_request.tEnd) && m_request.tEnd > 0) {
    fraction = std::max(fraction, m_t / m_request.tEnd);
  }
  return std::clamp(fraction, 0.0, 1.0);
}

void Simulator::finish(StopReason reason, double t, const State& state) {
  m_result.stop = reason;
  m_result.tFinal = t;
  m_result.final = state;
  m_done = true;
}

void Simulator::addSample(double t, const State& state) {
  if (m_result.samples.size() >= m_request.needs.samples.maxCount) {
    m_result.samplesTruncated = true;
    return;
  }
  m_result.samples.push_back({t, state});
}

template <typename Motion>
void Simulator::addSamplesUntil(double tEndOfPhase, const Motion& motion) {
  const SampleSpec& spec = m_request.needs.samples;
  if (spec.spacing <= 0) return;
  const double last = std::min(tEndOfPhase, spec.tEnd);
  while (m_nextSampleTime <= last && !m_result.samplesTruncated) {
    if (m_nextSampleTime >= m_t) addSample(m_nextSampleTime, motion.at(m_nextSampleTime - m_t));
    ++m_nextSampleIndex;
    m_nextSampleTime = spec.tBegin + double(m_nextSampleIndex) * spec.spacing;
  }
}

void Simulator::recordContact(const Event& event, double residual) {
  Cost& cost = m_result.cost;
  ++cost.contacts;
  if (event.type == EventType::Impact) ++cost.impacts;
  if (event.type == EventType::Grazing) ++cost.grazings;
  if (event.type == EventType::Stick) ++cost.sticks;
  const double e0 = m_result.initialEnergy;
  const double drift = std::abs(energy(m_model, event.after) - e0) / (e0 > 0 ? e0 : 1.0);
  cost.maxRelEnergyDrift = std::max(cost.maxRelEnergyDrift, drift);
  cost.maxContactResidual = std::max(cost.maxContactResidual, residual);

  const Needs& needs = m_request.needs;
  if (needs.events && event.t <= needs.eventsUntil) m_result.events.push_back(event);
  if (needs.poincare) {
    m_result.poincare.push_back(
        {event.t, event.after.u1, event.after.v1, event.after.v2, event.type});
  }
  if (needs.samples.spacing > 0 && needs.samples.includeContacts && event.t >= needs.samples.tBegin &&
      event.t <= needs.samples.tEnd) {
    addSample(event.t, event.before);
    if (!(event.after == event.before)) addSample(event.t, event.after);
  }
}

bool Simulator::advance(std::int64_t contactBudget, std::stop_token stop) {
  const auto started = std::chrono::steady_clock::now();
  const std::int64_t target =
      m_result.cost.contacts + std::min(contactBudget, std::numeric_limits<std::int64_t>::max() -
                                                            m_result.cost.contacts);
  while (!m_done && m_result.cost.contacts < target) {
    if (stop.stop_requested()) {
      finish(StopReason::Cancelled, m_t, m_state);
    } else if (m_result.cost.contacts >= m_request.maxContacts) {
      finish(StopReason::ContactLimit, m_t, m_state);
    } else if (m_t >= m_request.tEnd) {
      finish(StopReason::TimeLimit, m_t, m_state);
    } else if (m_state.u2 == m_model.gap && m_state.v2 > 0) {
      // a start on the stop moving into it: the impact happens at once
      State after = m_state;
      after.v2 = -m_state.v2;
      recordContact({m_t, EventType::Impact, m_state, after}, 0.0);
      m_state = after;
    } else if (pressedOnStop(m_model, m_state)) {
      stepStuck();
    } else {
      stepFlight();
    }
  }
  if (!m_done && m_result.cost.contacts >= m_request.maxContacts) {
    finish(StopReason::ContactLimit, m_t, m_state);
  }
  m_result.cost.wallSeconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return m_done;
}

void Simulator::stepStuck() {
  // the contact that starts the phase; stopping here leaves the run on the stop, stuck
  if (!m_stuck) {
    m_stuck = true;
    recordContact({m_t, EventType::Stick, m_state, m_state}, 0.0);
    return;
  }
  const StuckMotion motion(m_model, m_state);
  const double release = motion.releaseTime();
  if (m_t + release > m_request.tEnd) {
    addSamplesUntil(m_request.tEnd, motion);
    finish(StopReason::TimeLimit, m_request.tEnd, motion.at(m_request.tEnd - m_t));
    return;
  }
  addSamplesUntil(m_t + release, motion);
  const State before = motion.at(release);
  const State after = motion.releaseState();
  m_t += release;
  if (m_request.needs.events && m_t <= m_request.needs.eventsUntil) {
    m_result.events.push_back({m_t, EventType::Release, before, after});
  }
  m_state = after;
  m_stuck = false;
}

void Simulator::stepFlight() {
  const Modes& modes = m_result.modes;
  const Flight flight(m_model, modes, m_state);
  const double searchLimit = m_request.flightSearchPeriods * modes.T2;
  const double remaining = m_request.tEnd - m_t;
  const Contact contact = nextContact(flight, std::min(remaining, searchLimit));

  if (contact.kind == ContactKind::None) {
    if (std::isfinite(remaining) && (modes.resonant || remaining <= searchLimit)) {
      addSamplesUntil(m_request.tEnd, flight);
      finish(StopReason::TimeLimit, m_request.tEnd, flight.at(remaining));
    } else if (modes.resonant) {
      m_result.message = "the free motion stays below the stop forever: no further contact";
      finish(StopReason::NoFurtherContact, m_t, m_state);
    } else {
      std::ostringstream text;
      text << "no contact within " << m_request.flightSearchPeriods << " T2 of free flight";
      m_result.message = text.str();
      addSamplesUntil(m_t + searchLimit, flight);
      finish(StopReason::SearchLimit, m_t + searchLimit, flight.at(searchLimit));
    }
    return;
  }

  const double duration = contact.time.value(modes.T2);
  if (m_t + duration > m_request.tEnd) {
    addSamplesUntil(m_request.tEnd, flight);
    finish(StopReason::TimeLimit, m_request.tEnd, flight.at(remaining));
    return;
  }
  addSamplesUntil(m_t + duration, flight);

  State before = flight.at(contact.time);
  before.u2 = m_model.gap;
  const double flightError = restoreEnergy(m_model, before, energy(m_model, m_state));
  m_result.cost.maxFlightEnergyError = std::max(m_result.cost.maxFlightEnergyError, flightError);
  if (flight.startsOnStop() && m_request.needs.freeFlights) {
    const double shortfall = contact.time.fromReturn ? -contact.time.offset : modes.T2 - duration;
    m_result.freeFlights.push_back({m_result.cost.contacts, duration, shortfall});
  }
  m_t += duration;

  if (contact.kind == ContactKind::Tangent || before.v2 <= 0) {
    before.v2 = 0;
    m_state = before;
    // a touch pressed into the stop starts a stuck phase (recorded by the next step)
    if (!pressedOnStop(m_model, before)) {
      recordContact({m_t, EventType::Grazing, before, before}, contact.residual);
    }
    return;
  }
  State after = before;
  after.v2 = -before.v2;
  recordContact({m_t, EventType::Impact, before, after}, contact.residual);
  m_state = after;
}

Result simulate(const Model& model, const Request& request, std::stop_token stop) {
  Simulator simulator(model, request);
  while (!simulator.advance(std::numeric_limits<std::int64_t>::max(), stop)) {
  }
  return simulator.takeResult();
}

}  // namespace grazelab::core
