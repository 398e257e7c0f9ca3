// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/pictures/colors.h"

namespace grazelab::pictures {

QColor curveColor(int index) {
  // Okabe-Ito, with black first and the yellow (weak on white) last, then a grey
  static const QColor palette[] = {QColor(0x00, 0x00, 0x00), QColor(0xE6, 0x9F, 0x00),
                                   QColor(0x56, 0xB4, 0xE9), QColor(0x00, 0x9E, 0x73),
                                   QColor(0x00, 0x72, 0xB2), QColor(0xD5, 0x5E, 0x00),
                                   QColor(0xCC, 0x79, 0xA7), QColor(0xB8, 0xA8, 0x00),
                                   QColor(0x8C, 0x8C, 0x8C)};
  return palette[index % 9];
}

Qt::PenStyle curveDash(int index) {
  static const Qt::PenStyle dashes[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine,
                                        Qt::DashDotLine, Qt::SolidLine, Qt::DashDotDotLine,
                                        Qt::DashLine, Qt::DotLine, Qt::DashDotLine};
  return dashes[index % 9];
}

}  // namespace grazelab::pictures
