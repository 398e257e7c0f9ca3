// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QColor>
#include <QPainterPath>
#include <QPen>

#include "ui/pictures/colors.h"

class QLineSeries;
class QScatterSeries;

namespace grazelab::ui {

namespace colors = pictures::colors;
using pictures::kViridis;

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

/// A spring drawn from x0 to x1 at height y (the animated chains): straight ends and `coils`
/// zigzags of half-height `rise`.
QPainterPath springPath(double x0, double x1, double y, double rise, int coils);

}  // namespace grazelab::ui
