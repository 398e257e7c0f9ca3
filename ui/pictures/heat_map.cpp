// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/pictures/heat_map.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace grazelab::pictures {
namespace {

// matplotlib's viridis at t = 0, 1/8, ..., 1
const QColor kViridisStops[9] = {
    QColor(0x44, 0x01, 0x54), QColor(0x47, 0x2d, 0x7b), QColor(0x3b, 0x52, 0x8b),
    QColor(0x2c, 0x72, 0x8e), QColor(0x21, 0x91, 0x8c), QColor(0x28, 0xae, 0x80),
    QColor(0x5e, 0xc9, 0x62), QColor(0xad, 0xdc, 0x30), QColor(0xfd, 0xe7, 0x25)};
const QColor kNanColor(0xb0, 0xb0, 0xb0);
const QColor kInfColor(Qt::white);

const QColor kPendingColor(0xee, 0xee, 0xee);

QString tickLabel(double value) {
  if (value == 0) return "0";
  return QString::number(value, 'g', 6);
}

}  // namespace

std::pair<double, double> cellExtent(double from, double to, std::int64_t count) {
  const double half = count > 1 ? 0.5 * (to - from) / double(count - 1) : 0.5;
  return {from - half, to + half};
}

QColor viridis(double t) {
  if (!(t > 0)) return kViridisStops[0];
  if (t >= 1) return kViridisStops[8];
  const double scaled = t * 8;
  const int i = std::min(7, int(scaled));
  const double f = scaled - i;
  const QColor& a = kViridisStops[i];
  const QColor& b = kViridisStops[i + 1];
  return QColor(int(std::lround(a.red() + f * (b.red() - a.red()))),
                int(std::lround(a.green() + f * (b.green() - a.green()))),
                int(std::lround(a.blue() + f * (b.blue() - a.blue()))));
}

std::pair<double, double> finiteRange(const std::vector<double>& values) {
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values) {
    if (std::isfinite(v)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (!(lo <= hi)) return {0, 1};
  if (lo == hi) return {lo - 0.5, hi + 0.5};
  return {lo, hi};
}

QImage heatMapImage(const HeatMapData& data) {
  QImage image(int(data.columns), int(data.rows), QImage::Format_RGB32);
  const std::int64_t ready = data.rowsReady < 0 ? data.rows : std::min(data.rowsReady, data.rows);
  const auto [lo, hi] = finiteRange(std::vector<double>(data.values.begin(),
                                                        data.values.begin() + ready * data.columns));
  for (std::int64_t r = 0; r < data.rows; ++r) {
    auto* line = reinterpret_cast<QRgb*>(image.scanLine(int(data.rows - 1 - r)));
    if (r >= ready) {
      std::fill(line, line + data.columns, kPendingColor.rgb());
      continue;
    }
    for (std::int64_t c = 0; c < data.columns; ++c) {
      const double v = data.values[std::size_t(r * data.columns + c)];
      const QColor color = std::isnan(v) ? kNanColor : std::isinf(v) ? kInfColor : viridis((v - lo) / (hi - lo));
      line[c] = color.rgb();
    }
  }
  return image;
}

std::vector<double> niceTicks(double from, double to, int target) {
  std::vector<double> ticks;
  const double lo = std::min(from, to), hi = std::max(from, to);
  if (!(hi > lo) || !std::isfinite(hi - lo)) return {lo};
  const double raw = (hi - lo) / target;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * power;
    if (step >= raw) break;
  }
  // a span of a few ulps has a step below an ulp of the values: t += step would not move
  for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step && ticks.size() < 64; t += step) {
    if (!ticks.empty() && t == ticks.back()) break;
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  }
  return ticks;
}

namespace {

/// The widest of the labels of `ticks`.
double widestLabel(const QFontMetricsF& metrics, const std::vector<double>& ticks) {
  double widest = 0;
  for (double t : ticks) widest = std::max(widest, metrics.horizontalAdvance(tickLabel(t)));
  return widest;
}

/// The colour bar's range: the finite values of the rows computed so far.
std::pair<double, double> readyRange(const HeatMapData& data) {
  const std::int64_t ready = data.rowsReady < 0 ? data.rows : std::min(data.rowsReady, data.rows);
  return finiteRange(std::vector<double>(data.values.begin(), data.values.begin() + ready * data.columns));
}

/// As many x ticks as fit under a map `width` wide without their labels touching.
std::vector<double> xTicks(const QFontMetricsF& metrics, double x0, double x1, double width) {
  for (int target = 6; target > 1; --target) {
    const std::vector<double> ticks = niceTicks(x0, x1, target);
    const double room = width / double(std::max<std::size_t>(1, ticks.size()));
    if (widestLabel(metrics, ticks) + metrics.height() <= room) return ticks;
  }
  return {x0, x1};
}

}  // namespace

QRectF heatMapPlotArea(const QRectF& area, const QFont& font, const HeatMapData& data) {
  // margins from the labels drawn in them: fixed margins for the longest possible label left
  // a map a few pixels wide on a small window with large text
  const QFontMetricsF metrics(font);
  const double line = metrics.height();
  const double tick = 0.4 * line;
  const auto [y0, y1] = cellExtent(data.yFrom, data.yTo, data.rows);
  const auto [lo, hi] = readyRange(data);
  const double left = 2.0 * line + widestLabel(metrics, niceTicks(y0, y1)) + tick + 0.3 * line;
  const double keys = std::max(metrics.horizontalAdvance(QStringLiteral("not defined")),
                               widestLabel(metrics, niceTicks(lo, hi, 5)));
  const double right = 2.7 * line + 1.5 * tick + keys + 0.4 * line + 1.8 * line;
  const double top = 2.2 * line;
  const double bottom = 3.5 * line;
  return area.adjusted(left, top, -right, -bottom);
}

