// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/recorder.h"

#include <algorithm>
#include <cmath>

namespace grazelab::core {

Recorder::Recorder(const TwoMassForm<double>& chain, const Scale<double>& scale, const State& initial,
                   const Needs& needs, Result& result)
    : m_chain(chain),
      m_scale(scale),
      m_needs(needs),
      m_result(result),
      m_initialScaledEnergy(scaledEnergy(chain, initial)) {
  m_nextSampleTime = needs.samples.timeOf(0);
}

void Recorder::addSample(double t, const State& state) {
  if (m_result.samples.size() >= m_needs.samples.maxCount) {
    m_result.samplesTruncated = true;
    return;
  }
  m_result.samples.push_back({t, state});
}

void Recorder::samplePoint(double tau, const State& scaled) {
  const SampleSpec& spec = m_needs.samples;
  if (spec.spacing <= 0 || m_result.samplesTruncated) return;
  const double t = m_scale.toPhysicalTime(tau);
  if (t < m_nextSampleTime || t > spec.tEnd) return;
  addSample(t, m_scale.toPhysical(scaled));
  // the next sample is due one spacing after this one (a coarse step skips the ones it jumps)
  m_nextSampleIndex = std::int64_t(std::floor(t / spec.spacing)) + 1;
  m_nextSampleTime = double(m_nextSampleIndex) * spec.spacing;
}

void Recorder::record(const Step<double>& step) {
  Cost& cost = m_result.cost;
  if (isContact(step.type)) {
    ++cost.contacts;
    if (step.type == EventType::Impact) ++cost.impacts;
    if (step.type == EventType::Grazing) ++cost.grazings;
    if (step.type == EventType::Stick) ++cost.sticks;
    const double e0 = m_initialScaledEnergy;
    const double drift = std::abs(scaledEnergy(m_chain, step.after) - e0) / (e0 > 0 ? e0 : 1.0);
    cost.maxRelEnergyDrift = std::max(cost.maxRelEnergyDrift, drift);
    cost.maxContactResidual = std::max(cost.maxContactResidual, timesPowerOfTwo(step.residual, m_scale.exponent));
  }
  const Event event{m_scale.toPhysicalTime(step.tau), step.type, m_scale.toPhysical(step.before),
                    m_scale.toPhysical(step.after)};
  if (m_needs.events && event.t <= m_needs.eventsUntil) m_result.events.push_back(event);
  if (isContact(step.type) && m_needs.poincare) {
    m_result.poincare.push_back({event.t, event.after.u1, event.after.v1, event.after.v2, step.type});
  }
  const SampleSpec& samples = m_needs.samples;
  if (isContact(step.type) && samples.wanted() && samples.includeContacts && event.t <= samples.tEnd) {
    addSample(event.t, event.before);
    if (!(event.after == event.before)) addSample(event.t, event.after);
  }
}

void Recorder::finish(StopReason reason, double t, const State& scaled) {
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

}  // namespace grazelab::core
