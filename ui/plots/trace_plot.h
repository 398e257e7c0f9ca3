// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <memory>

#include "ui/plots/plot_view.h"

namespace grazelab::ui {

class TracePlot final : public PlotView {
  Q_OBJECT

 public:
  explicit TracePlot(QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;
  /// Draws another method's run over the exact one (its u2 at its own steps, dashed, and its
  /// contacts as crosses); an empty run removes the overlay.
  void setOverlay(std::shared_ptr<const core::Result> run, const QString& name);
  void setTimeCursor(double t, const core::State& state) override;

 private:
  void drawOverlay();

  std::shared_ptr<const core::Result> m_overlayRun;
  double m_gap = 1;
  double m_window = 0;
  int m_overlayTrace = -1;
  int m_overlayContacts = -1;
  int m_trace = 0;
  int m_stop = 0;
  int m_impacts = 0;
  int m_grazings = 0;
  QXYSeries* m_cursor = nullptr;  ///< the animation's time, made on first use
  RunProgress m_taken;  ///< samples and events already drawn
};

}  // namespace grazelab::ui
