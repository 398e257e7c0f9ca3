// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/methods/method.h"

#include <cmath>
#include <sstream>

#include "core/methods/runners.h"
#include "core/methods/scaled_run.h"
#include "core/numbers/vector_state.h"

namespace grazelab::core::methods {

std::string_view methodName(MethodKind kind) {
  switch (kind) {
    case MethodKind::Exact:
      return "exact";
    case MethodKind::MoreauJean:
      return "moreau-jean";
    case MethodKind::MoreauJeanTheta1:
      return "moreau-jean-theta1";
    case MethodKind::SchatzmanPaoli:
      return "schatzman-paoli";
    case MethodKind::Dopri5Events:
      return "dopri5-events";
    case MethodKind::CvodeAdams:
      return "cvode-adams";
    case MethodKind::CvodeBdf:
      return "cvode-bdf";
    case MethodKind::Penalty:
      return "penalty";
  }
  return "unknown";
}

std::optional<MethodKind> parseMethod(std::string_view name) {
  for (MethodKind kind : kAllMethods) {
    if (methodName(kind) == name) return kind;
  }
  return std::nullopt;
}

std::string_view parameterName(MethodKind kind) {
  switch (kind) {
    case MethodKind::Exact:
      return "eps";
    case MethodKind::MoreauJean:
    case MethodKind::MoreauJeanTheta1:
    case MethodKind::SchatzmanPaoli:
      return "h";
    case MethodKind::Dopri5Events:
    case MethodKind::CvodeAdams:
    case MethodKind::CvodeBdf:
      return "rtol";
    case MethodKind::Penalty:
      return "k_c";
  }
  return "";
}

std::string_view toString(RunStatus status) {
  switch (status) {
    case RunStatus::Completed:
      return "completed";
    case RunStatus::Budget:
      return "budget";
    case RunStatus::Undecided:
      return "undecided";
    case RunStatus::Failed:
      return "failed";
    case RunStatus::Refused:
      return "refused";
    case RunStatus::Cancelled:
      return "cancelled";
  }
  return "unknown";
}

std::string_view MethodSetting::parameter() const {
  return kind == MethodKind::Penalty && penaltyToleranceSweep ? "rtol" : parameterName(kind);
}

double MethodSetting::parameterValue() const {
  if (kind == MethodKind::Penalty && penaltyToleranceSweep) return penaltyRtol;
  if (kind != MethodKind::Exact) return value;
  switch (precision) {
    case Precision::Double:
      return std::ldexp(1.0, -53);
    case Precision::Long:
      return std::ldexp(1.0, -64);
    case Precision::Quad:
      return std::ldexp(1.0, -113);
  }
  return 0;
}

std::string MethodSetting::label() const {
  std::ostringstream out;
  out << methodName(kind) << ' ';
  if (kind == MethodKind::Exact) {
    out << toString(precision);
  } else {
    out.precision(3);
    out << parameter() << '=' << parameterValue();
    if (kind == MethodKind::Penalty && penaltyToleranceSweep) out << " (k_c=" << value << ')';
  }
  return out.str();
}

namespace {

template <typename T>
typename ScaledRun<T>::Output runOn(const T& task, const MethodSetting& setting,
                                    const WorkBudget& budget, std::stop_token stop) {
  const double value = setting.value;
  if (setting.kind != MethodKind::Exact && !(value > 0 && std::isfinite(value))) {
    return refusedRun(task, std::string(parameterName(setting.kind)) +
                                " must be positive and finite");
  }
  if (setting.kind == MethodKind::Exact) return runExact(task, setting.precision, budget, stop);
  ScaledRun<T> run(task, budget, stop);
  if (run.refused()) return run.take();
  switch (setting.kind) {
    case MethodKind::Exact:
      break;
    case MethodKind::MoreauJean:
      runMoreauJean(run, 0.5, value, budget);
      break;
    case MethodKind::MoreauJeanTheta1:
      runMoreauJean(run, 1.0, value, budget);
      break;
    case MethodKind::SchatzmanPaoli:
      runSchatzmanPaoli(run, value, budget);
      break;
    case MethodKind::Dopri5Events:
      runDopri5Events(run, value);
      break;
    case MethodKind::CvodeAdams:
      runCvode(run, false, value);
      break;
    case MethodKind::CvodeBdf:
      runCvode(run, true, value);
      break;
    case MethodKind::Penalty:
      runPenalty(run, value, setting.penaltyRtol);
      break;
  }
  return run.take();
}

}  // namespace

ChainTask prepared(ChainTask task) {
  if (!validate(task.chain).empty()) return task;
  const ChainModes modes = chainModes(task.chain);
  task.prepared = std::make_shared<const PreparedChain>(PreparedChain{
      readyChain(task.chain), readyChain(chainCast<long double>(task.chain)),
      readyChain(chainCast<Quad>(task.chain)), slowestFrequency(modes.omega), modes.omega.maxCoeff()});
  return task;
}

Task prepared(Task task) {
  if (!validate(task.model).empty() || !makeTwoMassForm(task.model).chain) return task;
  const ReadyChain ready = readyChain(task.model);
  const ChainVector<double>& omega = ready.dynamics.omega;
  task.prepared = std::make_shared<const PreparedChain>(PreparedChain{
      ready, readyChain(convertModel<long double>(task.model)), readyChain(convertModel<Quad>(task.model)),
      slowestFrequency(omega), omega.maxCoeff()});
  return task;
}

MethodRun runMethod(const Task& task, const MethodSetting& setting, const WorkBudget& budget,
                    std::stop_token stop) {
  clearUpperVectorState();  // timed: at the CPU's full speed, whatever ran before
  return runOn(task, setting, budget, std::move(stop));
}

ChainMethodRun runMethod(const ChainTask& task, const MethodSetting& setting,
                         const WorkBudget& budget, std::stop_token stop) {
  clearUpperVectorState();  // timed: at the CPU's full speed, whatever ran before
  return runOn(task, setting, budget, std::move(stop));
}

}  // namespace grazelab::core::methods
