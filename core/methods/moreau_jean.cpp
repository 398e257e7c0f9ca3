// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Moreau-Jean time stepping (docs/model.md section 8; Jean 1999, Acary & Brogliato 2008 ch. 10,
// Siconos MoreauJeanOSI): the theta-method at velocity level with Newton's impact law, e = 1.
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

#include "core/methods/impulse_steps.h"
#include "core/methods/runners.h"

namespace grazelab::core::methods {

MethodRun runMoreauJean(const Task& task, double theta, double h, const WorkBudget& budget,
                        std::stop_token stop) {
  ScaledRun run(task, budget, stop);
  if (run.refused()) return run.take();
  const FixedSteps steps = fixedSteps(run.tauEnd(), run.toTau(h));
  if (steps.count > budget.maxSteps) {
    run.finish(RunStatus::Budget,
               "needs " + std::to_string(steps.count) + " steps, over the budget of " +
                   std::to_string(budget.maxSteps),
               0, run.scaledStart());
    return run.take();
  }
  // x'' = -A x with A = M^-1 K of the scaled chain; the impulse on mass 2 enters through
  // M^-1 (0, -P) = -mu e2 with mu = P / beta >= 0, so the mass ratio drops out of the law.
  const Chain<double>& c = run.chain();
  Eigen::Matrix2d A;
  A << c.p + c.q, -c.q, -c.w, c.w;
  const double hs = steps.h;
  const Eigen::Matrix2d identity = Eigen::Matrix2d::Identity();
  // (I + h^2 theta^2 A) v+ = v - h A (q + h theta (1 - theta) v) - mu e2, from
  // M (v+ - v) = h [theta f(q+) + (1 - theta) f(q)] + impulse with q+ = q + h [theta v+ + (1-theta) v]
  const Eigen::Matrix2d Winv = (identity + hs * hs * theta * theta * A).inverse();
  const Eigen::Matrix2d fromV = Winv * (identity - hs * hs * theta * (1 - theta) * A);
  const Eigen::Matrix2d fromQ = -hs * Winv * A;
  const Eigen::Vector2d impulseColumn = Winv.col(1);
  const double w22 = Winv(1, 1);
  const double delta = run.gap();
  constexpr double restitution = 1.0;

  const State& x0 = run.scaledStart();
  Eigen::Vector2d q(x0.u1, x0.u2), v(x0.v1, x0.v2);
  auto state = [](const Eigen::Vector2d& q, const Eigen::Vector2d& v) {
    return State{q(0), q(1), v(0), v(1)};
  };
  ImpulseSteps impulses;
  for (std::int64_t k = 0; k < steps.count; ++k) {
    const double tau = double(k) * hs;
    if (k % kCheckEverySteps == 0 && run.mustStop(k, tau, state(q, v))) {
      run.run().steps = k;
      return run.take();
    }
    Eigen::Vector2d vNext = fromV * v + fromQ * q;
    // active when the gap predicted at mid-step is closed: g(q + h/2 v) <= 0
    double mu = 0;
    if (q(1) + 0.5 * hs * v(1) >= delta) {
      // 0 <= U+ + e U  _|_  P >= 0 with U = -v2: one contact, a scalar LCP
      mu = std::max(0.0, (vNext(1) + restitution * v(1)) / w22);
      vNext -= mu * impulseColumn;
    }
    const Eigen::Vector2d qNext = q + hs * (theta * vNext + (1 - theta) * v);
    impulses.step(run, mu > 0, tau + 0.5 * hs, state(q, v), state(qNext, vNext));
    q = qNext;
    v = vNext;
    run.sample(double(k + 1) * hs, state(q, v));
  }
  impulses.flush(run, run.tauEnd(), state(q, v));
  run.run().steps = steps.count;
  run.complete(state(q, v));
  return run.take();
}

}  // namespace grazelab::core::methods
