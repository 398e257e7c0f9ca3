// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/chain_run.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <utility>

#include "core/numbers/vector_state.h"
#include "core/solver/chain_stick.h"

namespace grazelab::core {

template <typename S>
S chainEnergy(const BasicMassChain<S>& chain, const BasicChainState<S>& state) {
  // each spring's stretch squared, in O(N) with no matrix made: a run measures its energy at
  // every event, and a chain may have a thousand masses
  const Eigen::Index n = state.u.size();
  S kinetic = 0;
  S potential = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    kinetic += chain.masses[std::size_t(i)] * state.v[i] * state.v[i];
    const S stretch = i == 0 ? state.u[0] : S(state.u[i] - state.u[i - 1]);
    potential += chain.springs[std::size_t(i)] * stretch * stretch;
  }
  if (chain.rightSpring > 0) potential += chain.rightSpring * state.u[n - 1] * state.u[n - 1];
  return S(0.5) * kinetic + S(0.5) * potential;
}

namespace {

// the slowest period of a stuck phase's sides (0 when no mass moves)
template <typename S>
S slowestPeriod(const BasicChainStuckPhase<S>& phase) {
  S slowest = 0;
  for (const typename BasicChainStuckPhase<S>::Side* side : {&phase.left, &phase.right}) {
    if (side->count == 0) continue;
    const S period = twoPi<S>() / slowestFrequency(side->dynamics.omega);
    if (period > slowest) slowest = period;
  }
  return slowest;
}

// The springs' force on mass i over its mass, k_i (x_(i-1) - x_i) + k_(i+1) (x_(i+1) - x_i)
// over m_i (walls at 0), for x the displacements (the acceleration) or the velocities (its rate),
// with a bound of its rounding (`error`: the error x carries already, as a multiple of |x|).
template <typename S>
struct Rate {
  S value = 0, error = 0;
};
template <typename S>
Rate<S> springsOn(const BasicMassChain<S>& chain, Eigen::Index i, const ChainVector<S>& x, const S& relativeError) {
  using std::abs;
  const Eigen::Index n = chain.size();
  const S leftK = S(chain.springs[std::size_t(i)]);
  const S rightK = S(i + 1 < n ? chain.springs[std::size_t(i + 1)] : chain.rightSpring);
  const S leftX = i > 0 ? S(x[i - 1]) : S(0), rightX = i + 1 < n ? S(x[i + 1]) : S(0);
  const S mass = S(chain.masses[std::size_t(i)]);
  const S size = (leftK * (abs(leftX) + abs(x[i])) + rightK * (abs(rightX) + abs(x[i]))) / mass;
  return {(leftK * (leftX - x[i]) + rightK * (rightX - x[i])) / mass,
          (4 * std::numeric_limits<S>::epsilon() + relativeError) * size};
}

// k (x - y) when the difference and the product are exact in S (an error-free sum and an fma
// say so); nothing when either rounds
template <typename S>
std::optional<S> exactTerm(const S& k, const S& x, const S& y) {
  using std::fma;
  const S difference = x - y;
  const S back = difference - x;
  if ((x - (difference - back)) + (-y - back) != 0) return std::nullopt;  // the difference rounded
  const S product = k * difference;
  if (fma(k, difference, -product) != 0) return std::nullopt;            // the product rounded
  return product;
}

// Whether mass s, at rest on the stop in a given start, is exactly flat: the springs' force on it
// and that force's rate are both exactly 0 in the start's own numbers (each term exact, the two
// sides exact opposites). Only then may its fourth derivative decide: a force within rounding
// but not 0 (a neighbour one ulp past the gap) is undecided here and decided one precision up,
// where it is resolved.
template <typename S>
bool exactlyFlat(const BasicMassChain<S>& chain, const BasicChainState<S>& at) {
  const Eigen::Index n = chain.size();
  const Eigen::Index s = chain.stopped() - 1;
  const S us = at.u[s];
  const S zero = 0;
  const S leftK = S(chain.springs[std::size_t(s)]);
  const S rightK = S(s + 1 < n ? chain.springs[std::size_t(s + 1)] : chain.rightSpring);
  const auto left = exactTerm(leftK, s > 0 ? S(at.u[s - 1]) : zero, us);
  const auto right = exactTerm(rightK, s + 1 < n ? S(at.u[s + 1]) : zero, us);
  if (!left || !right || *left != -*right) return false;
  const auto leftRate = exactTerm(leftK, s > 0 ? S(at.v[s - 1]) : zero, zero);
  const auto rightRate = exactTerm(s + 1 < n ? rightK : zero, s + 1 < n ? S(at.v[s + 1]) : zero, zero);
  return leftRate && rightRate && *leftRate == -*rightRate;
}

// How mass s at rest on the stop with no force (v_s = 0, F_s = 0: a release, or a start there)
// moves first: by the force's rate, u_s''' = (k_s v_(s-1) + k_(s+1) v_(s+1)) / m_s, when its sign
// is resolved; or, when the start is exactly flat (`flat`: exactlyFlat, no force and no rate at
// all), by u_s'''' = (k_s a_(s-1) + k_(s+1) a_(s+1)) / m_s with a the neighbours' accelerations.
// As its order and value; nothing when neither decides. Negative: the mass leaves the stop;
// positive: the springs start pressing it on. `computed`: the state comes from a closed form (a
// touch, a release), its velocities good to some tens of roundings of the motion's speed (each
// mass's sqrt(2E / m_i)), not exact as a given start's are.
template <typename S>
std::optional<BasicLeaving<S>> stopLeaving(const BasicMassChain<S>& chain, const BasicChainState<S>& at, bool computed,
                                           bool flat) {
  using std::abs;
  using std::sqrt;
  const Eigen::Index n = chain.size();
  const Eigen::Index s = chain.stopped() - 1;
  const S mass = S(chain.masses[std::size_t(s)]);
  const auto next = [&](const auto& rateOf) {
    const Rate<S> left = s > 0 ? rateOf(s - 1) : Rate<S>{};
    const Rate<S> right = s + 1 < n ? rateOf(s + 1) : Rate<S>{};
    const S leftK = S(chain.springs[std::size_t(s)]), rightK = s + 1 < n ? S(chain.springs[std::size_t(s + 1)]) : S(0);
    const S value = (leftK * left.value + rightK * right.value) / mass;
    const S error = (4 * std::numeric_limits<S>::epsilon() * (leftK * abs(left.value) + rightK * abs(right.value)) +
                     leftK * left.error + rightK * right.error) /
                    mass;
    return Rate<S>{value, error};
  };
  const S energy = computed ? chainEnergy(chain, at) : S(0);
  const Rate<S> jerk = next([&](Eigen::Index i) {
    const S speed = sqrt(2 * abs(energy) / S(chain.masses[std::size_t(i)]));
    return Rate<S>{at.v[i], 64 * std::numeric_limits<S>::epsilon() * speed};
  });
  if (abs(jerk.value) > jerk.error) return BasicLeaving<S>{3, jerk.value};
  if (!flat) return std::nullopt;
  // exactly flat: the fourth derivative, from the neighbours' accelerations (the start's own
  // numbers: rounded only by this arithmetic)
  const Rate<S> snap = next([&](Eigen::Index i) { return springsOn(chain, i, at.u, S(0)); });
  if (abs(snap.value) > snap.error) return BasicLeaving<S>{4, snap.value};
  return std::nullopt;
}

// how a flight leaves the stop after a release: stopLeaving when negative
template <typename S>
std::optional<BasicLeaving<S>> releaseLeaving(const BasicMassChain<S>& chain, const BasicChainState<S>& at) {
  const std::optional<BasicLeaving<S>> leaving = stopLeaving(chain, at, true, false);
  if (!leaving || !(leaving->value < 0)) return std::nullopt;
  return leaving;
}

// The note's model of a two-mass chain stopped on its second mass with no right wall, when the
// note's kernel runs it: in 1:2 resonance (the design branch its k2 is nearer), or not
// commensurate (its springs as given). Nothing otherwise (another ratio: the modal kernel).
template <typename S>
std::optional<BasicModel<S>> notesModelOf(const BasicMassChain<S>& chain, const BasicChainDynamics<S>& dynamics) {
  using std::abs;
  if (chain.size() != 2 || chain.stopped() != 2 || chain.rightSpring != 0) return std::nullopt;
  const S& m1 = chain.masses[0];
  const S& m2 = chain.masses[1];
  const S& k1 = chain.springs[0];
  const S& k2 = chain.springs[1];
  if (dynamics.harmonics.empty()) return BasicModel<S>{m1, m2, k1, k2, chain.gap, std::nullopt};
  if (dynamics.harmonics != std::vector<int>{2, 1}) return std::nullopt;
  // the ratio is found to 1e-9, which near m2/m1 = 9/16 (where the ratio is flat in k2) lets k2
  // be 1e-4 off the design: the note's kernel, which runs the design itself, takes only springs
  // that are a design's to rounding (the others keep theirs, on the modal kernel)
  const S tolerance = S(1024) * std::numeric_limits<S>::epsilon();
  for (const Branch branch : {Branch::Upper, Branch::Lower}) {
    const auto model = designedModel(m1, m2, k1, chain.gap, branch);
    if (model && abs(model->k2 - k2) <= tolerance * model->k2) return model;
  }
  return std::nullopt;
}

template <typename S>
std::optional<TwoMassForm<S>> notesFormOf(const BasicModel<S>& model) {
  if (!validate(model).empty()) return std::nullopt;
  return makeTwoMassForm(model).chain;
}

// the chain of the note's model: a design's k2 from the design itself (the model's may be a
// rounding of it for display)
template <typename S>
BasicMassChain<S> notesChainOf(const BasicModel<S>& model) {
  const S k2 = model.design ? S(designKappa(S(model.m2 / model.m1), *model.design) * model.k1) : model.k2;
  return {{model.m1, model.m2}, {model.k1, k2}, S(0), 2, model.gap};
}

}  // namespace

