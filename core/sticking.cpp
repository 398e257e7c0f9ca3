// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/sticking.h"

#include <cassert>
#include <cmath>
#include <numbers>

namespace grazelab::core {

bool pressedOnStop(const Model& model, const State& state) {
  if (state.u2 != model.gap || state.v2 != 0) return false;
  return state.u1 > model.gap || (state.u1 == model.gap && state.v1 > 0);
}

StuckMotion::StuckMotion(const Model& model, const State& start)
    : m_model(model),
      m_start(start),
      m_omega(std::sqrt((model.k1 + model.k2) / model.m1)),
      m_centre(model.k2 * model.gap / (model.k1 + model.k2)) {
  assert(pressedOnStop(model, start));
  // u1(t) - centre = a cos(w t) + b sin(w t) = R cos(w t - phi); release where it falls to
  // gap - centre: w t = phi + acos((gap - centre) / R), positive because u1(0) >= gap
  const double a = start.u1 - m_centre;
  const double b = start.v1 / m_omega;
  const double radius = std::hypot(a, b);
  const double phi = std::atan2(b, a);
  const double level = std::min(1.0, (model.gap - m_centre) / radius);
  double t = (phi + std::acos(level)) / m_omega;
  // polish on u1(t) - gap = (u1(0) - gap) + a (cos wt - 1) + b sin wt, free of cancellation
  for (int step = 0; step < 3; ++step) {
    const double half = 0.5 * m_omega * t;
    const double sine = std::sin(2 * half);
    const double cosMinusOne = -2.0 * std::sin(half) * std::sin(half);
    const double value = (start.u1 - model.gap) + a * cosMinusOne + b * sine;
    const double slope = m_omega * (-a * sine + b * (1.0 + cosMinusOne));
    if (slope >= 0 || value == 0) break;
    const double next = t - value / slope;
    if (!(next > 0) || std::abs(next - t) > 1e-3 * t) break;
    t = next;
  }
  m_releaseTime = t;
}

State StuckMotion::at(double t) const {
  const double a = m_start.u1 - m_centre;
  const double b = m_start.v1 / m_omega;
  const double half = 0.5 * m_omega * t;
  const double sine = std::sin(2 * half);
  const double cosMinusOne = -2.0 * std::sin(half) * std::sin(half);
  return {m_start.u1 + a * cosMinusOne + b * sine, m_model.gap,
          m_omega * (-a * sine + b * (1.0 + cosMinusOne)), 0.0};
}

State StuckMotion::releaseState() const {
  State state = at(m_releaseTime);
  state.u1 = m_model.gap;
  state.v1 = std::min(state.v1, 0.0);
  return state;
}

}  // namespace grazelab::core
