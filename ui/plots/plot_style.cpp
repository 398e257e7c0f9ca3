// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/plot_style.h"

#include <QImage>
#include <QLineSeries>
#include <QPainter>
#include <QScatterSeries>
#include <QVariant>

#include <algorithm>
#include <cmath>

namespace grazelab::ui {

QLineSeries* makeLine(const QString& name, const QColor& color, double width, Qt::PenStyle style) {
  auto* series = new QLineSeries;
  series->setName(name);
  QPen pen(color);
  pen.setWidthF(width);
  pen.setStyle(style);
  series->setPen(pen);
  return series;
}

QScatterSeries* makeScatter(const QString& name, const QColor& color, double size) {
  auto* series = new QScatterSeries;
  series->setName(name);
  series->setColor(color);
  series->setBorderColor(color);
  series->setMarkerShape(QScatterSeries::MarkerShapeCircle);
  series->setMarkerSize(size);
  series->setPen(Qt::NoPen);
  useLightMarker(series);
  return series;
}

void useLightMarker(QScatterSeries* series, const QPen& outline) {
  // drawn at the marker's own size: Qt then blits it without scaling
  const int pixels = std::max(2, int(std::lround(series->markerSize())));
  QImage image(pixels, pixels, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::transparent);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  QPen pen = outline;
  painter.setPen(pen);
  painter.setBrush(series->color());
  const double inset = pen.style() == Qt::NoPen ? 0.0 : 0.5 * pen.widthF();
  const QRectF box(inset, inset, pixels - 2 * inset, pixels - 2 * inset);
  switch (series->markerShape()) {
    case QScatterSeries::MarkerShapeRectangle: painter.drawRect(box); break;
    case QScatterSeries::MarkerShapeTriangle:
      painter.drawPolygon(QPolygonF({QPointF(box.center().x(), box.top()), box.bottomRight(),
                                     box.bottomLeft()}));
      break;
    default: painter.drawEllipse(box); break;
  }
  painter.end();
  series->setLightMarker(image);
  // kept so that a change of size (presentation mode) can draw the marker again
  series->setProperty("grazelabOutline", QVariant::fromValue(outline));
}

QPainterPath springPath(double x0, double x1, double y, double rise, int coils) {
  QPainterPath path(QPointF(x0, y));
  const double lead = 0.12 * (x1 - x0);
  path.lineTo(x0 + lead, y);
  const double step = (x1 - x0 - 2 * lead) / (2 * coils);
  for (int i = 0; i < 2 * coils; ++i) {
    path.lineTo(x0 + lead + (i + 0.5) * step, y + (i % 2 == 0 ? -rise : rise));
  }
  path.lineTo(x1 - lead, y);
  path.lineTo(x1, y);
  return path;
}

}  // namespace grazelab::ui
