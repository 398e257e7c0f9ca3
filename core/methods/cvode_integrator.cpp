// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/methods/cvode_integrator.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cstdlib>

namespace grazelab::core::methods {

CvodeIntegrator::CvodeIntegrator(const ScaledRun& run, const Options& options)
    : m_run(run), m_options(options) {
  SUNContext_Create(nullptr, &m_context);
  m_y = N_VNew_Serial(4, m_context);
  m_memory = CVodeCreate(options.bdf ? CV_BDF : CV_ADAMS, m_context);
}

CvodeIntegrator::~CvodeIntegrator() {
  if (m_memory != nullptr) CVodeFree(&m_memory);
  if (m_nonlinearSolver != nullptr) SUNNonlinSolFree(m_nonlinearSolver);
  if (m_linearSolver != nullptr) SUNLinSolFree(m_linearSolver);
  if (m_matrix != nullptr) SUNMatDestroy(m_matrix);
  if (m_y != nullptr) N_VDestroy(m_y);
  if (m_context != nullptr) SUNContext_Free(&m_context);
}

int CvodeIntegrator::rhs(double, N_Vector y, N_Vector ydot, void* self) {
  auto& integrator = *static_cast<CvodeIntegrator*>(self);
  ++integrator.m_evaluations;
  const double* x = N_VGetArrayPointer(y);
  double* dx = N_VGetArrayPointer(ydot);
  auto a = integrator.m_run.acceleration(x[0], x[1]);
  if (integrator.m_inContact) a[1] -= integrator.m_options.stopStiffness * (x[1] - integrator.m_run.gap());
  dx[0] = x[2];
  dx[1] = x[3];
  dx[2] = a[0];
  dx[3] = a[1];
  return 0;
}

int CvodeIntegrator::jacobian(double, N_Vector, N_Vector, SUNMatrix J, void* self, N_Vector,
                              N_Vector, N_Vector) {
  auto& integrator = *static_cast<CvodeIntegrator*>(self);
  const Chain<double>& c = integrator.m_run.chain();
  SUNMatZero(J);
  SM_ELEMENT_D(J, 0, 2) = 1;
  SM_ELEMENT_D(J, 1, 3) = 1;
  SM_ELEMENT_D(J, 2, 0) = -(c.p + c.q);
  SM_ELEMENT_D(J, 2, 1) = c.q;
  SM_ELEMENT_D(J, 3, 0) = c.w;
  SM_ELEMENT_D(J, 3, 1) =
      -c.w - (integrator.m_inContact ? integrator.m_options.stopStiffness : 0.0);
  return 0;
}

int CvodeIntegrator::root(double, N_Vector y, double* g, void* self) {
  auto& integrator = *static_cast<CvodeIntegrator*>(self);
  g[0] = N_VGetArrayPointer(y)[1] - integrator.m_run.gap();
  return 0;
}

void CvodeIntegrator::errorHandler(int, const char*, const char* function, char* message,
                                   void* self) {
  // CVODE prints to stderr by default: keep the message for the run's reason instead
  auto& integrator = *static_cast<CvodeIntegrator*>(self);
  integrator.m_lastMessage = std::string(function) + ": " + message;
}

void CvodeIntegrator::restart(double tau, const State& x, bool inContact) {
  m_inContact = inContact;
  double* y = N_VGetArrayPointer(m_y);
  y[0] = x.u1;
  y[1] = x.u2;
  y[2] = x.v1;
  y[3] = x.v2;
  if (!m_started) {
    CVodeInit(m_memory, &CvodeIntegrator::rhs, tau, m_y);
    CVodeSetUserData(m_memory, this);
    CVodeSetErrHandlerFn(m_memory, &CvodeIntegrator::errorHandler, this);
    CVodeSStolerances(m_memory, m_options.rtol, m_options.rtol);
    if (m_options.bdf) {
      m_matrix = SUNDenseMatrix(4, 4, m_context);
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

CvodeIntegrator::Outcome CvodeIntegrator::step(double& tau, State& x) {
  m_lastMessage.clear();
  const int flag = CVode(m_memory, m_run.tauEnd(), m_y, &tau, CV_ONE_STEP);
  const double* y = N_VGetArrayPointer(m_y);
  x = {y[0], y[1], y[2], y[3]};
  if (flag == CV_ROOT_RETURN) return Outcome::Root;
  if (flag == CV_TSTOP_RETURN) return Outcome::End;
  if (flag == CV_SUCCESS) return Outcome::Step;
  char* name = CVodeGetReturnFlagName(flag);
  m_error = std::string("CVODE ") + name + (m_lastMessage.empty() ? "" : " (" + m_lastMessage + ")");
  std::free(name);
  return Outcome::Error;
}

}  // namespace grazelab::core::methods
