// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/pictures/family_picture.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

#include "ui/pictures/energy_frame.h"
#include "ui/pictures/colors.h"

namespace grazelab::pictures {

void paintFrequencyEnergy(QPainter& painter, const QRectF& area,
                          const std::vector<FrequencyEnergyPoint>& family,
                          const FrequencyEnergyPoint& grazingEnd, const QString& title, const QString& endLabel) {
  painter.save();
  const QFontMetricsF metrics(painter.font());
  const double line = metrics.height();
  painter.fillRect(area, Qt::white);
  const QRectF plot = area.adjusted(5 * line, 2.5 * line, -1.5 * line, -5.5 * line);

  // the window: the admissible orbits and the grazing end
  double eLo = std::log10(grazingEnd.energy), eHi = eLo;
  double wLo = grazingEnd.omega, wHi = grazingEnd.omega;
  for (const FrequencyEnergyPoint& p : family) {
    if (!p.admissible || !(p.energy > 0)) continue;
    eLo = std::min(eLo, std::log10(p.energy));
    eHi = std::max(eHi, std::log10(p.energy));
    wLo = std::min(wLo, p.omega);
    wHi = std::max(wHi, p.omega);
  }
  const double ePad = std::max(0.05 * (eHi - eLo), 0.05);
  const double wPad = std::max(0.05 * (wHi - wLo), 0.02 * wHi);
  eLo -= ePad, eHi += ePad, wLo -= wPad, wHi += wPad;
  const EnergyFrame frame = makeEnergyFrame(plot, eLo, eHi, wLo, wHi);
  auto at = [&](double energy, double omega) { return frame.at(std::log10(energy), omega); };

  paintPictureTitle(painter, area, title, line);

  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setClipRect(plot);
  paintEnergyGrid(painter, frame);
  // inadmissible orbits: grey crosses; admissible: a solid line through consecutive members.
  // Points outside the plot are left out rather than clipped: an SVG painter ignores clips.
  painter.setPen(QPen(QColor(0x99, 0x99, 0x99), 1.2));
  const QRectF inner = plot.adjusted(4, 4, -4, -4);
  for (const FrequencyEnergyPoint& p : family) {
    if (p.admissible || !(p.energy > 0)) continue;
    const QPointF q = at(p.energy, p.omega);
    if (!inner.contains(q)) continue;
    painter.drawLine(q + QPointF(-3, -3), q + QPointF(3, 3));
    painter.drawLine(q + QPointF(-3, 3), q + QPointF(3, -3));
  }
  painter.setPen(QPen(colors::kTrace, 2.5));
  QPainterPath path;
  bool drawing = false;
  for (const FrequencyEnergyPoint& p : family) {
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

  paintEnergyAxes(painter, frame, area, line);

  // the key under the axis title
  const double keyY = plot.bottom() + 0.4 * line + 3 * line;
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
  painter.drawText(QPointF(x + 1.4 * line, keyY + 0.8 * line), endLabel);
  painter.restore();
}

}  // namespace grazelab::pictures
