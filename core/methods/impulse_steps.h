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
class ImpulseSteps {
 public:
  /// Impulse steps in a row from which on the contact is a stuck phase.
  static constexpr int kStuckSteps = 3;

  /// One step that began at `tau` in state `before` and ended in `after`; `impulse` says whether
  /// the method applied a contact impulse in it.
  void step(ScaledRun& run, bool impulse, double tau, const State& before, const State& after) {
    if (impulse) {
      if (m_count == 0) {
        m_firstTau = tau;
        m_first = before;
      }
      m_lastTau = tau;
      if (++m_count == kStuckSteps) run.contact(EventType::Stick, m_firstTau, m_first, after);
      return;
    }
    flush(run, tau, before);
  }

  /// Ends a contact still open at `tau` (the end of the run) in state x.
  void flush(ScaledRun& run, double tau, const State& x) {
    if (m_count == 0) return;
    if (m_count < kStuckSteps) {
      run.contact(m_first.v2 > 0 ? EventType::Impact : EventType::Stick,
                  0.5 * (m_firstTau + m_lastTau), m_first, x);
    } else {
      run.release(tau, x);
    }
    m_count = 0;
  }

 private:
  int m_count = 0;
  double m_firstTau = 0;
  double m_lastTau = 0;
  State m_first;
};

}  // namespace grazelab::core::methods
