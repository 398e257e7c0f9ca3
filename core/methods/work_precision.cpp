// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/methods/work_precision.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/solver/chain_run.h"
#include "core/solver/trust.h"
#include "core/solver/two_mass_run.h"
#include "core/solver/simulate.h"

namespace grazelab::core::methods {
namespace {

constexpr double kRoundingFloor = 1e-13;
constexpr double kSaturated = 1e-2;

double errorOf(const WorkPrecisionPoint& point, ErrorMeasure measure) {
  return measure == ErrorMeasure::State ? point.errors.state : point.errors.contactTime;
}

bool usable(const WorkPrecisionPoint& point) {
  return point.status == RunStatus::Completed && std::isfinite(point.errors.state) &&
         point.secondsMin > 0;
}

template <typename T, typename R>
WorkPrecisionPoint measure(const T& task, const BasicReference<R>& reference,
                           const MethodSetting& setting, const WorkBudget& budget,
                           const TimingPolicy& timing, std::stop_token stop,
                           BasicMethodRun<R>* firstRun) {
  WorkPrecisionPoint point;
  point.setting = setting;
  std::vector<double> seconds;
  double spent = 0;
  for (int run = 0;; ++run) {
    BasicMethodRun<R> result = runMethod(task, setting, budget, stop);
    seconds.push_back(result.seconds);
    spent += result.seconds;
    if (run == 0) {
      point.errors = compare(reference, result);
      point.status = result.status;
      point.reason = result.reason;
      point.steps = result.steps;
    }
    // a run that did not complete is not repeated: its time says nothing more
    const bool enough = run + 1 >= std::max(1, timing.runs) &&
                        (spent >= timing.minSeconds || run + 1 >= timing.maxRuns);
    const bool last = result.status != RunStatus::Completed || spent > timing.capSeconds ||
                      stop.stop_requested() || enough;
    if (run == 0 && firstRun != nullptr) *firstRun = std::move(result);
    if (last) break;
  }
  std::sort(seconds.begin(), seconds.end());
  point.runs = int(seconds.size());
  point.secondsMin = seconds.front();
  const std::size_t n = seconds.size();
  point.secondsMedian = n % 2 == 1 ? seconds[n / 2] : 0.5 * (seconds[n / 2 - 1] + seconds[n / 2]);
  return point;
}

/// The period of a task's slowest mode.
double slowestPeriod(const Task& task) {
  return twoPi<double>() / makeTwoMassForm(task.model).chain->omegaSlow;
}
double slowestPeriod(const ChainTask& task) {
  return twoPi<double>() / (task.prepared ? task.prepared->slowest : slowestFrequency(chainModes(task.chain).omega));
}

}  // namespace

WorkPrecisionPoint measurePoint(const Task& task, const Reference& reference,
                                const MethodSetting& setting, const WorkBudget& budget,
                                const TimingPolicy& timing, std::stop_token stop,
                                MethodRun* firstRun) {
  return measure(task, reference, setting, budget, timing, std::move(stop), firstRun);
}

WorkPrecisionPoint measurePoint(const ChainTask& task, const ChainReference& reference,
                                const MethodSetting& setting, const WorkBudget& budget,
                                const TimingPolicy& timing, std::stop_token stop,
                                ChainMethodRun* firstRun) {
  return measure(task, reference, setting, budget, timing, std::move(stop), firstRun);
}

std::vector<MethodSetting> reportSettings(MethodKind kind, double period, double k1, bool quick) {
  std::vector<MethodSetting> settings;
  auto add = [&](double value) { settings.push_back({kind, value}); };
  switch (kind) {
    case MethodKind::Exact:
      for (Precision precision : {Precision::Double, Precision::Long, Precision::Quad}) {
        settings.push_back({kind, 0, precision});
      }
      break;
    case MethodKind::MoreauJean:
    case MethodKind::MoreauJeanTheta1:
    case MethodKind::SchatzmanPaoli: {
      // h / T2 = 1e-3 ... 1e-6 in quarter decades (quick: ... 1e-5 in half decades)
      const int last = quick ? 4 : 12;
      const double step = quick ? 0.5 : 0.25;
      for (int i = 0; i <= last; ++i) add(period * 1e-3 * std::pow(10.0, -step * i));
      break;
    }
    case MethodKind::Dopri5Events:
    case MethodKind::CvodeAdams:
    case MethodKind::CvodeBdf:
      for (int e = 3; e <= (quick ? 13 : 15); e += quick ? 2 : 1) add(std::pow(10.0, -e));
      break;
    case MethodKind::Penalty:
      // a tight tolerance, so that the modelling error of a finite k_c shows, not CVODE's
      for (int e = 2; e <= 12; e += quick ? 2 : 1) {
        settings.push_back({kind, k1 * std::pow(10.0, e), Precision::Double, kPenaltyReportRtol});
      }
      // and the stiffest spring at looser tolerances: the cost side of the method
      if (!quick) {
        for (int e = 4; e <= 10; e += 2) {
          MethodSetting setting{kind, k1 * 1e12, Precision::Double, std::pow(10.0, -e)};
          setting.penaltyToleranceSweep = true;
          settings.push_back(setting);
        }
      }
      break;
  }
  return settings;
}

std::optional<Slope> fittedSlope(const std::vector<WorkPrecisionPoint>& points,
                                 ErrorMeasure measure) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (const WorkPrecisionPoint& point : points) {
    const double error = errorOf(point, measure);
    if (!usable(point) || point.errors.missed > 0 || point.errors.extra > 0) continue;
    if (point.setting.penaltyToleranceSweep) continue;  // the penalty's order is in k_c
    if (!(error > kRoundingFloor && error < kSaturated)) continue;
    // smaller is finer for every knob: h, rtol, eps, and 1 / k_c
    const double knob = point.setting.parameterValue();
    const double x = std::log10(point.setting.kind == MethodKind::Penalty ? 1 / knob : knob);
    const double y = std::log10(error);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    ++n;
  }
  if (n < 3) return std::nullopt;
  const double denominator = n * sxx - sx * sx;
  if (!(denominator > 0)) return std::nullopt;
  return Slope{(n * sxy - sx * sy) / denominator, n};
}

