// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once
// The definitions of core/orbits/chain_monodromy.h, included by the two files that instantiate
// them: chain_monodromy.cpp (double, long double) and chain_monodromy_quad.cpp (binary128), so
// that the heavy binary128 eigen-solver (std::complex<Quad>) compiles beside the others.
#include "core/orbits/chain_monodromy.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "core/numbers/eigen_quad.h"
#include "core/orbits/chain_onepp.h"

namespace grazelab::core {

namespace monodromy_detail {

template <typename S>
ChainVector<S> stacked(const ChainVector<S>& u, const ChainVector<S>& v) {
  ChainVector<S> x(u.size() + v.size());
  x << u, v;
  return x;
}

// -M^-1 K u = -P W^2 P^T M u (P^T M P = I)
template <typename S>
ChainVector<S> acceleration(const BasicChainDynamics<S>& dynamics, const ChainVector<S>& u) {
  const ChainVector<S> q = dynamics.P.transpose() * dynamics.mass.cwiseProduct(u);
  return -(dynamics.P * dynamics.omega.cwiseAbs2().cwiseProduct(q));
}

template <typename S>
S infinity() {
  return std::numeric_limits<S>::infinity();
}

// The nontrivial multipliers of the monodromy `phi` (scaled) of the orbit through x0, with
// flow direction `flow` and energy gradient `gradient` there (both scaled): phi maps the energy
// level's tangent ker(gradient) to itself and fixes `flow` in it, so on an orthonormal basis Q of
// ker(gradient) whose first vector is along `flow`, Q^T phi Q has first column e1, and its lower
// right block is the map induced on ker(gradient) / span(flow): the 2N - 2 multipliers left.
template <typename S>
struct Reduced {
  ChainMatrix<S> basis;   // the last 2N - 2 columns of Q
  ChainMatrix<S> matrix;  // (2N - 2) square
  S trivialPairDefect = 0;
};

template <typename S>
Reduced<S> reduce(const ChainMatrix<S>& phi, const ChainVector<S>& flow, const ChainVector<S>& gradient) {
  const Eigen::Index size = phi.rows();
  const ChainMatrix<S> normal = gradient.normalized();
  const ChainMatrix<S> full = Eigen::HouseholderQR<ChainMatrix<S>>(normal).householderQ();
  const ChainMatrix<S> level = full.rightCols(size - 1);  // ker(gradient)
  const ChainMatrix<S> along = level.transpose() * flow.normalized();
  const ChainMatrix<S> turn = Eigen::HouseholderQR<ChainMatrix<S>>(along).householderQ();
  const ChainMatrix<S> q = level * turn;  // q.col(0) = +-flow / |flow|
  const ChainMatrix<S> b = q.transpose() * phi * q;
  Reduced<S> reduced;
  reduced.basis = q.rightCols(size - 2);
  reduced.matrix = b.bottomRightCorner(size - 2, size - 2);
  const ChainVector<S> x = flow.normalized();
  reduced.trivialPairDefect = (phi * x - x).norm();
  return reduced;
}

// in (-pi, pi]: a real negative multiplier at pi, whatever the sign of its zero imaginary part
template <typename S>
S angleOf(const ChainMultiplier<S>& m) {
  using std::atan2;
  return atan2(m.im == 0 ? S(0) : m.im, m.re);
}

template <typename S>
S modulusOf(const ChainMultiplier<S>& m) {
  using std::sqrt;
  return sqrt(m.re * m.re + m.im * m.im);
}

template <typename S>
ChainStability classify(const std::vector<ChainMultiplier<S>>& multipliers) {
  using std::abs;
  const ChainMultiplier<S>* largest = nullptr;
  for (std::size_t i = 0; i < multipliers.size(); ++i) {
    const ChainMultiplier<S>& m = multipliers[i];
    if (!(m.error < infinity<S>())) return ChainStability::Undecided;
    if (!m.onCircle) {
      if (!largest || modulusOf(m) > modulusOf(*largest)) largest = &m;
      continue;
    }
    // on the circle within its error: it stays there unless it meets another multiplier, and
    // two of equal signature pass each other (Krein): it may leave only at a collision of
    // opposite or unknown signatures, or at +-1 with its reciprocal
    for (std::size_t j = 0; j < multipliers.size(); ++j) {
      const ChainMultiplier<S>& other = multipliers[j];
      if (j == i) continue;
      const S apart = abs(std::complex<S>(m.re - other.re, m.im - other.im));
      const bool sameSignature = m.krein != 0 && m.krein == other.krein;
      if (apart <= m.error + other.error && !sameSignature) return ChainStability::Undecided;
    }
  }
  if (!largest) return ChainStability::Elliptic;
  if (abs(largest->im) > largest->error) return ChainStability::ComplexQuadruplet;
  return largest->re > 0 ? ChainStability::Hyperbolic : ChainStability::FlipHyperbolic;
}


template <typename S>
using ComplexVector = Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1>;
template <typename S>
using ComplexMatrix = Eigen::Matrix<std::complex<S>, Eigen::Dynamic, Eigen::Dynamic>;

// The Krein signature of a multiplier on the circle from its eigenvector `lifted` to the state
// (scaled): sign Im(u^H p) in physical u and p = M v; 0 when the form is within `error` of 0
// (relative to |u| |p|: an eigenvector at a collision, where the form vanishes).
template <typename S>
int kreinSignature(const ComplexVector<S>& lifted, const BasicChainDynamics<S>& dynamics, const ChainStateScale<S>& scale,
                   const S& error) {
  using std::abs;
  using std::sqrt;
  const Eigen::Index n = lifted.size() / 2;
  std::complex<S> form(0, 0);
  S uNorm = 0;
  S pNorm = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const std::complex<S> u = lifted[k] * scale.length;
    const std::complex<S> p = lifted[n + k] * scale.speed * dynamics.mass[k];
    form += std::conj(u) * p;
    uNorm += std::norm(u);
    pNorm += std::norm(p);
  }
  const S relative = form.imag() / sqrt(uNorm * pNorm);
  if (!(abs(relative) > error)) return 0;
  return relative > 0 ? 1 : -1;
}

// How far each multiplier in `values` moves over the legs' sigma errors: for each leg, the full
// monodromy's eigenvalues with its sigma moved by sqrt(eps) of itself (`movedBy(leg, by)`, scaled)
// against those of `phi`, the nearest to the multiplier's, times sigma's error over the move;
// twice that, summed over the legs.
template <typename S, typename Moved>
std::vector<S> sigmaMoves(const std::vector<MonodromyLeg<S>>& legs, const ComplexVector<S>& values, Moved movedBy,
                          const ChainMatrix<S>& phi, const ChainStateScale<S>& scale) {
  using std::abs;
  using std::sqrt;
  const auto eigenvalues = [](const ChainMatrix<S>& m) -> ComplexVector<S> {
    const Eigen::EigenSolver<ChainMatrix<S>> solver(m, false);
    // (a solve that failed moves every multiplier without bound: its bar says so)
    if (solver.info() != Eigen::Success) {
      return ComplexVector<S>::Constant(m.rows(), std::complex<S>(infinity<S>(), 0));
    }
    return ComplexVector<S>(solver.eigenvalues());
  };
  const auto nearest = [](const ComplexVector<S>& among, const std::complex<S>& to) {
    Eigen::Index at = 0;
    for (Eigen::Index k = 1; k < among.size(); ++k) {
      if (abs(among[k] - to) < abs(among[at] - to)) at = k;
    }
    return among[at];
  };
  std::vector<S> moves(std::size_t(values.size()), S(0));
  const ComplexVector<S> unmoved = eigenvalues(phi);
  for (std::size_t leg = 0; leg < legs.size(); ++leg) {
    const S& sigma = legs[leg].sigma;
    const S by = sqrt(std::numeric_limits<S>::epsilon()) * std::max<S>(abs(sigma), scale.speed / scale.length);
    const ComplexVector<S> moved = eigenvalues(movedBy(leg, by));
    for (Eigen::Index i = 0; i < values.size(); ++i) {
      const std::complex<S> here = nearest(unmoved, values[i]);
      moves[std::size_t(i)] += 2 * abs(nearest(moved, here) - here) / by * abs(sigma) * legs[leg].sigmaError;
    }
  }
  return moves;
}

}  // namespace monodromy_detail

