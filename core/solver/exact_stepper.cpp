// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/exact_stepper.h"

#include <cmath>

#include "core/solver/impact_law.h"

namespace grazelab::core {

// Free flight is exact and conserves the energy, but its computed end state carries rounding
// that the rounded modal basis biases the same way at every contact: left alone, the energy
// drifts linearly, about one ulp per flight. The end state is therefore moved back onto the
// energy level of the flight's start, along the energy gradient with x2 held on the stop.
template <typename S>
S restoreEnergy(const TwoMassForm<S>& chain, BasicState<S>& state, const S& target) {
  using std::abs;
  const S error = scaledEnergy(chain, state) - target;
  const S gradientU1 = (S(1) + chain.kappa) * state.u1 - chain.kappa * state.u2;
  const S gradientV1 = chain.lambdaSlow * state.v1;
  const S gradientV2 = chain.lambdaSlow * chain.beta * state.v2;
  const S norm = gradientU1 * gradientU1 + gradientV1 * gradientV1 + gradientV2 * gradientV2;
  if (norm > 0) {
    const S step = -error / norm;
    state.u1 += step * gradientU1;
    state.v1 += step * gradientV1;
    state.v2 += step * gradientV2;
  }
  return abs(error) / (target > 0 ? target : S(1));
}

template <typename S>
ExactStepper<S>::ExactStepper(const TwoMassForm<S>& chain, const S& scaledGap)
    : m_chain(chain), m_gap(scaledGap) {}

template <typename S>
Step<S> ExactStepper<S>::advance(IntegrationState<S>& state, const S& tauEnd,
                                 const S& searchHorizon, const std::stop_token& stop,
                                 std::int64_t searchSteps) {
  using std::min;
  Step<S> step;
  step.segmentStart = state.tau;
  m_segmentStart = state.tau;
  m_segmentState = state.x;
  m_flight.reset();
  m_stuck.reset();
  const BasicState<S>& x = state.x;

  if (x.u2 == m_gap && x.v2 > 0) {
    // a start on the stop moving into it: the impact happens at once
    const ContactOutcome<S> outcome = applyImpactLaw(x, m_gap, false);
    step.type = outcome.type;
    step.tau = state.tau;
    step.before = outcome.before;
    step.after = outcome.after;
    state.x = outcome.after;
    return step;
  }

  if (pressedOnStop(x, m_gap, state.u1Residual)) {
    if (!state.stuck) {
      // the contact that starts the phase; stopping here leaves the run on the stop, stuck
      state.stuck = true;
      step.type = EventType::Stick;
      step.tau = state.tau;
      step.before = step.after = x;
      return step;
    }
    m_stuck.emplace(m_chain, m_gap, x, state.u1Residual);
    const S release = m_stuck->releaseTime();
    if (state.tau + release > tauEnd) {
      step.kind = Step<S>::Kind::End;
      step.tau = tauEnd;
      step.before = step.after = m_stuck->at(tauEnd - state.tau);
      return step;
    }
    step.type = EventType::Release;
    state.advanceTime(0, release);
    step.tau = state.tau;
    step.before = m_stuck->at(release);
    step.after = m_stuck->releaseState();
    state.x = step.after;
    state.u1Residual = 0;  // released where u1 = gap exactly
    state.stuck = false;
    return step;
  }

  m_flight.emplace(m_chain, m_gap, x, state.u1Residual);
  const Flight<S>& flight = *m_flight;
  const S remaining = tauEnd - state.tau;
  // (a flight that cannot reach the stop is said so at once, as the modal kernel says it: a
  // detuned one's search would run out of its budget, a resonant one's decide it within a period,
  // or find a top within rounding of the stop undecided)
  const bool neverReaches = flight.neverReachesStop();
  const Contact<S> contact =
      neverReaches ? Contact<S>{} : nextContact(flight, min(remaining, searchHorizon), stop, searchSteps);
  auto endAt = [&](const S& tau, typename Step<S>::Kind kind) {
    step.kind = kind;
    step.tau = tau;
    step.before = step.after = flight.at(FlightTime<S>::nearest(tau - state.tau));
    return step;
  };

  if (contact.kind == ContactKind::Cancelled) {
    step.kind = Step<S>::Kind::Cancelled;
    step.tau = state.tau;
    step.before = step.after = x;
    return step;
  }
  if (contact.kind == ContactKind::Budget) {
    return endAt(state.tau + contact.time.value(), Step<S>::Kind::SearchBudget);
  }
  if (contact.kind == ContactKind::None) {
    const bool never = m_chain.resonant || neverReaches;
    if (isFinite(remaining) && (never || remaining <= searchHorizon)) {
      return endAt(tauEnd, Step<S>::Kind::End);
    }
    if (never) {
      step.kind = Step<S>::Kind::NoFurtherContact;
      step.tau = state.tau;
      step.before = step.after = x;
      return step;
    }
    return endAt(state.tau + searchHorizon, Step<S>::Kind::SearchLimit);
  }

  const S duration = contact.time.value();
  if (state.tau + duration > tauEnd) return endAt(tauEnd, Step<S>::Kind::End);
  if (flight.startsOnStop() && !(duration > 0)) {
    // a flight from the stop cannot come back to it in no time: that would be the start itself,
    // recorded for ever; the horizon is below what the search can tell from it
    return endAt(isFinite(remaining) ? tauEnd : state.tau, Step<S>::Kind::End);
  }
  S u1Residual = 0;
  BasicState<S> arrival = flight.at(contact.time, &u1Residual);
  arrival.u2 = m_gap;
  // a crossing whose arrival speed is below the range of S (it underflows to 0) cannot be told
  // from a touch in S: an impact of speed 1e-450 after a release needs binary128's exponents
  const bool undecided =
      contact.undecided || (contact.kind == ContactKind::Crossing && !(arrival.v2 > 0));
  if (undecided) {
    step.kind = Step<S>::Kind::Undecided;
    step.tau = state.tau + duration;
    step.before = step.after = x;
    return step;
  }
  // restoring the energy moves the stored u1 on purpose; the residual is what is below it
  step.flightEnergyError = restoreEnergy(m_chain, arrival, scaledEnergy(m_chain, x));
  const ContactOutcome<S> outcome =
      applyImpactLaw(arrival, m_gap, contact.kind == ContactKind::Tangent, u1Residual);
  step.type = outcome.type;
  state.advanceTime(contact.time.periods, contact.time.offset);
  step.tau = state.tau;
  step.before = outcome.before;
  step.after = outcome.after;
  step.residual = contact.residual;
  step.endsFlight = true;
  step.flightFromStop = flight.startsOnStop();
  step.flightDuration = contact.time;
  state.x = outcome.after;
  state.u1Residual = u1Residual;
  state.stuck = outcome.type == EventType::Stick;
  return step;
}

template <typename S>
BasicState<S> ExactStepper<S>::segmentAt(const S& tau) const {
  if (m_stuck) return m_stuck->at(tau - m_segmentStart);
  if (m_flight) return m_flight->at(FlightTime<S>::nearest(tau - m_segmentStart));
  // a step that took no time (an impact or a stick at its start): the state it began from,
  // not zeros (a sticking start drew a line from the origin)
  return m_segmentState;
}

template <typename S>
void ExactStepper<S>::segmentOnGrid(const S& first, const S& step, std::span<BasicState<S>> out) const {
  if (m_flight && !m_stuck) {
    m_flight->statesOnGrid(first - m_segmentStart, step, out);
    return;
  }
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = segmentAt(first + S(k) * step);
}

#define GRAZELAB_INSTANTIATE(S)  \
  template class ExactStepper<S>; \
  template S restoreEnergy<S>(const TwoMassForm<S>&, BasicState<S>&, const S&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