template <typename S>
BasicReadyChain<S> readyChain(const BasicMassChain<S>& chain, Kernel kernel) {
  BasicReadyChain<S> ready{chain, chainDynamicsIn<S>(chain), std::nullopt};
  if (kernel == Kernel::Best) {
    if (const auto model = notesModelOf(chain, ready.dynamics)) {
      ready.notes = notesFormOf(*model);
      if (ready.notes) ready.notesModel = model;
    }
  }
  return ready;
}

template <typename S>
BasicReadyChain<S> readyChain(const BasicModel<S>& model) {
  const BasicMassChain<S> chain = notesChainOf(model);
  BasicReadyChain<S> ready{chain, chainDynamicsIn<S>(chain), notesFormOf(model)};
  if (ready.notes) ready.notesModel = model;
  return ready;
}

template <typename S>
BasicReadyChain<S> readyChain(const TwoMassForm<S>& form) {
  using std::sqrt;
  const BasicModel<S>& model = form.model;
  BasicChainDynamics<S> dynamics;
  dynamics.omega.resize(2);
  dynamics.omega << form.ratio * form.omegaSlow, form.omegaSlow;
  // the mode shapes (rho, 1), M-orthonormal: fastest first
  dynamics.P.resize(2, 2);
  const S rho[2] = {form.rhoFast, form.rhoSlow};
  for (int j = 0; j < 2; ++j) {
    const S norm = sqrt(model.m1 * rho[j] * rho[j] + model.m2);
    dynamics.P(0, j) = rho[j] / norm;
    dynamics.P(1, j) = 1 / norm;
  }
  dynamics.nodeAtStop = {false, false};  // P(1, j) = 1 / norm
  dynamics.mass.resize(2);
  dynamics.mass << model.m1, model.m2;
  dynamics.stop = 1;
  dynamics.gap = model.gap;
  if (form.resonant) {
    dynamics.omega0 = form.omegaSlow;
    dynamics.period = twoPi<S>() / form.omegaSlow;
    dynamics.harmonics = {2, 1};
  }
  return {notesChainOf(model), std::move(dynamics), form, model};
}