using namespace monodromy_detail;  // NOLINT: this header is the two files' own


template <typename S>
ChainMatrix<S> chainFlowMatrix(const BasicChainDynamics<S>& dynamics, const S& tau) {
  using std::cos;
  using std::sin;
  const Eigen::Index n = dynamics.P.rows();
  const Eigen::Index modes = dynamics.omega.size();
  ChainVector<S> c(modes), sOverW(modes), wS(modes);
  for (Eigen::Index j = 0; j < modes; ++j) {
    const S w = dynamics.omega[j];
    c[j] = cos(w * tau);
    sOverW[j] = w > 0 ? S(sin(w * tau) / w) : tau;  // a rigid-body mode moves linearly
    wS[j] = w * sin(w * tau);
  }
  // q = P^T M u: u(tau) = P (C q + S W^-1 qdot), v(tau) = P (-W S q + C qdot)
  const ChainMatrix<S> toModes = dynamics.P.transpose() * dynamics.mass.asDiagonal();
  ChainMatrix<S> phi(2 * n, 2 * n);
  const ChainMatrix<S> cosine = dynamics.P * c.asDiagonal() * toModes;
  phi.topLeftCorner(n, n) = cosine;
  phi.topRightCorner(n, n) = dynamics.P * sOverW.asDiagonal() * toModes;
  phi.bottomLeftCorner(n, n) = -(dynamics.P * wS.asDiagonal() * toModes);
  phi.bottomRightCorner(n, n) = cosine;
  return phi;
}

