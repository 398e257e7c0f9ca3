// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Event-driven Dormand-Prince 5(4) (docs/model.md section 8) through Boost.Odeint's dense-output
// stepper. A contact is a sign change of u2 - d at the end of an accepted step, located on the
// dense output; at an impact v2 -> -v2 and the stepper restarts from the stop.
//
// At a tangency: only a sign change is seen. A touch of the stop inside one step whose end lies
// below the stop again is missed by construction (the interpolant is not searched for a
// maximum); a crossing located with v2 <= 0 (a graze that the interpolant's error pushed over)
// is recorded as a grazing and the flight goes on unchanged. A start pressed onto the stop makes
// the restarts chatter in zero time: the method has no stuck mode, and stops with a failure.
#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>
#include <exception>

#include "core/methods/root_bracket.h"
#include "core/methods/runners.h"
#include "core/methods/scaled_run.h"

namespace grazelab::core::methods {
namespace {

using Vector = std::array<double, 4>;

State toState(const Vector& x) { return {x[0], x[1], x[2], x[3]}; }

/// Restarts in a row that advanced by less than this fraction of 2 pi: chattering.
constexpr double kNoProgress = 1e-12;
constexpr int kMaxRestartsWithoutProgress = 200;

}  // namespace

MethodRun runDopri5Events(const Task& task, double rtol, const WorkBudget& budget,
                          std::stop_token stop) {
  namespace odeint = boost::numeric::odeint;
  ScaledRun run(task, budget, stop);
  if (run.refused()) return run.take();
  std::int64_t evaluations = 0;
  auto system = [&run, &evaluations](const Vector& x, Vector& dxdt, double) {
    ++evaluations;
    const auto a = run.acceleration(x[0], x[1]);
    dxdt = {x[2], x[3], a[0], a[1]};
  };
  // the scaled state is O(1): the absolute tolerance is the relative one times that scale
  auto stepper = odeint::make_dense_output(rtol, rtol, odeint::runge_kutta_dopri5<Vector>());
  const double delta = run.gap();
  const double tauEnd = run.tauEnd();
  const State& x0 = run.scaledStart();
  Vector x{x0.u1, x0.u2, x0.v1, x0.v2};
  double tau = 0;
  double lastContact = -1;
  int restartsWithoutProgress = 0;
  std::int64_t steps = 0;
  stepper.initialize(x, tau, std::min(0.01, tauEnd));
  auto finishRun = [&]() {
    run.run().steps = steps;
    run.run().rhsEvaluations = evaluations;
    return run.take();
  };
  try {
    while (true) {
      if (steps % 64 == 0 && run.mustStop(steps, tau, toState(x))) return finishRun();
      const auto [t0, t1] = stepper.do_step(system);
      ++steps;
      const double tLimit = std::min(t1, tauEnd);
      Vector atLimit = stepper.current_state();
      if (t1 > tauEnd) stepper.calc_state(tauEnd, atLimit);
      if (atLimit[1] > delta) {
        // the first crossing of the stop on the dense output of [t0, tLimit]
        Vector probe;
        auto gap = [&](double t) {
          stepper.calc_state(t, probe);
          return probe[1] - delta;
        };
        stepper.calc_state(t0, probe);
        const double g0 = std::min(probe[1] - delta, 0.0);
        const double tContact = illinoisRoot(gap, t0, g0, tLimit, atLimit[1] - delta);
        stepper.calc_state(tContact, probe);
        State before = toState(probe);
        before.u2 = delta;  // on the stop, to the resolution of the located time
        State after = before;
        if (before.v2 > 0) {
          after.v2 = -before.v2;
          run.contact(EventType::Impact, tContact, before, after);
        } else {
          run.contact(EventType::Grazing, tContact, before, after);
        }
        if (tContact - lastContact < kNoProgress * twoPi<double>()) {
          if (++restartsWithoutProgress > kMaxRestartsWithoutProgress) {
            run.finish(RunStatus::Failed,
                       "chattering: " + std::to_string(kMaxRestartsWithoutProgress) +
                           " restarts on the stop without progress (a stuck phase: this method "
                           "has no stuck mode)",
                       tContact, after);
            return finishRun();
          }
        } else {
          restartsWithoutProgress = 0;
        }
        lastContact = tContact;
        tau = tContact;
        x = {after.u1, after.u2, after.v1, after.v2};
        stepper.initialize(x, tau, stepper.current_time_step());
        run.sample(tau, after);
        continue;
      }
      tau = tLimit;
      x = atLimit;
      run.sample(tau, toState(x));
      if (t1 >= tauEnd) break;
    }
  } catch (const std::exception& error) {
    run.finish(RunStatus::Failed, std::string("Boost.Odeint: ") + error.what(), tau, toState(x));
    return finishRun();
  }
  run.complete(toState(x));
  return finishRun();
}

}  // namespace grazelab::core::methods
