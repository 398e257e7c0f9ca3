// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>

#include "ui/plots/plot_view.h"
#include "ui/plots/shown_run.h"

namespace grazelab::ui {

/// A phase portrait of one mass of any chain's run, u/d against v/(d ω₁) (ω₁ the fastest
/// frequency): the mass the panel's 'phase of' names (mass 2 of the note's chain, the stopped
/// mass of N unless another is named), with the stop line when it is the stopped one and its
/// state at each contact when it is not; or mass 1.
class PhasePlot final : public PlotView {
  Q_OBJECT

 public:
  enum class Mass { Chosen, First };
  explicit PhasePlot(Mass mass, QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;
  /// The animation's time: a ring on the run's state there (between samples, interpolated).
  void setTimeCursor(double t) override;
  void setWholeRun(bool whole) override;
  Mass mass() const { return m_mass; }
  /// What it draws, in its units: the path, and the mass's states at the contacts (a mass
  /// other than the stopped one).
  PointSpan path() const { return entries()[std::size_t(m_path)].points(); }
  PointSpan atContacts() const { return entries()[std::size_t(m_contacts)].points(); }

 private:
  /// The titles, names and tooltip of a portrait of mass `index` of this run.
  void nameFor(const ShownRun& run, int index);
  /// Draws the window's stretch of the path over the pale whole run, or the whole run alone.
  void placeWindow();
  double lastTime() const;  ///< the time of the last sample shown (0 when none)
  /// the mass's point at time t, interpolated between the samples shown (none: nothing)
  std::optional<QPointF> pointAt(double t) const;

  Mass m_mass;
  int m_path = 0;    ///< the whole run
  int m_recent = 0;  ///< the window's stretch, over it
  int m_stop = 0;
  int m_start = 0;
  int m_contacts = 0;  ///< the mass's state at each contact (not the stopped mass)
  std::optional<ShownRun> m_run;  ///< the run shown, whose samples the path reads in place
  int m_index = -1;               ///< its mass drawn (0-based)
  RunWindow m_runWindow;
  double m_cursorTime = 0;  ///< [time]
  bool m_whole = false;
  bool m_windowed = false;  ///< what the series show now
  QXYSeries* m_cursor = nullptr;  ///< the animation's state, made on first use
  std::size_t m_samplesTaken = 0;  ///< samples already drawn
  std::size_t m_eventsTaken = 0;   ///< events already marked (or past the samples)
  double m_vLow = 0;  ///< the velocity range so far (the stop line spans it)
  double m_vHigh = 0;
};

}  // namespace grazelab::ui
