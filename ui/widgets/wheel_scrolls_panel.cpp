// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/widgets/wheel_scrolls_panel.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QScrollArea>
#include <QScrollBar>

namespace grazelab::ui {
namespace {

bool takesValuesFromTheWheel(const QWidget* widget) {
  return qobject_cast<const QAbstractSpinBox*>(widget) || qobject_cast<const QComboBox*>(widget) ||
         (qobject_cast<const QAbstractSlider*>(widget) && !qobject_cast<const QScrollBar*>(widget));
}

}  // namespace

WheelScrollsPanel::WheelScrollsPanel(QScrollArea* area) : QObject(area), m_area(area) {}

bool WheelScrollsPanel::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() != QEvent::Wheel && event->type() != QEvent::Polish) return false;
  auto* widget = qobject_cast<QWidget*>(watched);
  if (!m_area || !widget || !takesValuesFromTheWheel(widget) || !m_area->isAncestorOf(widget)) return false;
  if (event->type() == QEvent::Polish) {
    // not focused by the wheel itself (Qt's default for spin boxes and lists), only by a click
    // or the Tab key
    widget->setFocusPolicy(Qt::StrongFocus);
    return false;
  }
  // a focused number steps; a list never turns under the wheel (a flick over the resonance box
  // chose another resonance and computed everything again), it opens with a click or the keys
  if (widget->hasFocus() && !qobject_cast<QComboBox*>(widget)) return false;
  QCoreApplication::sendEvent(m_area->verticalScrollBar(), event);
  return true;
}

}  // namespace grazelab::ui
