// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/free_flight.h"

#include <cmath>
#include <limits>

namespace grazelab::core {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// 1 / n! for the Taylor sums
constexpr std::array<double, Flight::kTaylorOrder + 2> inverseFactorials() {
  std::array<double, Flight::kTaylorOrder + 2> values{};
  double factorial = 1;
  for (int n = 0; n < static_cast<int>(values.size()); ++n) {
    if (n > 0) factorial *= n;
    values[n] = 1.0 / factorial;
  }
  return values;
}
constexpr auto kInverseFactorial = inverseFactorials();

// (sin x, cos x - 1) without cancellation for small x
struct Phase {
  double sine;
  double cosineMinusOne;
};

Phase phaseOf(double halfSine, double halfCosine) {
  return {2.0 * halfSine * halfCosine, -2.0 * halfSine * halfSine};
}

}  // namespace

Flight::Flight(const Model& model, const Modes& modes, const State& start)
    : m_model(model), m_modes(modes), m_start(start), m_startsOnStop(start.u2 == model.gap) {
  const Eigen::Vector2d u(start.u1, start.u2);
  const Eigen::Vector2d v(start.v1, start.v2);
  m_q = modes.Pinv * u;
  m_qDot = modes.Pinv * v;
  const Eigen::Vector2d omega(modes.omegaFast, modes.omegaSlow);
  m_omega = omega;
  m_amplitudeRatio = m_qDot.cwiseQuotient(omega);
  for (int j = 0; j < 2; ++j) {
    m_alpha(j) = modes.P(1, j) * m_q(j);
    m_beta(j) = modes.P(1, j) * m_qDot(j) / omega(j);
  }

  if (start.u2 != model.gap) {
    m_contactOrder = 0;
  } else if (start.v2 != 0) {
    m_contactOrder = 1;  // the common case, decided without the series
  } else {
    m_contactOrder = 2;
    while (m_contactOrder <= kTaylorOrder && gapDerivative(m_contactOrder) == 0) ++m_contactOrder;
  }

  // the Taylor form is needed only where u2 - gap is small against its amplitude, so that the
  // modal sum would lose it; 0.05 / w_fast keeps the series short (11 terms at most)
  m_taylorRadius = 0.05 / modes.omegaFast;
  m_gapAmplitude = 0;
  m_accelerationBound = 0;
  for (int j = 0; j < 2; ++j) {
    const double amplitude = std::sqrt(m_alpha(j) * m_alpha(j) + m_beta(j) * m_beta(j));
    m_gapAmplitude += amplitude;
    m_accelerationBound += amplitude * omega(j) * omega(j);
  }
  m_gapTolerance = 16 * kEpsilon * (2 * m_gapAmplitude + std::abs(start.u2 - model.gap));
}

void Flight::ensureTaylor() const {
  if (m_taylorReady) return;
  m_taylorReady = true;
  // derivatives of u at the start: u'' = A u with A = -M^-1 K, applied in a form that keeps the
  // spring stretch u2 - u1 as one difference
  const double a = m_model.k1 / m_model.m1;
  const double b = m_model.k2 / m_model.m1;
  const double c = m_model.k2 / m_model.m2;
  m_derivatives[0] = Eigen::Vector2d(m_start.u1, m_start.u2);
  m_derivatives[1] = Eigen::Vector2d(m_start.v1, m_start.v2);
  for (int n = 2; n < static_cast<int>(m_derivatives.size()); ++n) {
    const Eigen::Vector2d& x = m_derivatives[n - 2];
    m_derivatives[n] = Eigen::Vector2d(b * (x(1) - x(0)) - a * x(0), c * (x(0) - x(1)));
  }
  for (int n = 0; n <= kTaylorOrder; ++n) {
    const double gapDerivativeN = n == 0 ? m_start.u2 - m_model.gap : m_derivatives[n](1);
    m_gapAndRateSeries[2 * n] = gapDerivativeN * kInverseFactorial[n];
    m_gapAndRateSeries[2 * n + 1] = m_derivatives[n + 1](1) * kInverseFactorial[n];
  }
}

