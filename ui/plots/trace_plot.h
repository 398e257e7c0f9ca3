// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <memory>
#include <optional>

#include "ui/plots/plot_view.h"
#include "ui/plots/shown_run.h"

namespace grazelab::ui {

/// A run's stopped mass against time, any chain: u_s / d against t over the chain's period (T₂
/// of the note's chain), the stop at 1, its contacts on it, and the mass the panel's 'phase of'
/// names beside it when that is another; a few periods at the animation's time, or the whole
/// run (W).
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
  /// What it draws, in its units (t over the period, u over d): the stopped mass, the chosen
  /// one (empty when it is the stopped one), and the contacts (impacts, then the others).
  PointSpan stoppedMass() const { return entries()[std::size_t(m_trace)].points(); }
  PointSpan chosenMass() const { return entries()[std::size_t(m_other)].points(); }
  std::vector<QPointF> contacts() const;

 private:
  void drawOverlay();
  /// The time axis: a few slow periods at the animation's time, or the whole run.
  void placeWindow();

  /// The titles and names of a run of this chain (its stopped and chosen masses).
  void nameFor(const ShownRun& run, const ViewWords* words);
  /// The cursor's line at the animation's time, across the y axis as it is.
  void placeCursor();
  /// The animation's time in the axis' units.
  double cursorOnAxis() const { return m_run ? m_cursorTime * (1 / m_run->unit.length) : m_cursorTime; }

  std::shared_ptr<const core::Result> m_overlayRun;
  std::optional<ShownRun> m_run;  ///< the run drawn
  QString m_wordsTitle;           ///< the scene's title it was named with (none: its own)
  double m_window = 0;  ///< the end of the drawn samples [period]
  double m_cursorTime = 0;  ///< [time]
  bool m_whole = false;
  double m_tFinal = 0;
  RunWindow m_runWindow;
  int m_overlayTrace = -1;
  int m_overlayContacts = -1;
  int m_trace = 0;
  int m_other = 0;  ///< the chosen mass, when another
  int m_stop = 0;
  int m_impacts = 0;
  int m_grazings = 0;
  QXYSeries* m_cursor = nullptr;  ///< the animation's time, made on first use
  std::size_t m_eventsTaken = 0;  ///< events already drawn (or past the samples)
};

}  // namespace grazelab::ui
