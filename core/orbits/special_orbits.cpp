// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/numbers/roots.h"
#include "core/orbits/special_orbits.h"

#include <boost/math/special_functions/next.hpp>

#include <cmath>

#include "core/solver/contact.h"
#include "core/solver/free_flight.h"

namespace grazelab::core {

template <typename S>
BasicState<S> glomData(const TwoMassForm<S>& chain, Mode mode) {
  const S& gap = chain.model.gap;
  return {gap * (mode == Mode::Fast ? chain.rhoFast : chain.rhoSlow), gap, S(0), S(0)};
}

template <typename S>
GloKind classifyGlo(const S& lambda) {
  using std::fma;
  if (lambda < 0) return GloKind::ImpactsFollow;
  // 3 lambda - 4 with one rounding: its sign is exact, so lambda is compared with 4/3 itself
  if (fma(S(3), lambda, S(-4)) > 0) return GloKind::StickingStart;
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

template <typename S>
BasicState<S> gloData(const TwoMassForm<S>& chain, const S& lambda) {
  using std::fma;
  const S& gap = chain.model.gap;
  // u2 stays exactly the gap: (1 - l) gap + l gap would round
  if (!chain.resonant) {
    return {gap * ((S(1) - lambda) * chain.rhoFast + lambda * chain.rhoSlow), gap, S(0), S(0)};
  }
  // resonance identity -rho_fast / 3 + 4 rho_slow / 3 = 1 (u1 = gap at lambda = 4/3) gives
  // u1 - gap = gap (4 - 3 lambda) / 3 (rho_fast - rho_slow), with rho_fast - rho_slow < 0
  const S fourMinusThreeLambda = -fma(S(3), lambda, S(-4));  // exact sign
  const S excess = gap * (fourMinusThreeLambda / S(3)) * (chain.rhoFast - chain.rhoSlow);
  S u1 = gap + excess;
  // the class is decided by lambda; the data must agree with it after rounding
  const GloKind kind = classifyGlo(lambda);
  if (kind == GloKind::StickingStart && !(u1 > gap)) u1 = boost::math::float_next(gap);
  if (kind != GloKind::StickingStart && u1 > gap) u1 = gap;
  return {u1, gap, S(0), S(0)};
}

template <typename S>
S lambdaStar(const TwoMassForm<S>& chain) {
  // P_2j^2 = 1 / (m1 (rho_j^2 + beta)); lambda* = (P22^2 / w2^2) / (P21^2 / w1^2 + P22^2 / w2^2)
  const S fastWeight = S(1) / ((chain.rhoFast * chain.rhoFast + chain.beta) * chain.ratio * chain.ratio);
  const S slowWeight = S(1) / (chain.rhoSlow * chain.rhoSlow + chain.beta);
  return slowWeight / (fastWeight + slowWeight);
}

template <typename S>
OnePeriodicOrbit<S> onePeriodicOrbit(const TwoMassForm<S>& chain, const S& T) {
  using std::abs;
  using std::cos;
  using std::max;
  using std::sin;
  OnePeriodicOrbit<S> orbit;
  orbit.T = T;
  const S T2 = twoPi<S>() / chain.omegaSlow;
  if (!isFinite(T) || T <= 0) {
    orbit.refusal = OnePeriodicRefusal::BadPeriod;
    orbit.reason = "the period T must be positive and finite (got " + formatScalar(T) + ")";
    return orbit;
  }
  const S tau = chain.omegaSlow * T;  // scaled period
  const S omega[2] = {chain.ratio, S(1)};
  const S rho[2] = {chain.rhoFast, chain.rhoSlow};
  // scaled g_k = sum_j beta phi_kj / (rho_j^2 + beta) cot(w_j tau / 2) / w_j, phi_1j = rho_j
  S g[2] = {0, 0};
  for (int j = 0; j < 2; ++j) {
    const S half = omega[j] * tau / S(2);
    const S sine = sin(half);
    // a multiple of T_j only within the rounding of the phase itself (T2 (1 - 8e-14) is not)
    if (abs(sine) <= S(4) * epsilon<S>() * abs(half)) {
      orbit.refusal = OnePeriodicRefusal::MultipleOfPeriod;
      orbit.reason = "T = " + formatScalar(T) + " is a multiple of T" + std::to_string(j + 1) +
                     " = " + formatScalar(S(T2 / omega[j])) + ": no 1IPP orbit";
      return orbit;
    }
    const S weight = chain.beta / (rho[j] * rho[j] + chain.beta) * cos(half) / (sine * omega[j]);
    g[0] += weight * rho[j];
    g[1] += weight;
  }
  const S& gap = chain.model.gap;
  orbit.V = gap * chain.omegaSlow / g[1];
  orbit.postImpact = {gap * g[0] / g[1], gap, S(0), orbit.V};
  orbit.energy = physicalEnergy(chain, orbit.postImpact);
  if (!(orbit.V < 0)) {
    orbit.refusal = OnePeriodicRefusal::LeavesIntoStop;
    orbit.reason = "V = " + formatScalar(orbit.V) +
                   " >= 0: the data would leave into the stop, not away from it";
    if (T > T2) orbit.reason += " (1IPP orbits near T2 need T < T2 = " + formatScalar(T2) + ")";
    return orbit;
  }
  const Scale<S> scale = chooseScale(chain, orbit.postImpact);
  const Flight<S> flight(chain, scale.gap, scale.toScaled(orbit.postImpact));
  const Contact<S> contact = nextContact(flight, S(1.5) * tau);
  const S arrival = contact.time.value();
  if (contact.kind == ContactKind::Budget) {
    orbit.refusal = OnePeriodicRefusal::NotDecided;
    orbit.reason = "the contact search from the data ran out of its budget: not decided";
    return orbit;
  }
  if (contact.kind == ContactKind::None || contact.kind == ContactKind::Cancelled) {
    orbit.refusal = OnePeriodicRefusal::NeverReturns;
    orbit.reason = "the free flight from the data never comes back to the stop";
    return orbit;
  }
  if (contact.undecided && abs(arrival - tau) > S(1e-9) * max(tau, twoPi<S>())) {
    orbit.refusal = OnePeriodicRefusal::NotDecided;
    orbit.reason = "the free flight from the data touches the stop at t = " +
                   formatScalar(S(arrival / chain.omegaSlow)) + " within the rounding of " +
                   std::string(toString(precisionOf<S>())) +
                   ": whether it returns first at T is not decided in this precision";
    return orbit;
  }
  if (abs(arrival - tau) > S(1e-9) * max(tau, twoPi<S>())) {
    orbit.refusal = OnePeriodicRefusal::ReturnsEarly;
    orbit.reason = "the free flight from the data first comes back to the stop at t = " +
                   formatScalar(S(arrival / chain.omegaSlow)) + ", not at the period T = " +
                   formatScalar(T) + ": not admissible";
    return orbit;
  }
  orbit.admissible = true;
  return orbit;
}

namespace {
TwoMassForm<double> chainOf(const Model& model) { return *makeTwoMassForm(model).chain; }
}  // namespace

State glomData(const Model& model, const Modes&, Mode mode) { return glomData(chainOf(model), mode); }
State gloData(const Model& model, const Modes&, double lambda) {
  return gloData(chainOf(model), lambda);
}
double lambdaStar(const Modes& modes) {
  const double fast = modes.P(1, 0) * modes.P(1, 0) / (modes.omegaFast * modes.omegaFast);
  const double slow = modes.P(1, 1) * modes.P(1, 1) / (modes.omegaSlow * modes.omegaSlow);
  return slow / (fast + slow);
}
OnePeriodicOrbit<double> onePeriodicOrbit(const Model& model, const Modes&, double T) {
  return onePeriodicOrbit(chainOf(model), T);
}

double onePeriodicLowerEnd(const Model& model, const Modes& modes) {
  const TwoMassForm<double> chain = chainOf(model);
  auto admissible = [&](double T) { return onePeriodicOrbit(chain, T).admissible; };
  const double T2 = modes.T2;
  const double step = T2 / 256;
  double high = T2 * (1 - 1e-9);  // admissible: the family reaches T2 (Theorem 2.1)
  double low = high - step;
  while (low > 0 && admissible(low)) {
    high = low;
    low -= step;
  }
  if (low <= 0) return 0;
  return bisectBoundary(high, low, admissible, [] { return false; }, 1e-12 * T2);
}

#define GRAZELAB_INSTANTIATE(S)                                              \
  template BasicState<S> glomData<S>(const TwoMassForm<S>&, Mode);                 \
  template GloKind classifyGlo<S>(const S&);                                 \
  template BasicState<S> gloData<S>(const TwoMassForm<S>&, const S&);              \
  template S lambdaStar<S>(const TwoMassForm<S>&);                                 \
  template OnePeriodicOrbit<S> onePeriodicOrbit<S>(const TwoMassForm<S>&, const S&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
