// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QColor>
#include <QImage>
#include <QRectF>
#include <QString>

#include <cstdint>
#include <vector>

class QPainter;

namespace grazelab::pictures {

/// Viridis (matplotlib's), t in [0, 1], interpolated between nine stops.
QColor viridis(double t);

/// A grid of values to draw as a colour map: row-major, row 0 at y = yFrom (the bottom).
/// Values are the centres of their cells.
struct HeatMapData {
  std::int64_t columns = 0;
  std::int64_t rows = 0;
  std::vector<double> values;
  double xFrom = 0, xTo = 1, yFrom = 0, yTo = 1;
  QString title, xTitle, yTitle, valueTitle;
  /// rows from this one on are still being computed: drawn pale, left out of the colour range
  /// and of the keys (-1: all rows are ready)
  std::int64_t rowsReady = -1;
};

/// The extent of `count` cells centred on the values from..to (one cell: +-0.5).
std::pair<double, double> cellExtent(double from, double to, std::int64_t count);

/// The finite range of the values (lo == hi widened by one unit; nothing finite: [0, 1]).
std::pair<double, double> finiteRange(const std::vector<double>& values);

/// One pixel per cell, top row = the last row: viridis over finiteRange, NaN grey, +-inf white.
QImage heatMapImage(const HeatMapData& data);

/// The plot area of the map inside `area` once titles, ticks and the colour bar are placed.
QRectF heatMapPlotArea(const QRectF& area, const QFont& font, const HeatMapData& data);

/// Paints the map into `area`: title, the cells (nearest neighbour, no smoothing), axes with
/// ticks and titles, and a colour bar with its range and a key for NaN and inf cells.
/// `image`, when given, is heatMapImage(data) made before (a view repainting an unchanged map).
void paintHeatMap(QPainter& painter, const QRectF& area, const HeatMapData& data,
                  const QImage* image = nullptr);

/// Ticks at 1, 2 or 5 times a power of ten inside [from, to] (about `target` of them).
std::vector<double> niceTicks(double from, double to, int target = 6);

}  // namespace grazelab::pictures
