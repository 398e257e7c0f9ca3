// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The scaled free flight of core/solver/free_flight.h seen in physical units (time t, lengths, speeds),
// so that tests state their properties in the units of docs/model.md.
#pragma once

#include <cmath>
#include <memory>

#include "core/model/two_mass_form.h"
#include "core/solver/contact.h"
#include "core/solver/free_flight.h"

namespace grazelab::testing {

/// A contact in physical time.
struct PhysicalContact {
  core::ContactKind kind = core::ContactKind::None;
  double time = 0;          ///< from the start of the flight [time]
  double offsetFromT2 = 0;  ///< time - T2, exact when the contact is anchored at the return
  bool fromReturn = false;
  double residual = 0;      ///< |u2 - gap| [length]
  core::FlightTime<double> scaledTime;  ///< the anchored scaled time the core returned
};

class PhysicalFlight {
 public:
  /// `march`: treat a resonant chain as detuned (same numbers), so that the detuned march
  /// searches it: a second, independent search to compare with.
  PhysicalFlight(const core::Model& model, const core::State& start, bool march = false)
      : m_chain(std::make_unique<core::TwoMassForm<double>>(chainOf(model, march))),
        m_scale(core::chooseScale(*m_chain, start)),
        m_flight(*m_chain, m_scale.gap, m_scale.toScaled(start)) {}

  const core::TwoMassForm<double>& chain() const { return *m_chain; }
  const core::Flight<double>& scaled() const { return m_flight; }
  double omega() const { return m_chain->omegaSlow; }
  double length() const { return std::ldexp(1.0, m_scale.exponent); }
  double T2() const { return 2 * M_PI / omega(); }

  core::State at(double t) const {
    return m_scale.toPhysical(m_flight.at(core::FlightTime<double>::nearest(t * omega())));
  }
  /// The state at a contact, from its anchored time (full relative precision near T2).
  core::State at(const PhysicalContact& contact) const {
    return m_scale.toPhysical(m_flight.at(contact.scaledTime));
  }
  std::pair<double, double> gapAndRate(double t) const {
    const auto [gap, rate] = m_flight.gapAndRate(core::FlightTime<double>::nearest(t * omega()));
    return {gap * length(), rate * length() * omega()};
  }
  double gap(double t) const { return gapAndRate(t).first; }
  /// (u2 - gap) / x^m and its derivative, x a physical time from the start (x < 0: before T2).
  std::pair<double, double> reducedGapAndRate(double x, int m) const {
    const long long anchor = x < 0 ? 1 : 0;
    const auto [g, rate] = m_flight.reducedGapAndRate(anchor, x * omega(), m);
    const double factor = length() * std::pow(omega(), m);
    return {g * factor, rate * factor * omega()};
  }
  int contactOrder() const { return m_flight.contactOrder(); }
  double taylorRadius() const { return m_flight.taylorRadius() / omega(); }

  PhysicalContact nextContact(double horizon = INFINITY) const {
    const core::Contact<double> contact = core::nextContact(m_flight, horizon * omega());
    PhysicalContact out;
    out.kind = contact.kind;
    out.time = contact.time.value() / omega();
    out.fromReturn = contact.time.periods == 1 && m_chain->resonant;
    out.offsetFromT2 = out.fromReturn ? contact.time.offset / omega() : out.time - T2();
    out.residual = contact.residual * length();
    out.scaledTime = contact.time;
    return out;
  }

 private:
  static core::TwoMassForm<double> chainOf(const core::Model& model, bool march) {
    core::TwoMassForm<double> chain = *core::makeTwoMassForm(model).chain;
    if (march) chain.resonant = false;
    return chain;
  }

  std::unique_ptr<core::TwoMassForm<double>> m_chain;  // the flight points into it
  core::Scale<double> m_scale;
  core::Flight<double> m_flight;
};

}  // namespace grazelab::testing
