// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/family_picture.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

#include "ui/plots/heat_map.h"
#include "ui/plots/plot_style.h"

namespace grazelab::ui {

void paintFrequencyEnergy(QPainter& painter, const QRectF& area,
                          const std::vector<core::FamilyPoint>& family,
                          const core::FamilyPoint& grazingEnd, const QString& title) {
  painter.save();
  const QFontMetricsF metrics(painter.font());
  const double line = metrics.height();
  painter.fillRect(area, Qt::white);
  const QRectF plot = area.adjusted(5 * line, 2.5 * line, -1.5 * line, -5.5 * line);

  // the window: the admissible orbits and the grazing end
  double eLo = std::log10(grazingEnd.energy), eHi = eLo;
  double wLo = grazingEnd.omega, wHi = grazingEnd.omega;
  for (const core::FamilyPoint& p : family) {
    if (!p.admissible || !(p.energy > 0)) continue;
    eLo = std::min(eLo, std::log10(p.energy));
    eHi = std::max(eHi, std::log10(p.energy));
    wLo = std::min(wLo, p.omega);
    wHi = std::max(wHi, p.omega);
  }
  const double ePad = std::max(0.05 * (eHi - eLo), 0.05);
  const double wPad = std::max(0.05 * (wHi - wLo), 0.02 * wHi);
  eLo -= ePad, eHi += ePad, wLo -= wPad, wHi += wPad;
  auto at = [&](double energy, double omega) {
    return QPointF(plot.left() + (std::log10(energy) - eLo) / (eHi - eLo) * plot.width(),
                   plot.bottom() - (omega - wLo) / (wHi - wLo) * plot.height());
  };

  const QFont font = painter.font();
  QFont bold = font;
  bold.setBold(true);
  painter.setFont(bold);
  painter.setPen(Qt::black);
  painter.drawText(QRectF(area.left(), area.top(), area.width(), 2 * line), Qt::AlignCenter, title);
  painter.setFont(font);

  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setPen(QPen(QColor(0xdd, 0xdd, 0xdd), 1));
  const double tick = 0.4 * line;
  // x: decades (and 2, 5 between them when few decades show)
  std::vector<double> xTicks;
  for (double d = std::floor(eLo); d <= eHi; d += 1) {
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = std::log10(m) + d;
      if (v >= eLo && v <= eHi && (m == 1 || eHi - eLo < 3)) xTicks.push_back(v);
    }
  }
  painter.setClipRect(plot);
  for (double v : xTicks) {
    const double px = plot.left() + (v - eLo) / (eHi - eLo) * plot.width();
    painter.drawLine(QPointF(px, plot.top()), QPointF(px, plot.bottom()));
  }
  const std::vector<double> yTicks = niceTicks(wLo, wHi, 6);
  for (double w : yTicks) {
    const double py = plot.bottom() - (w - wLo) / (wHi - wLo) * plot.height();
    painter.drawLine(QPointF(plot.left(), py), QPointF(plot.right(), py));
  }
  // inadmissible orbits: grey crosses; admissible: a solid line through consecutive members.
  // Points outside the plot are left out rather than clipped: an SVG painter ignores clips.
  painter.setPen(QPen(QColor(0x99, 0x99, 0x99), 1.2));
  const QRectF inner = plot.adjusted(4, 4, -4, -4);
  for (const core::FamilyPoint& p : family) {
    if (p.admissible || !(p.energy > 0)) continue;
    const QPointF q = at(p.energy, p.omega);
    if (!inner.contains(q)) continue;
    painter.drawLine(q + QPointF(-3, -3), q + QPointF(3, 3));
    painter.drawLine(q + QPointF(-3, 3), q + QPointF(3, -3));
  }
  painter.setPen(QPen(colors::kTrace, 2.5));
  QPainterPath path;
  bool drawing = false;
  for (const core::FamilyPoint& p : family) {
    const QPointF q = p.energy > 0 ? at(p.energy, p.omega) : QPointF();
    if (!p.admissible || !plot.contains(q)) {
      drawing = false;
      continue;
    }
    drawing ? path.lineTo(q) : path.moveTo(q);
    drawing = true;
  }
  painter.drawPath(path);
  painter.setPen(QPen(Qt::black, 1.5));
  painter.setBrush(colors::kImpact);
  const QPointF end = at(grazingEnd.energy, grazingEnd.omega);
  painter.drawEllipse(end, 6, 6);
  painter.setClipping(false);

  painter.setBrush(Qt::NoBrush);
  painter.setPen(QPen(Qt::black, 1));
  painter.drawRect(plot);
  for (double v : xTicks) {
    const double px = plot.left() + (v - eLo) / (eHi - eLo) * plot.width();
    painter.drawLine(QPointF(px, plot.bottom()), QPointF(px, plot.bottom() + tick));
    painter.drawText(QRectF(px - 3 * line, plot.bottom() + tick, 6 * line, line), Qt::AlignCenter,
                     QString::number(std::pow(10.0, v), 'g', 3));
  }
  for (double w : yTicks) {
    const double py = plot.bottom() - (w - wLo) / (wHi - wLo) * plot.height();
    painter.drawLine(QPointF(plot.left() - tick, py), QPointF(plot.left(), py));
    painter.drawText(QRectF(plot.left() - tick - 5 * line, py - line / 2, 5 * line - 0.3 * line, line),
                     Qt::AlignRight | Qt::AlignVCenter, QString::number(w, 'g', 4));
  }
  painter.drawText(QRectF(plot.left(), plot.bottom() + tick + 1.1 * line, plot.width(), 1.4 * line),
                   Qt::AlignCenter, "energy E of the orbit (log scale)");
  painter.save();
  painter.translate(area.left() + 0.9 * line, plot.center().y());
  painter.rotate(-90);
  painter.drawText(QRectF(-plot.height() / 2, -0.8 * line, plot.height(), 1.6 * line), Qt::AlignCenter,
                   "frequency 2π / T");
  painter.restore();

  // the key under the axis title
  const double keyY = plot.bottom() + tick + 3 * line;
  double x = plot.left();
  painter.setPen(QPen(colors::kTrace, 2.5));
  painter.drawLine(QPointF(x, keyY + line / 2), QPointF(x + 2 * line, keyY + line / 2));
  painter.setPen(Qt::black);
  QString text = "admissible 1IPP orbits";
  painter.drawText(QPointF(x + 2.4 * line, keyY + 0.8 * line), text);
  x += 3 * line + metrics.horizontalAdvance(text);
  painter.setPen(QPen(QColor(0x99, 0x99, 0x99), 1.2));
  const QPointF cross(x + line / 2, keyY + line / 2);
  painter.drawLine(cross + QPointF(-3, -3), cross + QPointF(3, 3));
  painter.drawLine(cross + QPointF(-3, 3), cross + QPointF(3, -3));
  painter.setPen(Qt::black);
  text = "inadmissible (penetrate the stop or V ≥ 0)";
  painter.drawText(QPointF(x + 1.4 * line, keyY + 0.8 * line), text);
  x += 2 * line + metrics.horizontalAdvance(text);
  painter.setPen(QPen(Qt::black, 1.5));
  painter.setBrush(colors::kImpact);
  painter.drawEllipse(QPointF(x + line / 2, keyY + line / 2), 6, 6);
  painter.setBrush(Qt::NoBrush);
  painter.drawText(QPointF(x + 1.4 * line, keyY + 0.8 * line), "grazing end: T → T₂, V → 0, GLO(λ*)");
  painter.restore();
}

}  // namespace grazelab::ui
