// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <stop_token>

#include "core/methods/method.h"

// One entry point per method, one file each; runMethod() dispatches to them.
namespace grazelab::core::methods {

MethodRun runExact(const Task& task, Precision precision, const WorkBudget& budget,
                   std::stop_token stop);
/// theta = 1/2 (moreau-jean) or 1 (moreau-jean-theta1); h in physical time.
MethodRun runMoreauJean(const Task& task, double theta, double h, const WorkBudget& budget,
                        std::stop_token stop);
MethodRun runSchatzmanPaoli(const Task& task, double h, const WorkBudget& budget,
                            std::stop_token stop);
MethodRun runDopri5Events(const Task& task, double rtol, const WorkBudget& budget,
                          std::stop_token stop);
/// bdf = false: Adams-Moulton with fixed-point iteration (CVODE's non-stiff choice); true: BDF
/// with Newton iteration and the exact Jacobian.
MethodRun runCvode(const Task& task, bool bdf, double rtol, const WorkBudget& budget,
                   std::stop_token stop);
MethodRun runPenalty(const Task& task, double kc, double rtol, const WorkBudget& budget,
                     std::stop_token stop);

}  // namespace grazelab::core::methods
