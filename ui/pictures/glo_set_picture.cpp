// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/pictures/glo_set_picture.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>

#include <algorithm>
#include <functional>

#include "ui/pictures/colors.h"
#include "ui/pictures/energy_frame.h"
#include "ui/pictures/heat_map.h"

namespace grazelab::pictures {

namespace {

// a plot with linear axes over [xLo, xHi] x [yLo, yHi]
struct LinearFrame {
  QRectF plot;
  double xLo, xHi, yLo, yHi;
  QPointF at(double x, double y) const {
    return {plot.left() + (x - xLo) / (xHi - xLo) * plot.width(),
            plot.bottom() - (y - yLo) / (yHi - yLo) * plot.height()};
  }
};

void paintGrid(QPainter& painter, const LinearFrame& frame) {
  painter.setPen(QPen(QColor(0xdd, 0xdd, 0xdd), 1));
  for (double x : niceTicks(frame.xLo, frame.xHi, 8)) {
    painter.drawLine(frame.at(x, frame.yLo), frame.at(x, frame.yHi));
  }
  for (double y : niceTicks(frame.yLo, frame.yHi, 6)) {
    painter.drawLine(frame.at(frame.xLo, y), frame.at(frame.xHi, y));
  }
}

void paintAxes(QPainter& painter, const LinearFrame& frame, const QRectF& area, double line,
               const QString& xTitle, const QString& yTitle) {
  const QRectF& plot = frame.plot;
  painter.setRenderHint(QPainter::Antialiasing, false);
  painter.setClipping(false);
  painter.setBrush(Qt::NoBrush);
  painter.setPen(QPen(Qt::black, 1));
  painter.drawRect(plot);
  const double tick = 0.4 * line;
  for (double x : niceTicks(frame.xLo, frame.xHi, 8)) {
    const double px = frame.at(x, frame.yLo).x();
    painter.drawLine(QPointF(px, plot.bottom()), QPointF(px, plot.bottom() + tick));
    painter.drawText(QRectF(px - 3 * line, plot.bottom() + tick, 6 * line, line), Qt::AlignCenter,
                     QString::number(x, 'g', 4));
  }
  for (double y : niceTicks(frame.yLo, frame.yHi, 6)) {
    const double py = frame.at(frame.xLo, y).y();
    painter.drawLine(QPointF(plot.left() - tick, py), QPointF(plot.left(), py));
    painter.drawText(QRectF(plot.left() - tick - 5 * line, py - line / 2, 5 * line - 0.3 * line, line),
                     Qt::AlignRight | Qt::AlignVCenter, QString::number(y, 'g', 4));
  }
  painter.drawText(QRectF(plot.left(), plot.bottom() + tick + 1.1 * line, plot.width(), 1.4 * line),
                   Qt::AlignCenter, xTitle);
  painter.save();
  // beside the tick labels (a plot narrowed to equal scales sits away from the area's edge)
  painter.translate(std::max(area.left() + 0.9 * line, plot.left() - 4.1 * line), plot.center().y());
  painter.rotate(-90);
  painter.drawText(QRectF(-plot.height() / 2, -0.8 * line, plot.height(), 1.6 * line), Qt::AlignCenter, yTitle);
  painter.restore();
}

// one line of key under the plot: each entry a swatch drawn by `swatch` and its words
void paintKey(QPainter& painter, const QRectF& row, const std::vector<QString>& words,
              const std::vector<std::function<void(const QRectF&)>>& swatches) {
  const QFontMetricsF metrics(painter.font());
  double width = 0;
  for (const QString& text : words) width += 2.2 * metrics.height() + metrics.horizontalAdvance(text) + metrics.height();
  double x = row.center().x() - width / 2;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const QRectF box(x, row.top() + 0.2 * row.height(), 1.8 * metrics.height(), 0.6 * row.height());
    swatches[i](box);
    x += 2.2 * metrics.height();
    painter.setPen(Qt::black);
    painter.drawText(QRectF(x, row.top(), metrics.horizontalAdvance(words[i]) + 2, row.height()),
                     Qt::AlignVCenter | Qt::AlignLeft, words[i]);
    x += metrics.horizontalAdvance(words[i]) + metrics.height();
  }
}

const QColor kShade(0x00, 0x9E, 0x73, 60);  // the grazing set: bluish green, light

}  // namespace

