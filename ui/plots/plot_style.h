// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QColor>
#include <QPen>

class QLineSeries;
class QScatterSeries;

namespace grazelab::ui {

/// Colours used across plots: the Okabe–Ito palette, told apart by the colour-blind and on a
/// projector; markers and dashes are a second code (impacts circles, grazings and sticks
/// triangles, the stop dashed).
namespace colors {
inline const QColor kTrace{0x00, 0x72, 0xB2};      ///< blue
inline const QColor kStop{0x00, 0x00, 0x00};       ///< black, dashed
inline const QColor kImpact{0xD5, 0x5E, 0x00};     ///< vermillion
inline const QColor kGrazing{0xE6, 0x9F, 0x00};    ///< orange
inline const QColor kReference{0x00, 0x00, 0x00};  ///< black
inline const QColor kOverlay{0x00, 0x9E, 0x73};    ///< bluish green: another method's run
inline const QColor kAccent{0xCC, 0x79, 0xA7};     ///< reddish purple
}  // namespace colors

/// A solid line series of the given colour and width.
QLineSeries* makeLine(const QString& name, const QColor& color, double width = 1.5,
                      Qt::PenStyle style = Qt::SolidLine);
/// A round-marker scatter series without outline, drawn with light markers.
QScatterSeries* makeScatter(const QString& name, const QColor& color, double size = 5.0);

/// Viridis at five evenly spaced stops of [0, 0.9] (its palest end is lost on white), for
/// colour scales such as the contact index.
inline const QColor kViridis[5] = {QColor(0x44, 0x01, 0x54), QColor(0x41, 0x44, 0x87),
                                   QColor(0x2a, 0x78, 0x8e), QColor(0x22, 0xa8, 0x84),
                                   QColor(0x7a, 0xd1, 0x51)};

/// Draws the series' markers as one painted image per point (Qt Charts "light markers") from its
/// current shape, colour and size, with the given outline: Qt Charts' default makes one
/// QGraphicsItem per point, whose updates dominated the time from a slider move to the redraw.
/// Call again after changing the shape, colour or size.
void useLightMarker(QScatterSeries* series, const QPen& outline = Qt::NoPen);

}  // namespace grazelab::ui
