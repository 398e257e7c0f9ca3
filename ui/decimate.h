// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QList>
#include <QPointF>

#include <span>
#include <vector>

namespace grazelab::ui {

/// The visible data rectangle and the pixel size of the plot area it is drawn into.
struct PixelFrame {
  double xMin = 0;
  double xMax = 1;
  double yMin = 0;
  double yMax = 1;
  int width = 1;   ///< pixels, > 0
  int height = 1;  ///< pixels, > 0
};

/// Reduces a trace (x non-decreasing) to at most four points per pixel column: the first, the
/// lowest, the highest and the last of the column, in their original order, so the drawn
/// polyline covers exactly the same pixels. Points left of xMin or right of xMax are dropped
/// except the nearest one on each side, which keeps the line running to the frame's edge.
QList<QPointF> decimateTrace(std::span<const QPointF> points, const PixelFrame& frame);

/// Reduces a scatter to at most one point per pixel cell (the first one found); points outside
/// the frame and non-finite points are dropped.
QList<QPointF> decimateScatter(std::span<const QPointF> points, const PixelFrame& frame);

/// Reduces several scatters drawn over each other (colour classes of one cloud) jointly to at
/// most one point per pixel cell, chosen at random (a fixed hash of its set and index) among
/// every point of every set in that cell: each class shows in proportion to its share of the
/// cell, and none hides the others by being drawn last. Returns one list per set.
std::vector<QList<QPointF>> decimateScatterSets(const std::vector<std::span<const QPointF>>& sets,
                                                const PixelFrame& frame);

/// Reduces a polyline with any x order (a phase portrait) by dropping each point that falls in
/// the same pixel cell as the point kept before it. The first and last points are kept.
QList<QPointF> decimatePath(std::span<const QPointF> points, const PixelFrame& frame);

}  // namespace grazelab::ui
