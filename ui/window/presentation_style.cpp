// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/window/presentation_style.h"

#include <QApplication>
#include <QStyleFactory>

#include <cmath>

namespace grazelab::ui {

PresentationStyle::PresentationStyle(QStyle* base, double scale) : QProxyStyle(base), m_scale(scale) {}

int PresentationStyle::pixelMetric(PixelMetric metric, const QStyleOption* option,
                                   const QWidget* widget) const {
  const int size = QProxyStyle::pixelMetric(metric, option, widget);
  switch (metric) {
    case PM_IndicatorWidth:
    case PM_IndicatorHeight:
    case PM_ExclusiveIndicatorWidth:
    case PM_ExclusiveIndicatorHeight:
    case PM_SliderThickness:
    case PM_SliderLength:
    case PM_SliderControlThickness:
    case PM_ButtonIconSize:
    case PM_SmallIconSize:
    case PM_ToolBarIconSize:
      return int(std::lround(size * m_scale));
    default:
      return size;
  }
}

void installPresentationStyle() {
  if (qobject_cast<PresentationStyle*>(QApplication::style())) return;
  QApplication::setStyle(new PresentationStyle(QStyleFactory::create(QApplication::style()->name()), 1.0));
}

}  // namespace grazelab::ui
