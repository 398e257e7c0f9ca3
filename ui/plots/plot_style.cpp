// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/plot_style.h"

#include <QLineSeries>
#include <QScatterSeries>

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
  return series;
}

}  // namespace grazelab::ui