template <typename S>
BasicChainSimulator<S>::BasicChainSimulator(std::optional<BasicReadyChain<S>> owned, const BasicReadyChain<S>* given,
                                            const BasicChainStart<S>& start, long maxContacts, S tEnd,
                                            ChainEventSink<S> sink, ChainSampling<S> sampling,
                                            std::int64_t searchSteps)
    : m_owned(std::move(owned)),
      m_chain((given ? *given : *m_owned).numbers),
      m_dynamics((given ? *given : *m_owned).dynamics),
      m_maxContacts(maxContacts),
      m_tEnd(tEnd),
      m_searchSteps(searchSteps > 0 ? searchSteps : defaultSearchSteps<S>()),
      m_slowest(twoPi<S>() / slowestFrequency(m_dynamics.omega)),
      m_period(m_dynamics.period > 0 ? m_dynamics.period : m_slowest),
      m_sink(std::move(sink)),
      m_sampling(std::move(sampling)),
      m_state(start.state),
      m_stillModes(start.stillModes),
      m_notes(takesTheNotesKernel(given ? *given : *m_owned, start) ? (given ? *given : *m_owned).notes
                                                                     : std::nullopt) {
  if (!m_notes) {
    m_run.energyInitial = chainEnergy(m_chain, start.state);
    return;
  }
  // the note's kernel, as the note's simulator sets it up (the same scales: the same bits)
  const BasicState<S> initial = twoMassStateOf(start.state);
  m_scale = chooseScale(*m_notes, initial);
  m_scaled.x = m_scale.toScaled(initial);
  m_stepper.emplace(*m_notes, m_scale.gap);
  m_at = {ChainVector<S>(2), ChainVector<S>(2)};
  m_vBefore.resize(2);
  m_run.energyInitial = physicalEnergy(*m_notes, initial);
}

