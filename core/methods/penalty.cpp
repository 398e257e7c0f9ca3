// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The penalty method (docs/model.md section 8): the stop as a stiff spring k_c (u_s - d)+ on the
// stopped mass, integrated by CVODE BDF with the exact Jacobian. The force switches on and off
// where u_s = d: CVODE's root finding stops there and the integrator restarts with the other
// force, so that each segment it integrates is smooth. A contact is the interval spent past the
// stop; it is reported as one impact at the middle of that interval, with the entry and exit
// states.
#include <cmath>

#include "core/methods/cvode_integrator.h"
#include "core/methods/runners.h"

namespace grazelab::core::methods {

template <typename T>
void runPenalty(ScaledRun<T>& run, double kc, double rtol) {
  using Vector = typename ScaledRun<T>::Vector;
  if (!(rtol > 0 && rtol < 1)) {
    run.finish(RunStatus::Refused, "the penalty's CVODE tolerance must lie in (0, 1)", 0,
               run.startPosition(), run.startVelocity());
    return;
  }
  const double stiffness = run.scaledStopStiffness(kc);
  CvodeIntegrator<T> cvode(run, {true, rtol, stiffness, 0});
  const int s = run.stop();
  const double delta = run.gap();
  const Vector& q0 = run.startPosition();
  const Vector& v0 = run.startVelocity();
  // a start on the stop is in contact when it moves or is pushed into it
  const Vector a0 = run.system().acceleration(q0);
  bool inContact = q0(s) >= delta && (v0(s) > 0 || (v0(s) == 0 && a0(s) > 0));
  double entryTau = 0;
  Vector entryQ = q0, entryV = v0;
  cvode.restart(0, q0, v0, inContact);
  auto onStep = [&](double tau, const Vector& q, const Vector& v) {
    run.sample(tau, q, v);
    return true;
  };
  auto onRoot = [&](double tau, Vector& q, Vector& v) {
    if (!inContact) {
      entryTau = tau;
      entryQ = q;
      entryV = v;
    } else {
      run.contact(entryV(s) > 0 ? EventType::Impact : EventType::Stick, 0.5 * (entryTau + tau),
                  entryQ, entryV, q, v);
    }
    inContact = !inContact;
    cvode.restart(tau, q, v, inContact);
    run.sample(tau, q, v);
    return true;
  };
  driveCvode(run, cvode, onStep, onRoot);
}

template void runPenalty(ScaledRun<Task>&, double, double);
template void runPenalty(ScaledRun<ChainTask>&, double, double);

}  // namespace grazelab::core::methods
