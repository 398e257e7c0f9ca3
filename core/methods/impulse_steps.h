// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "core/methods/scaled_run.h"

namespace grazelab::core::methods {

/// Turns the steps in which a time-stepping method applied a contact impulse into events. A
/// time stepper has no contact instant: an impact is a short run of impulse steps (one for
/// Moreau-Jean, one or two for Schatzman-Paoli, whose reflection is symmetric about the middle
/// of the pair). Such a run is one impact at its middle, from the state before its first step
/// to the state after its last. A longer run is a stuck phase: a stick at its first step and a
/// release after its last.
template <typename T>
class ImpulseSteps {
 public:
  using Vector = typename ScaledRun<T>::Vector;
  /// Impulse steps in a row from which on the contact is a stuck phase.
  static constexpr int kStuckSteps = 3;

  /// One step that began at `tau` in state (q0, v0) and ended in (q1, v1); `impulse` says
  /// whether the method applied a contact impulse in it.
  void step(ScaledRun<T>& run, bool impulse, double tau, const Vector& q0, const Vector& v0,
            const Vector& q1, const Vector& v1) {
    if (impulse) {
      if (m_count == 0) {
        m_firstTau = tau;
        m_firstQ = q0;
        m_firstV = v0;
      }
      m_lastTau = tau;
      if (++m_count == kStuckSteps) run.contact(EventType::Stick, m_firstTau, m_firstQ, m_firstV, q1, v1);
      return;
    }
    flush(run, tau, q0, v0);
  }

  /// Ends a contact still open at `tau` (the end of the run) in state (q, v).
  void flush(ScaledRun<T>& run, double tau, const Vector& q, const Vector& v) {
    if (m_count == 0) return;
    if (m_count < kStuckSteps) {
      run.contact(m_firstV(run.stop()) > 0 ? EventType::Impact : EventType::Stick,
                  0.5 * (m_firstTau + m_lastTau), m_firstQ, m_firstV, q, v);
    } else {
      run.release(tau, q, v);
    }
    m_count = 0;
  }

 private:
  int m_count = 0;
  double m_firstTau = 0;
  double m_lastTau = 0;
  Vector m_firstQ, m_firstV;
};

}  // namespace grazelab::core::methods
