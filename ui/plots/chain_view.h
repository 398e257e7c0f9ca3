// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

#include <cstdint>
#include <optional>
#include <vector>

#include "ui/compute/sim_types.h"
#include "ui/plots/scene_view.h"
#include "ui/plots/shown_run.h"

class QCheckBox;
class QComboBox;
class QSlider;
class QToolButton;

namespace grazelab::ui {

/// A chain of any number of masses, moving: the wall, every spring and mass (sized by the cube
/// root of its mass), the stop at d beside the stopped mass (a post it strikes with a tab), the
/// right wall when there is one; displacements true to scale. Driven by the run the other run
/// views show (ShownRun: its samples, linearly interpolated, and its contacts, which flash). Play / pause (Space), speed, slow motion near
/// contacts, step to the next or previous contact ([ and ]), and a time slider; the time it
/// shows is the cursor of every time-based view (timeChanged).
class ChainView : public QWidget, public SceneView {
  Q_OBJECT

 public:
  explicit ChainView(QWidget* parent = nullptr);
  QWidget* widget() override { return this; }
  QString viewTitle() const override { return tr("The chain, moving"); }
  void setEmptyNote(const QString& why) override;
  void show(const SimUpdate& update) override;
  void setPresentation(bool on, int textPixels) override;
  double time() const { return m_time; }
  bool playing() const { return m_timer.isActive(); }
  /// Every mass's displacement at time t (interpolated between the samples); empty when there
  /// is no motion.
  std::vector<double> displacementsAt(double t) const;
  void setTime(double t);
  void setPlaying(bool on);
  /// Moves to the next (+1) or previous (-1) contact after / before the current time.
  void stepContact(int direction);
  /// Time units of the run per second of wall time at speed 1 (one slowest period in 2 s).
  double rate() const { return m_rate; }
  /// Animation steps taken while playing (one per timer tick, at most 62.5 a second): the
  /// latency benchmark's animation rate.
  std::int64_t framesPlayed() const { return m_framesPlayed; }

 signals:
  /// The animation shows time t (the other views mark it).
  void timeChanged(double t);

 protected:
  void keyPressEvent(QKeyEvent* event) override;

 private:
  class Canvas;
  void tick();
  double speedFactor() const;
  /// the motion's scales grown by its records from `from` on
  void widen(std::size_t from);

  Canvas* m_canvas = nullptr;
  QToolButton* m_play = nullptr;
  QComboBox* m_speed = nullptr;
  QCheckBox* m_slowNearContacts = nullptr;
  QSlider* m_slider = nullptr;
  /// the run moving (none yet): the records of its motion are `m_run->samples`
  std::optional<ShownRun> m_run;
  std::size_t m_eventsTaken = 0;       ///< the run's events looked at for contacts
  std::vector<double> m_contactTimes;  ///< within the motion's span
  std::vector<core::EventType> m_contactTypes;
  QString m_emptyNote;  ///< why there is no motion (setEmptyNote)
  double m_time = 0;
  double m_end = 0;
  double m_rate = 1;
  double m_nearContact = 0;  ///< a contact closer than this slows the motion [time]
  double m_amplitude = 1;    ///< the largest |u| of the motion, for the scale
  double m_squeeze = 0;      ///< the largest u_i - u_(i+1): how far neighbours close in
  QTimer m_timer;
  QElapsedTimer m_clock;
  bool m_presentation = false;
  std::int64_t m_framesPlayed = 0;
};

}  // namespace grazelab::ui