template <typename S>
S BasicChainSimulator<S>::energyOf(const BasicChainState<S>& at) const {
  return m_notes ? physicalEnergy(*m_notes, twoMassStateOf(at)) : chainEnergy(m_chain, at);
}

template <typename S>
bool BasicChainSimulator<S>::finish(StopReason reason, const BasicChainState<S>& at, const S& when) {
  m_run.stop = reason;
  m_run.final = at;
  m_run.tFinal = when;
  m_run.energyFinal = energyOf(at);
  m_done = true;
  return true;
}

template <typename S>
void BasicChainSimulator<S>::record(EventType type, const BasicChainState<S>& at, const ChainVector<S>& vBefore,
                                    const S& when, const S& residual, const S& flight, const S& shortfall) {
  const int s = m_dynamics.stop;
  if (m_sink) {
    // into the event reused from call to call: its vectors keep their storage (no allocation)
    m_event.t = when;
    m_event.type = type;
    m_event.u = at.u;
    m_event.vBefore = vBefore;
    m_event.vAfter = at.v[s];
    m_event.flight = flight;
    m_event.shortfall = shortfall;
    m_sink(m_event);
  } else {
    m_run.events.push_back({when, type, at.u, vBefore, at.v[s], flight, shortfall});
  }
  m_anyEvent = true;
  m_lastType = type;
  m_lastTime = when;
  // the run's own accuracy, event by event: its energy against the start's (the stopped mass's
  // distance from the stop at a contact, before it is put on it, comes with the contact)
  using std::abs;
  const double drift = toDouble(S(abs(energyOf(at) / m_run.energyInitial - 1)));
  if (drift > m_run.maxEnergyDrift || !(drift == drift)) m_run.maxEnergyDrift = drift;
  if (isContact(type)) {
    ++m_run.contacts;
    m_run.maxContactResidual = std::max(m_run.maxContactResidual, toDouble(residual));
  }
  switch (type) {
    case EventType::Impact: ++m_run.impacts; break;
    case EventType::Grazing: ++m_run.grazings; break;
    case EventType::Stick: ++m_run.sticks; break;
    case EventType::Release: ++m_run.releases; break;
  }
}

template <typename S>
double BasicChainSimulator<S>::sampleTime(std::size_t index) const {
  if (!m_sampling.times.empty()) {
    return index < m_sampling.times.size() ? m_sampling.times[index] : std::numeric_limits<double>::infinity();
  }
  return double(index) * m_sampling.spacing;
}

// where a flight that never meets the stop again is drawn to: the samples' end, or one slowest
// period when they have none
template <typename S>
S BasicChainSimulator<S>::neverEnds(const S& from) const {
  return std::isfinite(m_sampling.until) ? std::max(from, S(m_sampling.until)) : S(from + m_slowest);
}

// dense samples: the next one due, handed out over each piece of motion [from, until) (its end
// too when the run ends there), `at(offset)` the piece's closed form
template <typename S>
template <typename At>
void BasicChainSimulator<S>::samplePiece(const S& from, const S& until, bool withEnd, const At& at) {
  if (!m_sampling.wanted()) return;
  for (double due = sampleTime(m_sampleIndex);
       (S(due) < until || (withEnd && S(due) == until)) && due <= m_sampling.until;
       due = sampleTime(++m_sampleIndex)) {
    if (m_stop.stop_requested()) return;
    if (S(due) >= from) m_sampling.sink(due, at(S(due) - from));
  }
}

