// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/widgets/eliding_combo_box.h"

#include <QHelpEvent>
#include <QStyleOptionComboBox>
#include <QStylePainter>
#include <QToolTip>

namespace grazelab::ui {

ElidingComboBox::ElidingComboBox(QWidget* parent) : QComboBox(parent) {}

void ElidingComboBox::paintEvent(QPaintEvent*) {
  QStylePainter painter(this);
  QStyleOptionComboBox option;
  initStyleOption(&option);
  painter.drawComplexControl(QStyle::CC_ComboBox, option);
  const QRect field = style()->subControlRect(QStyle::CC_ComboBox, &option, QStyle::SC_ComboBoxEditField, this);
  const QString whole = option.currentText;
  option.currentText = fontMetrics().elidedText(whole, Qt::ElideRight, field.width());
  m_elided = option.currentText != whole;
  painter.drawControl(QStyle::CE_ComboBoxLabel, option);
}

bool ElidingComboBox::event(QEvent* event) {
  if (event->type() == QEvent::ToolTip && m_elided) {
    // the whole item first, then the box's own explanation (kept: it is not replaced)
    const QString tip = toolTip().isEmpty() ? currentText() : currentText() + QStringLiteral("\n\n") + toolTip();
    QToolTip::showText(static_cast<QHelpEvent*>(event)->globalPos(), tip, this);
    return true;
  }
  return QComboBox::event(event);
}

}  // namespace grazelab::ui