void paintHeatMap(QPainter& painter, const QRectF& area, const HeatMapData& data,
                  const QImage* image) {
  painter.save();
  const QFont font = painter.font();
  const QFontMetricsF metrics(font);
  const double line = metrics.height();
  const QRectF plot = heatMapPlotArea(area, font, data);
  painter.fillRect(area, Qt::white);
  painter.setPen(Qt::black);

  QFont titleFont = font;
  titleFont.setBold(true);
  painter.setFont(titleFont);
  // across the whole width (the colour bar's title stands along its side), cut only if even
  // that is too short
  const QFontMetricsF boldMetrics(titleFont);
  const QString title = boldMetrics.elidedText(data.title, Qt::ElideRight, area.width());
  painter.drawText(QRectF(area.left(), area.top(), area.width(), 2 * line), Qt::AlignCenter, title);
  painter.setFont(font);

  // the cells, without smoothing: each is one value
  painter.setRenderHint(QPainter::SmoothPixmapTransform, false);
  painter.drawImage(plot, image ? *image : heatMapImage(data));
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setPen(QPen(Qt::black, 1));
  painter.drawRect(plot);

  const auto [x0, x1] = cellExtent(data.xFrom, data.xTo, data.columns);
  const auto [y0, y1] = cellExtent(data.yFrom, data.yTo, data.rows);
  const double tick = 0.4 * line;
  for (double t : xTicks(metrics, x0, x1, plot.width())) {
    const double px = plot.left() + (t - x0) / (x1 - x0) * plot.width();
    painter.drawLine(QPointF(px, plot.bottom()), QPointF(px, plot.bottom() + tick));
    painter.drawText(QRectF(px - 4 * line, plot.bottom() + tick, 8 * line, line), Qt::AlignCenter, tickLabel(t));
  }
  for (double t : niceTicks(y0, y1)) {
    const double py = plot.bottom() - (t - y0) / (y1 - y0) * plot.height();
    painter.drawLine(QPointF(plot.left() - tick, py), QPointF(plot.left(), py));
    painter.drawText(QRectF(plot.left() - tick - 8 * line, py - line / 2, 8 * line - 0.3 * line, line),
                     Qt::AlignRight | Qt::AlignVCenter, tickLabel(t));
  }
  // centred under the map, as wide as the whole area allows
  const double xTitleWidth = std::min(area.width(), metrics.horizontalAdvance(data.xTitle) + line);
  const double xTitleLeft = std::clamp(plot.center().x() - xTitleWidth / 2, area.left(), area.right() - xTitleWidth);
  painter.drawText(QRectF(xTitleLeft, plot.bottom() + tick + 1.2 * line, xTitleWidth, 1.5 * line), Qt::AlignCenter,
                   metrics.elidedText(data.xTitle, Qt::ElideRight, area.width()));
  painter.save();
  painter.translate(area.left() + 0.8 * line, plot.center().y());
  painter.rotate(-90);
  painter.drawText(QRectF(-plot.height() / 2, -0.8 * line, plot.height(), 1.6 * line), Qt::AlignCenter, data.yTitle);
  painter.restore();

  // the colour bar: the finite range, then keys for NaN and inf cells when there are any
  const std::int64_t ready = data.rowsReady < 0 ? data.rows : std::min(data.rowsReady, data.rows);
  const std::vector<double> readyValues(data.values.begin(), data.values.begin() + ready * data.columns);
  const auto [lo, hi] = finiteRange(readyValues);
  const QRectF bar(plot.right() + 1.5 * line, plot.top(), 1.2 * line, plot.height() * 0.75);
  QLinearGradient gradient(bar.bottomLeft(), bar.topLeft());
  for (int i = 0; i <= 8; ++i) gradient.setColorAt(i / 8.0, kViridisStops[i]);
  painter.fillRect(bar, gradient);
  painter.drawRect(bar);
  for (double t : niceTicks(lo, hi, 5)) {
    const double py = bar.bottom() - (t - lo) / (hi - lo) * bar.height();
    painter.drawLine(QPointF(bar.right(), py), QPointF(bar.right() + tick, py));
    painter.drawText(QRectF(bar.right() + 1.5 * tick, py - line / 2, 6 * line, line),
                     Qt::AlignLeft | Qt::AlignVCenter, tickLabel(t));
  }
  // the colour bar's title along its right side, turned like the y axis title: above the bar
  // it ran into the map's title and past the window's edge
  painter.save();
  painter.translate(area.right() - 0.9 * line, area.center().y());
  painter.rotate(-90);
  const QString valueTitle = metrics.elidedText(data.valueTitle, Qt::ElideRight, area.height() - line);
  painter.drawText(QRectF(-area.height() / 2, -0.8 * line, area.height(), 1.6 * line), Qt::AlignCenter,
                   valueTitle);
  painter.restore();
  double keyY = bar.bottom() + 0.8 * line;
  const bool anyNan = std::any_of(readyValues.begin(), readyValues.end(), [](double v) { return std::isnan(v); });
  const bool anyInf = std::any_of(readyValues.begin(), readyValues.end(), [](double v) { return std::isinf(v); });
  for (const auto& [present, color, label] :
       {std::tuple{anyNan, kNanColor, QString("not defined")}, std::tuple{anyInf, kInfColor, QString("infinite")}}) {
    if (!present) continue;
    const QRectF swatch(bar.left(), keyY, bar.width(), line);
    painter.fillRect(swatch, color);
    painter.drawRect(swatch);
    painter.drawText(QRectF(bar.right() + 1.5 * tick, keyY, 6 * line, line), Qt::AlignLeft | Qt::AlignVCenter, label);
    keyY += 1.4 * line;
  }
  painter.restore();
}

}  // namespace grazelab::pictures
