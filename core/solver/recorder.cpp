// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/recorder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace grazelab::core {

template <typename S>
Recorder<S>::Recorder(const TwoMassForm<S>& chain, const Scale<S>& scale, const BasicState<S>& initial,
                      const Needs& needs, std::function<void(const BasicEvent<S>&)> onEvent,
                      BasicResult<S>& result)
    : m_chain(chain),
      m_scale(scale),
      m_needs(needs),
      m_onEvent(std::move(onEvent)),
      m_result(result),
      m_initialScaledEnergy(scaledEnergy(chain, initial)) {
  m_nextSampleTime = needs.samples.timeOf(0);
}

template <typename S>
void Recorder<S>::addSample(double t, const State& state) {
  if (m_result.samples.size() >= m_needs.samples.maxCount) {
    m_result.samplesTruncated = true;
    return;
  }
  m_result.samples.push_back({t, state});
}

template <typename S>
void Recorder<S>::sampleUntil(const ExactStepper<S>& stepper, const S& segmentStart,
                              const S& tauEnd) {
  const SampleSpec& spec = m_needs.samples;
  if (!spec.wanted()) return;
  const double tSegment = toDouble(m_scale.toPhysicalTime(segmentStart));
  const double last = std::min(toDouble(m_scale.toPhysicalTime(tauEnd)), spec.tEnd);
  if (spec.times.empty() && spec.spacing > 0) {
    // the grid: the step's motion evaluated a batch at a time (a flight by rotation, several
    // times faster than a state at a time: the explorer's animation samples a whole run)
    constexpr std::int64_t kBatch = 64;
    std::array<BasicState<S>, kBatch> states;
    if (m_nextSampleTime < tSegment) {
      // samples before the step's start are not its motion (a coarse jump skipped them)
      m_nextSampleIndex =
          std::max(m_nextSampleIndex, std::int64_t(std::ceil((tSegment - spec.tBegin) / spec.spacing)));
      m_nextSampleTime = spec.timeOf(m_nextSampleIndex);
    }
    const S step = m_scale.toScaledTime(S(spec.spacing));
    while (m_nextSampleTime <= last && !m_result.samplesTruncated) {
      const std::int64_t due =
          std::int64_t(std::floor((last - spec.tBegin) / spec.spacing)) - m_nextSampleIndex + 1;
      const std::int64_t count = std::clamp<std::int64_t>(due, 1, kBatch);
      stepper.segmentOnGrid(m_scale.toScaledTime(S(m_nextSampleTime)), step,
                            std::span(states.data(), std::size_t(count)));
      for (std::int64_t k = 0; k < count; ++k) {
        const double t = spec.timeOf(m_nextSampleIndex);
        if (t > last) break;
        addSample(t, convertState<double>(m_scale.toPhysical(states[std::size_t(k)])));
        ++m_nextSampleIndex;
      }
      m_nextSampleTime = spec.timeOf(m_nextSampleIndex);
    }
    return;
  }
  while (m_nextSampleTime <= last && !m_result.samplesTruncated) {
    if (m_nextSampleTime >= tSegment) {
      const S tau = m_scale.toScaledTime(S(m_nextSampleTime));
      const BasicState<S> physical = m_scale.toPhysical(stepper.segmentAt(tau));
      addSample(m_nextSampleTime, convertState<double>(physical));
    }
    ++m_nextSampleIndex;
    m_nextSampleTime = spec.timeOf(m_nextSampleIndex);
  }
}

template <typename S>
void Recorder<S>::samplePoint(const S& tau, const BasicState<S>& scaled) {
  const SampleSpec& spec = m_needs.samples;
  if (spec.spacing <= 0 || m_result.samplesTruncated) return;
  const double t = toDouble(m_scale.toPhysicalTime(tau));
  if (t < m_nextSampleTime || t > spec.tEnd) return;
  addSample(t, convertState<double>(m_scale.toPhysical(scaled)));
  // the next sample is due one spacing after this one (a coarse step skips the ones it jumps)
  m_nextSampleIndex = std::int64_t(std::floor((t - spec.tBegin) / spec.spacing)) + 1;
  m_nextSampleTime = spec.tBegin + double(m_nextSampleIndex) * spec.spacing;
}

