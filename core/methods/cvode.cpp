// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// SUNDIALS CVODE, Adams or BDF, event-driven (docs/model.md section 8): a contact is a root of
// u2 - d crossed toward the stop, found by CVODE's root finding; at an impact v2 -> -v2 and the
// integrator restarts (CVodeReInit) from the stop.
//
// At a tangency: CVODE sees sign changes only, so a touch inside one step is missed; a root
// returned with v2 <= 0 is recorded as a grazing and the flight goes on. A root function that
// is zero at the restart point is inactive until it moves away (CVODE's rule), so a start
// pressed onto the stop would slide through it: the run stops with "passed through the stop".
#include <cmath>

#include "core/methods/cvode_integrator.h"
#include "core/methods/runners.h"

namespace grazelab::core::methods {
namespace {

constexpr double kNoProgress = 1e-12;  // of 2 pi: a restart that did not move
constexpr int kMaxRestartsWithoutProgress = 200;

}  // namespace

MethodRun runCvode(const Task& task, bool bdf, double rtol, const WorkBudget& budget,
                   std::stop_token stop) {
  ScaledRun run(task, budget, stop);
  if (run.refused()) return run.take();
  CvodeIntegrator cvode(run, {bdf, rtol, 0.0, 1});
  const double delta = run.gap();
  // beyond this the flight went through the stop unnoticed (far past the tolerance's reach)
  const double throughStop = delta + std::max(1e3 * rtol, 1e-6);
  double lastContact = -1;
  int restartsWithoutProgress = 0;
  cvode.restart(0, run.scaledStart(), false);
  auto onStep = [&](double tau, const State& x) {
    if (x.u2 > throughStop) {
      run.finish(RunStatus::Failed,
                 "passed through the stop (a root at the restart point is inactive in CVODE: "
                 "a stuck phase is not seen)",
                 tau, x);
      return false;
    }
    run.sample(tau, x);
    return true;
  };
  auto onRoot = [&](double tau, State& x) {
    State before = x;
    before.u2 = delta;  // on the stop, to the resolution of the root
    State after = before;
    if (before.v2 > 0) {
      after.v2 = -before.v2;
      run.contact(EventType::Impact, tau, before, after);
    } else {
      run.contact(EventType::Grazing, tau, before, after);
    }
    if (tau - lastContact < kNoProgress * twoPi<double>()) {
      if (++restartsWithoutProgress > kMaxRestartsWithoutProgress) {
        run.finish(RunStatus::Failed,
                   "chattering: restarts on the stop without progress (a stuck phase: this "
                   "method has no stuck mode)",
                   tau, after);
        return false;
      }
    } else {
      restartsWithoutProgress = 0;
    }
    lastContact = tau;
    x = after;
    cvode.restart(tau, x, false);
    run.sample(tau, x);
    return true;
  };
  return driveCvode(run, cvode, run.scaledStart(), onStep, onRoot);
}

}  // namespace grazelab::core::methods
