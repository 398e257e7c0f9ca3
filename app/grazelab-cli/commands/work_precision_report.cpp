// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/work_precision_report.h"

#include <utility>

namespace grazelab::cli {

core::methods::TimingPolicy ReportRequest::timing() const {
  return quick ? core::methods::TimingPolicy{2, 0.5, 0.05, 1000} : core::methods::TimingPolicy{5, 3.0, 0.2, 1000};
}

core::methods::WorkBudget ReportRequest::budget() const {
  core::methods::WorkBudget budget;
  budget.maxSteps = 1'000'000'000;
  budget.maxSeconds = quick ? 5 : 60;
  return budget;
}

namespace {

template <typename T>
ReportOutcome reportOn(T task, const ReportRequest& request, std::stop_token stop, const ReportProgress& progress) {
  using namespace core::methods;
  const TimingPolicy timing = request.timing();
  const WorkBudget budget = request.budget();
  ReportOutcome outcome;
  if (progress.horizon) progress.horizon();
  outcome.end = comparisonEnd(task, stop);
  if (stop.stop_requested()) return ReportOutcome{};
  if (outcome.end.shortened) task.tEnd = outcome.end.tEnd;
  outcome.tEnd = task.tEnd;
  if (progress.reference) progress.reference(task.tEnd);
  const auto reference = makeReference(task, budget, stop);
  if (stop.stop_requested()) return ReportOutcome{};
  if (reference.run.status != RunStatus::Completed) {
    outcome.status = ReportStatus::NoReference;
    outcome.problem = "no trustworthy reference for this problem: " + reference.run.reason;
    return outcome;
  }
  outcome.referenceContacts = reference.run.steps;
  outcome.referenceSeconds = reference.seconds;
  outcome.referencePeriod = reference.period;
  std::vector<MethodSetting> plan;
  for (MethodKind kind : request.methods) {
    for (const MethodSetting& setting : reportSettings(kind, request.period, request.k1, request.quick)) {
      plan.push_back(setting);
    }
  }
  for (const MethodSetting& setting : plan) {
    outcome.points.push_back(measurePoint(task, reference, setting, budget, timing, stop));
    if (stop.stop_requested()) return ReportOutcome{};
    if (progress.point) progress.point(outcome.points.size(), plan.size(), outcome.points.back());
  }
  outcome.status = ReportStatus::Computed;
  return outcome;
}

}  // namespace

ReportOutcome workPrecisionReport(const ReportRequest& request, std::stop_token stop, const ReportProgress& progress) {
  return std::visit([&](const auto& task) { return reportOn(task, request, stop, progress); }, request.task);
}

}  // namespace grazelab::cli
