// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/window/presentation_style.h"

#include <QApplication>
#include <QStyleFactory>
#include <QStyleOptionComplex>

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

// how much wider a spin box's arrows are drawn than the base style draws them (0 at the desk)
int PresentationStyle::spinArrowsExtra(const QStyleOptionComplex* option, const QWidget* widget) const {
  if (!(m_scale > 1) || !option) return 0;
  const QRect up = QProxyStyle::subControlRect(CC_SpinBox, option, SC_SpinBoxUp, widget);
  return up.isValid() ? int(std::lround(up.width() * (m_scale - 1))) : 0;
}

QRect PresentationStyle::subControlRect(ComplexControl control, const QStyleOptionComplex* option, SubControl sub,
                                        const QWidget* widget) const {
  const QRect rect = QProxyStyle::subControlRect(control, option, sub, widget);
  if (control != CC_SpinBox) return rect;
  const int extra = spinArrowsExtra(option, widget);
  switch (sub) {
    case SC_SpinBoxUp:
    case SC_SpinBoxDown: return rect.adjusted(-extra, 0, 0, 0);
    case SC_SpinBoxEditField: return rect.adjusted(0, 0, -extra, 0);
    default: return rect;
  }
}

QSize PresentationStyle::sizeFromContents(ContentsType type, const QStyleOption* option, const QSize& size,
                                          const QWidget* widget) const {
  QSize contents = QProxyStyle::sizeFromContents(type, option, size, widget);
  if (type == CT_SpinBox) {
    contents.rwidth() += spinArrowsExtra(qstyleoption_cast<const QStyleOptionComplex*>(option), widget);
  }
  return contents;
}

void installPresentationStyle() {
  if (qobject_cast<PresentationStyle*>(QApplication::style())) return;
  QApplication::setStyle(new PresentationStyle(QStyleFactory::create(QApplication::style()->name()), 1.0));
}

}  // namespace grazelab::ui
