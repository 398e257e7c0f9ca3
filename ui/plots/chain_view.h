// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

#include <cstdint>
#include <memory>
#include <vector>

#include "core/solver/simulate.h"
#include "ui/plots/scene_view.h"
#include "ui/compute/sim_types.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;
class QToolButton;

namespace grazelab::ui {

/// The chain itself, moving: the wall, the two springs drawn as springs, the masses and the
/// stop at d, displacements true to scale. Driven by the run's dense output (its samples, with
/// linear interpolation between them) and its contacts, which flash. Play / pause (Space),
/// speed, slow motion near contacts, step to the next or previous contact ([ and ]), and a
/// time slider; the time it shows is the cursor of every time-based plot (timeChanged).
class ChainView : public QWidget, public SceneView {
  Q_OBJECT

 public:
  explicit ChainView(QWidget* parent = nullptr);

  QWidget* widget() override { return this; }
  QString viewTitle() const override { return tr("The chain, moving"); }
  void show(const SimUpdate& update) override;
  void setPresentation(bool on, int textPixels) override;

  double time() const { return m_time; }
  bool playing() const { return m_timer.isActive(); }
  /// The state shown at time t (interpolated between samples).
  core::State stateAt(double t) const;
  void setTime(double t);
  void setPlaying(bool on);
  /// Moves to the next (+1) or previous (-1) contact after / before the current time.
  void stepContact(int direction);
  /// Time units of the run per second of wall time at speed 1 (one slow period in 2 s).
  double rate() const { return m_rate; }
  /// Animation steps taken while playing (one per timer tick, at most 62.5 a second): the
  /// latency benchmark's animation rate.
  std::int64_t framesPlayed() const { return m_framesPlayed; }

 signals:
  /// The animation shows time t, state `state` (the plots draw their cursor there).
  void timeChanged(double t, const grazelab::core::State& state);

 protected:
  void keyPressEvent(QKeyEvent* event) override;

 private:
  class Canvas;
  void tick();
  double speedFactor() const;

  Canvas* m_canvas = nullptr;
  QToolButton* m_play = nullptr;
  QToolButton* m_previous = nullptr;
  QToolButton* m_next = nullptr;
  QComboBox* m_speed = nullptr;
  QCheckBox* m_slowNearContacts = nullptr;
  QSlider* m_slider = nullptr;

  std::shared_ptr<const core::Result> m_result;
  std::vector<double> m_contactTimes;  ///< within the samples' window
  std::vector<core::EventType> m_contactTypes;
  core::Model m_model;
  double m_time = 0;
  double m_end = 0;
  double m_rate = 1;
  double m_nearContact = 0;  ///< a contact closer than this slows the motion [time]
  double m_amplitude = 1;    ///< the largest |u| of the run, for the scale
  double m_squeeze = 0;      ///< the largest u1 - u2 of the run: how far the masses close in
  QTimer m_timer;
  QElapsedTimer m_clockTimer;
  bool m_presentation = false;
  std::int64_t m_framesPlayed = 0;
  RunProgress m_taken;  ///< samples and events already taken in
};

}  // namespace grazelab::ui
