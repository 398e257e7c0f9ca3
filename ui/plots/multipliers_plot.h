// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

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
  int m_circle = 0;
  int m_multipliers = 0;
};

}  // namespace grazelab::ui
