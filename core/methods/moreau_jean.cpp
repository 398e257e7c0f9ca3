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

template <typename T>
void runMoreauJean(ScaledRun<T>& run, double theta, double h, const WorkBudget& budget) {
  using Matrix = typename ScaledRun<T>::System::Matrix;
  using Vector = typename ScaledRun<T>::Vector;
  const FixedSteps steps = fixedSteps(run.tauEnd(), run.toTau(h));
  if (steps.count > budget.maxSteps) {
    run.finish(RunStatus::Budget,
               "needs " + std::to_string(steps.count) + " steps, over the budget of " +
                   std::to_string(budget.maxSteps),
               0, run.startPosition(), run.startVelocity());
    return;
  }
  // x'' = -A x; the impulse on the stopped mass s enters through M^-1 (0, ..., -P, ..., 0)
  // = -mu e_s with mu = P / m_s >= 0, so its mass drops out of the law.
  const int n = run.size();
  const int s = run.stop();
  const Matrix A = run.system().stiffness();
  const double hs = steps.h;
  const Matrix identity = Matrix::Identity(n, n);
  // (I + h^2 theta^2 A) v+ = v - h A (q + h theta (1 - theta) v) - mu e_s, from
  // M (v+ - v) = h [theta f(q+) + (1 - theta) f(q)] + impulse with q+ = q + h [theta v+ + (1-theta) v]
  const Matrix Winv = (identity + hs * hs * theta * theta * A).inverse();
  const Matrix fromV = Winv * (identity - hs * hs * theta * (1 - theta) * A);
  const Matrix fromQ = -hs * Winv * A;
  const Vector impulseColumn = Winv.col(s);
  const double wss = Winv(s, s);
  const double delta = run.gap();
  constexpr double restitution = 1.0;

  Vector q = run.startPosition(), v = run.startVelocity();
  Vector qNext(n), vNext(n), fromPosition(n);
  ImpulseSteps<T> impulses;
  for (std::int64_t k = 0; k < steps.count; ++k) {
    const double tau = double(k) * hs;
    if (k % kCheckEverySteps == 0 && run.mustStop(k, tau, q, v)) {
      run.run().steps = k;
      return;
    }
    vNext.noalias() = fromV * v;
    fromPosition.noalias() = fromQ * q;
    vNext += fromPosition;
    // active when the gap predicted at mid-step is closed: g(q + h/2 v) <= 0
    double mu = 0;
    if (q(s) + 0.5 * hs * v(s) >= delta) {
      // 0 <= U+ + e U  _|_  P >= 0 with U = -v_s: one contact, a scalar LCP
      mu = std::max(0.0, (vNext(s) + restitution * v(s)) / wss);
      vNext -= mu * impulseColumn;
    }
    qNext = q + hs * (theta * vNext + (1 - theta) * v);
    impulses.step(run, mu > 0, tau + 0.5 * hs, q, v, qNext, vNext);
    q.swap(qNext);
    v.swap(vNext);
    run.sample(double(k + 1) * hs, q, v);
  }
  impulses.flush(run, run.tauEnd(), q, v);
  run.run().steps = steps.count;
  run.complete(q, v);
}

template void runMoreauJean(ScaledRun<Task>&, double, double, const WorkBudget&);
template void runMoreauJean(ScaledRun<ChainTask>&, double, double, const WorkBudget&);

}  // namespace grazelab::core::methods
