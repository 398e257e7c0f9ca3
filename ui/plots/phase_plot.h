// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>

#include "ui/plots/plot_view.h"

namespace grazelab::ui {

/// A phase portrait of one mass: (u2, v2) with the stop line, or (u1, v1).
class PhasePlot final : public PlotView {
  Q_OBJECT

 public:
  enum class Mass { One, Two };
  explicit PhasePlot(Mass mass, QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;
  /// The animation's time: a ring on the run's state there (between samples, interpolated).
  void setTimeCursor(double t) override;
  void setWholeRun(bool whole) override;
  Mass mass() const { return m_mass; }

 private:
  Mass m_mass;
  /// Draws the window's stretch of the path over the pale whole run, or the whole run alone.
  void placeWindow();
  double lastTime() const;  ///< the time of the last sample shown (0 when none)
  /// the mass's (u, v) at time t, interpolated between the samples shown (none: nothing)
  std::optional<QPointF> pointAt(double t) const;

  int m_path = 0;    ///< the whole run
  int m_recent = 0;  ///< the window's stretch, over it
  /// the run shown, whose samples the path reads in place (their times place the window)
  std::shared_ptr<const core::Result> m_run;
  std::size_t m_samples = 0;  ///< how many of its samples were shown
  RunWindow m_runWindow;
  double m_T2 = 0;
  double m_cursorTime = 0;
  bool m_whole = false;
  bool m_windowed = false;  ///< what the series show now
  int m_stop = -1;
  int m_start = 0;
  QXYSeries* m_cursor = nullptr;  ///< the animation's state, made on first use
  RunProgress m_taken;  ///< samples already drawn
  double m_vLow = 0;    ///< the velocity range so far (the stop line spans it)
  double m_vHigh = 0;
};

}  // namespace grazelab::ui
