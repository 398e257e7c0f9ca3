// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QColor>
#include <Qt>

namespace grazelab::pictures {

/// Colours used across plots and pictures: the Okabe–Ito palette, told apart by the
/// colour-blind and on a projector; markers and dashes are a second code (impacts circles,
/// grazings and sticks triangles, the stop dashed).
namespace colors {
inline const QColor kTrace{0x00, 0x72, 0xB2};      ///< blue
inline const QColor kStop{0x00, 0x00, 0x00};       ///< black, dashed
inline const QColor kImpact{0xD5, 0x5E, 0x00};     ///< vermillion
inline const QColor kGrazing{0xE6, 0x9F, 0x00};    ///< orange
inline const QColor kReference{0x00, 0x00, 0x00};  ///< black
inline const QColor kOverlay{0x00, 0x9E, 0x73};    ///< bluish green: another method's run
inline const QColor kAccent{0xCC, 0x79, 0xA7};     ///< reddish purple
}  // namespace colors

/// Viridis at five evenly spaced stops of [0, 0.9] (its palest end is lost on white), for
/// colour scales such as the contact index.
inline const QColor kViridis[5] = {QColor(0x44, 0x01, 0x54), QColor(0x41, 0x44, 0x87),
                                   QColor(0x2a, 0x78, 0x8e), QColor(0x22, 0xa8, 0x84),
                                   QColor(0x7a, 0xd1, 0x51)};

/// The colour and dash pattern of curve `index` of a log-log chart (one per method):
/// Okabe-Ito, black first and the yellow (weak on white) last, then a grey; the dash a second
/// code.
QColor curveColor(int index);
Qt::PenStyle curveDash(int index);

}  // namespace grazelab::pictures
