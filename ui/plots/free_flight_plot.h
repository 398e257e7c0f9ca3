// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "ui/plots/plot_view.h"

namespace grazelab::ui {

class FreeFlightPlot final : public PlotView {
  Q_OBJECT

 public:
  explicit FreeFlightPlot(QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;
  void setPresentation(bool on, int textPixels) override;

 private:
  void applyMarkers();

  bool m_dense = false;  ///< more flights than pixel columns
  int m_flights = 0;
  int m_period = 0;
  RunProgress m_taken;  ///< flights already drawn
};

}  // namespace grazelab::ui
