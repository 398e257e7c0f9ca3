// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <array>
#include <chrono>
#include <optional>
#include <stop_token>
#include <string>

#include "core/model/chain.h"
#include "core/methods/method.h"
#include "core/solver/recorder.h"

namespace grazelab::core::methods {

/// The run of a comparison method: every method integrates the same nondimensional chain
/// (docs/model.md section 7: tau = w2 t, x = u / L, y = v / (w2 L)), so that none of them is
/// judged on the units of its input, and hands its events to the same Recorder as the exact
/// solver.
/// Holds references to its own members: neither copied nor moved.
class ScaledRun {
 public:
  /// Validates the task and forms the chain; refused() says whether that failed.
  ScaledRun(const Task& task, const WorkBudget& budget, std::stop_token stop);
  ScaledRun(const ScaledRun&) = delete;
  ScaledRun& operator=(const ScaledRun&) = delete;

  bool refused() const { return !m_recorder; }
  const Chain<double>& chain() const { return *m_chain; }
  double gap() const { return m_scale.gap; }  ///< the stop, delta = d / L
  double tauEnd() const { return m_tauEnd; }
  const State& scaledStart() const { return m_scaledStart; }
  /// Scaled time of a physical time, and the scaled value of a physical stiffness acting on m2.
  double toTau(double t) const { return m_scale.toScaledTime(t); }
  double scaledStopStiffness(double kc) const;

  /// Free accelerations (x1'', x2'') of the scaled chain at positions (x1, x2).
  std::array<double, 2> acceleration(double x1, double x2) const {
    const Chain<double>& c = *m_chain;
    const double stretch = x1 - x2;
    return {-(c.p * x1 + c.q * stretch), c.w * stretch};
  }

  /// A contact found by the method, with the states just before and after it.
  void contact(EventType type, double tau, const State& before, const State& after);
  /// The end of a stuck phase.
  void release(double tau, const State& x);
  /// A point of the method's own discrete solution (its dense output for overlays).
  void sample(double tau, const State& x);

  /// Called every few hundred steps with the steps so far: true when the run must stop now
  /// (the stop token, the step or time budget, or a non-finite state); the run is then finished.
  bool mustStop(std::int64_t steps, double tau, const State& x);
  /// Ends a run that reached its horizon in state x: completed, or failed when x is not finite.
  void complete(const State& x);
  /// Ends the run at scaled time tau in state x.
  void finish(RunStatus status, std::string reason, double tau, const State& x);
  /// Hands over the run (after finish()).
  MethodRun take();

  MethodRun& run() { return m_run; }

 private:
  MethodRun m_run;
  std::optional<Chain<double>> m_chain;
  Scale<double> m_scale;
  std::optional<Recorder<double>> m_recorder;
  State m_scaledStart;
  double m_tauEnd = 0;
  double m_initialEnergy = 0;
  WorkBudget m_budget;
  std::stop_token m_stop;
  std::chrono::steady_clock::time_point m_started = std::chrono::steady_clock::now();
};

/// Steps between checks of the budget and the stop token in time-stepping loops.
inline constexpr std::int64_t kCheckEverySteps = 512;

/// Validates a task the way every method does: the model, the start, the horizon. Empty when
/// usable, else the one line that says why not.
std::string taskProblem(const Task& task);

/// A run refused before it started, with its reason.
MethodRun refusedRun(const Task& task, std::string reason);

/// The fixed step of a time-stepping method, in scaled units: the given h made to divide the
/// horizon exactly (tauEnd / ceil(tauEnd / h)), with the number of steps.
struct FixedSteps {
  double h = 0;
  std::int64_t count = 0;
};
FixedSteps fixedSteps(double tauEnd, double hScaled);

}  // namespace grazelab::core::methods
