// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/experiments/chain_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/solver/chain_run.h"
#include "core/solver/chain_trust.h"

namespace grazelab::core {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::int64_t kMaxAxisCount = std::int64_t(1) << 24;

PointSummary noRun() {
  PointSummary point;
  point.fftFirst = point.fftMin = point.fftMax = point.fftMean = kNaN;
  point.firstImpactTime = point.horizon = kNaN;
  point.impacts = point.grazings = point.sticks = -1;
  return point;
}

// The summary of the run in S; false when it ended undecided and `raise` allows a higher
// precision to decide it
template <typename S>
bool summarize(const ChainMapSpec& spec, const ChainState& start, double period, bool raise, std::stop_token stop,
               PointSummary& point) {
  const int s = spec.chain.stopped() - 1;
  point = PointSummary{};
  point.valid = true;
  point.horizon = kNaN;
  point.firstImpactTime = kNaN;
  point.fftFirst = kNaN;
  double sum = 0, low = kInfinity, high = -kInfinity;
  long flights = 0;
  // a flight from the stop: from an impact, a grazing or a release (or a start on the stop
  // leaving it) to the next contact
  bool fromStop = start.u[s] == spec.chain.gap && start.v[s] <= 0;
  double leftAt = 0;
  const BasicChainState<S> first{start.u.cast<S>(), start.v.cast<S>()};
  std::optional<ChainTrustCheck<S>> check;
  if (spec.estimateHorizon) check.emplace(spec.chain, first, long(spec.contacts), S(0), TrustMode::Auto, stop);
  const ChainEventSink<S> sink = [&](const BasicChainEvent<S>& event) {
    if (check) check->observe(event);
    const double t = toDouble(event.t);
    if (event.type == EventType::Impact && std::isnan(point.firstImpactTime)) point.firstImpactTime = t;
    if (isContact(event.type) && fromStop && t > leftAt) {
      const double length = t - leftAt;
      if (std::isnan(point.fftFirst)) point.fftFirst = length;
      sum += length / period;
      low = std::min(low, length / period);
      high = std::max(high, length / period);
      ++flights;
    }
    fromStop = event.type != EventType::Stick;
    leftAt = t;
  };
  const BasicChainRun<S> run = runChain(spec.chain, first, long(spec.contacts), S(0), stop, sink);
  if (run.stop == ChainStop::Undecided) {
    if (raise) return false;
    // undecided in binary128 too: the map cannot say what the run does (no partial counts)
    point = noRun();
    return true;
  }
  // a flight from the stop that never ends: the resonant chain's flight stays below forever
  if (run.stop == ChainStop::NoFurtherContact && fromStop && std::isnan(point.fftFirst)) point.fftFirst = kInfinity;
  point.impacts = run.impacts;
  point.grazings = run.grazings;
  point.sticks = run.sticks;
  point.fftMin = flights > 0 ? low : kNaN;
  point.fftMax = flights > 0 ? high : kNaN;
  point.fftMean = flights > 0 ? sum / double(flights) : kNaN;
  if (check && run.stop != ChainStop::Cancelled) {
    const Trust trust = check->finish(run);
    if (trust.verdict != Verdict::Unchecked) point.horizon = trust.horizon;
  }
  return true;
}

}  // namespace

std::string ChainMapAxis::name() const {
  // appended, not "literal" + string: GCC 12 warns falsely on that at -O2
  return std::string(velocity ? "v" : "u").append(std::to_string(mass));
}

std::optional<ChainMapAxis> parseChainMapVariable(std::string_view text, Eigen::Index n) {
  if (text.size() < 2 || (text[0] != 'u' && text[0] != 'v')) return std::nullopt;
  int mass = 0;
  for (char c : text.substr(1)) {
    if (c < '0' || c > '9' || mass > 1000) return std::nullopt;
    mass = 10 * mass + (c - '0');
  }
  if (mass < 1 || mass > n) return std::nullopt;
  ChainMapAxis axis;
  axis.velocity = text[0] == 'v';
  axis.mass = mass;
  return axis;
}

double chainMapPeriod(const MassChain& chain) {
  const ChainDynamics dynamics = chainDynamics(chain);
  if (dynamics.period > 0) return dynamics.period;
  return twoPi<double>() / dynamics.omega.minCoeff();
}

std::string checkChainMap(const ChainMapSpec& spec) {
  const std::vector<Problem> problems = validate(spec.chain);
  if (!problems.empty()) return problems.front().field + " " + problems.front().reason;
  const Eigen::Index n = spec.chain.size();
  if (spec.start.u.size() != n || spec.start.v.size() != n) return "the start needs one u and one v per mass";
  for (const ChainMapAxis* axis : {&spec.x, &spec.y}) {
    if (axis->mass < 1 || axis->mass > n) return "an axis names a mass the chain does not have";
    if (axis->range.count < 1 || axis->range.count > kMaxAxisCount) return "an axis needs 1 to 2^24 points";
    if (!std::isfinite(axis->range.from) || !std::isfinite(axis->range.to)) return "an axis range is not finite";
  }
  if (spec.x.velocity == spec.y.velocity && spec.x.mass == spec.y.mass) return "the two axes set the same coordinate";
  if (spec.contacts < 1) return "a map's runs need at least one contact";
  return {};
}

PointSummary chainMapPoint(const ChainMapSpec& spec, std::int64_t column, std::int64_t row, std::stop_token stop) {
  ChainState start = spec.start;
  for (const auto& [axis, value] : {std::pair{&spec.x, spec.x.range.at(column)}, std::pair{&spec.y, spec.y.range.at(row)}}) {
    (axis->velocity ? start.v : start.u)[axis->mass - 1] = value;
  }
  const int s = spec.chain.stopped() - 1;
  if (!(start.u[s] <= spec.chain.gap)) return noRun();
  const double period = chainMapPeriod(spec.chain);
  PointSummary point;
  if (summarize<double>(spec, start, period, true, stop, point)) return point;
  if (summarize<long double>(spec, start, period, true, stop, point)) return point;
  summarize<Quad>(spec, start, period, false, stop, point);
  return point;
}

MapRows computeChainMap(const ChainMapSpec& spec, RowRange rows, const ParallelFor& parallelFor,
                        std::stop_token stop, const MapRowsProgress& progress) {
  MapRows map = computeRows(
      spec.x.range.count, rows,
      [&spec](std::int64_t column, std::int64_t row, std::stop_token pointStop) {
        return chainMapPoint(spec, column, row, pointStop);
      },
      noRun(), parallelFor, stop, progress);
  map.period = chainMapPeriod(spec.chain);
  return map;
}

}  // namespace grazelab::core
