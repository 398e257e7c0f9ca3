// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/mass_chain.h"
#include "core/model/model.h"
#include "core/solver/chain_run.h"
#include "core/solver/recorder.h"
#include "core/numbers/scalar.h"

namespace grazelab::core::methods {

/// The methods that can run the chain (issue 8): the exact solver and the standard methods of
/// nonsmooth mechanics it is compared with. One file each in core/methods/.
enum class MethodKind {
  Exact,             ///< closed-form flight, contacts from polynomial roots (double/long/quad)
  MoreauJean,        ///< Moreau-Jean time stepping, theta = 1/2, Newton impact law at velocity level
  MoreauJeanTheta1,  ///< the same with theta = 1 (implicit Euler)
  SchatzmanPaoli,    ///< central differences with the impact law on positions
  Dopri5Events,      ///< Dormand-Prince 5(4) with dense output, contacts located, restarted
  CvodeAdams,        ///< SUNDIALS CVODE, Adams-Moulton, root finding, restarted at impacts
  CvodeBdf,          ///< SUNDIALS CVODE, BDF, root finding, restarted at impacts
  Penalty,           ///< the stop as a stiff spring k_c (u2 - d)+, CVODE BDF
};

inline constexpr MethodKind kAllMethods[] = {
    MethodKind::Exact,          MethodKind::MoreauJean,   MethodKind::MoreauJeanTheta1,
    MethodKind::SchatzmanPaoli, MethodKind::Dopri5Events, MethodKind::CvodeAdams,
    MethodKind::CvodeBdf,       MethodKind::Penalty};

/// "exact", "moreau-jean", "moreau-jean-theta1", "schatzman-paoli", "dopri5-events",
/// "cvode-adams", "cvode-bdf", "penalty".
std::string_view methodName(MethodKind kind);
std::optional<MethodKind> parseMethod(std::string_view name);

/// The knob of a method: "h" (a fixed step [time]), "rtol" (a relative tolerance), "k_c" (the
/// penalty stiffness [force/length]) or "eps" (the exact solver's unit roundoff: its precision).
std::string_view parameterName(MethodKind kind);

/// One setting of one method.
struct MethodSetting {
  MethodKind kind = MethodKind::Exact;
  /// h, rtol or k_c (see parameterName); ignored by the exact solver, whose knob is `precision`.
  double value = 0;
  Precision precision = Precision::Double;  ///< exact only
  /// The penalty method's CVODE tolerance (its parameter is k_c).
  double penaltyRtol = 1e-10;
  /// Penalty only: this setting's knob is its CVODE tolerance, k_c held (a tolerance sweep).
  bool penaltyToleranceSweep = false;
  /// The knob of this setting: parameterName(kind), or "rtol" for a penalty tolerance sweep.
  std::string_view parameter() const;
  /// The value in the parameter's column: `value`, the unit roundoff of `precision`, or the
  /// penalty's rtol in a tolerance sweep.
  double parameterValue() const;
  /// e.g. "moreau-jean h=0.001", "exact quad".
  std::string label() const;
};

/// What a method may spend. Every method checks both (and its stop token) at least every few
/// hundred steps, so none can hang.
struct WorkBudget {
  std::int64_t maxSteps = 200'000'000;  ///< time steps (or contacts, for the exact solver)
  double maxSeconds = 60;               ///< wall time
};

/// How a method's run ended.
enum class RunStatus {
  Completed,  ///< reached the end time
  Budget,     ///< ran out of steps or seconds first
  Undecided,  ///< met a contact its precision cannot decide (the exact solver stops there, never guesses)
  Failed,     ///< the method broke down (a non-finite state, a solver error, chattering)
  Refused,    ///< the method cannot take this input (and said why before running)
  Cancelled,  ///< the stop token was triggered
};
std::string_view toString(RunStatus status);

/// The same chain, start and horizon for every method: the note's chain, written with its own
/// parameters (Task), or any chain of N masses (ChainTask).
struct PreparedChain;
struct Task {
  Model model;
  State start;
  double tEnd = 0;  ///< the horizon [time]
  Needs needs;      ///< what to keep (the events, samples for an overlay)
  /// The chain made ready once (prepared()), as ChainTask's: the exact solver's timed runs do
  /// not pay for its modes. Empty: each run makes what it needs.
  std::shared_ptr<const PreparedChain> prepared = {};
};
struct ChainTask {
  MassChain chain;
  ChainState start;
  double tEnd = 0;  ///< the horizon [time]
  /// The chain made ready once (prepared()), shared by every run of the task and its copies, so
  /// that no timed run pays for the chain's modes (a binary128 eigensolve: 0.37 ms at N = 10).
  /// Empty: each run makes what it needs.
  std::shared_ptr<const PreparedChain> prepared;
  /// the start's modes known to be exactly still (BasicChainStart): the exact method and the
  /// reference keep them so; the time-stepping methods have no use for it
  std::vector<bool> stillModes;
};

/// What every run of a chain needs of it, made once: the chain ready in each precision of the
/// exact solver, and its slowest and fastest frequencies (chainModes').
struct PreparedChain {
  BasicReadyChain<double> inDouble;
  BasicReadyChain<long double> inLong;
  BasicReadyChain<Quad> inQuad;
  double slowest = 0;  ///< w_N [1/time]
  double fastest = 0;  ///< w_1 [1/time]
};

/// The task with its chain made ready; a chain that is not usable is left as it is (its runs
/// refuse it).
ChainTask prepared(ChainTask task);
Task prepared(Task task);

/// What every method returns: its events with their states, final state and energy (the note's
/// chain: the recorder's Result, with samples for an overlay; any chain: a ChainRun, events in
/// the one layout of every chain) plus the method's own work and why it stopped.
template <typename R>
struct BasicMethodRun {
  R result;
  std::int64_t steps = 0;           ///< time steps taken (contacts for the exact solver)
  std::int64_t rhsEvaluations = 0;  ///< right-hand side evaluations, where the method has them
  double seconds = 0;               ///< wall time of the run
  double maxEnergyDrift = 0;        ///< max |E - E0| / E0 over the event states and the end
  RunStatus status = RunStatus::Completed;
  std::string reason;               ///< one line: why it stopped, or what it did at a tangency
};
using MethodRun = BasicMethodRun<Result>;
using ChainMethodRun = BasicMethodRun<ChainRun>;

/// Runs `setting` on `task`. Never throws for bad input: an unusable model or start is a
/// Refused run with its reason.
MethodRun runMethod(const Task& task, const MethodSetting& setting,
                    const WorkBudget& budget = {}, std::stop_token stop = {});
ChainMethodRun runMethod(const ChainTask& task, const MethodSetting& setting,
                         const WorkBudget& budget = {}, std::stop_token stop = {});

}  // namespace grazelab::core::methods
