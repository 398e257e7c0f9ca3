// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <stop_token>

#include "core/methods/method.h"
#include "core/methods/scaled_run.h"

// One entry point per method, one file each; runMethod() dispatches to them. A comparison
// method runs on a ScaledRun made for its task (the note's chain or any chain: each is
// instantiated for both) and finishes it.
namespace grazelab::core::methods {

MethodRun runExact(const Task& task, Precision precision, const WorkBudget& budget,
                   std::stop_token stop);
ChainMethodRun runExact(const ChainTask& task, Precision precision, const WorkBudget& budget,
                        std::stop_token stop);

/// theta = 1/2 (moreau-jean) or 1 (moreau-jean-theta1); h in physical time.
template <typename T>
void runMoreauJean(ScaledRun<T>& run, double theta, double h, const WorkBudget& budget);
template <typename T>
void runSchatzmanPaoli(ScaledRun<T>& run, double h, const WorkBudget& budget);
template <typename T>
void runDopri5Events(ScaledRun<T>& run, double rtol);
/// bdf = false: Adams-Moulton with fixed-point iteration (CVODE's non-stiff choice); true: BDF
/// with Newton iteration and the exact Jacobian.
template <typename T>
void runCvode(ScaledRun<T>& run, bool bdf, double rtol);
template <typename T>
void runPenalty(ScaledRun<T>& run, double kc, double rtol);

}  // namespace grazelab::core::methods
