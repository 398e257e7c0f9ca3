// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <variant>
#include <vector>

#include "core/methods/compare.h"

namespace grazelab::core::methods {

/// One row of the stability matrix: a stiff or extreme problem, run by every method.
struct StressCase {
  std::string name;         ///< e.g. "mass-ratio-1e-12-upper"
  std::string description;  ///< one line for the table
  /// The problem, on the note's chain or on any chain of N masses; nothing when it cannot be
  /// formed (then `problem` says why, and every cell is refused with that reason).
  std::optional<std::variant<Task, ChainTask>> task;
  std::string problem;
  /// Only this method runs here (the penalty stiffness rows); the others are refused as not
  /// applicable.
  std::optional<MethodKind> only;
  /// The penalty stiffness of this row (penalty rows), else the standard one.
  std::optional<double> penaltyStiffness;
  /// The long exact run: contacts instead of a horizon (no binary128 reference that long).
  std::int64_t longRunContacts = 0;
};

/// The verdict of one cell.
enum class CellVerdict {
  Ok,
  Inaccurate,
  Refused,
  Budget,
  Undecided,  ///< the method met a contact its precision cannot decide: no error to judge
  Failed,
};
std::string_view toString(CellVerdict verdict);

/// A finished cell.
struct StressCell {
  std::string caseName;
  MethodKind method = MethodKind::Exact;
  MethodSetting setting;
  double seconds = 0;
  Errors errors;
  CellVerdict verdict = CellVerdict::Ok;
  std::string reason;  ///< one line; empty when ok
};

/// Measurements along the long exact run: drift and cost as contacts accumulate.
struct LongRunMark {
  std::int64_t contacts = 0;
  double t = 0;
  double energyDrift = 0;        ///< max |E - E0| / E0 so far
  double nanosecondsPerContact = 0;  ///< over the stretch since the previous mark
};

/// Every case runs this many slow periods (the long run excepted).
inline constexpr double kCasePeriods = 20;

/// The accuracy an "ok" cell holds: every time stepper at its standard setting must reach it;
/// the exact solver is held to its own contract (kOkTolerance of the trust estimate, 1e-9).
inline constexpr double kStabilityTolerance = 1e-3;
inline constexpr double kExactTolerance = 1e-9;
/// The exact solver may be off by this many times its own error estimate.
inline constexpr double kEstimateMargin = 10;

/// The cases of the matrix. `quick`: a subset that runs in seconds (for ctest).
std::vector<StressCase> stressCases(bool quick);

/// The matrix of a chain of N masses (validate(chain) empty) from `start`: the chain as given,
/// then its stiff and extreme variants, each over kCasePeriods slowest periods: the stopped mass
/// 1e6 and 1e12 times lighter, the second spring (the first for one mass) 1e6 times stiffer and
/// softer, every length 1e-12 and 1e12 times (start included), its grazing orbit of `gloWeights`
/// (empty: the slowest mode that moves the stopped mass alone) pushed off the stop by 1e-15 ...
/// 1e-3 times d w_N, a right wall added (k = k_1) or taken away, the stop moved to the middle
/// mass (N >= 3). A variant whose start is past its stop, or whose weights make no grazing orbit,
/// is a row refused with its reason. `quick`: one of each. The start's still modes (a GLO start's
/// weights 0) hold for the chain given and its scaled copies, whose modes they are.
std::vector<StressCase> chainStressCases(const MassChain& chain, const ChainStart& start,
                                         const std::vector<double>& gloWeights, bool quick);

/// The standard setting of each method in the matrix, for a problem of slow period T2 and
/// spring k1: h = T2 / 1000, rtol = 1e-8, k_c = 1e8 k1 (rtol 1e-10), exact in double.
MethodSetting standardSetting(MethodKind kind, double period, double k1,
                              std::optional<double> penaltyStiffness = std::nullopt);

/// How a case was compared: over its horizon, cut to the predictability horizon of its start.
struct CaseHorizon {
  double tEnd = 0;       ///< the end of the comparison [time]
  double period = 0;     ///< T2 [time]
  bool shortened = false;  ///< the predictability horizon came before kCasePeriods T2
  double estimatedError = 0;  ///< the trust estimate of the exact double run at tEnd
  double horizon = 0;    ///< the predictability horizon of the start [time] (full shadow run)
};

/// Runs one case with every method (`methods`), calling `onCell` as each cell finishes.
/// The comparison ends at the predictability horizon of the start when that comes first (the
/// trust estimate of the exact double run, issue 7): past it, even the exact solver in double
/// is not right, and no method can be judged. The exact solver is held to max(1e-9, 10 times
/// its own error estimate, put in the units of the errors here): both its accuracy and the
/// honesty of its estimate are tested.
/// `longRun` receives the marks of a long exact run.
CaseHorizon runStressCase(const StressCase& stabilityCase, const std::vector<MethodKind>& methods,
                      const WorkBudget& budget,
                      const std::function<void(const StressCell&)>& onCell,
                      std::vector<LongRunMark>* longRun, std::stop_token stop = {});

}  // namespace grazelab::core::methods
