// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "core/solver/recorder.h"
#include "ui/plots/decimate.h"

/// A run's items as points, read where the run keeps them: the views draw a run without a
/// copy of it (they hold the run itself, shared, for as long as they show it).
namespace grazelab::ui {

/// Which coordinates of the samples.
enum class SampleAxes { TimeU2, U2V2, U1V1 };

inline PointSpan samplePoints(const core::Result& run, SampleAxes axes) {
  const core::Sample probe;
  const core::State& state = probe.state;
  const auto offset = [&probe](const double& field) { return PointSpan::fieldOffset(probe, field); };
  std::size_t x = 0;
  std::size_t y = 0;
  switch (axes) {
    case SampleAxes::TimeU2: x = offset(probe.t); y = offset(state.u2); break;
    case SampleAxes::U2V2: x = offset(state.u2); y = offset(state.v2); break;
    case SampleAxes::U1V1: x = offset(state.u1); y = offset(state.v1); break;
  }
  return PointSpan::ofRecords(run.samples.data(), run.samples.size(), sizeof(core::Sample), x, y);
}

/// The points (u1, v1) on the section H, one per contact.
inline PointSpan sectionPoints(const core::Result& run) {
  const core::PoincarePoint probe;
  return PointSpan::ofRecords(run.poincare.data(), run.poincare.size(), sizeof(core::PoincarePoint),
                              PointSpan::fieldOffset(probe, probe.u1),
                              PointSpan::fieldOffset(probe, probe.v1));
}

}  // namespace grazelab::ui
