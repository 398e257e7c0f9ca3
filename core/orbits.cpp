// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/contact.h"
#include "core/free_flight.h"

namespace grazelab::core {

State glomData(const Model& model, const Modes& modes, Mode mode) {
  const int column = mode == Mode::Fast ? 0 : 1;
  return {model.gap * modes.P(0, column) / modes.P(1, column), model.gap, 0.0, 0.0};
}

State gloData(const Model& model, const Modes& modes, double lambda) {
  const State fast = glomData(model, modes, Mode::Fast);
  const State slow = glomData(model, modes, Mode::Slow);
  // u2 stays exactly the gap: (1 - l) gap + l gap would round
  return {(1.0 - lambda) * fast.u1 + lambda * slow.u1, model.gap, 0.0, 0.0};
}

GloKind classifyGlo(double lambda) {
  if (lambda < 0) return GloKind::ImpactsFollow;
  if (lambda > 4.0 / 3.0) return GloKind::StickingStart;
  return GloKind::Grazing;
}

std::string describe(GloKind kind) {
  switch (kind) {
    case GloKind::Grazing:
      return "grazing linear orbit (lambda in [0, 4/3]): touches the stop once per period, no impact";
    case GloKind::ImpactsFollow:
      return "lambda < 0: the linear motion would cross the stop, impacts follow";
    case GloKind::StickingStart:
      return "lambda > 4/3: u1 > gap, the motion starts stuck on the stop, impacts follow";
  }
  return {};
}

double lambdaStar(const Modes& modes) {
  const double fastWeight = modes.P(1, 0) * modes.P(1, 0) / (modes.omegaFast * modes.omegaFast);
  const double slowWeight = modes.P(1, 1) * modes.P(1, 1) / (modes.omegaSlow * modes.omegaSlow);
  return slowWeight / (fastWeight + slowWeight);
}

OnePeriodicOrbit onePeriodicOrbit(const Model& model, const Modes& modes, double T) {
  OnePeriodicOrbit orbit;
  std::ostringstream why;
  why.precision(17);
  if (!std::isfinite(T) || T <= 0) {
    why << "the period T must be positive and finite (got " << T << ")";
    orbit.reason = why.str();
    return orbit;
  }
  const double omega[2] = {modes.omegaFast, modes.omegaSlow};
  double phi[2];
  for (int j = 0; j < 2; ++j) {
    const double half = 0.5 * omega[j] * T;
    const double sine = std::sin(half);
    if (std::abs(sine) <= 1e-12) {
      why << "T = " << T << " is a multiple of T" << (j + 1) << " = "
          << 2 * std::numbers::pi / omega[j] << ": no 1IPP orbit";
      orbit.reason = why.str();
      return orbit;
    }
    phi[j] = std::cos(half) / (sine * omega[j]);
  }
  // g_k = sum_j a_kj Phi_j, a_kj = m2 P_kj P_2j
  double g[2];
  for (int k = 0; k < 2; ++k) {
    g[k] = 0;
    for (int j = 0; j < 2; ++j) g[k] += model.m2 * modes.P(k, j) * modes.P(1, j) * phi[j];
  }
  orbit.V = model.gap / g[1];
  orbit.postImpact = {model.gap * g[0] / g[1], model.gap, 0.0, orbit.V};
  if (!(orbit.V < 0)) {
    why << "V = " << orbit.V << " >= 0: the data would leave into the stop (try T < T2 = "
        << modes.T2 << ")";
    orbit.reason = why.str();
    return orbit;
  }
  const Flight flight(model, modes, orbit.postImpact);
  const Contact contact = nextContact(flight, 1.5 * T);
  const double arrival = contact.time.value(modes.T2);
  if (contact.kind == ContactKind::None || std::abs(arrival - T) > 1e-9 * std::max(T, modes.T2)) {
    why << "the free flight from the data first comes back to the stop at t = " << arrival
        << ", not at the period T = " << T << ": not admissible";
    if (contact.kind == ContactKind::None) why.str("the free flight never comes back to the stop");
    orbit.reason = why.str();
    return orbit;
  }
  orbit.admissible = true;
  return orbit;
}

}  // namespace grazelab::core
