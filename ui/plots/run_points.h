// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstddef>
#include <cstring>

#include "core/experiments/state_records.h"
#include "core/solver/recorder.h"
#include "ui/plots/decimate.h"

/// A run's items as points, read where the run keeps them: the views draw a run without a
/// copy of it (they hold the run itself, shared, for as long as they show it).
namespace grazelab::ui {

/// States on a time grid read where they are, for any number of masses: flat records (t,
/// u1..uN, v1..vN), a two-mass run's samples (core::Sample is such a record) or the grid of a
/// series of N masses. Holds no memory, like PointSpan.
class StateSpan {
 public:
  StateSpan() = default;
  explicit StateSpan(const core::experiments::StateRecords& records)
      : m_first(reinterpret_cast<const std::byte*>(records.values.data())),
        m_count(records.size()),
        m_masses(records.masses) {}
  explicit StateSpan(const std::vector<core::Sample>& samples)
      : m_first(reinterpret_cast<const std::byte*>(samples.data())), m_count(samples.size()), m_masses(2) {
    static_assert(sizeof(core::Sample) == 5 * sizeof(double) && offsetof(core::Sample, state) == sizeof(double) &&
                      offsetof(core::State, u2) == sizeof(double) && offsetof(core::State, v1) == 2 * sizeof(double),
                  "a two-mass sample is the record (t, u1, u2, v1, v2)");
  }

  std::size_t size() const { return m_count; }
  bool empty() const { return m_count == 0; }
  int masses() const { return m_masses; }
  /// A record's fields: its time, mass i's displacement and velocity (0-based i).
  static int timeField() { return 0; }
  int displacementField(int i) const { return 1 + i; }
  int velocityField(int i) const { return 1 + m_masses + i; }
  double value(std::size_t k, int field) const {
    double x = 0;
    std::memcpy(&x, m_first + k * stride() + std::size_t(field) * sizeof(double), sizeof x);
    return x;
  }
  double t(std::size_t k) const { return value(k, timeField()); }
  double u(std::size_t k, int i) const { return value(k, displacementField(i)); }
  /// Two fields of every record as points.
  PointSpan points(int xField, int yField) const {
    return PointSpan::ofRecords(m_first, m_count, stride(), std::size_t(xField) * sizeof(double),
                                std::size_t(yField) * sizeof(double));
  }

 private:
  std::size_t stride() const { return (1 + 2 * std::size_t(m_masses)) * sizeof(double); }

  const std::byte* m_first = nullptr;
  std::size_t m_count = 0;
  int m_masses = 0;
};

/// The points (u1, v1) on the section H of the note's chain, one per contact.
inline PointSpan sectionPoints(const std::vector<core::PoincarePoint>& poincare) {
  const core::PoincarePoint probe;
  return PointSpan::ofRecords(poincare.data(), poincare.size(), sizeof(core::PoincarePoint),
                              PointSpan::fieldOffset(probe, probe.u1),
                              PointSpan::fieldOffset(probe, probe.v1));
}

}  // namespace grazelab::ui