template <typename S>
ChainMatrix<S> chainSaltationMatrix(const BasicChainDynamics<S>& dynamics, const ChainVector<S>& u,
                                    const ChainVector<S>& vBefore) {
  const Eigen::Index n = u.size();
  const Eigen::Index s = dynamics.stop;
  ChainMatrix<S> salt = ChainMatrix<S>::Identity(2 * n, 2 * n);
  salt(s, s) = -1;
  salt(n + s, n + s) = -1;
  salt(n + s, s) = 2 * acceleration(dynamics, u)[s] / vBefore[s];
  return salt;
}

template <typename S>
std::vector<MonodromyLeg<S>> legsOf(const BasicChainDynamics<S>& dynamics,
                                    const std::vector<BasicChainEvent<S>>& events) {
  using std::abs;
  const Eigen::Index s = dynamics.stop;
  const S eps = std::numeric_limits<S>::epsilon();
  const S fastest = dynamics.omega.size() > 0 ? S(dynamics.omega.cwiseAbs().maxCoeff()) : S(0);
  std::vector<MonodromyLeg<S>> legs;
  for (const BasicChainEvent<S>& event : events) {
    // a_s = -sum_j w_j^2 P[s][j] q_j and v_s = sum_j P[s][j] qdot_j: their terms over their sums
    const ChainVector<S> q = dynamics.P.transpose() * dynamics.mass.cwiseProduct(event.u);
    const ChainVector<S> qdot = dynamics.P.transpose() * dynamics.mass.cwiseProduct(event.vBefore);
    S accelerationTerms = 0;
    S speedTerms = 0;
    for (Eigen::Index j = 0; j < q.size(); ++j) {
      accelerationTerms += abs(dynamics.omega[j] * dynamics.omega[j] * dynamics.P(s, j) * q[j]);
      speedTerms += abs(dynamics.P(s, j) * qdot[j]);
    }
    const S a = acceleration(dynamics, event.u)[s];
    MonodromyLeg<S> leg;
    leg.flight = event.flight;
    leg.sigma = 2 * a / event.vBefore[s];
    // the state at the impact carries the flight's rounding too, which grows with its phase w tau
    // (binary128 bars of orbits Newton found were 1.25 times short without it: chain_kipp_check.py)
    leg.sigmaError = 8 * eps * (1 + fastest * abs(event.flight)) *
                     (accelerationTerms / abs(a) + speedTerms / abs(event.vBefore[s]));
    legs.push_back(leg);
  }
  return legs;
}

template <typename S>
ChainMatrix<S> chainMonodromyMatrix(const BasicChainDynamics<S>& dynamics, const std::vector<MonodromyLeg<S>>& legs) {
  const Eigen::Index n = dynamics.mass.size();
  const Eigen::Index s = dynamics.stop;
  ChainMatrix<S> m = ChainMatrix<S>::Identity(2 * n, 2 * n);
  for (const MonodromyLeg<S>& leg : legs) {
    m = chainFlowMatrix(dynamics, leg.flight) * m;
    // the saltation's rows: u_s -> -u_s, v_s -> sigma u_s - v_s
    m.row(n + s) = leg.sigma * m.row(s) - m.row(n + s);
    m.row(s) *= -1;
  }
  return m;
}

