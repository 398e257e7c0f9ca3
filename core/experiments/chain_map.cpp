// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/experiments/chain_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "core/experiments/map_chains.h"
#include "core/orbits/chain_glo.h"
#include "core/solver/chain_run.h"
#include "core/solver/trust.h"

namespace grazelab::core {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::int64_t kMaxAxisCount = std::int64_t(1) << 24;

PointSummary noRun() {
  PointSummary point;
  point.fftFirst = point.fftMin = point.fftMax = point.fftMean = kNaN;
  point.firstImpactTime = point.horizon = kNaN;
  point.impacts = point.grazings = point.sticks = -1;
  return point;
}

// chainMapPeriod of a chain's dynamics
double periodOf(const ChainDynamics& dynamics) {
  if (dynamics.period > 0) return dynamics.period;
  return twoPi<double>() / slowestFrequency(dynamics.omega);
}

}  // namespace

std::string ChainMapAxis::name() const {
  const char* letter = kind == Kind::Weight ? "w" : kind == Kind::Velocity ? "v" : "u";
  // appended, not "literal" + string: GCC 12 warns falsely on that at -O2
  return std::string(letter).append(std::to_string(index));
}

std::optional<ChainMapAxis> parseChainMapVariable(std::string_view text, Eigen::Index n) {
  if (text.size() < 2 || (text[0] != 'u' && text[0] != 'v' && text[0] != 'w')) return std::nullopt;
  int index = 0;
  for (char c : text.substr(1)) {
    if (c < '0' || c > '9' || index > 1000) return std::nullopt;
    index = 10 * index + (c - '0');
  }
  if (index < 1 || index > n) return std::nullopt;
  ChainMapAxis axis;
  axis.kind = text[0] == 'w' ? ChainMapAxis::Kind::Weight
              : text[0] == 'v' ? ChainMapAxis::Kind::Velocity
                               : ChainMapAxis::Kind::Position;
  axis.index = index;
  return axis;
}

int balancingWeight(const ChainMapSpec& spec) {
  int mode = int(spec.chain.size()) - 1;
  while (mode == spec.x.index - 1 || mode == spec.y.index - 1) --mode;
  return mode;
}

double chainMapPeriod(const MassChain& chain) { return periodOf(chainDynamics(chain)); }

std::string checkChainMap(const ChainMapSpec& spec) {
  const std::vector<Problem> problems = validate(spec.chain);
  if (!problems.empty()) return problems.front().field + " " + problems.front().reason;
  const Eigen::Index n = spec.chain.size();
  if (spec.start.u.size() != n || spec.start.v.size() != n) return "the start needs one u and one v per mass";
  for (const ChainMapAxis* axis : {&spec.x, &spec.y}) {
    if (axis->index < 1 || axis->index > n) return "an axis names a mass or mode the chain does not have";
    if (axis->range.count < 1 || axis->range.count > kMaxAxisCount) return "an axis needs 1 to 2^24 points";
    if (!std::isfinite(axis->range.from) || !std::isfinite(axis->range.to)) return "an axis range is not finite";
  }
  if (spec.x.kind == spec.y.kind && spec.x.index == spec.y.index) return "the two axes set the same coordinate";
  if (spec.x.weight() != spec.y.weight()) {
    return "a map over GLO weights has two weight axes (w<j>): its start is GLO_lambda plus a push";
  }
  if (spec.x.weight()) {
    if (n < 3) return "a map over GLO weights needs three modes or more (two weights on the axes, one balancing them)";
    if (!spec.weights.empty() && Eigen::Index(spec.weights.size()) != n) return "the GLO weights need one per mode";
    if (spec.push.u.size() != n || spec.push.v.size() != n) return "the push needs one u and one v per mass";
  }
  if (spec.contacts < 1) return "a map's runs need at least one contact";
  return {};
}

namespace {

PointSummary pointOf(const ChainMapSpec& spec, const MapChains& chain, std::int64_t column, std::int64_t row,
                     std::stop_token stop) {
  ChainState start = spec.start;
  std::vector<bool> stillModes;  // a GLO start left unpushed: its modes of weight 0 exactly still
  if (spec.x.weight()) {
    std::vector<double> weights = spec.weights.empty() ? std::vector<double>(std::size_t(spec.chain.size()), 0.0)
                                                       : spec.weights;
    weights[std::size_t(spec.x.index - 1)] = spec.x.range.at(column);
    weights[std::size_t(spec.y.index - 1)] = spec.y.range.at(row);
    const std::size_t balancing = std::size_t(balancingWeight(spec));
    double others = 0;
    for (std::size_t j = 0; j < weights.size(); ++j) others += j == balancing ? 0.0 : weights[j];
    weights[balancing] = 1 - others;
    const ChainGloStart glo = chainGloStartIn(chain.inDouble.dynamics, weights);
    if (glo.problem != GloStartProblem::None) return noRun();
    start = {glo.state.u + spec.push.u, glo.state.v + spec.push.v};
    if (spec.push.u.isZero(0) && spec.push.v.isZero(0)) stillModes = glo.stillModes;
  } else {
    for (const auto& [axis, value] : {std::pair{&spec.x, spec.x.range.at(column)}, std::pair{&spec.y, spec.y.range.at(row)}}) {
      (axis->kind == ChainMapAxis::Kind::Velocity ? start.v : start.u)[axis->index - 1] = value;
    }
  }
  const int s = spec.chain.stopped() - 1;
  if (!(start.u[s] <= spec.chain.gap)) return noRun();
  // the map's chain is in double (a parameter axis moves it by double steps): a point raised to a
  // higher precision runs that same chain there
  const double period = periodOf(chain.inDouble.dynamics);
  PointSummary point;
  const auto summarized = [&](auto zero, bool raise) {
    using S = decltype(zero);
    const BasicChainState<S> first{start.u.cast<S>(), start.v.cast<S>()};
    return summarizeRun(chain.ready<S>(), BasicChainStart<S>(first, stillModes), spec.contacts, period,
                        spec.estimateHorizon, raise, stop, point, chain.shadow<S>());
  };
  if (summarized(0.0, true) || summarized(0.0L, true)) return point;
  summarized(Quad(0), false);
  return point;
}

}  // namespace

PointSummary chainMapPoint(const ChainMapSpec& spec, std::int64_t column, std::int64_t row, std::stop_token stop) {
  const MapChains chain(spec.chain, spec.estimateHorizon);
  return pointOf(spec, chain, column, row, std::move(stop));
}

MapRows computeChainMap(const ChainMapSpec& spec, RowRange rows, const ParallelFor& parallelFor,
                        std::stop_token stop, const MapRowsProgress& progress) {
  const MapChains chain(spec.chain, spec.estimateHorizon);
  MapRows map = computeRows(
      spec.x.range.count, rows,
      [&spec, &chain](std::int64_t column, std::int64_t row, std::stop_token pointStop) {
        return pointOf(spec, chain, column, row, std::move(pointStop));
      },
      noRun(), parallelFor, stop, progress);
  map.period = periodOf(chain.inDouble.dynamics);
  return map;
}

}  // namespace grazelab::core
