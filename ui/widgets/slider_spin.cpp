// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/widgets/slider_spin.h"

#include "ui/widgets/number_box.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QSignalBlocker>
#include <QStyleOptionSlider>

#include <algorithm>
#include <cmath>

namespace grazelab::ui {
namespace {

constexpr int kSteps = 1000;

}  // namespace

MarkedSlider::MarkedSlider(QWidget* parent) : QSlider(Qt::Horizontal, parent) {}

void MarkedSlider::setMarks(QList<QPair<int, QString>> marks) {
  m_marks = std::move(marks);
  reserveLabelRoom();
  update();
}

QFont MarkedSlider::labelFont() const {
  // smaller than the labels; the font may be set in pixels (presentation mode) or in points
  QFont small = font();
  if (small.pixelSize() > 0) small.setPixelSize(std::max(8, int(small.pixelSize() * 0.8)));
  else small.setPointSizeF(small.pointSizeF() * 0.8);
  return small;
}

void MarkedSlider::reserveLabelRoom() {
  // the slider in the top strip, the labels in a strip of their own below it: drawn over the
  // slider they hid its handle ("0.5625" on m2's)
  const QFontMetrics metrics(labelFont());
  // the tick, a gap of 3 px and the label (as paintEvent draws them)
  const int labels = m_marks.isEmpty() ? 0 : metrics.height() + std::max(3, metrics.height() / 4) + 5;
  setMinimumHeight(QSlider::sizeHint().height() + labels);
}

void MarkedSlider::changeEvent(QEvent* event) {
  QSlider::changeEvent(event);
  if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange) reserveLabelRoom();
}

void MarkedSlider::initStyleOption(QStyleOptionSlider* option) const {
  QSlider::initStyleOption(option);
  // drawn and hit-tested in the top strip (the style centres a slider in its rect); sizeHint()
  // asks for the option too, hence the guard
  if (m_marks.isEmpty() || m_measuring) return;
  m_measuring = true;
  const int strip = QSlider::sizeHint().height();
  m_measuring = false;
  option->rect.setHeight(std::min(height(), strip));
}

void MarkedSlider::paintEvent(QPaintEvent* event) {
  QSlider::paintEvent(event);
  if (m_marks.isEmpty()) return;
  QStyleOptionSlider option;
  initStyleOption(&option);
  const QRect groove = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderGroove, this);
  const QRect handle = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, this);
  QPainter painter(this);
  painter.setPen(palette().color(QPalette::WindowText));
  painter.setFont(labelFont());
  const QFontMetrics metrics = painter.fontMetrics();
  const int span = groove.width() - handle.width();
  const int top = option.rect.bottom() + 1;
  // left to right; a label that would touch the one before moves right (its tick stays); the
  // ticks end 3 px above the labels (they struck through "0.5625" when it sat under its tick)
  int free = 0;
  const int tick = std::max(3, metrics.height() / 4);
  for (const auto& [position, label] : m_marks) {
    const int x = groove.x() + handle.width() / 2 +
                  QStyle::sliderPositionFromValue(minimum(), maximum(), position, span);
    painter.drawLine(x, top, x, top + tick);
    const int textWidth = metrics.horizontalAdvance(label);
    const int left = std::clamp(std::max(x - textWidth / 2, free), 0, std::max(0, width() - textWidth));
    painter.drawText(left, top + tick + 3 + metrics.ascent(), label);
    // two spaces between labels: "1" and "4/3" a space apart read as one "1 4/3"
    free = left + textWidth + 2 * metrics.horizontalAdvance(QLatin1Char(' '));
  }
}