void paintGrazingInterval(QPainter& painter, const QRectF& area, const std::vector<QPointF>& curve,
                          double low, double high, const QString& title, const QString& modes) {
  painter.save();
  const double line = QFontMetricsF(painter.font()).height();
  painter.fillRect(area, Qt::white);
  const QRectF plot = area.adjusted(5 * line, 2.5 * line, -1.5 * line, -6 * line);
  double xLo = curve.empty() ? 0 : curve.front().x(), xHi = curve.empty() ? 1 : curve.back().x();
  double yHi = 1.0;
  for (const QPointF& p : curve) yHi = std::max(yHi, p.y());
  const double yLo = 1.0 - 0.12 * (yHi - 1.0) - 0.05;
  yHi += 0.05 * (yHi - yLo);
  if (!(xHi > xLo)) xHi = xLo + 1;
  const LinearFrame frame{plot, xLo, xHi, yLo, yHi};
  paintPictureTitle(painter, area, title, line);
  paintGrid(painter, frame);
  painter.setRenderHint(QPainter::Antialiasing, true);
  // the set: a band over [low, high]
  painter.fillRect(QRectF(frame.at(low, yHi), frame.at(high, yLo)).normalized(), kShade);
  painter.setPen(QPen(colors::kStop, 1.5, Qt::DashLine));
  painter.drawLine(frame.at(xLo, 1.0), frame.at(xHi, 1.0));
  QPainterPath path;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    const QPointF q = frame.at(curve[i].x(), curve[i].y());
    if (i == 0) path.moveTo(q);
    else path.lineTo(q);
  }
  painter.setPen(QPen(colors::kTrace, 2.5));
  painter.drawPath(path);
  // the ends, marked and labelled on the line top = 1
  painter.setBrush(colors::kImpact);
  painter.setPen(Qt::NoPen);
  for (double end : {low, high}) painter.drawEllipse(frame.at(end, 1.0), 5, 5);
  painter.setPen(Qt::black);
  for (double end : {low, high}) {
    const QPointF q = frame.at(end, 1.0);
    painter.drawText(QRectF(q.x() - 4 * line, q.y() + 0.4 * line, 8 * line, line), Qt::AlignCenter,
                     QStringLiteral("λ = %1").arg(end, 0, 'g', 6));
  }
  paintAxes(painter, frame, area, line, QStringLiteral("λ in %1").arg(modes),
            QStringLiteral("max over a period of uₛ / d"));
  painter.setRenderHint(QPainter::Antialiasing, true);
  paintKey(painter, QRectF(area.left(), plot.bottom() + 3.6 * line, area.width(), 1.4 * line),
           {QStringLiteral("top of GLO(λ)"), QStringLiteral("uₛ = d"),
            QStringLiteral("grazing set [%1, %2]").arg(low, 0, 'g', 6).arg(high, 0, 'g', 6)},
           {[&](const QRectF& box) {
              painter.setPen(QPen(colors::kTrace, 2.5));
              painter.drawLine(QPointF(box.left(), box.center().y()), QPointF(box.right(), box.center().y()));
            },
            [&](const QRectF& box) {
              painter.setPen(QPen(colors::kStop, 1.5, Qt::DashLine));
              painter.drawLine(QPointF(box.left(), box.center().y()), QPointF(box.right(), box.center().y()));
            },
            [&](const QRectF& box) { painter.fillRect(box, kShade); }});
  painter.restore();
}

void paintGrazingRegion(QPainter& painter, const QRectF& area, const std::vector<QPointF>& boundary,
                        const QString& title) {
  painter.save();
  const double line = QFontMetricsF(painter.font()).height();
  painter.fillRect(area, Qt::white);
  QRectF plot = area.adjusted(5 * line, 2.5 * line, -1.5 * line, -6 * line);
  // the window: the region and the simplex, with equal scales on both axes
  double xLo = 0, xHi = 1, yLo = 0, yHi = 1;
  for (const QPointF& p : boundary) {
    xLo = std::min(xLo, p.x()), xHi = std::max(xHi, p.x());
    yLo = std::min(yLo, p.y()), yHi = std::max(yHi, p.y());
  }
  const double pad = 0.08 * std::max(xHi - xLo, yHi - yLo);
  xLo -= pad, xHi += pad, yLo -= pad, yHi += pad;
  const double scale = std::min(plot.width() / (xHi - xLo), plot.height() / (yHi - yLo));
  const QSizeF used((xHi - xLo) * scale, (yHi - yLo) * scale);
  plot = QRectF(QPointF(plot.center().x() - used.width() / 2, plot.top()), used);
  const LinearFrame frame{plot, xLo, xHi, yLo, yHi};
  paintPictureTitle(painter, area, title, line);
  paintGrid(painter, frame);
  painter.setRenderHint(QPainter::Antialiasing, true);
  QPolygonF region;
  for (const QPointF& p : boundary) region << frame.at(p.x(), p.y());
  painter.setPen(QPen(colors::kTrace, 2));
  painter.setBrush(kShade);
  painter.drawPolygon(region);
  painter.setBrush(Qt::NoBrush);
  painter.setPen(QPen(colors::kStop, 1.5, Qt::DashLine));
  painter.drawPolygon(QPolygonF({frame.at(0, 0), frame.at(1, 0), frame.at(0, 1)}));
  const QPointF corners[3] = {{0, 0}, {1, 0}, {0, 1}};
  const char* names[3] = {"GLOM₁", "GLOM₂", "GLOM₃"};
  for (int i = 0; i < 3; ++i) {
    const QPointF q = frame.at(corners[i].x(), corners[i].y());
    painter.setPen(Qt::NoPen);
    painter.setBrush(colors::kImpact);
    painter.drawEllipse(q, 5, 5);
    painter.setPen(Qt::black);
    painter.drawText(QRectF(q.x() + 0.3 * line, q.y() - 1.3 * line, 5 * line, line), Qt::AlignLeft,
                     QString::fromUtf8(names[i]));
  }
  paintAxes(painter, frame, area, line, QStringLiteral("λ₂ (weight of GLOM₂)"),
            QStringLiteral("λ₃ (weight of GLOM₃)"));
  painter.setRenderHint(QPainter::Antialiasing, true);
  paintKey(painter, QRectF(area.left(), plot.bottom() + 3.6 * line, area.width(), 1.4 * line),
           {QStringLiteral("grazing set (λ₁ = 1 − λ₂ − λ₃)"), QStringLiteral("simplex: every λ ≥ 0")},
           {[&](const QRectF& box) {
              painter.setPen(QPen(colors::kTrace, 2));
              painter.setBrush(kShade);
              painter.drawRect(box);
              painter.setBrush(Qt::NoBrush);
            },
            [&](const QRectF& box) {
              painter.setPen(QPen(colors::kStop, 1.5, Qt::DashLine));
              painter.drawRect(box);
            }});
  painter.restore();
}

}  // namespace grazelab::pictures