template <typename S>
void BasicChainSimulator<S>::sampleStep(const S& from, const S& until, bool withEnd) {
  if (!m_sampling.wanted()) return;
  const auto motion = [this, from](const S& offset) {
    return chainStateOf(m_scale.toPhysical(m_stepper->segmentAt(m_scale.toScaledTime(S(from + offset)))));
  };
  if (!m_sampling.times.empty()) return samplePiece(from, until, withEnd, motion);
  // the grid: the step's motion a batch at a time (a flight by rotation, several times faster
  // than a state at a time: the explorer's animation samples a whole run), from the first
  // sample due at or after `from`
  const double spacing = m_sampling.spacing;
  const auto due = [&](double t) {
    return (S(t) < until || (withEnd && S(t) == until)) && t <= m_sampling.until;
  };
  while (sampleTime(m_sampleIndex) < toDouble(from) && S(sampleTime(m_sampleIndex)) < from) {
    // (a long piece, a stick held for many samples, jumped at once)
    m_sampleIndex = std::max(m_sampleIndex + 1, std::size_t(std::max(0.0, std::floor(toDouble(from) / spacing))));
  }
  constexpr std::size_t kBatch = 64;
  std::array<BasicState<S>, kBatch> states;
  const S step = m_scale.toScaledTime(S(spacing));
  while (due(sampleTime(m_sampleIndex))) {
    if (m_stop.stop_requested()) return;
    std::size_t count = 1;
    while (count < kBatch && due(sampleTime(m_sampleIndex + count))) ++count;
    m_stepper->segmentOnGrid(m_scale.toScaledTime(S(sampleTime(m_sampleIndex))), step, std::span(states.data(), count));
    for (std::size_t k = 0; k < count; ++k) {
      m_sampling.sink(sampleTime(m_sampleIndex), chainStateOf(m_scale.toPhysical(states[k])));
      ++m_sampleIndex;
    }
  }
}

