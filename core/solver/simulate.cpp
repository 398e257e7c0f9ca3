// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/simulate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace grazelab::core {

template <typename S>
std::vector<Problem> validate(const BasicRequest<S>& request) {
  std::vector<Problem> problems;
  auto add = [&](const char* field, const std::string& reason, const std::string& value) {
    problems.push_back({field, reason + " (got " + value + ")"});
  };
  if (request.maxContacts < 0) {
    add("contacts", "must not be negative", std::to_string(request.maxContacts));
  }
  if (!(request.tEnd >= 0)) add("t-end", "must be >= 0", formatScalar(request.tEnd));
  if (request.flightSearchSteps < 1) {
    add("flightSearchSteps", "must be at least 1", std::to_string(request.flightSearchSteps));
  }
  if (!std::isfinite(request.flightSearchPeriods) || request.flightSearchPeriods <= 0) {
    add("flightSearchPeriods", "must be positive and finite",
        std::to_string(request.flightSearchPeriods));
  }
  const SampleSpec& samples = request.needs.samples;
  if (!std::isfinite(samples.spacing) || samples.spacing < 0) {
    add("samples.spacing", "must be >= 0 and finite", std::to_string(samples.spacing));
  }
  for (std::size_t i = 0; i < samples.times.size(); ++i) {
    if (!std::isfinite(samples.times[i]) || samples.times[i] < 0 ||
        (i > 0 && !(samples.times[i] >= samples.times[i - 1]))) {
      add("samples.times", "must be finite, >= 0 and ascending", std::to_string(samples.times[i]));
      break;
    }
  }
  if (!std::isfinite(samples.tBegin) || samples.tBegin < 0) {
    add("samples.tBegin", "must be >= 0 and finite", std::to_string(samples.tBegin));
  }
  return problems;
}


template <typename S>
BasicSimulator<S>::BasicSimulator(const BasicModel<S>& model, const BasicRequest<S>& request)
    : m_request(request) {
  std::vector<Problem> problems = validate(model);
  for (Problem& problem : validateState(model, request.initial, "initial")) {
    problems.push_back(std::move(problem));
  }
  for (Problem& problem : validate(request)) problems.push_back(std::move(problem));
  m_result.final = request.initial;
  if (problems.empty()) {
    TwoMassFormOrProblem<S> formed = makeTwoMassForm(model);
    if (!formed.chain) problems.push_back({"model", formed.problem});
    m_chain = std::move(formed.chain);
  }
  if (!problems.empty()) {
    m_result.stop = StopReason::InvalidInput;
    m_result.message = describe(problems);
    m_done = true;
    return;
  }
  const TwoMassForm<S>& chain = *m_chain;
  m_scale = chooseScale(chain, request.initial);
  m_state.x = m_scale.toScaled(request.initial);
  m_result.initialEnergy = physicalEnergy(chain, request.initial);
  m_tauEnd = m_scale.toScaledTime(request.tEnd);
  // an explicit end time bounds the search; without one, the detuned search limit does
  m_searchHorizon = isFinite(request.tEnd) ? S(kInfinity)
                                           : S(twoPi<S>() * S(request.flightSearchPeriods));
  m_stepper.emplace(chain, m_scale.gap);
  m_recorder.emplace(chain, m_scale, m_state.x, request.needs, request.onEvent, m_result);
  // one entry per contact: reserve up front, capped (a section longer than the cap regrows
  // geometrically; a cap of millions costs a page-mapping of hundreds of MB for every short run)
  const std::size_t expected =
      std::size_t(std::clamp<std::int64_t>(request.maxContacts, 0, 1 << 16));
  if (request.needs.events && !std::isfinite(request.needs.eventsUntil)) {
    m_result.events.reserve(expected);
  }
  if (request.needs.poincare) m_result.poincare.reserve(expected);
  if (request.needs.freeFlights) m_result.freeFlights.reserve(expected);
}

template <typename S>
double BasicSimulator<S>::progress() const {
  if (m_done) return 1.0;
  double fraction = 0;
  if (m_request.maxContacts > 0) {
    fraction = double(m_result.cost.contacts) / double(m_request.maxContacts);
  }
  if (isFinite(m_tauEnd) && m_tauEnd > 0) {
    fraction = std::max(fraction, toDouble(m_state.tau / m_tauEnd));
  }
  return std::clamp(fraction, 0.0, 1.0);
}

template <typename S>
void BasicSimulator<S>::finish(StopReason reason, const S& t, const BasicState<S>& scaled) {
  m_recorder->finish(reason, t, scaled);
  m_done = true;
}

