// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QColor>
#include <QPen>

class QLineSeries;
class QScatterSeries;

namespace grazelab::ui {

/// Colours used across plots, chosen to stay apart on a projector and in grey print.
namespace colors {
inline const QColor kTrace{0x1f, 0x4e, 0x9a};
inline const QColor kStop{0x60, 0x60, 0x60};
inline const QColor kImpact{0xc0, 0x1c, 0x28};
inline const QColor kGrazing{0xe6, 0x61, 0x00};
inline const QColor kReference{0x00, 0x00, 0x00};
inline const QColor kOverlay{0x00, 0x9E, 0x73};  ///< another method's run over the exact one
}  // namespace colors

/// A solid line series of the given colour and width.
QLineSeries* makeLine(const QString& name, const QColor& color, double width = 1.5,
                      Qt::PenStyle style = Qt::SolidLine);
/// A round-marker scatter series without outline, drawn with light markers.
QScatterSeries* makeScatter(const QString& name, const QColor& color, double size = 5.0);

/// Draws the series' markers as one painted image per point (Qt Charts "light markers") from its
/// current shape, colour and size, with the given outline: Qt Charts' default makes one
/// QGraphicsItem per point, whose updates dominated the time from a slider move to the redraw.
/// Call again after changing the shape, colour or size.
void useLightMarker(QScatterSeries* series, const QPen& outline = Qt::NoPen);

}  // namespace grazelab::ui
