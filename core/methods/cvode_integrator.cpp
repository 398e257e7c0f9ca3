// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/methods/cvode_integrator.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cstdlib>

namespace grazelab::core::methods {

template <typename T>
CvodeIntegrator<T>::CvodeIntegrator(const ScaledRun<T>& run, const Options& options)
    : m_run(run), m_options(options) {
  SUNContext_Create(nullptr, &m_context);
  m_y = N_VNew_Serial(2 * run.size(), m_context);
  m_memory = CVodeCreate(options.bdf ? CV_BDF : CV_ADAMS, m_context);
}

template <typename T>
CvodeIntegrator<T>::~CvodeIntegrator() {
  if (m_memory != nullptr) CVodeFree(&m_memory);
  if (m_nonlinearSolver != nullptr) SUNNonlinSolFree(m_nonlinearSolver);
  if (m_linearSolver != nullptr) SUNLinSolFree(m_linearSolver);
  if (m_matrix != nullptr) SUNMatDestroy(m_matrix);
  if (m_y != nullptr) N_VDestroy(m_y);
  if (m_context != nullptr) SUNContext_Free(&m_context);
}

template <typename T>
int CvodeIntegrator<T>::rhs(double, N_Vector y, N_Vector ydot, void* self) {
  auto& integrator = *static_cast<CvodeIntegrator*>(self);
  ++integrator.m_evaluations;
  const ScaledRun<T>& run = integrator.m_run;
  const int n = run.size();
  const double* x = N_VGetArrayPointer(y);
  double* dx = N_VGetArrayPointer(ydot);
  for (int i = 0; i < n; ++i) dx[i] = x[n + i];
  run.system().accelerationInto([x](int i) { return x[i]; },
                                [dx, n](int i) -> double& { return dx[n + i]; });
  const int s = run.stop();
  if (integrator.m_inContact) dx[n + s] -= integrator.m_options.stopStiffness * (x[s] - run.gap());
  return 0;
}

template <typename T>
int CvodeIntegrator<T>::jacobian(double, N_Vector, N_Vector, SUNMatrix J, void* self, N_Vector,
                                 N_Vector, N_Vector) {
  auto& integrator = *static_cast<CvodeIntegrator*>(self);
  const ScaledRun<T>& run = integrator.m_run;
  const int n = run.size();
  const auto A = run.system().stiffness();
  SUNMatZero(J);
  for (int i = 0; i < n; ++i) {
    SM_ELEMENT_D(J, i, n + i) = 1;
    for (int j = std::max(0, i - 1); j <= std::min(n - 1, i + 1); ++j) SM_ELEMENT_D(J, n + i, j) = -A(i, j);
  }
  if (integrator.m_inContact) SM_ELEMENT_D(J, n + run.stop(), run.stop()) -= integrator.m_options.stopStiffness;
  return 0;
}

template <typename T>
int CvodeIntegrator<T>::root(double, N_Vector y, double* g, void* self) {
  auto& integrator = *static_cast<CvodeIntegrator*>(self);
  g[0] = N_VGetArrayPointer(y)[integrator.m_run.stop()] - integrator.m_run.gap();
  return 0;
}

template <typename T>
void CvodeIntegrator<T>::errorHandler(int, const char*, const char* function, char* message,
                                      void* self) {
  // CVODE prints to stderr by default: keep the message for the run's reason instead
  auto& integrator = *static_cast<CvodeIntegrator*>(self);
  integrator.m_lastMessage = std::string(function) + ": " + message;
}

template <typename T>
void CvodeIntegrator<T>::restart(double tau, const Vector& q, const Vector& v, bool inContact) {
  m_inContact = inContact;
  const int n = m_run.size();
  double* y = N_VGetArrayPointer(m_y);
  for (int i = 0; i < n; ++i) {
    y[i] = q(i);
    y[n + i] = v(i);
  }
  if (!m_started) {
    CVodeInit(m_memory, &CvodeIntegrator::rhs, tau, m_y);
    CVodeSetUserData(m_memory, this);
    CVodeSetErrHandlerFn(m_memory, &CvodeIntegrator::errorHandler, this);
    CVodeSStolerances(m_memory, m_options.rtol, m_options.rtol);
    if (m_options.bdf) {
      m_matrix = SUNDenseMatrix(2 * n, 2 * n, m_context);
      m_linearSolver = SUNLinSol_Dense(m_y, m_matrix, m_context);
      CVodeSetLinearSolver(m_memory, m_linearSolver, m_matrix);
      CVodeSetJacFn(m_memory, &CvodeIntegrator::jacobian);
    } else {
      m_nonlinearSolver = SUNNonlinSol_FixedPoint(m_y, 0, m_context);
      CVodeSetNonlinearSolver(m_memory, m_nonlinearSolver);
    }
    CVodeRootInit(m_memory, 1, &CvodeIntegrator::root);
    int direction = m_options.rootDirection;
    CVodeSetRootDirection(m_memory, &direction);
    CVodeSetNoInactiveRootWarn(m_memory);
    m_started = true;
  } else {
    CVodeReInit(m_memory, tau, m_y);
  }
  CVodeSetStopTime(m_memory, m_run.tauEnd());
}

template <typename T>
typename CvodeIntegrator<T>::Outcome CvodeIntegrator<T>::step(double& tau, Vector& q, Vector& v) {
  m_lastMessage.clear();
  const int flag = CVode(m_memory, m_run.tauEnd(), m_y, &tau, CV_ONE_STEP);
  const int n = m_run.size();
  const double* y = N_VGetArrayPointer(m_y);
  for (int i = 0; i < n; ++i) {
    q(i) = y[i];
    v(i) = y[n + i];
  }
  if (flag == CV_ROOT_RETURN) return Outcome::Root;
  if (flag == CV_TSTOP_RETURN) return Outcome::End;
  if (flag == CV_SUCCESS) return Outcome::Step;
  char* name = CVodeGetReturnFlagName(flag);
  m_error = std::string("CVODE ") + name + (m_lastMessage.empty() ? "" : " (" + m_lastMessage + ")");
  std::free(name);
  return Outcome::Error;
}

template class CvodeIntegrator<Task>;
template class CvodeIntegrator<ChainTask>;

}  // namespace grazelab::core::methods
