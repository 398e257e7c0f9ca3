// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <Eigen/Core>

#include <string>
#include <string_view>
#include <vector>

#include "core/orbits/periodic_orbit.h"
#include "core/orbits/special_orbits.h"
#include "core/solver/chain_flight.h"
#include "core/solver/chain_run.h"

/// The exact stability of a periodic impacting orbit of a chain of N masses (docs/model.md
/// section 12): the 2N x 2N monodromy as the product of the flights' closed-form flow matrices and
/// the impacts' saltation matrices; its trivial pair (the flow and the energy) set apart by
/// restricting it to the energy level modulo the flow; the 2N - 2 multipliers left, each with a
/// first-order error bar and, on the unit circle, its Krein signature; and the class they give.
namespace grazelab::core {

template <typename S>
using ChainMatrix = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;

/// The units the checks and error bars are in: lengths over the gap, velocities over the slowest
/// moving mode's frequency times the gap (a chain's matrices are then of order one whatever its
/// units, as in docs/model.md section 7).
template <typename S>
struct ChainStateScale {
  S length = 1;
  S speed = 1;

  explicit ChainStateScale(const BasicChainDynamics<S>& dynamics) : length(dynamics.gap) {
    S slowest = 0;
    for (Eigen::Index j = 0; j < dynamics.omega.size(); ++j) {
      if (dynamics.omega[j] > 0 && (slowest == 0 || dynamics.omega[j] < slowest)) slowest = dynamics.omega[j];
    }
    speed = (slowest > 0 ? slowest : S(1)) * length;
  }
  // D x: the state in these units
  ChainVector<S> scaled(const ChainVector<S>& x) const {
    const Eigen::Index n = x.size() / 2;
    ChainVector<S> out(x.size());
    out.head(n) = x.head(n) / length;
    out.tail(n) = x.tail(n) / speed;
    return out;
  }
  // D A D^-1: a matrix on the state in these units
  ChainMatrix<S> scaled(const ChainMatrix<S>& a) const {
    const Eigen::Index n = a.rows() / 2;
    ChainMatrix<S> out = a;
    out.topRightCorner(n, n) *= speed / length;
    out.bottomLeftCorner(n, n) *= length / speed;
    return out;
  }
};

/// The flow matrix of a free flight of duration `tau` on x = (u, v) (2N, physical units):
/// x(tau) = Phi x(0), from the chain's modes (a mode of frequency 0 moves linearly in time).
template <typename S>
ChainMatrix<S> chainFlowMatrix(const BasicChainDynamics<S>& dynamics, const S& tau);

/// The saltation matrix of an elastic impact of the stopped mass s at displacements `u` (u_s = d)
/// arriving with velocities `vBefore` (v_s > 0): S = R + (f+ - R f-) e_(u_s)^T / v_s, R the reset
/// v_s -> -v_s; that is I except S[u_s][u_s] = S[v_s][v_s] = -1 and S[v_s][u_s] = 2 a_s / v_s,
/// a_s = -(M^-1 K u)_s the stopped mass's acceleration at the contact.
template <typename S>
ChainMatrix<S> chainSaltationMatrix(const BasicChainDynamics<S>& dynamics, const ChainVector<S>& u,
                                    const ChainVector<S>& vBefore);

/// The linear stability an orbit's 2N - 2 nontrivial multipliers give.
enum class ChainStability {
  Elliptic,           ///< every multiplier on the unit circle: linearly stable
  Hyperbolic,         ///< the largest off the circle is real and positive
  FlipHyperbolic,     ///< the largest off the circle is real and negative
  ComplexQuadruplet,  ///< the largest off the circle is not real: lambda, 1/lambda and their
                      ///< conjugates (a Krein collision's outcome; N >= 3 only)
  Undecided,          ///< a multiplier within its error of the circle and of another one (a
                      ///< collision, or +-1): this precision cannot tell whether it leaves
};
/// "elliptic", "hyperbolic", "flip-hyperbolic", "complex-quadruplet", "undecided".
std::string_view toString(ChainStability stability);

/// One nontrivial multiplier.
template <typename S>
struct ChainMultiplier {
  S re = 0;
  S im = 0;
  /// first-order error bar: the eigenvalue's condition number times the monodromy's rounding
  /// (infinite at a defective eigenvalue, a collision)
  S error = 0;
  bool onCircle = false;  ///< | |lambda| - 1 | within the error bar
  /// the Krein signature sign(Im(u^H p)) of its eigenvector (u, p = M v), +1 or -1, for a
  /// multiplier on the circle off the real axis; 0 otherwise, or where the form is within its
  /// rounding of 0 (an eigenvector at a collision)
  int krein = 0;
};

/// The monodromy of a periodic orbit and what it says.
template <typename S>
struct ChainMonodromy {
  ChainMatrix<S> matrix;  ///< 2N x 2N on (u, v), from just after the start's impact
  /// the 2N - 2 nontrivial multipliers, by angle in (-pi, pi], then modulus
  std::vector<ChainMultiplier<S>> multipliers;
  ChainStability stability = ChainStability::Undecided;
  /// how far it is from the identities it must satisfy (free accuracy checks), in the scaled
  /// units of the state (lengths over the gap, velocities over the slowest frequency times it):
  S symplecticDefect = 0;   ///< |Phi^T J Phi - J| / |Phi|^2 in (u, p = M v)
  S trivialPairDefect = 0;  ///< |Phi X - X| / |X| for the flow direction X after the start
  S detDefect = 0;          ///< |prod of the nontrivial multipliers - 1|
  /// the monodromy's rounding estimate: epsilon times the product of its factors' norms (scaled)
  /// times their count
  S rounding = 0;
};

/// One flight of a periodic path and the impact that ends it, as the monodromy takes them.
template <typename S>
struct MonodromyLeg {
  S flight = 0;  ///< its duration [time]
  /// the saltation matrix's entry S[v_s][u_s] = 2 a_s / v_s- [1/time]
  S sigma = 0;
  /// an estimate of sigma's relative error: what the orbit's own data (its state, known to its
  /// rounding) leave uncertain in the multipliers, beside the rounding of their product
  S sigmaError = 0;
};

/// The legs of a path from the impacts `events` runChain reports over one period: sigma from each
/// impact's state, its error from the cancellation in the stopped mass's acceleration and speed.
template <typename S>
std::vector<MonodromyLeg<S>> legsOf(const BasicChainDynamics<S>& dynamics,
                                    const std::vector<BasicChainEvent<S>>& events);

/// The product S_k Phi(tau_k) ... S_1 Phi(tau_1) along `legs` alone (2N x 2N, physical units): what
/// Newton's Jacobian needs, without the multipliers.
template <typename S>
ChainMatrix<S> chainMonodromyMatrix(const BasicChainDynamics<S>& dynamics, const std::vector<MonodromyLeg<S>>& legs);

/// The monodromy of the periodic path that starts at `start` (just after an impact of the stopped
/// mass) and goes along `legs` back to it. Each multiplier's error bar is the rounding of the
/// product times the eigenvalue's condition number, plus how far it moves over each sigma's
/// error (its derivative by differences of sqrt(epsilon)).
template <typename S>
ChainMonodromy<S> chainMonodromy(const BasicChainDynamics<S>& dynamics, const BasicChainState<S>& start,
                                 const std::vector<MonodromyLeg<S>>& legs);

/// A periodic orbit of a chain of N masses with k impacts per period, from its state just after
/// an impact (t = 0).
template <typename S>
struct BasicChainPeriodicOrbit {
  BasicChainState<S> state;
  int impacts = 0;  ///< k
  S period = 0;     ///< the time of the k-th impact
  S energy = 0;
  std::vector<BasicChainEvent<S>> events;  ///< the contacts over one period
  ChainMonodromy<S> monodromy;
  /// |x_k - x_0| over max(1, |x_0|), in the scaled units of the state
  S periodicityResidual = 0;
  OrbitRefusal refusal = OrbitRefusal::None;
  bool admissible() const { return refusal == OrbitRefusal::None; }
};
using ChainPeriodicOrbit = BasicChainPeriodicOrbit<double>;

/// The orbit through `start` closed after `impacts` contacts: the exact run's path and its
/// monodromy (chainMonodromy of legsOf its impacts). Admissible when the path's contacts are `impacts` impacts (no grazing, stick or
/// undecided contact), it closes to `closeTolerance` (relative, as periodicityResidual), and it is
/// no shorter orbit repeated.
template <typename S>
BasicChainPeriodicOrbit<S> evaluateChainOrbit(const BasicReadyChain<S>& chain, const BasicChainState<S>& start,
                                              int impacts, const std::type_identity_t<S>& closeTolerance);

/// The path of evaluateChainOrbit without its monodromy: its events, period, energy, residual and
/// refusal.
template <typename S>
BasicChainPeriodicOrbit<S> evaluateChainPath(const BasicReadyChain<S>& chain, const BasicChainState<S>& start,
                                             int impacts, const std::type_identity_t<S>& closeTolerance);

/// The monodromy of the 1IPP orbit of period T whose state after its impact is `postImpact` (its
/// closed-form data), from the closed form's sigma (below); the path is not run.
template <typename S>
ChainMonodromy<S> chainOnePeriodicMonodromy(const BasicReadyChain<S>& chain, const BasicChainState<S>& postImpact,
                                            const std::type_identity_t<S>& T);

/// The 1IPP orbit of period T of any chain (its closed-form data, chainOnePeriodicOrbitIn) with
/// its exact stability; `refusal` says why there is none (the data's refusal is in `onePeriodic`).
/// The monodromy's one leg is the flight T and the closed form's sigma = 2 m_s sum_j w_j P[s][j]^2
/// cot(w_j T / 2), whose error follows from its terms (near a multiple of a mode's period the
/// path's own sigma, through the large modal amplitudes there, is hundreds of times less exact).
template <typename S>
struct ChainOnePeriodicStability {
  OnePeriodicRefusal onePeriodic = OnePeriodicRefusal::BadPeriod;
  BasicChainPeriodicOrbit<S> orbit = [] {  // (no data: no start, no orbit admissible)
    BasicChainPeriodicOrbit<S> none;
    none.refusal = OrbitRefusal::BadStart;
    return none;
  }();
};
template <typename S>
ChainOnePeriodicStability<S> chainOnePeriodicStability(const BasicReadyChain<S>& chain,
                                                       const std::type_identity_t<S>& T);

}  // namespace grazelab::core
