// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Schatzman-Paoli (docs/model.md section 8; Paoli & Schatzman 2002): central differences on
// positions with the impact law written on positions, g((q_{k+1} + e q_{k-1}) / (1 + e)) >= 0,
// e = 1.
#include <cmath>

#include "core/methods/impulse_steps.h"
#include "core/methods/runners.h"

namespace grazelab::core::methods {

template <typename T>
void runSchatzmanPaoli(ScaledRun<T>& run, double h, const WorkBudget& budget) {
  using Vector = typename ScaledRun<T>::Vector;
  const FixedSteps steps = fixedSteps(run.tauEnd(), run.toTau(h));
  if (steps.count + 1 > budget.maxSteps) {
    run.finish(RunStatus::Budget,
               "needs " + std::to_string(steps.count + 1) + " steps, over the budget of " +
                   std::to_string(budget.maxSteps),
               0, run.startPosition(), run.startVelocity());
    return;
  }
  const int n = run.size();
  const int s = run.stop();
  const double hs = steps.h;
  const double delta = run.gap();
  // The summed form: positions x_k and increments d_k = x_k - x_{k-1}, with
  // d_{k+1} = d_k + h^2 a(x_k). The same recursion as x_{k+1} = 2 x_k - x_{k-1} + h^2 a(x_k),
  // whose rounding would otherwise grow like N^(3/2) over N steps (Henrici).
  // d_0 from the start's Taylor expansion, so that x_1 = x_0 + h v_0 + h^2/2 a(x_0).
  Vector x = run.startPosition();
  Vector a = run.system().acceleration(x);
  Vector d = hs * run.startVelocity() - 0.5 * hs * hs * a;
  // the state at the current grid point (velocity by central difference)
  Vector reportedQ = x, reported = run.startVelocity();
  Vector next(n), before(n), after(n);
  ImpulseSteps<T> impulses;
  // one step more than the horizon: the velocity at the last grid point is a central difference
  for (std::int64_t k = 0; k <= steps.count; ++k) {
    const double tau = double(k) * hs;
    if (k % kCheckEverySteps == 0 && run.mustStop(k, tau, reportedQ, reported)) {
      run.run().steps = k;
      return;
    }
    run.system().accelerationInto(x, a);
    next = d + hs * hs * a;
    // the reaction acts on the stopped mass alone (M is diagonal): when the average of x_{k+1}
    // and x_{k-1} = x_k - d_k lies past the stop, it puts that average on the stop
    const bool impulse = (x(s) + next(s)) + (x(s) - d(s)) > 2 * delta;
    if (impulse) next(s) = 2 * (delta - x(s)) + d(s);
    reportedQ = x;
    reported = (next + d) / (2 * hs);
    if (k < steps.count) {
      // around a contact: the backward difference before it, the forward one after it
      before = d / hs;
      after = next / hs;
      impulses.step(run, impulse, tau, x, before, x, after);
      if (k > 0) run.sample(tau, x, reported);
    }
    x += next;
    d.swap(next);
  }
  impulses.flush(run, run.tauEnd(), reportedQ, reported);
  run.run().steps = steps.count + 1;
  run.complete(reportedQ, reported);
}

template void runSchatzmanPaoli(ScaledRun<Task>&, double, const WorkBudget&);
template void runSchatzmanPaoli(ScaledRun<ChainTask>&, double, const WorkBudget&);

}  // namespace grazelab::core::methods
