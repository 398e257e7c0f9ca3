// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QSlider>
#include <QWidget>

#include "ui/widgets/param_specs.h"

class QLabel;

namespace grazelab::ui {

class NumberBox;

/// A horizontal slider that paints small marks with labels under chosen values (λ = 1, 4/3).
class MarkedSlider : public QSlider {
  Q_OBJECT

 public:
  explicit MarkedSlider(QWidget* parent = nullptr);
  /// Marks at slider positions with their labels.
  void setMarks(QList<QPair<int, QString>> marks);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void changeEvent(QEvent* event) override;
  void initStyleOption(QStyleOptionSlider* option) const override;

 private:
  QFont labelFont() const;
  void reserveLabelRoom();

  QList<QPair<int, QString>> m_marks;
  mutable bool m_measuring = false;  ///< within sizeHint(): the option of the whole widget
};

/// A labelled slider and spin box bound both ways: dragging moves the spin box, typing an exact
/// value moves the slider. The spin box may accept a wider range than the slider covers; such a
/// value is kept as typed (the slider stays at its end), never clamped.
class SliderSpin : public QWidget {
  Q_OBJECT

 public:
  explicit SliderSpin(const ParamSpec& spec, QWidget* parent = nullptr);

  double value() const;
  /// Sets the value without emitting valueChanged.
  void setValue(double value);
  /// Moves the slider's ends (a range that depends on the chain); the value is kept, never
  /// clamped, and no valueChanged is emitted.
  void setSliderRange(double low, double high);

  QSlider* slider() const { return m_slider; }
  NumberBox* spinBox() const { return m_spin; }
  ParamKey key() const { return m_spec.key; }

 signals:
  void valueChanged(double value);
  /// A typed value was refused (and the previous one kept); `reason` says why.
  void refused(const QString& reason);

 private:
  int toPosition(double value) const;
  double fromPosition(int position) const;
  void sliderMoved(int position);
  void spinChanged(double value);

  ParamSpec m_spec;
  QLabel* m_label = nullptr;
  MarkedSlider* m_slider = nullptr;
  NumberBox* m_spin = nullptr;
};

}  // namespace grazelab::ui
