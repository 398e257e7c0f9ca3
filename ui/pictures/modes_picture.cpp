// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/pictures/modes_picture.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <set>

#include "ui/pictures/energy_frame.h"
#include "ui/pictures/colors.h"

namespace grazelab::pictures {

QColor modesColor(int impacts) {
  switch (impacts) {
    case 1: return colors::kTrace;
    case 2: return colors::kImpact;
    case 4: return QColor(0x00, 0x9E, 0x73);  // bluish green
    default: return colors::kAccent;
  }
}

void paintModes(QPainter& painter, const QRectF& area, const std::vector<ModesPictureFamily>& families,
                const std::vector<ModesPictureMark>& marks, const QString& title) {
  painter.save();
  const QFontMetricsF metrics(painter.font());
  const double line = metrics.height();
  painter.fillRect(area, Qt::white);
  const QRectF plot = area.adjusted(5 * line, 2.5 * line, -1.5 * line, -5.5 * line);

  // the window: every point of every family, and the marks
  double eLo = INFINITY, eHi = -INFINITY, wLo = INFINITY, wHi = -INFINITY;
  const auto take = [&](const QPointF& p) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return;
    eLo = std::min(eLo, p.x()), eHi = std::max(eHi, p.x());
    wLo = std::min(wLo, p.y()), wHi = std::max(wHi, p.y());
  };
  for (const ModesPictureFamily& family : families) {
    for (const QPointF& p : family.points) take(p);
  }
  for (const ModesPictureMark& mark : marks) take(mark.at);
  if (!(eLo <= eHi)) eLo = -1, eHi = 1, wLo = 0, wHi = 1;
  const double ePad = std::max(0.05 * (eHi - eLo), 0.05);
  const double wPad = std::max(0.05 * (wHi - wLo), 0.02 * std::abs(wHi));
  eLo -= ePad, eHi += ePad, wLo -= wPad, wHi += wPad;
  const EnergyFrame frame = makeEnergyFrame(plot, eLo, eHi, wLo, wHi);
  const auto at = [&](const QPointF& p) { return frame.at(p.x(), p.y()); };

  paintPictureTitle(painter, area, title, line);
  painter.setRenderHint(QPainter::Antialiasing, true);
  paintEnergyGrid(painter, frame);

  // the families: runs of stable points solid, unstable dashed (points outside are left out:
  // an SVG painter ignores clips)
  for (const ModesPictureFamily& family : families) {
    const QColor colour = modesColor(family.impacts);
    for (const bool stablePart : {true, false}) {
      QPen pen(colour, 2.2);
      if (!stablePart) pen.setStyle(Qt::DashLine);
      painter.setPen(pen);
      QPainterPath path;
      bool drawing = false;
      for (std::size_t i = 0; i < family.points.size(); ++i) {
        const bool stable = i < family.stable.size() && family.stable[i];
        const QPointF q = at(family.points[i]);
        if (stable != stablePart || !plot.contains(q)) {
          // a run ends on the point after it, so that stable and unstable parts join
          if (drawing && plot.contains(q)) path.lineTo(q);
          drawing = false;
          continue;
        }
        if (drawing) path.lineTo(q);
        else if (i > 0 && plot.contains(at(family.points[i - 1]))) {
          path.moveTo(at(family.points[i - 1]));
          path.lineTo(q);
        } else {
          path.moveTo(q);
        }
        drawing = true;
      }
      painter.drawPath(path);
    }
  }
  // the marks, each named beside it where its name overlaps no other (right, left, above,
  // below, in that order)
  painter.setPen(QPen(Qt::black, 1.3));
  std::vector<QRectF> taken;
  for (const ModesPictureMark& mark : marks) {
    const QPointF q = at(mark.at);
    if (!plot.contains(q)) continue;
    // as in the explorer: flips are squares, ends black dots
    if (mark.label.startsWith(QLatin1String("flip"))) {
      painter.setBrush(Qt::white);
      painter.drawRect(QRectF(q - QPointF(5.5, 5.5), QSizeF(11, 11)));
    } else {
      painter.setBrush(Qt::black);
      painter.drawEllipse(q, 4.5, 4.5);
    }
    taken.push_back(QRectF(q - QPointF(6, 6), QSizeF(12, 12)));
  }
  painter.setBrush(Qt::NoBrush);
  for (const ModesPictureMark& mark : marks) {
    const QPointF q = at(mark.at);
    if (!plot.contains(q)) continue;
    const QString text = QString(mark.label).replace(QLatin1Char('-'), QLatin1Char(' '));
    const double width = metrics.horizontalAdvance(text) + 4;
    const QRectF candidates[] = {
        QRectF(q.x() + 8, q.y() - line, width, line), QRectF(q.x() - 8 - width, q.y() - line, width, line),
        QRectF(q.x() - width / 2, q.y() - 8 - line, width, line), QRectF(q.x() - width / 2, q.y() + 8, width, line)};
    QRectF chosen = candidates[0];
    for (const QRectF& candidate : candidates) {
      const bool inside = plot.contains(candidate);
      const bool free = std::none_of(taken.begin(), taken.end(), [&](const QRectF& r) { return r.intersects(candidate); });
      if (inside && free) {
        chosen = candidate;
        break;
      }
    }
    taken.push_back(chosen);
    painter.drawText(chosen, Qt::AlignCenter, text);
  }

  paintEnergyAxes(painter, frame, area, line);

  // the key: one entry per number of impacts shown, then the line styles and the flip mark;
  // an entry that would pass the right edge starts a new row
  double keyY = plot.bottom() + 0.4 * line + 3 * line;
  double x = plot.left();
  const auto room = [&](double width) {
    if (x + width > area.right() - line && x > plot.left()) {
      x = plot.left();
      keyY += 1.3 * line;
    }
  };
  std::set<int> shown;
  for (const ModesPictureFamily& family : families) shown.insert(family.impacts);
  const auto entry = [&](const QPen& pen, const QString& text) {
    room(2.4 * line + metrics.horizontalAdvance(text));
    painter.setPen(pen);
    painter.drawLine(QPointF(x, keyY + line / 2), QPointF(x + 2 * line, keyY + line / 2));
    painter.setPen(Qt::black);
    painter.drawText(QPointF(x + 2.4 * line, keyY + 0.8 * line), text);
    x += 3.2 * line + metrics.horizontalAdvance(text);
  };
  for (int impacts : shown) {
    entry(QPen(modesColor(impacts), 2.2), impacts == 1 ? QStringLiteral("1 impact per period")
                                                       : QStringLiteral("%1 impacts").arg(impacts));
  }
  entry(QPen(Qt::black, 2.2), "stable");
  QPen dashed(Qt::black, 2.2);
  dashed.setStyle(Qt::DashLine);
  entry(dashed, "unstable");
  const QString flipText = "flip: twice the impacts born";
  room(1.4 * line + metrics.horizontalAdvance(flipText));
  painter.setPen(QPen(Qt::black, 1.3));
  const QPointF d(x + line / 2, keyY + line / 2);
  painter.setBrush(Qt::white);
  painter.drawRect(QRectF(d - QPointF(5.5, 5.5), QSizeF(11, 11)));
  painter.setBrush(Qt::NoBrush);
  painter.drawText(QPointF(x + 1.4 * line, keyY + 0.8 * line), flipText);
  painter.restore();
}

}  // namespace grazelab::pictures
