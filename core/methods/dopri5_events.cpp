// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Event-driven Dormand-Prince 5(4) (docs/model.md section 8) through Boost.Odeint's dense-output
// stepper. A contact is a sign change of u_s - d at the end of an accepted step, located on the
// dense output; at an impact v_s -> -v_s and the stepper restarts from the stop.
//
// At a tangency: only a sign change is seen. A touch of the stop inside one step whose end lies
// below the stop again is missed by construction (the interpolant is not searched for a
// maximum); a crossing located with v_s <= 0 (a graze that the interpolant's error pushed over)
// is recorded as a grazing and the flight goes on unchanged. A start pressed onto the stop makes
// the restarts chatter in zero time: the method has no stuck mode, and stops with a failure.
#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>
#include <exception>
#include <vector>

#include "core/methods/root_bracket.h"
#include "core/methods/runners.h"

namespace grazelab::core::methods {
namespace {

/// Restarts in a row that advanced by less than this fraction of 2 pi: chattering.
constexpr double kNoProgress = 1e-12;
constexpr int kMaxRestartsWithoutProgress = 200;

}  // namespace

template <typename T>
void runDopri5Events(ScaledRun<T>& run, double rtol) {
  namespace odeint = boost::numeric::odeint;
  using Vector = typename ScaledRun<T>::Vector;
  // Odeint's own containers: (x, v) of the note's chain in a fixed array, of any chain in a vector
  using OdeState = std::conditional_t<ScaledRun<T>::kNotesChain, std::array<double, 4>, std::vector<double>>;
  const int n = run.size();
  const int s = run.stop();
  auto newState = [n]() {
    OdeState x{};
    if constexpr (!ScaledRun<T>::kNotesChain) x.resize(std::size_t(2 * n));
    return x;
  };
  Vector q(n), v(n);
  auto split = [&](const OdeState& x) {
    for (int i = 0; i < n; ++i) {
      q(i) = x[std::size_t(i)];
      v(i) = x[std::size_t(n + i)];
    }
  };
  auto join = [&](const Vector& position, const Vector& velocity, OdeState& x) {
    for (int i = 0; i < n; ++i) {
      x[std::size_t(i)] = position(i);
      x[std::size_t(n + i)] = velocity(i);
    }
  };
  std::int64_t evaluations = 0;
  const auto& system = run.system();
  auto rhs = [&system, &evaluations, n](const OdeState& x, OdeState& dxdt, double) {
    ++evaluations;
    if constexpr (ScaledRun<T>::kNotesChain) {
      // every value read before dxdt is written (it could alias x): the note's runs are timed
      double a[2];
      system.accelerationInto([&x](int i) { return x[std::size_t(i)]; }, [&a](int i) -> double& { return a[i]; });
      dxdt = {x[2], x[3], a[0], a[1]};
    } else {
      for (int i = 0; i < n; ++i) dxdt[std::size_t(i)] = x[std::size_t(n + i)];
      system.accelerationInto([&x](int i) { return x[std::size_t(i)]; },
                              [&dxdt, n](int i) -> double& { return dxdt[std::size_t(n + i)]; });
    }
  };
  // the scaled state is O(1): the absolute tolerance is the relative one times that scale
  auto stepper = odeint::make_dense_output(rtol, rtol, odeint::runge_kutta_dopri5<OdeState>());
  const double delta = run.gap();
  const double tauEnd = run.tauEnd();
  OdeState x = newState(), atLimit = newState(), probe = newState();
  join(run.startPosition(), run.startVelocity(), x);
  double tau = 0;
  double lastContact = -1;
  int restartsWithoutProgress = 0;
  std::int64_t steps = 0;
  stepper.initialize(x, tau, std::min(0.01, tauEnd));
  auto finishRun = [&]() {
    run.run().steps = steps;
    run.run().rhsEvaluations = evaluations;
  };
  try {
    while (true) {
      if (steps % 64 == 0) {
        split(x);
        if (run.mustStop(steps, tau, q, v)) return finishRun();
      }
      const auto [t0, t1] = stepper.do_step(rhs);
      ++steps;
      const double tLimit = std::min(t1, tauEnd);
      atLimit = stepper.current_state();
      if (t1 > tauEnd) stepper.calc_state(tauEnd, atLimit);
      if (atLimit[std::size_t(s)] > delta) {
        // the first crossing of the stop on the dense output of [t0, tLimit]
        auto gap = [&](double t) {
          stepper.calc_state(t, probe);
          return probe[std::size_t(s)] - delta;
        };
        stepper.calc_state(t0, probe);
        const double g0 = std::min(probe[std::size_t(s)] - delta, 0.0);
        const double tContact = illinoisRoot(gap, t0, g0, tLimit, atLimit[std::size_t(s)] - delta);
        stepper.calc_state(tContact, probe);
        split(probe);
        q(s) = delta;  // on the stop, to the resolution of the located time
        Vector vAfter = v;
        const bool impact = v(s) > 0;
        if (impact) vAfter(s) = -v(s);
        run.contact(impact ? EventType::Impact : EventType::Grazing, tContact, q, v, q, vAfter);
        if (tContact - lastContact < kNoProgress * twoPi<double>()) {
          if (++restartsWithoutProgress > kMaxRestartsWithoutProgress) {
            run.finish(RunStatus::Failed,
                       "chattering: " + std::to_string(kMaxRestartsWithoutProgress) +
                           " restarts on the stop without progress (a stuck phase: this method "
                           "has no stuck mode)",
                       tContact, q, vAfter);
            return finishRun();
          }
        } else {
          restartsWithoutProgress = 0;
        }
        lastContact = tContact;
        tau = tContact;
        join(q, vAfter, x);
        stepper.initialize(x, tau, stepper.current_time_step());
        run.sample(tau, q, vAfter);
        continue;
      }
      tau = tLimit;
      x = atLimit;
      if constexpr (ScaledRun<T>::kNotesChain) {
        split(x);
        run.sample(tau, q, v);
      }
      if (t1 >= tauEnd) break;
    }
  } catch (const std::exception& error) {
    split(x);
    run.finish(RunStatus::Failed, std::string("Boost.Odeint: ") + error.what(), tau, q, v);
    return finishRun();
  }
  split(x);
  run.complete(q, v);
  finishRun();
}

template void runDopri5Events(ScaledRun<Task>&, double);
template void runDopri5Events(ScaledRun<ChainTask>&, double);

}  // namespace grazelab::core::methods
