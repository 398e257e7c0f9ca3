// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The penalty method (docs/model.md section 8): the stop as a stiff spring k_c (u2 - d)+ on mass 2,
// integrated by CVODE BDF with the exact Jacobian. The force switches on and off where u2 = d:
// CVODE's root finding stops there and the integrator restarts with the other force, so that
// each segment it integrates is smooth. A contact is the interval spent past the stop; it is
// reported as one impact at the middle of that interval, with the entry and exit states.
#include <cmath>

#include "core/methods/cvode_integrator.h"
#include "core/methods/runners.h"

namespace grazelab::core::methods {

MethodRun runPenalty(const Task& task, double kc, double rtol, const WorkBudget& budget,
                     std::stop_token stop) {
  ScaledRun run(task, budget, stop);
  if (run.refused()) return run.take();
  if (!(rtol > 0 && rtol < 1)) {
    run.finish(RunStatus::Refused, "the penalty's CVODE tolerance must lie in (0, 1)", 0,
               run.scaledStart());
    return run.take();
  }
  const double stiffness = run.scaledStopStiffness(kc);
  CvodeIntegrator cvode(run, {true, rtol, stiffness, 0});
  const double delta = run.gap();
  const State& x0 = run.scaledStart();
  // a start on the stop is in contact when it moves or is pushed into it
  const auto a0 = run.acceleration(x0.u1, x0.u2);
  bool inContact = x0.u2 >= delta && (x0.v2 > 0 || (x0.v2 == 0 && a0[1] > 0));
  double entryTau = 0;
  State entry = x0;
  cvode.restart(0, x0, inContact);
  auto onStep = [&](double tau, const State& x) {
    run.sample(tau, x);
    return true;
  };
  auto onRoot = [&](double tau, State& x) {
    if (!inContact) {
      entryTau = tau;
      entry = x;
    } else {
      run.contact(entry.v2 > 0 ? EventType::Impact : EventType::Stick, 0.5 * (entryTau + tau),
                  entry, x);
    }
    inContact = !inContact;
    cvode.restart(tau, x, inContact);
    run.sample(tau, x);
    return true;
  };
  return driveCvode(run, cvode, x0, onStep, onRoot);
}

}  // namespace grazelab::core::methods
