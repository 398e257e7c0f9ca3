// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/experiments/chain_series.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/solver/chain_trust.h"

namespace grazelab::core::experiments {

ChainSeries chainSeries(const ChainSeriesSpec& spec, std::stop_token stop) {
  ChainSeries series;
  series.chain = spec.chain;
  series.start = spec.start;
  series.contactsAsked = spec.contacts;
  series.modes = chainModes(spec.chain);
  series.ratios = detectRatios(series.modes.omega);
  if (series.ratios.commensurate) series.period = 2 * std::numbers::pi / series.ratios.omega0;
  const Eigen::Index s = spec.chain.stopped() - 1;
  const Eigen::Index chosen = spec.phaseMass > 0 ? Eigen::Index(spec.phaseMass - 1) : s;
  ChainSampling<double> sampling;
  if (spec.window > 0 && spec.gridPoints > 1) {
    for (int i = 0; i < spec.gridPoints; ++i)
      sampling.times.push_back(spec.window * i / (spec.gridPoints - 1));
    sampling.sink = [&](double t, const ChainState& state) {
      series.grid.push_back({t, state.u[s], state.v[s], state.u[chosen], state.v[chosen],
                             std::vector<double>(state.u.data(), state.u.data() + state.u.size())});
    };
  }
  if (spec.free) {
    // one closed-form flight over the grid, through the stop if it goes there
    const ChainDynamics dynamics = chainDynamics(spec.chain);
    const BasicChainFlight<double> flight = flightFrom(dynamics, spec.start);
    if (sampling.sink) {
      for (double t : sampling.times) sampling.sink(t, stateAt(dynamics, flight, t));
    }
    series.run.final = spec.start;
    series.run.stop = ChainStop::TimeLimit;
    return series;
  }
  series.run = runChain(spec.chain, spec.start, spec.contacts, 0.0, stop, {}, sampling);
  series.trust =
      chainTrust(spec.chain, spec.start, series.run, spec.contacts, 0.0, spec.trust, stop);
  // each flight ends at a contact: it started at the event before (or the start)
  double from = 0;
  bool fromStop = spec.start.u[s] == spec.chain.gap && spec.start.v[s] <= 0;
  bool afterImpact = false;
  long contact = 0;
  for (const ChainEvent& event : series.run.events) {
    if (event.type == EventType::Release) {  // a flight from the stop begins
      from = event.t;
      fromStop = true;
      afterImpact = false;
      continue;
    }
    ++contact;
    if (event.type != EventType::Stick || event.t > from) {
      series.flights.push_back({contact, event.t - from, fromStop, afterImpact});
    }
    from = event.t;
    fromStop = true;
    afterImpact = event.type == EventType::Impact;
  }
  return series;
}

}  // namespace grazelab::core::experiments