double Flight::gapDerivative(int n) const {
  if (n == 0) return m_start.u2 - m_model.gap;
  if (n == 1) return m_start.v2;
  ensureTaylor();
  return m_derivatives[n](1);
}

double Flight::reduce(double t) const {
  if (!m_modes.resonant) return t;
  // one period off covers every contact search; t - T2 is exact there (Sterbenz), and the
  // general remainder() (exact too, but slow) serves the rest
  const double half = 0.5 * m_modes.T2;
  if (t >= -half && t <= half) return t;
  if (t > half && t <= 2 * m_modes.T2) return t - m_modes.T2;
  if (t < -half && t >= -2 * m_modes.T2) return t + m_modes.T2;
  return std::remainder(t, m_modes.T2);
}

int Flight::taylorTerms(double s) const {
  // enough terms for (w_fast |s|)^n / n! to fall below 1e-19
  const double x = m_modes.omegaFast * std::abs(s);
  if (x <= 0.01) return 8;
  if (x <= 0.03) return 10;
  return kTaylorOrder;  // x <= 0.05 inside the Taylor window: 0.05^12 / 12! < 1e-24
}

State Flight::at(double t) const {
  const double s = reduce(t);
  return std::abs(s) <= m_taylorRadius ? taylorAt(s) : modalAt(s);
}

State Flight::taylorAt(double s) const {
  ensureTaylor();
  // Horner on sum d_n s^n / n!, from the highest order down
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
  for (int n = taylorTerms(s); n >= 0; --n) {
    position = position * s + m_derivatives[n] * kInverseFactorial[n];
    velocity = velocity * s + m_derivatives[n + 1] * kInverseFactorial[n];
  }
  return {position(0), position(1), velocity(0), velocity(1)};
}

Flight::Increments Flight::modalPhases(double s) const {
  Increments phases;
  if (m_modes.resonant) {
    // the fast phase is exactly twice the slow one: one sincos serves both
    const double halfSlow = 0.5 * m_modes.omegaSlow * s;
    const Phase slow = phaseOf(std::sin(halfSlow), std::cos(halfSlow));
    const double cosSlow = 1.0 + slow.cosineMinusOne;
    phases.sine = {2.0 * slow.sine * cosSlow, slow.sine};
    phases.cosineMinusOne = {-2.0 * slow.sine * slow.sine, slow.cosineMinusOne};
  } else {
    const double halfFast = 0.5 * m_modes.omegaFast * s;
    const double halfSlow = 0.5 * m_modes.omegaSlow * s;
    const Phase fast = phaseOf(std::sin(halfFast), std::cos(halfFast));
    const Phase slow = phaseOf(std::sin(halfSlow), std::cos(halfSlow));
    phases.sine = {fast.sine, slow.sine};
    phases.cosineMinusOne = {fast.cosineMinusOne, slow.cosineMinusOne};
  }
  return phases;
}

State Flight::modalAt(double s) const {
  const Increments phases = modalPhases(s);
  Eigen::Vector2d dq;
  Eigen::Vector2d dqDot;
  for (int j = 0; j < 2; ++j) {
    dq(j) = m_q(j) * phases.cosineMinusOne[j] + m_amplitudeRatio(j) * phases.sine[j];
    dqDot(j) = m_omega(j) *
               (-m_q(j) * phases.sine[j] + m_amplitudeRatio(j) * phases.cosineMinusOne[j]);
  }
  const Eigen::Vector2d du = m_modes.P * dq;
  const Eigen::Vector2d dv = m_modes.P * dqDot;
  return {m_start.u1 + du(0), m_start.u2 + du(1), m_start.v1 + dv(0), m_start.v2 + dv(1)};
}

