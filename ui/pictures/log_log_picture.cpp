// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/pictures/log_log_picture.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

#include "ui/pictures/colors.h"
#include "ui/pictures/energy_frame.h"

namespace grazelab::pictures {
namespace {

/// At most this many labelled ticks on an axis: a range of many decades ticks every 2, 3, ...
/// decades.
constexpr int kMaxTicks = 7;

/// An axis of whole powers of ten: log10 of its ends and of its ticks.
struct LogAxis {
  double low = 0, high = 1;  ///< log10 of the ends
  std::vector<double> ticks;
};

LogAxis logAxis(double low, double high) {
  // a marker within a tenth of a decade of an end would be cut in half by the frame: the end
  // moves out by a power
  const double from = std::log10(low) - 0.1;
  const double to = std::log10(high) + 0.1;
  const double decades = std::max(1.0, std::ceil(to + 1e-9) - std::floor(from));
  const int step = std::max(1, int(std::ceil(decades / kMaxTicks)));
  LogAxis axis;
  axis.low = std::floor(from / step) * step;
  axis.high = std::max(axis.low + step, std::ceil(to / step - 1e-9) * step);
  for (double power = axis.low; power <= axis.high + 1e-9; power += step) axis.ticks.push_back(power);
  return axis;
}

QString powerLabel(double power) { return QString::asprintf("%.0e", std::pow(10.0, power)); }

}  // namespace

void paintLogLog(QPainter& painter, const QRectF& area, const std::vector<LogLogCurve>& curves,
                 const QString& title, const QString& xTitle, const QString& yTitle) {
  painter.save();
  painter.fillRect(area, Qt::white);
  const QFontMetricsF metrics(painter.font());
  const double line = metrics.height();

  // the data's extent, every y floored
  double xLo = INFINITY, xHi = -INFINITY, yLo = INFINITY, yHi = -INFINITY;
  for (const LogLogCurve& curve : curves) {
    for (const QPointF& p : curve.points) {
      if (!(p.x() > 0) || !std::isfinite(p.x()) || !std::isfinite(p.y())) continue;
      const double y = std::max(p.y(), kLogLogFloor);
      xLo = std::min(xLo, p.x()), xHi = std::max(xHi, p.x());
      yLo = std::min(yLo, y), yHi = std::max(yHi, y);
    }
  }
  if (!(xLo <= xHi)) xLo = 1e-3, xHi = 1, yLo = 1e-6, yHi = 1;
  const LogAxis x = logAxis(xLo, xHi);
  const LogAxis y = logAxis(yLo, yHi);

  // the legend under the plot: entries on as many lines as they need
  const double sample = 2.4 * line;  // a stretch of the curve's line with its marker
  const double gap = 1.2 * line;
  std::vector<double> entryWidth;  // the line's stretch, a space, the name
  for (const LogLogCurve& curve : curves) entryWidth.push_back(sample + 0.4 * line + metrics.horizontalAdvance(curve.name));
  std::vector<std::vector<int>> rows(1);
  double used = 0;
  const double legendWidth = area.width() - 2 * line;
  for (int index = 0; index < int(curves.size()); ++index) {
    const double width = entryWidth[std::size_t(index)];
    if (!rows.back().empty() && used + gap + width > legendWidth) {
      rows.emplace_back();
      used = 0;
    }
    used += (rows.back().empty() ? 0 : gap) + width;
    rows.back().push_back(index);
  }
  const double legendHeight = curves.empty() ? 0 : double(rows.size()) * 1.3 * line + 0.6 * line;
  const double labelWidth = metrics.horizontalAdvance(QStringLiteral("1e-15"));
  const QRectF plot = area.adjusted(labelWidth + 2.6 * line, 2.5 * line, -1.5 * line,
                                    -(3.4 * line + legendHeight));
  const auto at = [&](double px, double py) {
    return QPointF(plot.left() + (std::log10(px) - x.low) / (x.high - x.low) * plot.width(),
                   plot.bottom() - (std::log10(std::max(py, kLogLogFloor)) - y.low) / (y.high - y.low) * plot.height());
  };

  paintPictureTitle(painter, area, title, line);
  // grid, frame, ticks and their labels
  painter.setPen(QPen(QColor(0xdd, 0xdd, 0xdd), 1));
  for (double power : x.ticks) {
    const double px = at(std::pow(10.0, power), 1).x();
    painter.drawLine(QPointF(px, plot.top()), QPointF(px, plot.bottom()));
  }
  for (double power : y.ticks) {
    const double py = at(1, std::pow(10.0, power)).y();
    painter.drawLine(QPointF(plot.left(), py), QPointF(plot.right(), py));
  }
  painter.setPen(QPen(Qt::black, 1));
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(plot);
  const double tick = 0.4 * line;
  for (double power : x.ticks) {
    const double px = at(std::pow(10.0, power), 1).x();
    painter.drawLine(QPointF(px, plot.bottom()), QPointF(px, plot.bottom() + tick));
    painter.drawText(QRectF(px - 3 * line, plot.bottom() + tick, 6 * line, line), Qt::AlignCenter, powerLabel(power));
  }
  for (double power : y.ticks) {
    const double py = at(1, std::pow(10.0, power)).y();
    painter.drawLine(QPointF(plot.left() - tick, py), QPointF(plot.left(), py));
    painter.drawText(QRectF(plot.left() - tick - labelWidth - 0.6 * line, py - line / 2, labelWidth + 0.3 * line, line),
                     Qt::AlignRight | Qt::AlignVCenter, powerLabel(power));
  }
  const QFont plain = painter.font();
  QFont bold = plain;
  bold.setBold(true);
  painter.setFont(bold);
  painter.drawText(QRectF(plot.left(), plot.bottom() + tick + 1.1 * line, plot.width(), 1.4 * line),
                   Qt::AlignCenter, xTitle);
  painter.save();
  painter.translate(area.left() + 0.9 * line, plot.center().y());
  painter.rotate(-90);
  painter.drawText(QRectF(-plot.height() / 2, -0.8 * line, plot.height(), 1.6 * line), Qt::AlignCenter, yTitle);
  painter.restore();
  painter.setFont(plain);

  // the curves: lines with their dashes, round markers (every point lies inside the frame:
  // the axes end beyond the data)
  painter.setRenderHint(QPainter::Antialiasing, true);
  const auto penOf = [](int index) {
    QPen pen(curveColor(index), 2.0);
    pen.setStyle(curveDash(index));
    return pen;
  };
  for (int index = 0; index < int(curves.size()); ++index) {
    QPainterPath path;
    std::vector<QPointF> points;
    for (const QPointF& p : curves[std::size_t(index)].points) {
      if (p.x() > 0 && std::isfinite(p.x()) && std::isfinite(p.y())) points.push_back(at(p.x(), p.y()));
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (i == 0) path.moveTo(points[i]);
      else path.lineTo(points[i]);
    }
    painter.setPen(penOf(index));
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(path);
    painter.setPen(Qt::NoPen);
    painter.setBrush(curveColor(index));
    for (const QPointF& p : points) painter.drawEllipse(p, 3.5, 3.5);
  }

  // the legend, each line centred
  double rowY = area.bottom() - legendHeight;
  for (const std::vector<int>& row : rows) {
    double width = 0;
    for (int index : row) width += (width > 0 ? gap : 0) + entryWidth[std::size_t(index)];
    double left = area.center().x() - width / 2;
    const double middle = rowY + 0.65 * line;
    for (int index : row) {
      painter.setPen(penOf(index));
      painter.drawLine(QPointF(left, middle), QPointF(left + sample, middle));
      painter.setPen(Qt::NoPen);
      painter.setBrush(curveColor(index));
      painter.drawEllipse(QPointF(left + sample / 2, middle), 3.5, 3.5);
      painter.setPen(Qt::black);
      const QString& name = curves[std::size_t(index)].name;
      painter.drawText(QRectF(left + sample + 0.4 * line, rowY, metrics.horizontalAdvance(name) + 1, 1.3 * line),
                       Qt::AlignLeft | Qt::AlignVCenter, name);
      left += entryWidth[std::size_t(index)] + gap;
    }
    rowY += 1.3 * line;
  }
  painter.restore();
}

}  // namespace grazelab::pictures
