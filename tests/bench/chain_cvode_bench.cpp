// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The exact N-mass run against SUNDIALS CVODE as an event-driven integrator is used: the chain's
// 2N first-order equations, a root function u_s - d (crossings toward the stop), the stopped
// mass's velocity reversed at each root and the integration restarted there. A uniform chain of
// 10 masses (frequencies not commensurate) started near grazing: its slowest mode with its top
// pushed 1e-6 past the stop, and a little of every other mode, so that many contacts are near
// touches. Both run to the same time; the counters: contacts per second, the contacts each found,
// how many of the exact run's CVODE matches before its first missed or spurious one, and its
// state error at the end against the exact run (max over u and v, relative to the largest entry).
//
//   grazelab_chain_cvode_bench --benchmark_filter=NearGrazingTenMasses
#include <benchmark/benchmark.h>

#include <Eigen/LU>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "core/model/mass_chain.h"
#include "core/solver/chain_run.h"

namespace {

using namespace grazelab;

struct Case {
  core::MassChain chain;
  core::ChainState start;
  double tEnd = 0;
};

Case tenMassesNearGrazing() {
  Case c;
  c.chain.masses.assign(10, 1.0);
  c.chain.springs.assign(10, 1.0);
  const core::ChainModes modes = core::chainModes(c.chain);
  const Eigen::Index n = 10, slowest = n - 1, s = n - 1;
  c.start.u = Eigen::VectorXd::Zero(n);
  // the slowest mode, its top 1e-6 past the stop a quarter period on; 1e-4 of each other mode
  c.start.v = (1 + 1e-6) * c.chain.gap * modes.omega[slowest] / modes.P(s, slowest) * modes.P.col(slowest);
  for (Eigen::Index j = 0; j < slowest; ++j) c.start.v += 1e-4 * modes.omega[j] * modes.P.col(j);
  c.tEnd = 200 * 2 * std::numbers::pi / modes.omega[slowest];
  return c;
}

struct CvodeRun {
  core::ChainState final;
  std::vector<double> times;  ///< of its roots
  bool failed = false;
};

struct Equations {
  Eigen::MatrixXd acceleration;  // -M^-1 K
};

int rhs(double, N_Vector y, N_Vector ydot, void* data) {
  const auto& equations = *static_cast<const Equations*>(data);
  const Eigen::Index n = equations.acceleration.rows();
  const Eigen::Map<const Eigen::VectorXd> state(N_VGetArrayPointer(y), 2 * n);
  Eigen::Map<Eigen::VectorXd> rate(N_VGetArrayPointer(ydot), 2 * n);
  rate.head(n) = state.tail(n);
  rate.tail(n) = equations.acceleration * state.head(n);
  return 0;
}

struct RootData {
  Equations equations;
  Eigen::Index stop = 0;
  double gap = 1;
};

int rhsOf(double t, N_Vector y, N_Vector ydot, void* data) {
  return rhs(t, y, ydot, &static_cast<RootData*>(data)->equations);
}

int root(double, N_Vector y, double* g, void* data) {
  const auto& root = *static_cast<const RootData*>(data);
  g[0] = N_VGetArrayPointer(y)[root.stop] - root.gap;
  return 0;
}

// CVODE (Adams, fixed-point iteration, rtol = atol = `tolerance`) with a root at u_s = d
CvodeRun runCvode(const Case& c, double tolerance) {
  CvodeRun result;
  const Eigen::Index n = c.chain.size();
  RootData data;
  data.equations.acceleration = -core::massMatrix(c.chain).inverse() * core::stiffnessMatrix(c.chain);
  data.stop = c.chain.stopped() - 1;
  data.gap = c.chain.gap;
  SUNContext context = nullptr;
  SUNContext_Create(nullptr, &context);
  N_Vector y = N_VNew_Serial(2 * n, context);
  Eigen::Map<Eigen::VectorXd> state(N_VGetArrayPointer(y), 2 * n);
  state.head(n) = c.start.u;
  state.tail(n) = c.start.v;
  void* memory = CVodeCreate(CV_ADAMS, context);
  CVodeInit(memory, rhsOf, 0.0, y);
  CVodeSStolerances(memory, tolerance, tolerance);
  CVodeSetUserData(memory, &data);
  SUNNonlinearSolver solver = SUNNonlinSol_FixedPoint(y, 0, context);
  CVodeSetNonlinearSolver(memory, solver);
  CVodeSetMaxNumSteps(memory, 100'000'000);
  CVodeRootInit(memory, 1, root);
  const int direction = 1;
  CVodeSetRootDirection(memory, const_cast<int*>(&direction));
  double t = 0;
  while (t < c.tEnd) {
    const int flag = CVode(memory, c.tEnd, y, &t, CV_NORMAL);
    if (flag == CV_ROOT_RETURN) {
      result.times.push_back(t);
      state[data.stop] = c.chain.gap;
      state[n + data.stop] = -std::abs(state[n + data.stop]);
      CVodeReInit(memory, t, y);
    } else if (flag < 0) {
      result.failed = true;
      break;
    }
  }
  result.final = {state.head(n), state.tail(n)};
  CVodeFree(&memory);
  SUNNonlinSolFree(solver);
  N_VDestroy(y);
  SUNContext_Free(&context);
  return result;
}

double relativeError(const core::ChainState& a, const core::ChainState& b) {
  const double scale = std::max(b.u.cwiseAbs().maxCoeff(), b.v.cwiseAbs().maxCoeff());
  return std::max((a.u - b.u).cwiseAbs().maxCoeff(), (a.v - b.v).cwiseAbs().maxCoeff()) / scale;
}

// How many of the exact run's first contacts `times` matches, each within 1e-6 of the slowest
// period (the first one it does not is missed, or comes after a spurious one)
std::int64_t agreeing(const core::ChainRun& exact, const std::vector<double>& times, double period) {
  std::int64_t k = 0;
  for (const core::ChainEvent& event : exact.events) {
    if (!core::isContact(event.type)) continue;
    if (std::size_t(k) >= times.size() || std::abs(times[std::size_t(k)] - event.t) > 1e-6 * period) break;
    ++k;
  }
  return k;
}

// Arg(0): the exact run; Arg(k > 0): CVODE at tolerance 10^-k. Counters: contacts found, how
// many of the exact run's agree before the first disagreement (a missed or a spurious contact),
// the state's error at the end
void NearGrazingTenMasses(benchmark::State& state) {
  const Case c = tenMassesNearGrazing();
  const core::ChainRun exact = core::runChain(c.chain, c.start, 10'000'000, c.tEnd);
  const double period = 2 * std::numbers::pi / core::chainModes(c.chain).omega.minCoeff();
  std::int64_t contacts = 0;
  double error = 0;
  std::int64_t found = 0;
  std::int64_t agree = 0;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      const core::ChainRun run = core::runChain(c.chain, c.start, 10'000'000, c.tEnd);
      found = run.contacts;
      agree = found;
      error = relativeError(run.final, exact.final);
    } else {
      const CvodeRun run = runCvode(c, std::pow(10.0, -double(state.range(0))));
      if (run.failed) state.SkipWithError("CVODE failed");
      found = std::int64_t(run.times.size());
      agree = agreeing(exact, run.times, period);
      error = relativeError(run.final, exact.final);
    }
    contacts += found;
  }
  state.SetItemsProcessed(contacts);
  state.counters["contacts"] = double(found);
  state.counters["agree"] = double(agree);
  state.counters["exact_contacts"] = double(exact.contacts);
  state.counters["state_error"] = error;
}
BENCHMARK(NearGrazingTenMasses)->Arg(0)->Arg(8)->Arg(10)->Arg(12)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