std::pair<double, double> Flight::gapAndRate(double t) const {
  const double s = reduce(t);
  if (std::abs(s) <= m_taylorRadius) {
    // value = sum_n c_n s^n / n!,  rate = sum_n c_(n+1) s^n / n!
    // both Horner sums in one pass over interleaved coefficients
    ensureTaylor();
    double value = 0;
    double rate = 0;
    for (int n = taylorTerms(s); n >= 0; --n) {
      const double* pair = &m_gapAndRateSeries[2 * n];
      value = value * s + pair[0];
      rate = rate * s + pair[1];
    }
    return {value, rate};
  }
  // only the mass-2 row of the modal sum: u2 - gap as (u2(0) - gap) + increment
  const Increments phases = modalPhases(s);
  double gapIncrement = 0;
  double rateIncrement = 0;
  for (int j = 0; j < 2; ++j) {
    gapIncrement += m_modes.P(1, j) * (m_q(j) * phases.cosineMinusOne[j] +
                                       m_amplitudeRatio(j) * phases.sine[j]);
    rateIncrement += m_modes.P(1, j) * m_omega(j) *
                     (-m_q(j) * phases.sine[j] + m_amplitudeRatio(j) * phases.cosineMinusOne[j]);
  }
  return {(m_start.u2 - m_model.gap) + gapIncrement, m_start.v2 + rateIncrement};
}

double Flight::acceleration2(double t) const {
  const double s = reduce(t);
  if (std::abs(s) <= m_taylorRadius) {
    // sum_n c_(n+2) s^n / n!
    ensureTaylor();
    double acceleration = 0;
    for (int n = kTaylorOrder - 1; n >= 0; --n) {
      acceleration = acceleration * s + m_derivatives[n + 2](1) * kInverseFactorial[n];
    }
    return acceleration;
  }
  const Increments phases = modalPhases(s);
  double acceleration = 0;
  for (int j = 0; j < 2; ++j) {
    acceleration -= m_omega(j) * m_omega(j) *
                    (m_alpha(j) * (1.0 + phases.cosineMinusOne[j]) + m_beta(j) * phases.sine[j]);
  }
  return acceleration;
}

std::pair<double, double> Flight::gapAndAccelerationAtPhase(double sine,
                                                           double cosineMinusOne) const {
  // fast phase 2 theta: sin 2th = 2 sin th cos th, cos 2th - 1 = -2 sin^2 th
  const double sines[2] = {2.0 * sine * (1.0 + cosineMinusOne), sine};
  const double cosinesMinusOne[2] = {-2.0 * sine * sine, cosineMinusOne};
  double gap = m_start.u2 - m_model.gap;
  double acceleration = 0;
  for (int j = 0; j < 2; ++j) {
    gap += m_modes.P(1, j) * (m_q(j) * cosinesMinusOne[j] + m_amplitudeRatio(j) * sines[j]);
    acceleration -= m_omega(j) * m_omega(j) *
                    (m_alpha(j) * (1.0 + cosinesMinusOne[j]) + m_beta(j) * sines[j]);
  }
  return {gap, acceleration};
}

std::pair<double, double> Flight::reducedGapAndRate(double x, int m) const {
  if (m == 0) return gapAndRate(x);
  if (std::abs(x) <= m_taylorRadius) {
    // g(x) = sum_{n>=m} c_n x^(n-m) / n!,  g'(x) = sum_{n>m} c_n (n-m) x^(n-m-1) / n!
    ensureTaylor();
    double value = 0;
    double rate = 0;
    for (int n = std::max(taylorTerms(x), m); n >= m; --n) {
      rate = rate * x + value;
      value = value * x + m_gapAndRateSeries[2 * n];
    }
    return {value, rate};
  }
  // divide by the unreduced x^m: the sign of g must follow the sign of u2 - gap over the whole
  // segment, not flip where a resonant time is reduced modulo T2
  const auto [gapValue, gapRate] = gapAndRate(x);
  const double power = std::pow(x, m);
  return {gapValue / power, (gapRate - m * gapValue / x) / power};
}

}  // namespace grazelab::core