std::optional<double> secondsToReach(const std::vector<WorkPrecisionPoint>& points,
                                     double target) {
  std::vector<const WorkPrecisionPoint*> sorted;
  for (const WorkPrecisionPoint& point : points) {
    if (usable(point)) sorted.push_back(&point);
  }
  std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->secondsMin < b->secondsMin; });
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const WorkPrecisionPoint& here = *sorted[i];
    if (here.errors.state > target) continue;
    // the first point (by cost) at the target: interpolate from the cheaper one before it
    if (i == 0 || !(sorted[i - 1]->errors.state > 0) || !(here.errors.state > 0)) {
      return here.secondsMin;
    }
    const WorkPrecisionPoint& before = *sorted[i - 1];
    const double x0 = std::log10(before.errors.state), x1 = std::log10(here.errors.state);
    const double y0 = std::log10(before.secondsMin), y1 = std::log10(here.secondsMin);
    const double fraction = (std::log10(target) - x0) / (x1 - x0);
    return std::pow(10.0, y0 + std::clamp(fraction, 0.0, 1.0) * (y1 - y0));
  }
  return std::nullopt;
}

const WorkPrecisionPoint* cheapestReaching(const std::vector<WorkPrecisionPoint>& points,
                                           double target) {
  const WorkPrecisionPoint* best = nullptr;
  for (const WorkPrecisionPoint& point : points) {
    if (!usable(point) || point.errors.state > target) continue;
    if (best == nullptr || point.secondsMin < best->secondsMin) best = &point;
  }
  return best;
}

Trust startTrust(const Task& task, std::stop_token stop) {
  const BasicReadyChain<long double> input = readyChain(convertModel<long double>(task.model));
  const ChainShadow<double> shadow = chainShadow<double>(input);
  TrustMonitor<double> monitor(shadow, chainStateOf(convertState<long double>(task.start)),
                               std::numeric_limits<long>::max(), task.tEnd, TrustMode::Full);
  Request request;
  request.initial = task.start;
  request.tEnd = task.tEnd;
  request.maxContacts = std::numeric_limits<std::int64_t>::max();
  request.needs.events = false;
  request.onEvent = [&monitor](const Event& event) { monitor.observe(chainEventOf(event)); };
  TwoMassRun<double> run(task.model, request);
  run.advance(std::numeric_limits<std::int64_t>::max(), stop);
  return monitor.finish(chainTotalsOf(run.result()));
}

Trust startTrust(const ChainTask& task, std::stop_token stop) {
  const ChainStart start{task.start, task.stillModes};
  const ReadyChain chain = readyChain(task.chain);
  std::optional<BasicReadyChain<long double>> widened;
  const ChainShadow<double> shadow = widenedShadow(chain, widened);
  TrustMonitor<double> monitor(shadow, {{task.start.u.cast<long double>(), task.start.v.cast<long double>()}, task.stillModes},
                               std::numeric_limits<long>::max(), task.tEnd, TrustMode::Full, stop);
  const ChainRun run = runChain(chain, start, std::numeric_limits<long>::max(), task.tEnd, stop,
                                [&monitor](const ChainEvent& event) { monitor.observe(event); });
  return monitor.finish(run);
}

namespace {

template <typename T>
ComparisonEnd endOf(const T& task, std::stop_token stop) {
  ComparisonEnd end;
  end.tEnd = task.tEnd;
  end.trust = startTrust(task, stop);
  end.horizon = end.trust.horizon;
  if (end.horizon > 0 && end.horizon < task.tEnd) {
    const double period = slowestPeriod(task);
    end.tEnd = std::max(end.horizon - period / 8, end.horizon / 2);
    end.shortened = true;
    T shorter = task;
    shorter.tEnd = end.tEnd;
    end.trust = startTrust(shorter, stop);
  }
  return end;
}

}  // namespace

ComparisonEnd comparisonEnd(const Task& task, std::stop_token stop) { return endOf(task, std::move(stop)); }
ComparisonEnd comparisonEnd(const ChainTask& task, std::stop_token stop) {
  return endOf(task, std::move(stop));
}

}  // namespace grazelab::core::methods
