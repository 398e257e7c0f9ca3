// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <chrono>
#include <optional>
#include <stop_token>
#include <string>
#include <type_traits>

#include "core/methods/method.h"
#include "core/methods/scaled_system.h"
#include "core/model/two_mass_form.h"
#include "core/solver/recorder.h"

namespace grazelab::core::methods {

/// The run of a comparison method: every method integrates its chain without units (docs/model.md
/// section 8), so that none of them is judged on the units of its input, and hands its contacts
/// here. One class for both tasks; T says how the run is kept:
/// - Task, the note's chain: scaled as in section 7 (tau = w2 t, x = u / L, y = v / (w2 L)) and
///   kept by a Recorder as the exact run's Result (samples for the explorer's overlays);
/// - ChainTask, any chain: time in units of its slowest mode (tau = w_N t), lengths in units of
///   L as the note's chain chooses it (the power of 2 at or below the larger of the gap and the
///   start's size), kept as a ChainRun in the one event layout of every chain.
/// Holds references to its own members: neither copied nor moved.
template <typename T>
class ScaledRun {
 public:
  static constexpr bool kNotesChain = std::is_same_v<T, Task>;
  // (a conditional type, not a conditional size: a signature that names Eigen::Dynamic, a
  // const of internal linkage, would give the members internal linkage)
  using System = std::conditional_t<kNotesChain, ScaledSystem<2>, ScaledSystem<Eigen::Dynamic>>;
  using Vector = typename System::Vector;
  using Output = std::conditional_t<kNotesChain, MethodRun, ChainMethodRun>;

  /// Validates the task and forms the system; refused() says whether that failed.
  ScaledRun(const T& task, const WorkBudget& budget, std::stop_token stop);
  ScaledRun(const ScaledRun&) = delete;
  ScaledRun& operator=(const ScaledRun&) = delete;

  bool refused() const { return m_refused; }
  const System& system() const { return m_system; }
  int size() const { return m_system.size(); }
  int stop() const { return m_system.stop; }     ///< the stopped mass, 0-based
  double gap() const { return m_system.gap; }    ///< the stop, in scaled length
  double tauEnd() const { return m_tauEnd; }
  const Vector& startPosition() const { return m_q0; }
  const Vector& startVelocity() const { return m_v0; }
  /// Scaled time of a physical time, and the scaled value of a physical stiffness acting on the
  /// stopped mass.
  double toTau(double t) const { return t * m_timeRate; }
  double scaledStopStiffness(double kc) const { return kc / m_stiffnessUnit; }

  /// A contact found by the method, with the states just before and after it.
  void contact(EventType type, double tau, const Vector& qBefore, const Vector& vBefore,
               const Vector& qAfter, const Vector& vAfter);
  /// The end of a stuck phase.
  void release(double tau, const Vector& q, const Vector& v);
  /// A point of the method's own discrete solution (its dense output for overlays; the note's
  /// chain only: a ChainRun keeps no samples).
  void sample(double tau, const Vector& q, const Vector& v) {
    if constexpr (kNotesChain) m_recorder->samplePoint(tau, twoMass(q, v));
  }

  /// Called every few hundred steps with the steps so far: true when the run must stop now
  /// (the stop token, the step or time budget, or a non-finite state); the run is then finished.
  bool mustStop(std::int64_t steps, double tau, const Vector& q, const Vector& v);
  /// Ends a run that reached its horizon in state (q, v): completed, or failed when not finite.
  void complete(const Vector& q, const Vector& v);
  /// Ends the run at scaled time tau in state (q, v).
  void finish(RunStatus status, std::string reason, double tau, const Vector& q, const Vector& v);
  /// Hands over the run (after finish()).
  Output take();

  Output& run() { return m_run; }

 private:
  static State twoMass(const Vector& q, const Vector& v) { return {q(0), q(1), v(0), v(1)}; }
  double physicalTime(double tau) const { return tau / m_timeRate; }
  /// The relative energy error of a scaled state (infinite when it is not finite).
  double drift(const Vector& q, const Vector& v) const;
  /// A ChainTask's state in its physical units.
  ChainState physical(const Vector& q, const Vector& v) const;

  Output m_run;
  bool m_refused = true;
  System m_system;
  Vector m_q0, m_v0;
  double m_tauEnd = 0;
  double m_timeRate = 1;       ///< tau / t
  double m_stiffnessUnit = 1;  ///< m_s w^2: a physical stiffness on the stopped mass over it is scaled
  double m_initialEnergy = 0;  ///< scaled (the note's chain) or physical (any chain)
  WorkBudget m_budget;
  std::stop_token m_stop;
  std::chrono::steady_clock::time_point m_started = std::chrono::steady_clock::now();
  // the note's chain
  std::optional<TwoMassForm<double>> m_chain;
  Scale<double> m_scale;
  std::optional<Recorder> m_recorder;
  // any chain
  MassChain m_massChain;
  double m_length = 1;  ///< L [length]
  double m_maxContactDrift = 0;
};

/// Steps between checks of the budget and the stop token in time-stepping loops.
inline constexpr std::int64_t kCheckEverySteps = 512;

/// Validates a task the way every method does: the chain, the start, the horizon. Empty when
/// usable, else the one line that says why not.
std::string taskProblem(const Task& task);
std::string taskProblem(const ChainTask& task);

/// A run refused before it started, with its reason.
MethodRun refusedRun(const Task& task, std::string reason);
ChainMethodRun refusedRun(const ChainTask& task, std::string reason);

/// The fixed step of a time-stepping method, in scaled units: the given h made to divide the
/// horizon exactly (tauEnd / ceil(tauEnd / h)), with the number of steps.
struct FixedSteps {
  double h = 0;
  std::int64_t count = 0;
};
FixedSteps fixedSteps(double tauEnd, double hScaled);

}  // namespace grazelab::core::methods