template <typename S>
void Recorder<S>::record(const Step<S>& step) {
  using std::abs;
  Cost& cost = m_result.cost;
  if (isContact(step.type)) {
    ++cost.contacts;
    if (step.type == EventType::Impact) ++cost.impacts;
    if (step.type == EventType::Grazing) ++cost.grazings;
    if (step.type == EventType::Stick) ++cost.sticks;
    if (step.undecided && cost.undecidedTouches++ == 0) {
      cost.firstUndecidedContact = cost.contacts;
      cost.firstUndecidedTime = toDouble(m_scale.toPhysicalTime(step.tau));
    }
    const S e0 = m_initialScaledEnergy;
    const S drift = abs(scaledEnergy(m_chain, step.after) - e0) / (e0 > 0 ? e0 : S(1));
    cost.maxRelEnergyDrift = std::max(cost.maxRelEnergyDrift, toDouble(drift));
    cost.maxContactResidual =
        std::max(cost.maxContactResidual, toDouble(timesPowerOfTwo(step.residual, m_scale.exponent)));
  }
  if (step.endsFlight) {
    cost.maxFlightEnergyError = std::max(cost.maxFlightEnergyError, toDouble(step.flightEnergyError));
    if (step.flightFromStop && m_needs.freeFlights) {
      const S duration = step.flightDuration.value();
      // T2 - FFT, exact from the offset when the contact is anchored at the return
      const S shortfall = step.flightDuration.periods == 1 ? S(-step.flightDuration.offset)
                                                          : S(twoPi<S>() - duration);
      m_result.freeFlights.push_back({cost.contacts - 1,
                                      toDouble(m_scale.toPhysicalTime(duration)),
                                      toDouble(m_scale.toPhysicalTime(shortfall))});
    }
  }
  // the event in physical units only when something keeps it (a run that keeps only the cost
  // spends no time converting)
  const SampleSpec& samples = m_needs.samples;
  const bool contactSamples = isContact(step.type) && samples.wanted() && samples.includeContacts;
  if (!m_onEvent && !m_needs.events && !(isContact(step.type) && m_needs.poincare) &&
      !contactSamples) {
    return;
  }
  const BasicEvent<S> event{m_scale.toPhysicalTime(step.tau), step.type,
                            m_scale.toPhysical(step.before), m_scale.toPhysical(step.after)};
  if (m_onEvent) m_onEvent(event);
  if (m_needs.events && toDouble(event.t) <= m_needs.eventsUntil) m_result.events.push_back(event);
  if (isContact(step.type) && m_needs.poincare) {
    m_result.poincare.push_back({toDouble(event.t), toDouble(event.after.u1),
                                 toDouble(event.after.v1), toDouble(event.after.v2), step.type});
  }
  const double t = toDouble(event.t);
  if (contactSamples && t >= samples.tBegin && t <= samples.tEnd) {
    addSample(t, convertState<double>(event.before));
    if (!(event.after == event.before)) addSample(t, convertState<double>(event.after));
  }
}

template <typename S>
void Recorder<S>::finish(StopReason reason, const S& t, const BasicState<S>& scaled) {
  m_result.stop = reason;
  m_result.tFinal = t;
  m_result.final = m_scale.toPhysical(scaled);
}

template <typename S>
Result toDoubleResult(const BasicResult<S>& from) {
  Result to;
  to.events.reserve(from.events.size());
  for (const BasicEvent<S>& e : from.events) {
    to.events.push_back({toDouble(e.t), e.type, convertState<double>(e.before),
                         convertState<double>(e.after)});
  }
  to.poincare = from.poincare;
  to.freeFlights = from.freeFlights;
  to.samples = from.samples;
  to.samplesTruncated = from.samplesTruncated;
  to.tFinal = toDouble(from.tFinal);
  to.final = convertState<double>(from.final);
  to.initialEnergy = toDouble(from.initialEnergy);
  to.cost = from.cost;
  to.stop = from.stop;
  to.message = from.message;
  return to;
}

template Result toDoubleResult<double>(const BasicResult<double>&);
template Result toDoubleResult<long double>(const BasicResult<long double>&);
template Result toDoubleResult<Quad>(const BasicResult<Quad>&);
template class Recorder<double>;
template class Recorder<long double>;
template class Recorder<Quad>;

}  // namespace grazelab::core