SliderSpin::SliderSpin(const ParamSpec& spec, QWidget* parent) : QWidget(parent), m_spec(spec) {
  const QString key = jsonKey(spec.key);
  setObjectName(key);
  m_label = new QLabel(spec.label, this);
  m_label->setMinimumWidth(92);
  m_slider = new MarkedSlider(this);
  m_slider->setObjectName(key + QStringLiteral("Slider"));
  m_slider->setRange(0, kSteps);
  m_slider->setPageStep(kSteps / 20);
  // the spin box keeps what is typed exactly; `decimals` only rounds what the slider gives
  m_spin = new NumberBox(spec.label, spec.spinMin, spec.spinMax, spec.decimals == 0, this);
  m_spin->setObjectName(key + QStringLiteral("Spin"));
  m_spin->setSingleStep(spec.logarithmic ? 1.0 : (spec.sliderMax - spec.sliderMin) / 100.0);
  m_spin->setStepDecimals(spec.decimals);
  m_spin->setMinimumWidth(96);
  m_spin->setAlignment(Qt::AlignRight);

  QList<QPair<int, QString>> marks;
  for (double mark : spec.marks) {
    const bool fourThirds = std::abs(mark - 4.0 / 3.0) < 1e-12;
    marks.append({toPosition(mark), fourThirds ? QStringLiteral("4/3") : QString::number(mark)});
  }
  m_slider->setMarks(marks);

  for (QWidget* widget : {static_cast<QWidget*>(m_label), static_cast<QWidget*>(m_slider),
                          static_cast<QWidget*>(m_spin)}) {
    widget->setToolTip(spec.toolTip);
  }
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(m_label);
  layout->addWidget(m_slider, 1);
  layout->addWidget(m_spin);

  connect(m_slider, &QSlider::valueChanged, this, &SliderSpin::sliderMoved);
  connect(m_spin, &QDoubleSpinBox::valueChanged, this, &SliderSpin::spinChanged);
  connect(m_spin, &NumberBox::refused, this, &SliderSpin::refused);
}

double SliderSpin::value() const { return m_spin->value(); }

void SliderSpin::setValue(double value) {
  const QSignalBlocker blockSpin(m_spin);
  const QSignalBlocker blockSlider(m_slider);
  m_spin->setValue(value);
  m_slider->setValue(toPosition(value));
}

void SliderSpin::setSliderRange(double low, double high) {
  if (!(low < high) || (low == m_spec.sliderMin && high == m_spec.sliderMax)) return;
  const double value = m_spin->value();
  m_spec.sliderMin = low;
  m_spec.sliderMax = high;
  setValue(value);
}

int SliderSpin::toPosition(double value) const {
  double fraction = 0;
  if (m_spec.logarithmic) {
    const double low = std::log(std::max(m_spec.sliderMin, 1e-300));
    fraction = (std::log(std::max(value, 1e-300)) - low) / (std::log(m_spec.sliderMax) - low);
  } else {
    fraction = (value - m_spec.sliderMin) / (m_spec.sliderMax - m_spec.sliderMin);
  }
  if (!std::isfinite(fraction)) fraction = 0;
  return int(std::lround(std::clamp(fraction, 0.0, 1.0) * kSteps));
}

double SliderSpin::fromPosition(int position) const {
  const double fraction = double(position) / kSteps;
  double value = m_spec.sliderMin + fraction * (m_spec.sliderMax - m_spec.sliderMin);
  if (m_spec.logarithmic) {
    const double low = std::log(m_spec.sliderMin);
    value = std::exp(low + fraction * (std::log(m_spec.sliderMax) - low));
  }
  // a dragged value is rounded to the parameter's decimals, so that it reads as a short number
  // (0.3025, not 0.30249999999999999) and a session records what the panel shows
  const double scale = std::pow(10.0, m_spec.decimals);
  return std::clamp(std::round(value * scale) / scale, m_spec.spinMin, m_spec.spinMax);
}

void SliderSpin::sliderMoved(int position) {
  {
    const QSignalBlocker block(m_spin);
    m_spin->setValue(fromPosition(position));
  }
  emit valueChanged(m_spin->value());
}

void SliderSpin::spinChanged(double value) {
  {
    const QSignalBlocker block(m_slider);
    m_slider->setValue(toPosition(value));
  }
  emit valueChanged(value);
}

}  // namespace grazelab::ui
