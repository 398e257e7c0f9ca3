// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QProxyStyle>

namespace grazelab::ui {

/// The application's style with its controls scaled like presentation mode's text: check
/// boxes, slider handles, spin-box arrows and tool-button icons stayed desk-sized next to text
/// twice as large, and were hard to hit and to see on a projector.
class PresentationStyle : public QProxyStyle {
  Q_OBJECT

 public:
  /// `base` is owned from now on; `scale` > 1 enlarges. Installed once, as the application's
  /// style (installPresentationStyle), and rescaled in place.
  PresentationStyle(QStyle* base, double scale);

  double scale() const { return m_scale; }
  /// Takes effect as widgets lay out again (presentation mode changes the font right after).
  void setScale(double scale) { m_scale = scale; }
  int pixelMetric(PixelMetric metric, const QStyleOption* option = nullptr,
                  const QWidget* widget = nullptr) const override;
  /// Spin boxes' arrows as wide as the text is large (the base style draws them a fixed 14 px).
  QRect subControlRect(ComplexControl control, const QStyleOptionComplex* option, SubControl sub,
                       const QWidget* widget = nullptr) const override;
  QSize sizeFromContents(ContentsType type, const QStyleOption* option, const QSize& size,
                         const QWidget* widget = nullptr) const override;

 private:
  int spinArrowsExtra(const QStyleOptionComplex* option, const QWidget* widget) const;
  double m_scale = 1;
};

/// Makes the application's style a PresentationStyle (at scale 1) unless it is one already.
/// Call before any widget exists: widgets with style sheets keep a hold on the style they met.
void installPresentationStyle();

}  // namespace grazelab::ui
