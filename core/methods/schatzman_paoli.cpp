// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Schatzman-Paoli (docs/model.md section 8; Paoli & Schatzman 2002): central differences on
// positions with the impact law written on positions, g((q_{k+1} + e q_{k-1}) / (1 + e)) >= 0,
// e = 1.
#include <cmath>

#include "core/methods/impulse_steps.h"
#include "core/methods/runners.h"

namespace grazelab::core::methods {

MethodRun runSchatzmanPaoli(const Task& task, double h, const WorkBudget& budget,
                            std::stop_token stop) {
  ScaledRun run(task, budget, stop);
  if (run.refused()) return run.take();
  const FixedSteps steps = fixedSteps(run.tauEnd(), run.toTau(h));
  if (steps.count + 1 > budget.maxSteps) {
    run.finish(RunStatus::Budget,
               "needs " + std::to_string(steps.count + 1) + " steps, over the budget of " +
                   std::to_string(budget.maxSteps),
               0, run.scaledStart());
    return run.take();
  }
  const double hs = steps.h;
  const double delta = run.gap();
  const State& x0 = run.scaledStart();
  // The summed form: positions x_k and increments d_k = x_k - x_{k-1}, with
  // d_{k+1} = d_k + h^2 a(x_k). The same recursion as x_{k+1} = 2 x_k - x_{k-1} + h^2 a(x_k),
  // whose rounding would otherwise grow like N^(3/2) over N steps (Henrici).
  // d_0 from the start's Taylor expansion, so that x_1 = x_0 + h v_0 + h^2/2 a(x_0).
  const auto a0 = run.acceleration(x0.u1, x0.u2);
  double x1 = x0.u1, x2 = x0.u2;
  double d1 = hs * x0.v1 - 0.5 * hs * hs * a0[0];
  double d2 = hs * x0.v2 - 0.5 * hs * hs * a0[1];
  State reported = x0;  // the state at the current grid point (velocity by central difference)
  ImpulseSteps impulses;
  // one step more than the horizon: the velocity at the last grid point is a central difference
  for (std::int64_t k = 0; k <= steps.count; ++k) {
    const double tau = double(k) * hs;
    if (k % kCheckEverySteps == 0 && run.mustStop(k, tau, reported)) {
      run.run().steps = k;
      return run.take();
    }
    const auto a = run.acceleration(x1, x2);
    const double next1 = d1 + hs * hs * a[0];
    double next2 = d2 + hs * hs * a[1];
    // the reaction acts on mass 2 alone (M is diagonal): when the average of x_{k+1} and
    // x_{k-1} = x_k - d_k lies past the stop, it puts that average on the stop
    const bool impulse = (x2 + next2) + (x2 - d2) > 2 * delta;
    if (impulse) next2 = 2 * (delta - x2) + d2;
    reported = {x1, x2, (next1 + d1) / (2 * hs), (next2 + d2) / (2 * hs)};
    if (k < steps.count) {
      // around a contact: the backward difference before it, the forward one after it
      const State before{x1, x2, d1 / hs, d2 / hs};
      const State after{x1, x2, next1 / hs, next2 / hs};
      impulses.step(run, impulse, tau, before, after);
      if (k > 0) run.sample(tau, reported);
    }
    x1 += next1;
    x2 += next2;
    d1 = next1;
    d2 = next2;
  }
  impulses.flush(run, run.tauEnd(), reported);
  run.run().steps = steps.count + 1;
  run.complete(reported);
  return run.take();
}

}  // namespace grazelab::core::methods
