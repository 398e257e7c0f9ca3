// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "ui/compute/figures.h"
#include "ui/plots/plot_view.h"

class QXYSeries;

namespace grazelab::ui {

/// A curve the scene computed itself (a family of orbits against its parameter), the current
/// value's point on it and a reference, on the scene's fixed axes: the point is seen moving.
class CurvePlot final : public PlotView {
  Q_OBJECT

 public:
  CurvePlot(PlotKind kind, QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;
  PlotKind kind() const { return m_kind; }
  /// The figure shown has a handle to drag (CurveFigure::draggedModes).
  bool draggable() const { return m_draggable; }

 signals:
  /// The ring of a draggable figure (CurveFigure::draggedModes) was dragged to `value`, in the
  /// data's coordinates (sent as it moves).
  void referenceDragged(QPointF value);

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;

 private:
  /// the press is on the handle: the ring, or the one marker (within a finger's reach)
  bool onRing(QPointF position) const;
  PlotKind m_kind;
  int m_dots = 0;  ///< the curve as dots (CurveFigure::dots)
  int m_curve = 0;
  int m_reference = 0;       ///< a dashed line (two points)
  int m_referencePoint = 0;  ///< a ring (one point)
  int m_marker = 0;
  bool m_draggable = false;
  bool m_dragging = false;
  QPointF m_ring;  ///< where the handle (ring or marker) is, in the data's coordinates
};

}  // namespace grazelab::ui
