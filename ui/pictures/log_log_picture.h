// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QPointF>
#include <QRectF>
#include <QString>

#include <vector>

class QPainter;

namespace grazelab::pictures {

/// One curve of a log-log chart (e.g. one method: run time against error).
struct LogLogCurve {
  QString name;
  std::vector<QPointF> points;  ///< x > 0 (others are left out); y <= kLogLogFloor drawn at it
};

/// y values below this are drawn on it (an error of exactly 0, e.g. equal roundings).
inline constexpr double kLogLogFloor = 1e-17;

/// The report's work-precision and convergence pictures: base-10 logarithmic axes on both sides
/// whose ends are whole powers (every label a power of ten, "1e-05"), one line with round
/// markers per curve in curveColor / curveDash, the names in a legend under the plot. The
/// explorer's Accuracy scene shows the same data in its interactive chart (LogLogChart).
void paintLogLog(QPainter& painter, const QRectF& area, const std::vector<LogLogCurve>& curves,
                 const QString& title, const QString& xTitle, const QString& yTitle);

}  // namespace grazelab::pictures
