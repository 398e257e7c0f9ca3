// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/eliding_combo_box.h"

#include <QStyleOptionComboBox>
#include <QStylePainter>

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
  // the whole text on hover when it does not fit (the item's own tooltip otherwise)
  if (option.currentText != whole) setToolTip(whole);
  painter.drawControl(QStyle::CE_ComboBoxLabel, option);
}

}  // namespace grazelab::ui