template <typename S>
ChainMonodromy<S> chainMonodromy(const BasicChainDynamics<S>& dynamics, const BasicChainState<S>& start,
                                 const std::vector<MonodromyLeg<S>>& legs) {
  using std::abs;
  using std::sqrt;
  const Eigen::Index n = start.u.size();
  const Eigen::Index s = dynamics.stop;
  const ChainStateScale<S> scale(dynamics);
  const S eps = std::numeric_limits<S>::epsilon();
  ChainMonodromy<S> out;
  // the product, and each leg's factors for the product again with its sigma moved
  std::vector<ChainMatrix<S>> flows;
  const auto saltation = [&](const S& sigma) {
    ChainMatrix<S> salt = ChainMatrix<S>::Identity(2 * n, 2 * n);
    salt(s, s) = -1;
    salt(n + s, n + s) = -1;
    salt(n + s, s) = sigma;
    return salt;
  };
  const auto product = [&](std::size_t moved, const S& by) {
    ChainMatrix<S> m = ChainMatrix<S>::Identity(2 * n, 2 * n);
    for (std::size_t i = 0; i < legs.size(); ++i) {
      m = saltation(i == moved ? S(legs[i].sigma + by) : legs[i].sigma) * flows[i] * m;
    }
    return m;
  };
  // each flight's matrix is off by its arguments' rounding too: eps w_j tau for the fastest mode
  const S fastest = dynamics.omega.size() > 0 ? S(dynamics.omega.cwiseAbs().maxCoeff()) : S(0);
  S norms = 1;
  for (const MonodromyLeg<S>& leg : legs) {
    flows.push_back(chainFlowMatrix(dynamics, leg.flight));
    norms *= scale.scaled(flows.back()).norm() * (1 + fastest * abs(leg.flight)) *
             scale.scaled(saltation(leg.sigma)).norm();
  }
  out.matrix = product(legs.size(), 0);
  out.rounding = eps * norms * S(2 * legs.size());
  const ChainMatrix<S> phi = scale.scaled(out.matrix);

  // symplectic in (u, p = M v), lengths and momenta scaled alike: J kept up to a constant
  ChainMatrix<S> toMomenta = ChainMatrix<S>::Identity(2 * n, 2 * n);
  const S massScale = dynamics.mass.maxCoeff();
  for (Eigen::Index i = 0; i < n; ++i) toMomenta(n + i, n + i) = dynamics.mass[i] / massScale;
  const ChainMatrix<S> phiUp = toMomenta * phi * toMomenta.inverse();
  ChainMatrix<S> j = ChainMatrix<S>::Zero(2 * n, 2 * n);
  j.topRightCorner(n, n) = ChainMatrix<S>::Identity(n, n);
  j.bottomLeftCorner(n, n) = -ChainMatrix<S>::Identity(n, n);
  out.symplecticDefect = (phiUp.transpose() * j * phiUp - j).norm() / phiUp.squaredNorm();

  // the trivial pair: the flow after the start's impact, and the energy's gradient (K u, M v)
  const ChainVector<S> a = acceleration(dynamics, start.u);
  const ChainVector<S> flow = scale.scaled(stacked<S>(start.v, a));
  ChainVector<S> gradient = stacked<S>(-dynamics.mass.cwiseProduct(a), dynamics.mass.cwiseProduct(start.v));
  gradient.head(n) *= scale.length;  // a covector scales inversely
  gradient.tail(n) *= scale.speed;
  if (!(flow.norm() > 0) || !(gradient.norm() > 0)) {
    out.trivialPairDefect = infinity<S>();
    out.stability = ChainStability::Undecided;
    return out;
  }
  const Reduced<S> reduced = reduce(phi, flow, gradient);
  out.trivialPairDefect = reduced.trivialPairDefect;
  if (n == 1) {  // one mass: the trivial pair is all there is
    out.stability = ChainStability::Elliptic;
    return out;
  }

  const Eigen::EigenSolver<ChainMatrix<S>> solver(reduced.matrix);
  if (solver.info() != Eigen::Success) {  // (no multipliers: nothing said of them)
    out.stability = ChainStability::Undecided;
    return out;
  }
  const ComplexVector<S> values = solver.eigenvalues();
  const ComplexMatrix<S> vectors = solver.eigenvectors();
  const ComplexMatrix<S> left = vectors.inverse();
  std::vector<S> moves = sigmaMoves(legs, values, [&](std::size_t leg, const S& by) {
    return scale.scaled(product(leg, by));
  }, phi, scale);
  std::complex<S> determinant(1, 0);
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    ChainMultiplier<S> m;
    m.re = values[i].real();
    m.im = values[i].imag();
    determinant *= values[i];
    const S condition = left.row(i).norm() * vectors.col(i).norm();
    m.error = isFinite(condition) ? S(condition * out.rounding + moves[std::size_t(i)]) : infinity<S>();
    m.onCircle = abs(abs(values[i]) - 1) <= m.error;
    if (m.onCircle && abs(m.im) > m.error) {
      const ComplexVector<S> lifted = reduced.basis.template cast<std::complex<S>>() * vectors.col(i);
      m.krein = kreinSignature(lifted, dynamics, scale, m.error);
    }
    out.multipliers.push_back(m);
  }
  out.detDefect = abs(determinant - std::complex<S>(1, 0));
  // by angle to 1e-9 of a radian, then modulus: lambda and 1 / conj(lambda) of a quadruplet lie on
  // one ray, their computed angles apart by rounding only, and keep one order however scaled
  std::sort(out.multipliers.begin(), out.multipliers.end(), [](const ChainMultiplier<S>& x, const ChainMultiplier<S>& y) {
    using std::llround;
    const long long ax = llround(toDouble(angleOf(x)) * 1e9);
    const long long ay = llround(toDouble(angleOf(y)) * 1e9);
    return ax != ay ? ax < ay : modulusOf(x) < modulusOf(y);
  });
  out.stability = classify(out.multipliers);
  return out;
}

