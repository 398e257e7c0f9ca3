// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <Eigen/Core>

namespace grazelab::core::methods {

/// The chain a comparison method integrates, without units (docs/model.md section 8): N masses
/// between walls at x_0 = 0 and x_(N+1) = 0,
///   x_i'' = -left_i (x_i - x_(i-1)) + right_i (x_(i+1) - x_i),
/// with left_i = k_i / m_i and right_i = k_(i+1) / m_i in the run's units (right_N = 0 without a
/// right wall), and the stop at x_stop = gap. Written spring by spring, so that the note's chain
/// (left = (p, w), right = (q, 0) of its scaled form) keeps the arithmetic it always had.
/// D = 2 for the note's chain (fixed size: its runs are timed in the report; no right wall),
/// Eigen::Dynamic for a chain of any N.
template <int D>
struct ScaledSystem {
  using Vector = Eigen::Matrix<double, D, 1>;
  using Matrix = Eigen::Matrix<double, D, D>;

  Vector left;
  Vector right;
  int stop = 0;     ///< the stopped mass, 0-based
  double gap = 1;   ///< where it meets the stop

  int size() const { return int(left.size()); }

  /// The free accelerations at positions x, written into a (both indexable by 0..N-1: vectors
  /// or maps of a method's own state).
  template <typename X, typename A>
  void accelerationInto(const X& x, A&& a) const {
    if constexpr (D == 2) {
      // the note's chain (no right wall), as its hot loops always computed it: the same bits as
      // the loop below, without its branches
      const double x0 = x(0), x1 = x(1);
      const double stretch = x0 - x1;
      a(0) = -(left(0) * x0 + right(0) * stretch);
      a(1) = left(1) * stretch;
      return;
    }
    const int n = size();
    for (int i = 0; i < n; ++i) {
      const double below = i > 0 ? x(i - 1) : 0.0;
      double ai = -(left(i) * (x(i) - below));
      if (i + 1 < n) {
        ai += right(i) * (x(i + 1) - x(i));
      } else if (right(i) != 0) {
        ai += right(i) * (0.0 - x(i));
      }
      a(i) = ai;
    }
  }
  Vector acceleration(const Vector& x) const {
    Vector a(x.size());
    accelerationInto(x, a);
    return a;
  }

  /// A with x'' = -A x: tridiagonal.
  Matrix stiffness() const {
    const int n = size();
    Matrix A = Matrix::Zero(n, n);
    for (int i = 0; i < n; ++i) {
      A(i, i) = left(i) + right(i);
      if (i + 1 < n) {
        A(i, i + 1) = -right(i);
        A(i + 1, i) = -left(i + 1);
      }
    }
    return A;
  }
};

}  // namespace grazelab::core::methods
