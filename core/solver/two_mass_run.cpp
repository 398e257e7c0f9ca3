// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/two_mass_run.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <string>
#include <utility>

namespace grazelab::core {

template <typename S>
TwoMassRun<S>::TwoMassRun(const BasicModel<S>& model, const BasicRequest<S>& request, std::vector<bool> stillModes,
                          const BasicReadyChain<S>* ready)
    : m_request(request) {
  std::vector<Problem> problems = validate(model);
  for (Problem& problem : validateState(model, request.initial, "initial")) problems.push_back(std::move(problem));
  for (Problem& problem : validate(request)) problems.push_back(std::move(problem));
  m_result.final = request.initial;
  if (problems.empty()) {
    TwoMassFormOrProblem<S> formed = makeTwoMassForm(model);
    if (!formed.chain) problems.push_back({"model", formed.problem});
    m_form = std::move(formed.chain);
  }
  if (!problems.empty()) {
    m_result.stop = StopReason::InvalidInput;
    m_result.message = describe(problems);
    m_done = true;
    return;
  }
  m_result.initialEnergy = physicalEnergy(*m_form, request.initial);
  const BasicState<S>& start = request.initial;
  m_fromStop = start.u2 == model.gap && start.v2 <= 0;
  const SampleSpec& samples = request.needs.samples;
  ChainSampling<S> sampling;
  if (samples.wanted()) {
    sampling.spacing = samples.times.empty() ? samples.spacing : 0;
    sampling.times = samples.times;
    sampling.until = samples.tEnd;
    sampling.sink = [this](double t, const BasicChainState<S>& state) {
      addSample(t, twoMassStateOf(state));
    };
  }
  const long contacts = long(std::min<std::int64_t>(request.maxContacts, std::numeric_limits<long>::max()));
  const S tEnd = isFinite(request.tEnd) ? request.tEnd : S(0);
  const std::int64_t steps = request.flightSearchSteps != defaultSearchSteps<S>() ? request.flightSearchSteps : 0;
  const BasicChainStart<S> from(chainStateOf(start), std::move(stillModes));
  const ChainEventSink<S> sink = [this](const BasicChainEvent<S>& event) { take(event); };
  if (ready) {
    m_run.emplace(*ready, from, contacts, tEnd, sink, std::move(sampling), steps);
  } else if (std::find(from.stillModes.begin(), from.stillModes.end(), true) == from.stillModes.end()) {
    m_run.emplace(readyChain(*m_form), from, contacts, tEnd, sink, std::move(sampling), steps);
  } else {
    m_run.emplace(readyChain(model), from, contacts, tEnd, sink, std::move(sampling), steps);
  }
  if (m_run->done()) finish();
}

template <typename S>
void TwoMassRun<S>::addSample(double t, const BasicState<S>& state) {
  if (m_result.samples.size() >= m_request.needs.samples.maxCount) {
    m_result.samplesTruncated = true;
    return;
  }
  m_result.samples.push_back({t, convertState<double>(state)});
}

template <typename S>
void TwoMassRun<S>::take(const BasicChainEvent<S>& event) {
  const BasicEvent<S> twoMass = twoMassEventOf(event);
  const BasicState<S>& before = twoMass.before;
  const BasicState<S>& after = twoMass.after;
  const Needs& needs = m_request.needs;
  if (m_request.onEvent) m_request.onEvent(twoMass);
  const double t = toDouble(event.t);
  if (needs.events && t <= needs.eventsUntil) m_result.events.push_back(twoMass);
  if (isContact(event.type)) {
    const std::int64_t index = m_contacts++;
    if (needs.poincare) {
      m_result.poincare.push_back({t, toDouble(after.u1), toDouble(after.v1), toDouble(after.v2), event.type});
    }
    // a flight that started on the stop: its length as the kernel computed it, and T2 - it
    if (needs.freeFlights && m_fromStop && event.flight > 0) {
      m_result.freeFlights.push_back({index, toDouble(event.flight), toDouble(event.shortfall)});
    }
    // the contact's corners in the samples: the states just before and after it
    const SampleSpec& samples = needs.samples;
    if (samples.wanted() && samples.includeContacts && t <= samples.tEnd) {
      addSample(t, before);
      if (!(after == before)) addSample(t, after);
    }
  }
  m_fromStop = event.type != EventType::Stick;
}

template <typename S>
double TwoMassRun<S>::progress() const {
  if (m_done) return 1.0;
  double fraction = 0;
  if (m_request.maxContacts > 0) fraction = double(m_contacts) / double(m_request.maxContacts);
  if (isFinite(m_request.tEnd) && m_request.tEnd > 0) {
    fraction = std::max(fraction, toDouble(S(m_run->time() / m_request.tEnd)));
  }
  return std::clamp(fraction, 0.0, 1.0);
}

template <typename S>
bool TwoMassRun<S>::advance(std::int64_t contactBudget, std::stop_token stop) {
  if (m_done) return true;
  const auto started = std::chrono::steady_clock::now();
  const long budget = long(std::clamp<std::int64_t>(contactBudget, 1, std::numeric_limits<long>::max()));
  const bool over = m_run->advance(budget, std::move(stop));
  // the counts and the accuracy so far (a run in pieces reports them as it goes)
  const BasicChainRun<S>& run = m_run->run();
  Cost& cost = m_result.cost;
  cost.contacts = run.contacts;
  cost.impacts = run.impacts;
  cost.grazings = run.grazings;
  cost.sticks = run.sticks;
  cost.maxRelEnergyDrift = run.maxEnergyDrift;
  cost.maxContactResidual = run.maxContactResidual;
  if (over) finish();
  cost.wallSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return m_done;
}

template <typename S>
void TwoMassRun<S>::finish() {
  const BasicChainRun<S>& run = m_run->run();
  // the largest drift at the events and at the end
  using std::abs;
  const S finalDrift = run.energyInitial > 0 ? S(abs(run.energyFinal / run.energyInitial - 1)) : S(0);
  m_result.cost.maxRelEnergyDrift = std::max(run.maxEnergyDrift, toDouble(finalDrift));
  m_result.stop = run.stop;
  m_result.tFinal = run.tFinal;
  m_result.final = twoMassStateOf(run.final);
  switch (run.stop) {
    case StopReason::Undecided:
      m_result.message = "contact " + std::to_string(run.contacts + 1) + " (after t = " + formatScalar(run.tFinal) +
                         ") touches the stop within rounding: " + std::string(toString(precisionOf<S>())) +
                         " cannot tell a graze from an impact there";
      break;
    case StopReason::NoFurtherContact:
      m_result.message = "the free motion stays below the stop forever: no further contact";
      break;
    case StopReason::SearchBudget:
      m_result.message = "no contact was decided within the search's budget after t = " + formatScalar(run.tFinal);
      break;
    default: break;
  }
  m_done = true;
}

template class TwoMassRun<double>;
template class TwoMassRun<long double>;
template class TwoMassRun<Quad>;

}  // namespace grazelab::core