template <typename S>
BasicChainPeriodicOrbit<S> evaluateChainPath(const BasicReadyChain<S>& chain, const BasicChainState<S>& start,
                                             int impacts, const std::type_identity_t<S>& closeTolerance) {
  BasicChainPeriodicOrbit<S> orbit;
  orbit.state = start;
  orbit.impacts = impacts;
  const Eigen::Index s = chain.dynamics.stop;
  if (impacts < 1 || start.u[s] != chain.dynamics.gap || start.v[s] > 0) {
    orbit.refusal = OrbitRefusal::BadStart;
    return orbit;
  }
  orbit.energy = chainEnergy(chain.numbers, start);
  BasicChainRun<S> run = runChain(chain, BasicChainStart<S>(start), long(impacts));
  orbit.events = std::move(run.events);
  orbit.period = run.tFinal;
  if (run.stop == StopReason::Undecided) {
    orbit.refusal = OrbitRefusal::Undecided;
    return orbit;
  }
  if (run.stop != StopReason::ContactLimit || long(orbit.events.size()) != impacts) {
    orbit.refusal = OrbitRefusal::ContactCount;
    return orbit;
  }
  for (const BasicChainEvent<S>& event : orbit.events) {
    if (event.type != EventType::Impact) {
      orbit.refusal = OrbitRefusal::NotImpact;
      return orbit;
    }
  }
  const ChainStateScale<S> scale(chain.dynamics);
  const ChainVector<S> x0 = scale.scaled(stacked<S>(start.u, start.v));
  // relative to the state's size (at least the gap's and the slowest frequency's scale)
  orbit.periodicityResidual =
      (scale.scaled(stacked<S>(run.final.u, run.final.v)) - x0).norm() / std::max<S>(S(1), x0.norm());
  if (!(orbit.periodicityResidual <= closeTolerance)) {
    orbit.refusal = OrbitRefusal::NotClosed;
    return orbit;
  }
  // a shorter orbit repeated comes back to its start at an earlier impact
  for (int i = 0; i + 1 < impacts; ++i) {
    const BasicChainEvent<S>& event = orbit.events[std::size_t(i)];
    ChainVector<S> v = event.vBefore;
    v[s] = event.vAfter;
    if ((scale.scaled(stacked<S>(event.u, v)) - x0).norm() / std::max<S>(S(1), x0.norm()) <= closeTolerance) {
      orbit.refusal = OrbitRefusal::Repeated;
      return orbit;
    }
  }
  return orbit;
}

template <typename S>
BasicChainPeriodicOrbit<S> evaluateChainOrbit(const BasicReadyChain<S>& chain, const BasicChainState<S>& start,
                                              int impacts, const std::type_identity_t<S>& closeTolerance) {
  BasicChainPeriodicOrbit<S> orbit = evaluateChainPath(chain, start, impacts, closeTolerance);
  if (orbit.refusal == OrbitRefusal::None || orbit.refusal == OrbitRefusal::NotClosed ||
      orbit.refusal == OrbitRefusal::Repeated) {
    orbit.monodromy = chainMonodromy(chain.dynamics, start, legsOf(chain.dynamics, orbit.events));
  }
  return orbit;
}

