// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "core/model.h"
#include "core/state.h"

namespace grazelab::core {

/// True when a state on the stop with v2 = 0 is pressed into it (MODEL.md section 4): the spring
/// pushes mass 2 toward the stop, u1 > gap, or u1 = gap with v1 > 0 (pushing next instant).
bool pressedOnStop(const Model& model, const State& state);

/// The stuck phase: mass 2 held at u2 = gap (reaction R = -k2 (u1 - gap) <= 0) while mass 1
/// oscillates alone, m1 u1'' + (k1 + k2) u1 = k2 gap, about the centre k2 gap / (k1 + k2) < gap.
/// It ends when u1 falls back to the gap (R reaches 0), always in finite time.
class StuckMotion {
 public:
  /// Precondition: pressedOnStop(model, start).
  StuckMotion(const Model& model, const State& start);

  /// State t after the start of the phase (u2 = gap, v2 = 0 throughout).
  State at(double t) const;
  /// Duration of the phase: the first t > 0 with u1(t) = gap and u1 decreasing.
  double releaseTime() const { return m_releaseTime; }
  /// The state at release: u1 = gap exactly, v1 <= 0, on the stop at rest.
  State releaseState() const;

 private:
  Model m_model;
  State m_start;
  double m_omega = 0;        // sqrt((k1 + k2) / m1)
  double m_centre = 0;       // k2 gap / (k1 + k2)
  double m_releaseTime = 0;
};

}  // namespace grazelab::core