template <typename S>
bool BasicSimulator<S>::advance(std::int64_t contactBudget, std::stop_token stop) {
  if (m_done) return true;
  const auto started = std::chrono::steady_clock::now();
  Cost& cost = m_result.cost;
  const std::int64_t target =
      cost.contacts + std::min(contactBudget, std::numeric_limits<std::int64_t>::max() - cost.contacts);
  auto lastEventTime = [&] { return m_scale.toPhysicalTime(m_state.tau); };
  while (!m_done && cost.contacts < target) {
    if (stop.stop_requested()) {
      finish(StopReason::Cancelled, lastEventTime(), m_state.x);
    } else if (cost.contacts >= m_request.maxContacts) {
      finish(StopReason::ContactLimit, lastEventTime(), m_state.x);
    } else if (m_state.tau >= m_tauEnd) {
      finish(StopReason::TimeLimit, m_request.tEnd, m_state.x);
    } else {
      const Step<S> step = m_stepper->advance(m_state, m_tauEnd, m_searchHorizon, stop,
                                              m_request.flightSearchSteps,
                                              m_request.stopAtUndecided);
      if (step.kind == Step<S>::Kind::Undecided) {
        // the state is where the flight began: a higher precision goes on from the input
        m_result.message = "contact " + std::to_string(cost.contacts + 1) + " (t = " +
                           formatScalar(m_scale.toPhysicalTime(step.tau)) +
                           ") touches the stop within rounding: " +
                           std::string(toString(precisionOf<S>())) +
                           " cannot tell a graze from an impact there";
        finish(StopReason::Undecided, lastEventTime(), m_state.x);
        break;
      }
      m_recorder->sampleUntil(*m_stepper, step.segmentStart, step.tau);
      switch (step.kind) {
        case Step<S>::Kind::Event:
          m_recorder->record(step);
          break;
        case Step<S>::Kind::End:
          finish(StopReason::TimeLimit, m_request.tEnd, step.before);
          break;
        case Step<S>::Kind::NoFurtherContact: {
          // the motion is still drawn: its free orbit over the sample window (one slow period,
          // 2 pi in scaled time, when the window is open-ended), or a plot would be blank
          const double windowEnd = m_request.needs.samples.tEnd;
          const S oneSlowPeriod = step.segmentStart + twoPi<S>();
          const S tauSamplesEnd = std::isfinite(windowEnd)
                                      ? m_scale.toScaledTime(S(windowEnd))
                                      : oneSlowPeriod;
          m_recorder->sampleUntil(*m_stepper, step.segmentStart, tauSamplesEnd);
          m_result.message = "the free motion stays below the stop forever: no further contact";
          finish(StopReason::NoFurtherContact, lastEventTime(), step.before);
          break;
        }
        case Step<S>::Kind::SearchLimit:
          m_result.message = "no contact within " + std::to_string(m_request.flightSearchPeriods) +
                             " T2 of free flight";
          finish(StopReason::SearchLimit, m_scale.toPhysicalTime(step.tau), step.before);
          break;
        case Step<S>::Kind::SearchBudget:
          m_result.message = "the contact search of a flight ran out of its budget of " +
                             std::to_string(m_request.flightSearchSteps) +
                             " steps at t = " + formatScalar(m_scale.toPhysicalTime(step.tau)) +
                             " without deciding whether the stop is reached";
          finish(StopReason::SearchBudget, m_scale.toPhysicalTime(step.tau), step.before);
          break;
        case Step<S>::Kind::Cancelled:
          finish(StopReason::Cancelled, lastEventTime(), m_state.x);
          break;
        case Step<S>::Kind::Undecided:
          break;  // ended above
      }
    }
  }
  if (!m_done && cost.contacts >= m_request.maxContacts) {
    finish(StopReason::ContactLimit, lastEventTime(), m_state.x);
  }
  cost.wallSeconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return m_done;
}

template <typename S>
BasicResult<S> simulate(const BasicModel<S>& model, const BasicRequest<S>& request,
                        std::stop_token stop) {
  BasicSimulator<S> simulator(model, request);
  while (!simulator.advance(std::numeric_limits<std::int64_t>::max(), stop)) {
  }
  return simulator.takeResult();
}

template <typename S>
void accountForUndecidedTouches(Trust& trust, const BasicResult<S>& result) {
  const Cost& cost = result.cost;
  if (cost.undecidedTouches == 0) return;
  const double hidden = std::sqrt(32 * toDouble(epsilon<S>()));
  trust.stateError = std::max(trust.stateError, hidden);
  trust.timeError = std::max(trust.timeError, hidden);
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", hidden);
  char time[32];
  std::snprintf(time, sizeof time, "%.10g", cost.firstUndecidedTime);
  std::string note = "contact " + std::to_string(cost.firstUndecidedContact) + " (t = " + time + ")";
  if (cost.undecidedTouches > 1) {
    note += " and " + std::to_string(cost.undecidedTouches - 1) + " more";
  }
  note += " touched the stop within rounding: " + std::string(toString(precisionOf<S>())) +
          " cannot tell a graze from an impact there (error up to " + text +
          " from there on" +
          (std::is_same_v<S, Quad> ? std::string(")") : std::string("; --precision auto goes higher)"));
  const double worst = std::max(trust.stateError, trust.timeError);
  if (trust.verdict != Verdict::Unreliable) {
    trust.verdict = worst > kHorizonTolerance ? Verdict::Unreliable : Verdict::Degraded;
  }
  trust.reason = note + "; " + trust.reason;
}

#define GRAZELAB_INSTANTIATE(S)                                                       \
  template std::vector<Problem> validate<S>(const BasicRequest<S>&);                  \
  template void accountForUndecidedTouches<S>(Trust&, const BasicResult<S>&);         \
  template class BasicSimulator<S>;                                                   \
  template BasicResult<S> simulate<S>(const BasicModel<S>&, const BasicRequest<S>&,   \
                                      std::stop_token);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