template <typename S>
bool BasicChainSimulator<S>::advance(long contactBudget, std::stop_token stop) {
  using std::abs;
  using State = BasicChainState<S>;
  if (m_done) return true;
  m_stop = std::move(stop);
  const BasicChainDynamics<S>& dynamics = m_dynamics;
  const BasicMassChain<S>& chain = m_chain;
  const int s = dynamics.stop;
  const S tEnd = m_tEnd;
  State& state = m_state;
  S& t = m_t;
  std::optional<BasicLeaving<S>>& leaving = m_leaving;
  // the piece ends after `contactBudget` more contacts (at least one: a caller looping on an
  // empty budget would never see the run end), at the top of the loop: the run then resumes
  // there as if it had never stopped
  contactBudget = std::max(contactBudget, 1L);
  const long pieceEnd = m_maxContacts - m_run.contacts > contactBudget ? m_run.contacts + contactBudget : m_maxContacts;
  if (m_stepper) return advanceNotes(pieceEnd);
  while (m_run.contacts < pieceEnd) {
    clearUpperVectorState();  // an event's sink may have run a library's AVX code
    if (m_stop.stop_requested()) return finish(StopReason::Cancelled, state, t);
    // m_flight goes on from `state` only into the flight right after its periodic touch
    const bool flightKept = std::exchange(m_flightKept, false);
    // at rest on the stop, pressed into it (a touch, or the start): held until released
    const BasicStopForce<S> force = stopForce(chain, state);
    const bool onStop = state.u[s] == dynamics.gap && state.v[s] == 0;
    // at rest on the stop with no force either way (a start there): the springs' first change
    // decides, as at a release: it pulls the mass off (a flight leaving by its jerk, or its
    // fourth derivative where the jerk is 0 too) or presses it on (held)
    std::optional<BasicLeaving<S>> startLeaving;
    if (onStop && !leaving && !(abs(force.value) > force.error)) {
      startLeaving = stopLeaving(chain, state, m_anyEvent, !m_anyEvent && exactlyFlat(chain, state));
    }
    if (startLeaving && startLeaving->value < 0) leaving = startLeaving;
    if (onStop && !leaving && (force.value > force.error || (startLeaving && startLeaving->value > 0))) {
      if (!m_anyEvent || m_lastType != EventType::Stick || m_lastTime != t) {
        record(EventType::Stick, state, state.v, t);
        // the last contact asked for: the run ends held there, as the note's kernel's does
        if (m_run.contacts >= m_maxContacts) {
          samplePiece(t, t, true, [&](const S&) { return state; });
          return finish(StopReason::ContactLimit, state, t);
        }
      }
      const BasicChainStuckPhase<S> phase = stuckPhase(chain, state);
      const S horizon = tEnd > 0 ? S(tEnd - t) : S(S(kFlightSearchPeriods) * slowestPeriod(phase));
      const BasicFirstZero<S> release = releaseOf(phase, horizon);
      if (m_stop.stop_requested()) return finish(StopReason::Cancelled, state, t);
      const bool past = tEnd > 0 && ((release.kind == ZeroKind::Budget && release.t >= horizon) || t + release.t > tEnd);
      const auto stuckAt = [&](const S& offset) { return stuckStateAt(phase, offset); };
      if (past) {
        samplePiece(t, S(tEnd), true, stuckAt);
        return finish(StopReason::TimeLimit, stuckStateAt(phase, tEnd - t), tEnd);
      }
      if (release.kind == ZeroKind::Budget) {
        samplePiece(t, S(t + release.t), true, stuckAt);  // held at least as far as it searched
        return finish(StopReason::SearchBudget, state, t);
      }
      if (release.kind != ZeroKind::Crossing) {
        return finish(StopReason::Undecided, stuckStateAt(phase, release.t), t + release.t);
      }
      samplePiece(t, S(t + release.t), false, stuckAt);
      State released = stuckStateAt(phase, release.t);
      t += release.t;
      leaving = releaseLeaving(chain, released);
      if (!leaving) return finish(StopReason::Undecided, released, t);
      record(EventType::Release, released, released.v, t);
      state = released;
      continue;
    }
    if (state.u[s] == dynamics.gap && state.v[s] > 0) {
      // a start on the stop moving into it: the impact at once (as for two masses)
      State reflected = state;
      reflected.v[s] = -reflected.v[s];
      record(EventType::Impact, reflected, state.v, t);
      state = reflected;
      continue;
    }
    if (!flightKept) {
      flightInto(dynamics, state, m_flight);
      if (!m_anyEvent) {
        // the start's first flight: the modes it names still are exactly 0, not P^T M u's roundings
        for (std::size_t j = 0; j < m_stillModes.size() && Eigen::Index(j) < m_flight.q.size(); ++j) {
          if (m_stillModes[j]) m_flight.q[Eigen::Index(j)] = m_flight.qdot[Eigen::Index(j)] = 0;
        }
      }
    }
    const S horizon = tEnd > 0 ? S(tEnd - t) : S(S(kFlightSearchPeriods) * m_slowest);
    const BasicChainContact<S> contact = firstContact(dynamics, m_flight, horizon, 1'000'000, leaving);
    const std::optional<BasicLeaving<S>> flightLeaving = leaving;
    leaving.reset();
    // (a search out of its window budget short of its horizon, the end time, decided nothing up
    // to there: not a time limit; at the horizon it says Budget with t = horizon exactly)
    const bool past = tEnd > 0 && (contact.kind == ChainContactKind::None || t + contact.t > tEnd ||
                                   (contact.kind == ChainContactKind::Budget && contact.t >= horizon));
    const auto flightAt = [&](const S& offset) { return stateAt(dynamics, m_flight, offset); };
    if (past) {
      samplePiece(t, S(tEnd), true, flightAt);
      return finish(StopReason::TimeLimit, stateAt(dynamics, m_flight, tEnd - t), tEnd);
    }
    if (contact.kind == ChainContactKind::None) {
      samplePiece(t, neverEnds(t), true, flightAt);
      return finish(StopReason::NoFurtherContact, state, t);
    }
    if (contact.kind == ChainContactKind::Budget) {
      // no contact as far as the search went: that much of the flight is drawn
      samplePiece(t, S(t + contact.t), true, flightAt);
      return finish(StopReason::SearchBudget, state, t);
    }
    if (contact.kind == ChainContactKind::Unresolved) {
      // a top within rounding of the stop (or, at 0, a flight not seen to leave the stop it starts
      // on): a grazing, a slow impact and a near miss differ there by less than S resolves, so
      // none is recorded; the run ends at the flight's start, decided one precision up
      return finish(StopReason::Undecided, state, t);
    }
    if (contact.kind == ChainContactKind::Touch) {
      // a start at rest on the stop back after u_s's own period T/g (firstContact calls a touch
      // only there): the frequencies are taken as exact multiples of w0, so every mode that moves
      // the stopped mass is as it was, exactly, and the flight goes on through the grazing
      // unchanged (the other modes turned); it leaves the stop as it left it before (a flat start
      // by its fourth derivative, with no force)
      samplePiece(t, S(t + contact.t), false, flightAt);
      t += contact.t;
      S residual = 0;
      if (afterStopPeriod(dynamics, stopRepeats(dynamics, m_flight), m_flight)) {
        stateInto(dynamics, m_flight, S(0), state);
        residual = abs(state.u[s] - dynamics.gap);
        state.u[s] = dynamics.gap;
        state.v[s] = 0;
      }
      record(EventType::Grazing, state, state.v, t, residual, contact.t, S(m_period - contact.t));
      leaving = flightLeaving;
      m_flightKept = true;
      continue;
    }
    samplePiece(t, S(t + contact.t), false, flightAt);
    stateInto(dynamics, m_flight, contact.t, m_at);
    m_vBefore = m_at.v;
    const S when = t + contact.t;
    const S residual = abs(m_at.u[s] - dynamics.gap);
    m_at.u[s] = dynamics.gap;  // on the stop exactly: the next flight starts on it
    m_at.v[s] = -m_at.v[s];  // an impact: the one contact left (a touch is a periodic return, above)
    record(EventType::Impact, m_at, m_vBefore, when, residual, contact.t, S(m_period - contact.t));
    state = m_at;
    t = when;
  }
  if (m_run.contacts < m_maxContacts) return false;  // the piece's contacts made: more to come
  // the last event's state, when a sample falls on it
  samplePiece(t, t, true, [&](const S&) { return state; });
  return finish(StopReason::ContactLimit, state, t);
}

