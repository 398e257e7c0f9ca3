// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cassert>
#include <cstddef>
#include <span>
#include <vector>

namespace grazelab::core::experiments {

/// States of a chain of N masses at increasing times, flat: each record is the N + N + 1
/// doubles (t, u1..uN, v1..vN), one after the other. It is the layout of the two-mass run's
/// samples (core::Sample: t, u1, u2, v1, v2), so that a view reads a run of either by its
/// record's stride and a field's offset, and a copy of them is one block, not one per point.
struct StateRecords {
  int masses = 0;
  std::vector<double> values = {};  ///< size() x stride()

  std::size_t stride() const { return 1 + 2 * std::size_t(masses); }
  std::size_t size() const { return masses > 0 ? values.size() / stride() : 0; }
  bool empty() const { return size() == 0; }
  double t(std::size_t k) const { return values[k * stride()]; }
  /// The last record's time; 0 when there is none.
  double lastTime() const { return empty() ? 0.0 : t(size() - 1); }
  /// Mass i's displacement and velocity (0-based i) in record k.
  double u(std::size_t k, int i) const { return values[k * stride() + 1 + std::size_t(i)]; }
  double v(std::size_t k, int i) const { return values[k * stride() + 1 + std::size_t(masses + i)]; }
  /// Every mass's displacement in record k.
  std::span<const double> displacements(std::size_t k) const {
    return {values.data() + k * stride() + 1, std::size_t(masses)};
  }
  /// Appends a record: `u` and `v` hold `masses` values each, of any precision (rounded to
  /// double once).
  template <typename Values>
  void push(double time, const Values& u, const Values& v) {
    assert(masses > 0);
    values.push_back(time);
    for (int i = 0; i < masses; ++i) values.push_back(static_cast<double>(u[i]));
    for (int i = 0; i < masses; ++i) values.push_back(static_cast<double>(v[i]));
  }
};

}  // namespace grazelab::core::experiments