template <typename S>
ChainMonodromy<S> chainOnePeriodicMonodromy(const BasicReadyChain<S>& chain, const BasicChainState<S>& postImpact,
                                            const std::type_identity_t<S>& T) {
  using std::abs;
  using std::cos;
  using std::sin;
  // the one leg from the closed form: sigma = 2 m_s sum_j w_j P[s][j]^2 cot(w_j T / 2), each term's
  // error from its argument's rounding (d cot x = -dx / sin^2 x) and its own
  const BasicChainDynamics<S>& dynamics = chain.dynamics;
  const Eigen::Index s = dynamics.stop;
  S sum = 0;
  S terms = 0;
  for (Eigen::Index j = 0; j < dynamics.omega.size(); ++j) {
    const S w = dynamics.omega[j];
    const S shape = dynamics.P(s, j) * dynamics.P(s, j);
    if (w > 0) {
      const S x = w * T / 2;
      const S sine = sin(x);
      const S cotangent = cos(x) / sine;
      sum += w * shape * cotangent;
      terms += w * shape * (abs(cotangent) + x / (sine * sine));
    } else {  // a rigid-body mode: w cot(w T / 2) -> 2 / T
      sum += 2 * shape / T;
      terms += 2 * shape / T;
    }
  }
  MonodromyLeg<S> leg;
  leg.flight = T;
  leg.sigma = 2 * dynamics.mass[s] * sum;
  leg.sigmaError = 8 * std::numeric_limits<S>::epsilon() * terms / abs(sum);
  return chainMonodromy(dynamics, postImpact, {leg});
}

template <typename S>
ChainOnePeriodicStability<S> chainOnePeriodicStability(const BasicReadyChain<S>& chain,
                                                       const std::type_identity_t<S>& T) {
  using std::abs;
  ChainOnePeriodicStability<S> out;
  const BasicChainOnePeriodicOrbit<S> data = chainOnePeriodicOrbitIn<S>(chain.numbers, chain.dynamics, T);
  out.onePeriodic = data.refusal;
  if (!data.admissible()) return out;
  out.orbit = evaluateChainPath(chain, data.postImpact, 1, infinity<S>());
  if (!out.orbit.admissible()) return out;
  out.orbit.period = T;  // (the path's impact at T to its rounding)
  out.orbit.monodromy = chainOnePeriodicMonodromy(chain, data.postImpact, T);
  // closed to the rounding of its path times how much the return map amplifies it
  S amplification = 1;
  for (const ChainMultiplier<S>& m : out.orbit.monodromy.multipliers) {
    amplification = std::max<S>(amplification, abs(std::complex<S>(m.re, m.im)));
  }
  if (!(out.orbit.periodicityResidual <= 8 * defaultCloseTolerance<S>() * amplification)) {
    out.orbit.refusal = OrbitRefusal::NotClosed;
  }
  return out;
}

// the explicit instantiations of one precision (each file its own)
#define GRAZELAB_CHAIN_MONODROMY(S)                                                                                \
  template ChainMatrix<S> chainFlowMatrix<S>(const BasicChainDynamics<S>&, const S&);                              \
  template ChainMatrix<S> chainSaltationMatrix<S>(const BasicChainDynamics<S>&, const ChainVector<S>&,             \
                                                  const ChainVector<S>&);                                          \
  template ChainMonodromy<S> chainMonodromy<S>(const BasicChainDynamics<S>&, const BasicChainState<S>&,            \
                                               const std::vector<MonodromyLeg<S>>&);                               \
  template ChainMatrix<S> chainMonodromyMatrix<S>(const BasicChainDynamics<S>&, const std::vector<MonodromyLeg<S>>&); \
  template BasicChainPeriodicOrbit<S> evaluateChainPath<S>(const BasicReadyChain<S>&, const BasicChainState<S>&,   \
                                                           int, const S&);                                         \
  template std::vector<MonodromyLeg<S>> legsOf<S>(const BasicChainDynamics<S>&,                                    \
                                                  const std::vector<BasicChainEvent<S>>&);                         \
  template BasicChainPeriodicOrbit<S> evaluateChainOrbit<S>(const BasicReadyChain<S>&, const BasicChainState<S>&,  \
                                                            int, const S&);                                        \
  template ChainMonodromy<S> chainOnePeriodicMonodromy<S>(const BasicReadyChain<S>&, const BasicChainState<S>&,    \
                                                          const S&);                                               \
  template ChainOnePeriodicStability<S> chainOnePeriodicStability<S>(const BasicReadyChain<S>&, const S&);

}  // namespace grazelab::core