// The note's kernel: its exact stepper moves the scaled state from event to event (a flight or a
// stuck phase each), as the note's simulator drives it; each event and the end in physical units
// by the same scales, so the note's chain gives the note's bits. A contact the precision cannot
// decide ends the run there (Undecided), as the modal kernel's do.
template <typename S>
bool BasicChainSimulator<S>::advanceNotes(long pieceEnd) {
  const S tauEnd = m_tEnd > 0 ? m_scale.toScaledTime(m_tEnd) : S(std::numeric_limits<double>::infinity());
  // without an end time the search goes 1000 slow periods, as the modal kernel's
  const S horizon = m_tEnd > 0 ? S(std::numeric_limits<double>::infinity()) : S(twoPi<S>() * S(kFlightSearchPeriods));
  const auto physical = [&](const BasicState<S>& scaled) { return chainStateOf(m_scale.toPhysical(scaled)); };
  while (m_run.contacts < pieceEnd) {
    clearUpperVectorState();  // an event's sink may have run a library's AVX code
    if (m_stop.stop_requested()) return finish(StopReason::Cancelled, physical(m_scaled.x), m_t);
    if (m_scaled.tau >= tauEnd) {
      // an event at the end time: its state is the end's (and the sample due there)
      const BasicChainState<S> end = physical(m_scaled.x);
      samplePiece(m_t, m_tEnd, true, [&](const S&) { return end; });
      return finish(StopReason::TimeLimit, end, m_tEnd);
    }
    const Step<S> step = m_stepper->advance(m_scaled, tauEnd, horizon, m_stop, m_searchSteps);
    const S from = m_t;
    const S when = m_scale.toPhysicalTime(step.tau);
    switch (step.kind) {
      case Step<S>::Kind::Event: {
        sampleStep(from, when, false);
        // into the vectors reused from event to event (no allocation per contact)
        const BasicState<S> after = m_scale.toPhysical(step.after);
        const BasicState<S> before = m_scale.toPhysical(step.before);
        m_at.u << after.u1, after.u2;
        m_at.v << after.v1, after.v2;
        m_vBefore << before.v1, before.v2;
        S flight = 0, shortfall = 0;
        if (step.endsFlight) {
          // T2 - FFT exact from the offset when the contact is anchored at the return
          const FlightTime<S>& duration = step.flightDuration;
          flight = m_scale.toPhysicalTime(duration.value());
          shortfall = m_scale.toPhysicalTime(duration.periods == 1 ? S(-duration.offset)
                                                                   : S(twoPi<S>() - duration.value()));
        }
        record(step.type, m_at, m_vBefore, when, timesPowerOfTwo(step.residual, m_scale.exponent), flight, shortfall);
        m_t = when;
        continue;
      }
      case Step<S>::Kind::End:
        // without an end time, a flight from the stop back on it in no time the search can tell:
        // undecided there, as the modal kernel's
        if (!(m_tEnd > 0)) return finish(StopReason::Undecided, m_anyEvent ? m_at : m_state, m_t);
        sampleStep(from, m_tEnd, true);
        return finish(StopReason::TimeLimit, physical(step.before), m_tEnd);
      case Step<S>::Kind::NoFurtherContact:
        sampleStep(from, neverEnds(from), true);
        return finish(StopReason::NoFurtherContact, physical(step.before), m_t);
      case Step<S>::Kind::SearchLimit:
      case Step<S>::Kind::SearchBudget:
        // no contact decided as far as the search went (drawn that far): the run ends at the
        // flight's start, as the modal kernel's (simulate ends at the search's end)
        sampleStep(from, when, true);
        return finish(StopReason::SearchBudget, m_anyEvent ? m_at : m_state, m_t);  // the start's own numbers
      case Step<S>::Kind::Undecided:
        return finish(StopReason::Undecided, physical(m_scaled.x), m_t);
      case Step<S>::Kind::Cancelled:
        return finish(StopReason::Cancelled, physical(m_scaled.x), m_t);
    }
  }
  if (m_run.contacts < m_maxContacts) return false;
  const BasicChainState<S> last = physical(m_scaled.x);
  samplePiece(m_t, m_t, true, [&](const S&) { return last; });
  return finish(StopReason::ContactLimit, last, m_t);
}

