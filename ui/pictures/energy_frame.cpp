// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/pictures/energy_frame.h"

#include <QPainter>

#include <cmath>

#include "ui/pictures/heat_map.h"

namespace grazelab::pictures {

QPointF EnergyFrame::at(double logEnergy, double omega) const {
  return {plot.left() + (logEnergy - eLo) / (eHi - eLo) * plot.width(),
          plot.bottom() - (omega - wLo) / (wHi - wLo) * plot.height()};
}

EnergyFrame makeEnergyFrame(const QRectF& plot, double eLo, double eHi, double wLo, double wHi) {
  EnergyFrame frame{plot, eLo, eHi, wLo, wHi, {}, {}};
  for (double d = std::floor(eLo); d <= eHi; d += 1) {
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = std::log10(m) + d;
      if (v >= eLo && v <= eHi && (m == 1 || eHi - eLo < 3)) frame.xTicks.push_back(v);
    }
  }
  frame.yTicks = niceTicks(wLo, wHi, 6);
  return frame;
}

void paintPictureTitle(QPainter& painter, const QRectF& area, const QString& title, double line) {
  const QFont font = painter.font();
  QFont bold = font;
  bold.setBold(true);
  painter.setFont(bold);
  painter.setPen(Qt::black);
  painter.drawText(QRectF(area.left(), area.top(), area.width(), 2 * line), Qt::AlignCenter, title);
  painter.setFont(font);
}

void paintEnergyGrid(QPainter& painter, const EnergyFrame& frame) {
  painter.setPen(QPen(QColor(0xdd, 0xdd, 0xdd), 1));
  for (double v : frame.xTicks) {
    const double px = frame.at(v, frame.wLo).x();
    painter.drawLine(QPointF(px, frame.plot.top()), QPointF(px, frame.plot.bottom()));
  }
  for (double w : frame.yTicks) {
    const double py = frame.at(frame.eLo, w).y();
    painter.drawLine(QPointF(frame.plot.left(), py), QPointF(frame.plot.right(), py));
  }
}

void paintEnergyAxes(QPainter& painter, const EnergyFrame& frame, const QRectF& area, double line) {
  const QRectF& plot = frame.plot;
  painter.setBrush(Qt::NoBrush);
  painter.setPen(QPen(Qt::black, 1));
  painter.drawRect(plot);
  const double tick = 0.4 * line;
  for (double v : frame.xTicks) {
    const double px = frame.at(v, frame.wLo).x();
    painter.drawLine(QPointF(px, plot.bottom()), QPointF(px, plot.bottom() + tick));
    painter.drawText(QRectF(px - 3 * line, plot.bottom() + tick, 6 * line, line), Qt::AlignCenter,
                     QString::number(std::pow(10.0, v), 'g', 7));  // 1000, not 1e+03
  }
  for (double w : frame.yTicks) {
    const double py = frame.at(frame.eLo, w).y();
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
}

}  // namespace grazelab::pictures
