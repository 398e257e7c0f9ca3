// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <Eigen/Core>

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "core/model/model.h"
#include "core/numbers/eigen_quad.h"
#include "core/numbers/scalar.h"

namespace grazelab::core {

/// A chain of N masses against a rigid stop (docs/model.md section 11): wall --k1-- [m1] --k2--
/// [m2] -- ... --kN-- [mN], optionally --k(N+1)-- wall on the right; the stop at `gap` acts on
/// mass `stopMass` (1-based, the last by default). N = 2 with the stop on mass 2 is the note's
/// chain (model.h). k1 = 0 leaves the left end free (no left wall); with no right wall either,
/// the chain floats: it also moves as a rigid body (a mode of frequency 0, a flight linear in
/// time), as a bar thrown at a wall does.
///
/// Its numbers are in a precision S: a run in binary128 takes its chain in binary128, read from
/// the decimal text in that precision (0.7 is not double's 0.7 there), and its designed springs
/// polished in it; everything else (the explorer, the double runs) uses MassChain.
template <typename S>
struct BasicMassChain {
  std::vector<S> masses;   ///< m_1 ... m_N [mass], all > 0
  std::vector<S> springs;  ///< k_1 ... k_N [force/length]: wall-m1 (>= 0, 0: no left wall), then m(i-1)-mi (> 0)
  S rightSpring = 0;       ///< k_(N+1) from m_N to a right wall [force/length]; 0: none
  int stopMass = 0;        ///< s, 1-based; 0: the last mass
  S gap = 1;               ///< d > 0 [length]

  int size() const { return int(masses.size()); }
  /// s, 1-based, with the default resolved.
  int stopped() const { return stopMass > 0 ? stopMass : size(); }
  /// Held by a wall at neither end: one mode is the rigid body's (w = 0).
  bool floats() const { return (springs.empty() || springs[0] == 0) && rightSpring == 0; }
};
using MassChain = BasicMassChain<double>;

/// The same chain with its numbers in another precision (exact from double to a wider one).
template <typename To, typename From>
BasicMassChain<To> chainCast(const BasicMassChain<From>& chain) {
  BasicMassChain<To> cast;
  for (const From& m : chain.masses) cast.masses.push_back(static_cast<To>(m));
  for (const From& k : chain.springs) cast.springs.push_back(static_cast<To>(k));
  cast.rightSpring = static_cast<To>(chain.rightSpring);
  cast.stopMass = chain.stopMass;
  cast.gap = static_cast<To>(chain.gap);
  return cast;
}

/// Every problem with the chain: no mass, lists of different lengths, values that are not
/// positive and finite (k1 and the right spring may be 0: no wall there), a stop mass out of
/// range. Empty when the chain is usable.
std::vector<Problem> validate(const MassChain& chain);

/// The two-mass chain of the note as a MassChain (the stop on mass 2).
MassChain massChainOf(const Model& model);

/// M = diag(m) and the tridiagonal K: K[i][i] = k_i + k_(i+1), K[i][i+1] = K[i+1][i] = -k_(i+1).
template <typename S>
Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> massMatrix(const BasicMassChain<S>& chain) {
  return Eigen::Map<const Eigen::Matrix<S, Eigen::Dynamic, 1>>(chain.masses.data(), chain.size()).asDiagonal();
}
template <typename S>
Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> stiffnessMatrix(const BasicMassChain<S>& chain) {
  const int n = chain.size();
  Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> K = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    const S right = i + 1 < n ? chain.springs[std::size_t(i + 1)] : chain.rightSpring;
    K(i, i) = chain.springs[std::size_t(i)] + right;
    if (i + 1 < n) K(i, i + 1) = K(i + 1, i) = -right;
  }
  return K;
}

/// The normal modes of a chain (docs/model.md section 11): P^T M P = I, P^T K P = diag(w_j^2),
/// listed fastest first (mode 1 = the fastest, as in the two-mass chain), each column signed so
/// that P[s][j] > 0. A floating chain's last mode is the rigid body's: w_N = 0 and P's column
/// 1 / sqrt(sum m_i) for every mass, exactly (not the solver's rounding of them). A mode with a node at the stopped mass (P[s][j] zero within rounding, as in
/// a symmetric chain stopped in its middle) never moves that mass: it has no GLOM and never
/// reaches the stop.
template <typename S>
struct BasicChainModes {
  Eigen::Matrix<S, Eigen::Dynamic, 1> omega;               ///< w_1 > ... > w_N [1/time]
  Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> P;      ///< mode shapes, column j for mode j+1, M-orthonormal
  std::vector<bool> nodeAtStop;                            ///< mode j+1 does not move the stopped mass
};
using ChainModes = BasicChainModes<double>;

/// The modes of a usable chain (precondition: validate(chain) is empty). Computed on the
/// symmetric form M^-1/2 K M^-1/2 (Eigen's self-adjoint solver) in binary128, so that every
/// frequency, the slowest of a stiff chain included, is exact to double's rounding. Its cost
/// grows as N^3 in software arithmetic: 7 us for N = 2, 0.4 ms for N = 8, 14 ms for N = 32
/// (grazelab_core_bench --benchmark_filter=ChainModes).
ChainModes chainModes(const MassChain& chain);
/// The same rounded to S (double, long double) or kept in binary128 (Quad), from a chain whose
/// numbers are in binary128 (the solver's own precision) or any narrower one.
template <typename S>
BasicChainModes<S> chainModesIn(const BasicMassChain<Quad>& chain);
template <typename S, typename R>
  requires(!std::is_same_v<R, Quad>)
BasicChainModes<S> chainModesIn(const BasicMassChain<R>& chain) {
  return chainModesIn<S>(chainCast<Quad>(chain));
}

/// Why a floating chain has no periodic impacting orbit: its momentum changes only at
/// the impacts, each taking 2 m_s v_s > 0 from it, so it never comes back.
inline constexpr const char* kFloatingChainHasNoOrbit =
    "a floating chain (no wall at either end) has no periodic impacting orbit: each impact takes momentum "
    "from it and nothing gives it back";

/// The slowest frequency of a chain that vibrates: the least w_j > 0 (a floating chain's rigid
/// mode, w = 0, has no period); 0 when no mode vibrates.
template <typename S>
S slowestFrequency(const Eigen::Matrix<S, Eigen::Dynamic, 1>& omega) {
  S slowest = 0;
  for (Eigen::Index j = 0; j < omega.size(); ++j) {
    if (omega[j] > 0 && (slowest == 0 || omega[j] < slowest)) slowest = omega[j];
  }
  return slowest;
}

/// The ratios of a chain's frequencies: commensurate when w_j = n_j w0 with positive integers
/// n_j (gcd 1, at most `maxHarmonic`) to within `tolerance` relative; `detuning` says how far
/// from exact: max_j |w_j / (n_j w0) - 1| with w0 fitted to all the modes. When no harmonics fit,
/// the nearest small ones (the slowest mode's at most 12) and their detuning: a detuned 1:2
/// chain reads "near 2:1, detuned by 2.5 %".
struct SpectrumRatios {
  bool commensurate = false;
  std::vector<int> harmonics;  ///< n_1 >= ... >= n_N (fastest first)
  double omega0 = 0;           ///< w0 [1/time]: T = 2 pi / w0 is the period of every free motion
  double detuning = 0;         ///< how far from the integer ratios (relative)
};

/// Detects integer ratios among `omega` (fastest first), the smallest harmonics that fit.
SpectrumRatios detectRatios(const Eigen::VectorXd& omega, double tolerance = 1e-9, int maxHarmonic = 64);

}  // namespace grazelab::core
