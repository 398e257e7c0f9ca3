// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <string>

#include "core/methods/scaled_run.h"

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nonlinearsolver.h>
#include <sundials/sundials_nvector.h>

namespace grazelab::core::methods {

/// SUNDIALS CVODE on the scaled chain's 2N first-order equations, with one root function
/// g = x_s - delta; owns every SUNDIALS object. Used as a user of the library would: one
/// internal step at a time (CV_ONE_STEP, so that budgets and the stop token are checked), a
/// stop time at the horizon, and a restart (CVodeReInit) after every impact or switch.
template <typename T>
class CvodeIntegrator {
 public:
  using Vector = typename ScaledRun<T>::Vector;
  struct Options {
    bool bdf = true;           ///< BDF + Newton with the exact Jacobian; else Adams + fixed point
    double rtol = 1e-8;        ///< relative tolerance; absolute = rtol (the scaled state is O(1))
    double stopStiffness = 0;  ///< penalty: the scaled k_c acting while in contact
    int rootDirection = 1;     ///< +1: only crossings toward the stop; 0: both ways
  };
  enum class Outcome { Step, Root, End, Error };

  CvodeIntegrator(const ScaledRun<T>& run, const Options& options);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  /// (Re)starts at tau from (q, v); `inContact` selects the penalty force (penalty only).
  void restart(double tau, const Vector& q, const Vector& v, bool inContact);
  /// One internal step toward the horizon: tau and (q, v) are where it stopped.
  Outcome step(double& tau, Vector& q, Vector& v);
  /// The error of the last Outcome::Error: CVODE's flag name and its message.
  const std::string& error() const { return m_error; }
  std::int64_t rhsEvaluations() const { return m_evaluations; }

 private:
  static int rhs(double t, N_Vector y, N_Vector ydot, void* self);
  static int jacobian(double t, N_Vector y, N_Vector fy,
                      SUNMatrix J, void* self, N_Vector, N_Vector, N_Vector);
  static int root(double t, N_Vector y, double* g, void* self);
  static void errorHandler(int code, const char* module, const char* function, char* message,
                           void* self);

  const ScaledRun<T>& m_run;
  Options m_options;
  bool m_inContact = false;
  bool m_started = false;
  std::int64_t m_evaluations = 0;
  std::string m_error;
  std::string m_lastMessage;
  SUNContext m_context = nullptr;
  N_Vector m_y = nullptr;
  SUNMatrix m_matrix = nullptr;
  SUNLinearSolver m_linearSolver = nullptr;
  SUNNonlinearSolver m_nonlinearSolver = nullptr;
  void* m_memory = nullptr;
};

/// The loop of every method built on CVODE: one internal step at a time from (q, v) at tau = 0,
/// the budget and the stop token checked every 64 steps, a solver error or the horizon ending
/// the run. `onStep(tau, q, v)` sees every step and `onRoot(tau, q, v)` every root; either
/// returns false after finishing the run itself (a failure it detected). The integrator must
/// have been started (restart()) at tau = 0.
template <typename T, typename OnStep, typename OnRoot>
void driveCvode(ScaledRun<T>& run, CvodeIntegrator<T>& cvode, OnStep onStep, OnRoot onRoot) {
  typename ScaledRun<T>::Vector q = run.startPosition(), v = run.startVelocity();
  double tau = 0;
  std::int64_t steps = 0;
  auto finishRun = [&]() {
    run.run().steps = steps;
    run.run().rhsEvaluations = cvode.rhsEvaluations();
  };
  while (true) {
    if (steps % 64 == 0 && run.mustStop(steps, tau, q, v)) return finishRun();
    const auto outcome = cvode.step(tau, q, v);
    ++steps;
    switch (outcome) {
      case CvodeIntegrator<T>::Outcome::Error:
        run.finish(RunStatus::Failed, cvode.error(), tau, q, v);
        return finishRun();
      case CvodeIntegrator<T>::Outcome::End:
        run.complete(q, v);
        return finishRun();
      case CvodeIntegrator<T>::Outcome::Step:
        if (!onStep(tau, q, v)) return finishRun();
        break;
      case CvodeIntegrator<T>::Outcome::Root:
        if (!onRoot(tau, q, v)) return finishRun();
        break;
    }
  }
}

}  // namespace grazelab::core::methods
