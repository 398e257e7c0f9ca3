// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/experiments/bar.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include "core/solver/chain_run.h"

namespace grazelab::core {

std::vector<Problem> validate(const Bar& bar) {
  std::vector<Problem> problems;
  const auto positive = [&](const char* field, double value) {
    if (!(value > 0) || !std::isfinite(value)) {
      problems.push_back({field, "must be positive and finite (got " + std::to_string(value) + ")"});
    }
  };
  positive("E", bar.youngModulus);
  positive("rho", bar.density);
  positive("S", bar.area);
  positive("L", bar.length);
  positive("speed", bar.speed);
  return problems;
}

BarContinuum barContinuum(const Bar& bar) {
  BarContinuum continuum;
  continuum.waveSpeed = std::sqrt(bar.youngModulus / bar.density);
  continuum.duration = 2 * bar.length / continuum.waveSpeed;
  continuum.force = bar.youngModulus * bar.area * bar.speed / continuum.waveSpeed;
  continuum.impulse = 2 * bar.density * bar.area * bar.length * bar.speed;
  continuum.rebound = -bar.speed;
  return continuum;
}

MassChain barChain(const Bar& bar, int masses, BarEnd end) {
  MassChain chain;
  const double n = masses;
  chain.masses.assign(std::size_t(masses), bar.density * bar.area * bar.length / n);
  chain.springs.assign(std::size_t(masses), bar.youngModulus * bar.area * n / bar.length);
  chain.springs[0] = 0;  // no wall: the bar floats
  chain.stopMass = end == BarEnd::Last ? masses : 1;
  chain.gap = bar.speed * bar.length / barContinuum(bar).waveSpeed;
  return chain;
}

ChainState barStart(const Bar& bar, int masses, BarEnd end) {
  const double gap = barChain(bar, 1, end).gap;
  return {Eigen::VectorXd::Constant(masses, gap), Eigen::VectorXd::Constant(masses, bar.speed)};
}

namespace {

// The run in S; nothing but the status when it is undecided (the caller goes one precision up)
template <typename S>
BarImpact throwIn(const Bar& bar, int masses, BarEnd end, std::stop_token stop, long maxImpacts) {
  const MassChain chain = barChain(bar, masses, end);
  const ChainState start = barStart(bar, masses, end);
  const BasicMassChain<S> wide = chainCast<S>(chain);
  const BasicChainState<S> wideStart{start.u.cast<S>(), start.v.cast<S>()};
  const int s = chain.stopped() - 1;
  const double m = chain.masses[0];
  BarImpact impact;
  impact.masses = masses;
  impact.precision = std::is_same_v<S, double> ? Precision::Double : std::is_same_v<S, Quad> ? Precision::Quad
                                                                                                : Precision::Long;
  // streamed: a thousand masses' events would each hold two vectors of a thousand
  const ChainEventSink<S> sink = [&](const BasicChainEvent<S>& event) {
    if (event.type != EventType::Impact) return;
    impact.times.push_back(toDouble(event.t));
    impact.impulses.push_back(m * toDouble(S(event.vBefore[s] - event.vAfter)));
  };
  const BasicChainRun<S> run = runChain<S>(wide, wideStart, maxImpacts, S(0), std::move(stop), sink);
  switch (run.stop) {
    case StopReason::NoFurtherContact: impact.status = BarStatus::Computed; break;
    case StopReason::Cancelled: impact.status = BarStatus::Cancelled; return impact;
    case StopReason::Undecided: impact.status = BarStatus::Undecided; return impact;
    default: impact.status = BarStatus::Unfinished; break;  // the contact limit, or a search's budget
  }
  impact.impacts = run.impacts;
  impact.energyDrift = run.maxEnergyDrift;
  // the wall's impulse by the momentum it took (a held phase's push included, were there one)
  S velocity = 0;
  for (Eigen::Index i = 0; i < run.final.v.size(); ++i) velocity += run.final.v[i];
  velocity /= S(masses);
  const S totalMass = S(m) * S(masses);
  impact.rebound = toDouble(velocity);
  impact.impulse = toDouble(S(totalMass * (S(bar.speed) - velocity)));
  impact.vibration = toDouble(S((run.energyFinal - totalMass * velocity * velocity / 2) / run.energyInitial));
  impact.duration = impact.times.empty() ? 0.0 : impact.times.back() - impact.times.front();
  impact.meanForce = impact.duration > 0 ? impact.impulse / impact.duration : 0.0;
  return impact;
}

}  // namespace

BarImpact throwBar(const Bar& bar, int masses, BarEnd end, std::stop_token stop, long maxImpacts) {
  if (maxImpacts <= 0) maxImpacts = 100L * masses + 100;
  BarImpact impact = throwIn<double>(bar, masses, end, stop, maxImpacts);
  if (impact.status == BarStatus::Undecided) impact = throwIn<long double>(bar, masses, end, stop, maxImpacts);
  if (impact.status == BarStatus::Undecided) impact = throwIn<Quad>(bar, masses, end, stop, maxImpacts);
  return impact;
}

Convergence convergence(const std::vector<int>& masses, const std::vector<double>& values, double limit) {
  Convergence result;
  const std::size_t count = std::min(masses.size(), values.size());
  for (std::size_t i = 0; i + 1 < count; ++i) {
    const double before = std::abs(values[i] - limit), after = std::abs(values[i + 1] - limit);
    result.orders.push_back(before > 0 && after > 0 ? std::log(before / after) / std::log(double(masses[i + 1]) / masses[i])
                                                    : std::nan(""));
  }
  if (count < 3) return result;
  // x = x_inf + C N^-p through the last three: (x1 - x2) / (x2 - x3) = (N1^-p - N2^-p) / (N2^-p -
  // N3^-p), which grows with p; solved by bisection for p in (0, 8]
  const double n1 = masses[count - 3], n2 = masses[count - 2], n3 = masses[count - 1];
  const double x1 = values[count - 3], x2 = values[count - 2], x3 = values[count - 1];
  const double first = x1 - x2, second = x2 - x3;
  if (!(first * second > 0) || !(n1 < n2 && n2 < n3)) return result;
  const double ratio = std::log(first / second);
  const auto shape = [&](double p) {
    return std::log((std::pow(n1, -p) - std::pow(n2, -p)) / (std::pow(n2, -p) - std::pow(n3, -p)));
  };
  double low = 1e-3, high = 8;
  if (!(shape(low) < ratio && ratio < shape(high))) return result;
  for (int step = 0; step < 200; ++step) {
    const double middle = (low + high) / 2;
    (shape(middle) < ratio ? low : high) = middle;
  }
  const double p = (low + high) / 2;
  const double c = second / (std::pow(n2, -p) - std::pow(n3, -p));
  result.extrapolated = x3 - c * std::pow(n3, -p);
  result.extrapolatedOrder = p;
  return result;
}

}  // namespace grazelab::core
