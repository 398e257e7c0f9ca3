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
  /// The animation's time: a line, drawn at once without re-decimating the data.
  void setTimeCursor(double t) override;
  void setWholeRun(bool whole) override;

 private:
  void drawOverlay();
  /// The time axis: a few slow periods at the animation's time, or the whole run.
  void placeWindow();

  std::shared_ptr<const core::Result> m_overlayRun;
  double m_gap = 1;
  double m_window = 0;  ///< the end of the drawn samples
  double m_T2 = 0;
  double m_cursorTime = 0;
  bool m_whole = false;
  double m_tFinal = 0;
  RunWindow m_runWindow;
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
