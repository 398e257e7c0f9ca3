// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QRectF>

#include <optional>

#include "ui/plots/plot_view.h"

namespace grazelab::ui {

/// The multipliers of the orbit the run follows (the eigenvalues of its return map at fixed
/// energy) against the unit circle: on it the orbit is stable, off it (a real pair mu, 1/mu)
/// unstable; a pair meeting at -1 is a flip.
class MultipliersPlot final : public PlotView {
  Q_OBJECT

 public:
  explicit MultipliersPlot(QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;

 private:
  /// Axes of equal scale in both directions, so that the unit circle is a circle: the range
  /// that holds the circle and the multipliers, widened along the longer side of the plot.
  void fitEqualScale();

  double m_reach = 1.15;
  std::optional<QRectF> m_fitted;  ///< the range last set  ///< the half-width that holds the circle and the multipliers
  int m_circle = 0;
  int m_multipliers = 0;
};

}  // namespace grazelab::ui
