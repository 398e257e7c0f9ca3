// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

#include <memory>
#include <vector>

#include "core/experiments/chain_series.h"
#include "ui/plots/scene_view.h"

class QLabel;
class QSlider;
class QToolButton;

namespace grazelab::ui {

/// A chain of N masses, moving: the wall, every spring and mass (sized by the cube root of its
/// mass), the stop at d beside the stopped mass (a post it strikes with a tab), the right wall
/// when there is one; displacements true to scale, from the scene's grid over the run's first
/// periods (the experiment's first chain run), contacts flashing. Play / pause and a time slider.
class MassChainView : public QWidget, public SceneView {
  Q_OBJECT

 public:
  explicit MassChainView(QWidget* parent = nullptr);

  QWidget* widget() override { return this; }
  QString viewTitle() const override { return tr("The chain of N masses, moving"); }
  void setEmptyNote(const QString& why) override;
  void show(const SimUpdate& update) override;
  void setPresentation(bool on, int textPixels) override;

  double time() const { return m_time; }
  bool playing() const { return m_timer.isActive(); }
  void setTime(double t);
  void setPlaying(bool on);
  /// Every mass's displacement at time t (interpolated between the grid's points).
  std::vector<double> displacementsAt(double t) const;

 signals:
  /// The animation's time moved (played, stepped or dragged): the other views mark it.
  void timeChanged(double t);

 private:
  class Canvas;
  void tick();

  Canvas* m_canvas = nullptr;
  QToolButton* m_play = nullptr;
  QSlider* m_slider = nullptr;
  std::shared_ptr<const core::experiments::ChainSeries> m_series;
  std::vector<double> m_contactTimes;  ///< within the grid
  double m_time = 0;
  double m_end = 0;
  double m_rate = 1;       ///< time units a second (one slowest period in 2 s)
  QString m_emptyNote;  ///< why there is no motion (setEmptyNote)
  double m_amplitude = 1;  ///< the largest |u| on the grid, for the scale
  double m_squeeze = 0;    ///< the largest u_i - u_(i+1) on the grid: how far neighbours close in
  QTimer m_timer;
  QElapsedTimer m_clock;
  bool m_presentation = false;
};

}  // namespace grazelab::ui