template <typename S>
BasicChainRun<S> runChain(const BasicMassChain<S>& chain, const std::type_identity_t<BasicChainStart<S>>& start,
                          long maxContacts,
                          std::type_identity_t<S> tEnd, std::stop_token stop,
                          const ChainEventSink<std::type_identity_t<S>>& sink,
                          const ChainSampling<std::type_identity_t<S>>& sampling) {
  return runChain(readyChain(chain), start, maxContacts, tEnd, std::move(stop), sink, sampling);
}

template <typename S>
BasicChainRun<S> runChain(const BasicReadyChain<S>& chain, const std::type_identity_t<BasicChainStart<S>>& start,
                          long maxContacts,
                          std::type_identity_t<S> tEnd, std::stop_token stop,
                          const ChainEventSink<std::type_identity_t<S>>& sink,
                          const ChainSampling<std::type_identity_t<S>>& sampling, std::int64_t searchSteps) {
  BasicChainSimulator<S> simulator(chain, start, maxContacts, tEnd, sink, sampling, searchSteps);
  simulator.advance(maxContacts, std::move(stop));
  return simulator.takeRun();
}

template <typename S>
ChainRun inDouble(const BasicChainRun<S>& from) {
  auto vector = [](const ChainVector<S>& x) {
    ChainVector<double> y(x.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) y(i) = toDouble(S(x(i)));
    return y;
  };
  ChainRun run;
  run.events.reserve(from.events.size());
  for (const BasicChainEvent<S>& e : from.events) {
    run.events.push_back({toDouble(e.t), e.type, vector(e.u), vector(e.vBefore), toDouble(e.vAfter),
                          toDouble(e.flight), toDouble(e.shortfall)});
  }
  run.contacts = from.contacts;
  run.impacts = from.impacts;
  run.grazings = from.grazings;
  run.sticks = from.sticks;
  run.releases = from.releases;
  run.final = {vector(from.final.u), vector(from.final.v)};
  run.tFinal = toDouble(from.tFinal);
  run.stop = from.stop;
  run.energyInitial = toDouble(from.energyInitial);
  run.energyFinal = toDouble(from.energyFinal);
  run.maxEnergyDrift = from.maxEnergyDrift;
  run.maxContactResidual = from.maxContactResidual;
  return run;
}

#define GRAZELAB_INSTANTIATE(S)                                                                                  \
  template BasicChainRun<S> runChain<S>(const BasicReadyChain<S>&, const BasicChainStart<S>&, long,                 \
                                        std::type_identity_t<S>, std::stop_token, const ChainEventSink<S>&,         \
                                        const ChainSampling<S>&, std::int64_t);                                     \
  template BasicReadyChain<S> readyChain<S>(const BasicMassChain<S>&, Kernel);                                      \
  template BasicReadyChain<S> readyChain<S>(const BasicModel<S>&);                                                     \
  template BasicReadyChain<S> readyChain<S>(const TwoMassForm<S>&);                                                   \
  template class BasicChainSimulator<S>;                                                                                 \
  template S chainEnergy<S>(const BasicMassChain<S>&, const BasicChainState<S>&);                                         \
  template ChainRun inDouble<S>(const BasicChainRun<S>&);                                                                 \
  template BasicChainRun<S> runChain<S>(const BasicMassChain<S>&, const BasicChainStart<S>&, long, std::type_identity_t<S>, \
                                        std::stop_token, const ChainEventSink<S>&, const ChainSampling<S>&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
