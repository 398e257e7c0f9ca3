// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "ui/compute/figures.h"
#include "ui/plots/plot_view.h"

namespace grazelab::ui {

/// A curve the scene computed itself (a family of orbits against its parameter), the current
/// value's point on it and a reference, on the scene's fixed axes: the point is seen moving.
class CurvePlot final : public PlotView {
  Q_OBJECT

 public:
  CurvePlot(PlotKind kind, QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;

 private:
  PlotKind m_kind;
  int m_dots = 0;  ///< the curve as dots (CurveFigure::dots)
  int m_curve = 0;
  int m_reference = 0;       ///< a dashed line (two points)
  int m_referencePoint = 0;  ///< a ring (one point)
  int m_marker = 0;
};

}  // namespace grazelab::ui
