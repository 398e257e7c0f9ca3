// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// SUNDIALS CVODE, Adams or BDF, event-driven (docs/model.md section 8): a contact is a root of
// u_s - d crossed toward the stop, found by CVODE's root finding; at an impact v_s -> -v_s and
// the integrator restarts (CVodeReInit) from the stop.
//
// At a tangency: CVODE sees sign changes only, so a touch inside one step is missed; a root
// returned with v_s <= 0 is recorded as a grazing and the flight goes on. A root function that
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

template <typename T>
void runCvode(ScaledRun<T>& run, bool bdf, double rtol) {
  using Vector = typename ScaledRun<T>::Vector;
  CvodeIntegrator<T> cvode(run, {bdf, rtol, 0.0, 1});
  const int s = run.stop();
  const double delta = run.gap();
  // beyond this the flight went through the stop unnoticed (far past the tolerance's reach)
  const double throughStop = delta + std::max(1e3 * rtol, 1e-6);
  double lastContact = -1;
  int restartsWithoutProgress = 0;
  Vector vAfter(run.size());
  cvode.restart(0, run.startPosition(), run.startVelocity(), false);
  auto onStep = [&](double tau, const Vector& q, const Vector& v) {
    if (q(s) > throughStop) {
      run.finish(RunStatus::Failed,
                 "passed through the stop (a root at the restart point is inactive in CVODE: "
                 "a stuck phase is not seen)",
                 tau, q, v);
      return false;
    }
    run.sample(tau, q, v);
    return true;
  };
  auto onRoot = [&](double tau, Vector& q, Vector& v) {
    q(s) = delta;  // on the stop, to the resolution of the root
    vAfter = v;
    const bool impact = v(s) > 0;
    if (impact) vAfter(s) = -v(s);
    run.contact(impact ? EventType::Impact : EventType::Grazing, tau, q, v, q, vAfter);
    if (tau - lastContact < kNoProgress * twoPi<double>()) {
      if (++restartsWithoutProgress > kMaxRestartsWithoutProgress) {
        run.finish(RunStatus::Failed,
                   "chattering: restarts on the stop without progress (a stuck phase: this "
                   "method has no stuck mode)",
                   tau, q, vAfter);
        return false;
      }
    } else {
      restartsWithoutProgress = 0;
    }
    lastContact = tau;
    v = vAfter;
    cvode.restart(tau, q, v, false);
    run.sample(tau, q, v);
    return true;
  };
  driveCvode(run, cvode, onStep, onRoot);
}

template void runCvode(ScaledRun<Task>&, bool, double);
template void runCvode(ScaledRun<ChainTask>&, bool, double);

}  // namespace grazelab::core::methods
