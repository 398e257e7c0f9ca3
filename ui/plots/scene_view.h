// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QRect>

#include "core/model/state.h"
#include "ui/compute/sim_types.h"
#include "ui/compute/time_text.h"

class QWidget;

namespace grazelab::ui {

class CsvTable;

/// What every view of a scene does, charts and the animation alike: take the worker's update,
/// take the presentation look, and follow the animation's time if it is time-based. The
/// window holds its scene's views as a list of these and lays out their widgets.
class SceneView {
 public:
  virtual ~SceneView() = default;
  virtual QWidget* widget() = 0;
  /// What the view is called where one is chosen (saving a plot): its title in words.
  virtual QString viewTitle() const = 0;
  /// Fills the view from an update of the worker.
  virtual void show(const SimUpdate& update) = 0;
  /// Presentation mode: text of `textPixels`, thicker lines; off restores the desk look.
  virtual void setPresentation(bool on, int textPixels) = 0;
  /// The animated chain's time: a view of the same run marks it (its own state there: the
  /// trace a line, the phase portrait a ring); others ignore it.
  virtual void setTimeCursor(double t) { (void)t; }
  /// Time-based views show a readable window of a long run (a few slow periods at the
  /// animation's time) unless the whole run is asked for.
  virtual void setWholeRun(bool whole) { (void)whole; }
  /// Why the view has nothing to show (a refused chain on a scene not run yet), said where its
  /// data would be; empty: the view shows its data.
  virtual void setEmptyNote(const QString& why) { (void)why; }
  /// The part of the view a saved picture of it shows, in its own coordinates (empty: all of
  /// it): a view with controls of its own leaves them out.
  virtual QRect pictureArea() const { return {}; }
  /// Whether the view draws the scene's own data only (no run), so that it can show what the
  /// scene has computed so far (SimUpdate::scenePartial).
  virtual bool drawsSceneDataOnly() const { return false; }
  /// Adds what the view shows to a CSV export (nothing for a view with no data of its own,
  /// such as the animated chain).
  virtual void appendCsv(CsvTable& table) const { (void)table; }
};

/// The stretch of a long run that time-based views show: kPeriods periods that hold the
/// animation's time (every time here in periods, the views' unit). It moves only when the time leaves its middle half, so that it stays still
/// while the animation plays through it (a plot redrawn every frame would flicker and cost).
class RunWindow {
 public:
  static constexpr double kPeriods = 3;
  /// Follows `cursor` within a run of `tLast`; true when it moved.
  bool follow(double cursor, double tLast);
  /// The whole run is short enough to be read whole: no window.
  bool wholeFits(double tLast) const { return !(tLast > 1.5 * kPeriods); }
  double from() const { return m_from; }
  double to() const { return m_to; }

 private:
  double m_from = 0;
  double m_to = 0;
};

/// Creates the view for one kind (a chart, the work-precision view or the animated chain).
SceneView* makeView(PlotKind kind, QWidget* parent = nullptr);

}  // namespace grazelab::ui
