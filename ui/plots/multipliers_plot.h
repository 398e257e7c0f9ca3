// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QRectF>

#include <optional>

#include "ui/plots/plot_view.h"

namespace grazelab::ui {

/// The multipliers of the orbit the run follows (the eigenvalues of its return map at fixed
/// energy) against the unit circle: on it the orbit is stable, off it unstable; a pair meeting
/// at -1 is a flip. Of three masses or more, those on the circle are coloured by their Krein
/// signature: two of opposite signature that meet can leave the circle (a Krein collision).
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
  int m_kreinPlus = 0;
  int m_kreinMinus = 0;
};

}  // namespace grazelab::ui
