// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <Eigen/Core>

#include <optional>
#include <type_traits>
#include <vector>

#include "core/numbers/scalar.h"

namespace grazelab::core {

/// f(t) = offset + slope t + sum_j (a_j cos w_j t + b_j sin w_j t): the distance of a chain's
/// stopped mass to the stop in a flight (the slope a floating chain's drift), or the springs'
/// force on it while it is held there.
template <typename S>
struct BasicSinusoidSum {
  Eigen::Matrix<S, Eigen::Dynamic, 1> a, b, w;  ///< w_j >= 0 (w_j = 0: a constant a_j, b_j = 0)
  S offset = 0;
  S slope = 0;  ///< 0 on a periodic f
  /// when every w_j = n_j omega0 (n_j <= 64), the n_j: cos and sin of n w0 t then come from one
  /// sincos by angle addition (its roundings counted in the error bound); empty otherwise
  std::vector<int> harmonics;
  S omega0 = 0;
  /// f's first `startTerms` Taylor coefficients at 0 are 0 exactly (0 .. 4): 1 when f starts on
  /// 0 (a flight from the stop: offset = -sum a_j), 2 when also at rest there (f'(0) = 0), 3 at a
  /// release (f''(0) = 0 too), 4 at a release with no jerk either (f'''(0) = 0). f is then evaluated as sum a_j C_k(w_j t) + b_j S_k(w_j t), the
  /// cosines and sines less their Taylor terms below degree k (offset unused; the slope only at
  /// k = 1, where it is f's first Taylor term), so that near t = 0
  /// (and near a period's end, by periodicity) its value keeps its relative precision instead of
  /// being lost in the rounding of offset + sum a_j
  int startTerms = 0;
};
using SinusoidSum = BasicSinusoidSum<double>;

/// How f first reaches 0 from below.
enum class ZeroKind {
  Crossing,  ///< f rises through 0
  Touch,     ///< f reaches 0 with f' = 0 within what the precision resolves (an even-multiplicity zero)
  None,      ///< never: f is periodic with `period` and stays below 0 over a whole period
  Budget,    ///< not within the horizon or the window budget
};

/// How f leaves 0 at t = 0 when its first `order` derivatives there are 0 (f = f' = f'' = 0 at
/// a release, f''' too at a flat one): by f^(order)(0) = `value` < 0.
template <typename S>
struct BasicLeaving {
  int order = 3;  ///< 3 or 4 (= the sum's startTerms)
  S value = 0;
};

template <typename S>
struct BasicFirstZero {
  ZeroKind kind = ZeroKind::None;
  S t = 0;
};
using FirstZero = BasicFirstZero<double>;

/// The first zero of f after t = 0, where f(0) <= 0, by a certified search (docs/model.md
/// section 11): f''' is at most B3 = sum w_j^3 R_j (R_j = hypot(a_j, b_j)); with r = h/2 a window
/// of width h around t_m holds no zero when |f(t_m)| > |f'(t_m)| r + |f''(t_m)| r^2/2 + B3 r^3/6,
/// and at most one when |f'(t_m)| > |f''(t_m)| r + B3 r^2/2; any other window is halved. Windows
/// are taken from the left, so the first zero found is the first zero: a touch (which no
/// sign-change method sees) is never missed, only possibly called a touch when two crossings lie
/// closer than double resolves. When f(0) = 0 within rounding, f must leave 0 downward by its
/// slope (or, at f'(0) = 0, its curvature): near t = 0 Taylor's bound rules out a zero; otherwise
/// the answer is a Touch at 0. A periodic f (`period` > 0) is searched over one period; any other
/// up to `horizon` or `maxWindows` windows, in pieces a fastest period wide. Where f is summed
/// mode by mode (no harmonics), the halvings turn each mode's cos and sin from the window they
/// halve instead of evaluating them, and the turns' roundings go into the bounds; a window's ends
/// and a crossing are still evaluated (docs/model.md section 11).
///
/// `leaving` (with startTerms = its order, 3 or 4) marks an f that starts where a held mass is
/// released: f and its first order - 1 derivatives are 0 there and f leaves 0 by the next one,
/// D = f^(k)(0) < 0; f(t) <= D t^k/k! + B_(k+1) t^(k+1)/(k+1)! < 0 rules out a zero below
/// (k+1)|D|/B_(k+1). At k = 4 a periodic f comes back to 0 from below at its period's end (a
/// flat return, as at k = 2: a touch at T).
/// In double, long double or binary128 (Quad): the rounding bounds and the resolution follow S.
template <typename S>
BasicFirstZero<S> firstZero(const BasicSinusoidSum<S>& f, std::type_identity_t<S> period,
                            std::type_identity_t<S> horizon, long maxWindows = 1'000'000,
                            std::optional<BasicLeaving<std::type_identity_t<S>>> leaving = std::nullopt);

}  // namespace grazelab::core
