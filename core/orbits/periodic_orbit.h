// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/two_mass_form.h"
#include "core/numbers/eigen_quad.h"
#include "core/solver/events.h"
#include "core/model/state.h"

/// Periodic impacting orbits (kIPP) and their stability, exactly (docs/model.md section 10):
/// the monodromy is the product of the free flights' exact flow matrices and the impacts'
/// saltation matrices, the return map's Jacobian on H+ at fixed energy follows from it, and an
/// orbit is found from a guess by Newton on that Jacobian. Every function is templated on the
/// scalar like the solver (double, long double, binary128).
namespace grazelab::core {

/// A 4x4 matrix on the state (u1, u2, v1, v2).
template <typename S>
using Matrix4 = Eigen::Matrix<S, 4, 4>;
/// A vector of the state (u1, u2, v1, v2).
template <typename S>
using Vector4 = Eigen::Matrix<S, 4, 1>;
/// A 2x2 matrix on the section coordinates (u1, v1).
template <typename S>
using Matrix2 = Eigen::Matrix<S, 2, 2>;

/// The exact flow matrix of a free flight of duration `tau` [time]: x(tau) = Phi x(0), from the
/// chain's modes (x = (u1, u2, v1, v2), physical units).
template <typename S>
Matrix4<S> flowMatrix(const TwoMassForm<S>& chain, const S& tau);

/// The saltation matrix of an elastic impact of mass 2 on the guard u2 = gap, arriving in the
/// state `before` (v2 > 0): I except S[u2][u2] = S[v2][v2] = -1, S[v2][u2] = 2 a2 / v2, with
/// a2 = k2 (u1 - gap) / m2 the acceleration of mass 2 at the contact.
template <typename S>
Matrix4<S> saltationMatrix(const TwoMassForm<S>& chain, const BasicState<S>& before);

/// The state on H+ (u2 = gap, leaving the stop: v2 <= 0) of energy `energy` with mass 1 at
/// (u1, v1); nothing when mass 1 and the springs alone hold more than `energy`.
template <typename S>
std::optional<BasicState<S>> sectionState(const TwoMassForm<S>& chain, const S& energy, const S& u1,
                                          const S& v1);

/// Linear stability of a periodic orbit from the trace of its reduced Jacobian DP^k (det 1).
enum class Stability {
  Elliptic,        ///< |tr| < 2: the multipliers on the unit circle, linearly stable
  Hyperbolic,      ///< tr > 2: real multipliers mu > 1 > 1/mu, unstable
  FlipHyperbolic,  ///< tr < -2: real negative multipliers, unstable (past a flip)
  Parabolic,       ///< |tr| = 2 within rounding: at a fold, branch point or flip
  Undecided,       ///< |tr| within its error of 2 (or -2): this precision cannot tell the class
                   ///< (said by decidedStability only; an orbit's own `stability` takes a side)
};
/// "elliptic", "hyperbolic", "flip-hyperbolic", "parabolic", "undecided".
std::string_view toString(Stability stability);

/// How far a computed orbit is from the identities it must satisfy (free accuracy checks).
template <typename S>
struct OrbitChecks {
  S detMinus1 = 0;            ///< det DP^k - 1 (0: the map is area-preserving at fixed energy)
  S trivialPair = 0;          ///< the largest distance of M's trivial pair of eigenvalues from 1
  S periodicityResidual = 0;  ///< |x_k - x_0| / scale: how far the path is from closing
};

/// Why a computed orbit is not admissible.
enum class OrbitRefusal {
  None,          ///< admissible
  BadStart,      ///< no impact asked for, or the start is not just after an impact
  Undecided,     ///< a contact of the path cannot be decided in this precision, or (1IPP) the
                 ///< path misses closing only by the rounding amplified near a multiple of T1
  ContactCount,  ///< the path made another number of contacts than asked
  NotImpact,     ///< a contact of the path is a grazing or a stick, not an impact
  NotClosed,     ///< the path does not come back to its start
  Repeated,      ///< a shorter orbit repeated
  TouchesStop,   ///< a flight touches or crosses the stop between impacts
};

/// A periodic orbit with k impacts per period, as computed from its state just after an impact
/// (t = 0): its path, monodromy, multipliers and checks, and whether it is admissible.
template <typename S>
struct PeriodicOrbit {
  BasicState<S> state;            ///< just after an impact (u2 = gap, v2 <= 0), t = 0
  int impacts = 0;                ///< k
  S period = 0;                   ///< the time of the k-th impact
  S energy = 0;
  std::vector<BasicEvent<S>> events;  ///< the contacts over one period (k of them when admissible)
  Matrix4<S> monodromy = Matrix4<S>::Zero();  ///< M = S_k Phi(tau_k) ... S_1 Phi(tau_1)
  Matrix2<S> reduced = Matrix2<S>::Zero();    ///< DP^k in (u1, v1) at fixed energy
  std::array<S, 2> energyDerivative{};  ///< d(P^k)/dE at fixed (u1, v1)
  S trace = 0;                    ///< tr DP^k = tr M - 2
  /// the largest entry of DP^k in units of the gap and of w2 times the gap (at least 1): how
  /// much the return map amplifies the rounding of its own path
  S amplification = 1;
  /// an estimate of the trace's error: epsilon times the product of the norms of the flights'
  /// and impacts' matrices (in units of the gap and of w2 times the gap; the rounding follows
  /// it, not the norm of the product), times the number of products, times the amplification
  /// (the orbit's state is itself only known to the rounding, and the trace moves with it).
  /// Checked against binary128 on degenerate flips of light-mass chains: 50 to 200 times the
  /// error met (tests/core/orbits/atlas_chains_test.cpp)
  S traceError = 0;
  /// the nontrivial pair of multipliers (eigenvalues of DP^k) as (re, im)
  std::array<std::array<S, 2>, 2> multipliers{};
  Stability stability = Stability::Elliptic;
  OrbitChecks<S> checks;
  S minImpactSpeed = 0;           ///< the smallest pre-impact speed v2- over the period
  /// the smallest distance below the stop of an interior maximum of u2 over the flights, over
  /// the gap (+infinity when no flight turns back before its impact)
  S minClearance = 0;
  bool admissible = false;
  OrbitRefusal refusal = OrbitRefusal::None;
  std::string reason;             ///< why not admissible, in words
};

/// The orbit through `start` (just after an impact) closed after `impacts` contacts: the
/// exact solver's path, the monodromy and the reduced Jacobian. Admissible when the path has
/// exactly `impacts` impacts and nothing else (no grazing, no stick, no contact double cannot
/// decide), closes to `closeTolerance` (relative), and is not a shorter orbit repeated.
template <typename S>
PeriodicOrbit<S> evaluateOrbit(const TwoMassForm<S>& chain, const BasicState<S>& start, int impacts,
                               const S& closeTolerance);

/// The tolerance a converged orbit closes to in S: a few hundred ulps of the state's scale.
template <typename S>
S defaultCloseTolerance();

/// The tolerance `orbit` can close to in S: defaultCloseTolerance times eight per impact (each
/// flight and impact adds its rounding: a long 2-impact path of a light mass 2 closes to about
/// 1000 ulps) times its amplification, since the return map amplifies the rounding of its own
/// path by as much; at most 1e6 times the default (next to a grazing the amplification grows
/// without bound).
template <typename S>
S closeTolerance(const PeriodicOrbit<S>& orbit);

/// Whether the orbit's return map passes its determinant check: det DP = 1 within 1e3 times the
/// default closing tolerance (next to a grazing or a multiple of T1 the amplification of the
/// rounding spoils it first). Tables of families keep only such orbits. (Whether the trace's
/// error decides the class is decidedStability's question, below.)
template <typename S>
bool determinantChecked(const PeriodicOrbit<S>& orbit);

/// The class as the faces report it: the orbit's `stability` where S decides it, else Undecided.
/// S decides it when the trace is farther from 2 and from -2 than its error (the larger of
/// `traceError` and |det DP^k - 1|), or the class is Parabolic (|tr| = 2 within the rounding the
/// checks show: on the boundary, no side claimed). Near a multiple of T1 in long double the trace
/// can be -2.24 with an error of 0.41: flip-hyperbolic or elliptic, S cannot say (the trace and
/// its error say how near the boundary it is; a higher precision may decide).
template <typename S>
Stability decidedStability(const PeriodicOrbit<S>& orbit);

/// The result of a search: the orbit, or the one line saying why none was found.
template <typename S>
struct OrbitSearch {
  std::optional<PeriodicOrbit<S>> orbit;
  std::string problem;
  /// why none was found when the path could not be decided in S (a higher precision may):
  /// OrbitRefusal::Undecided; the orbit's own refusal when one was computed; None otherwise
  OrbitRefusal refusal = OrbitRefusal::None;
  int iterations = 0;
  /// the Newton step from the orbit found, relative like the periodicity residual: how far the
  /// exact orbit may be. Small beside the residual's own size for a converged orbit; near a
  /// degenerate one (DP^k - I nearly singular) Newton may stall on a plateau that closes within
  /// the tolerance while the step from it stays large
  S correction = 0;
  /// the relative error of the orbit's data from the closed form (1IPP only): the rounding of
  /// S amplified by how near T is to a multiple of T1 or T2; 0 when not from the closed form
  S dataError = 0;
};

/// The trace's error at an orbit located by a search: its rounding (`traceError`) plus how far
/// the trace moves over the orbit's own uncertainty in the section (its periodicity residual,
/// at least one ulp), from the trace's gradient there (finite differences of sqrt(eps)). Near
/// a degenerate flip the trace can move by 1e-9 for a state moved by 1e-14.
template <typename S>
S locatedTraceError(const TwoMassForm<S>& chain, const PeriodicOrbit<S>& orbit);

/// A kIPP orbit of energy `energy` near the section point (u1, v1) on H+, by Newton on
/// P^k(x) - x with the exact Jacobian DP^k - I. Fails with a reason when the energy has no
/// state there, a step loses the impact sequence, Newton does not converge, the orbit is not
/// admissible, or a stop is requested.
template <typename S>
OrbitSearch<S> findOrbit(const TwoMassForm<S>& chain, const S& energy, const S& u1, const S& v1,
                         int impacts, std::stop_token stop = {});

/// The 1IPP orbit of period T (closed-form data, docs/model.md section 5) with its stability.
/// Near a multiple of T1 the impact speed V ~ T1 - T tends to 0 and the return map amplifies
/// the rounding like T1 / (T1 - T): a path from the data that misses closing by no more than
/// that (8 x 512 eps times the largest of |tr|, the amplification and the closed form's
/// conditioning), and that Newton cannot polish, is OrbitRefusal::Undecided, not NotClosed.
template <typename S>
OrbitSearch<S> onePeriodicOrbitStability(const TwoMassForm<S>& chain, const S& T);

/// The symmetry of an orbit under time reversal R(u1, v1) = (u1, -v1) on the section: "A" when
/// every impact has v1 = 0, "B" when the impacts are mirror images of each other in pairs,
/// (u1, v1) and (u1, -v1) (both within `tolerance`, relative to the state's scale); empty when
/// neither.
template <typename S>
std::string orbitSymmetry(const PeriodicOrbit<S>& orbit, const S& tolerance);

/// The tolerance of orbitSymmetry for an orbit computed in S: half its digits (a mirror image
/// matches to the orbit's closing times its amplification, which next to a grazing reaches 1e6).
template <typename S>
S symmetryTolerance() {
  using std::sqrt;
  return sqrt(std::numeric_limits<S>::epsilon());
}

}  // namespace grazelab::core
