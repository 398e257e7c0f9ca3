// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "core/state.h"
#include "ui/sim_types.h"

class QWidget;

namespace grazelab::ui {

/// What every view of a scene does, charts and the animation alike: take the worker's update,
/// take the presentation look, and follow the animation's time if it is time-based. The
/// window holds its scene's views as a list of these and lays out their widgets.
class SceneView {
 public:
  virtual ~SceneView() = default;
  virtual QWidget* widget() = 0;
  /// Fills the view from an update of the worker.
  virtual void show(const SimUpdate& update) = 0;
  /// Presentation mode: text of `textPixels`, thicker lines; off restores the desk look.
  virtual void setPresentation(bool on, int textPixels) = 0;
  /// The animation's time and state (time-based views mark it; others ignore it).
  virtual void setTimeCursor(double t, const core::State& state) {
    (void)t;
    (void)state;
  }
};

/// Which items of a run a view has taken, so that the next update of the same run (same
/// request id: the run grown) hands it only the items after them.
struct RunProgress {
  std::uint64_t runId = 0;  ///< 0: nothing taken yet
  int attempt = 0;          ///< SimUpdate::attempt of the run taken
  std::size_t events = 0;
  std::size_t poincare = 0;
  std::size_t freeFlights = 0;
  std::size_t samples = 0;
  /// True, with every count back at zero, when `update` is not the run taken so far grown
  /// (another request, or fewer items than taken); the view then draws it from the start.
  bool startsOver(const SimUpdate& update);
};

/// Creates the view for one kind (a chart, the work-precision view or the animated chain).
SceneView* makeView(PlotKind kind, QWidget* parent = nullptr);

}  // namespace grazelab::ui
