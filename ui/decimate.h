// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QList>
#include <QPointF>

#include <cstdint>
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
  bool operator==(const PixelFrame&) const = default;
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

/// One of the reductions above, kept up to date while a run appends points: update() feeds
/// only the points past those it has already seen, as long as the frame is the same and the
/// data were not replaced; otherwise it starts over. Its points always equal the one-shot
/// function's on all the data (the one-shot functions are this, run once), so a view pays for
/// what is new plus what the pixels show, not for the whole run at every update.
class IncrementalDecimation {
 public:
  enum class Kind { Trace, Scatter, Path };
  explicit IncrementalDecimation(Kind kind) : m_kind(kind) {}

  /// `replaced`: the data are not the earlier data with points appended.
  const QList<QPointF>& update(std::span<const QPointF> data, const PixelFrame& frame, bool replaced);
  /// Whether the last update went over all the data (the frame or the data changed).
  bool startedOver() const { return m_startedOver; }

 private:
  void restart(const PixelFrame& frame);
  void feedTrace(std::span<const QPointF> data);
  void feedScatter(std::span<const QPointF> data);
  void feedPath(std::span<const QPointF> data);

  Kind m_kind;
  PixelFrame m_frame;
  bool m_started = false;
  bool m_startedOver = false;
  std::size_t m_consumed = 0;  ///< points fed so far
  QList<QPointF> m_kept;       ///< settled output (closed trace columns; scatter; path cells)
  QList<QPointF> m_points;     ///< what update() returns
  // trace: the visible slice's first index and the start of the column still open
  std::size_t m_traceFirst = 0;
  std::size_t m_openColumn = 0;
  // scatter: cells taken; path: the cell and index of the last point kept
  std::vector<bool> m_taken;
  std::int64_t m_lastColumn = 0;
  std::int64_t m_lastRow = 0;
  std::size_t m_lastKept = SIZE_MAX;
};

/// decimateScatterSets kept up to date while the sets grow (each set only appended to): the
/// cells keep their choice (a hash of set and index, so the order of arrival does not
/// matter) and each update costs the new points plus one pass over the cells.
class IncrementalScatterSets {
 public:
  /// `replaced`: some set is not its earlier content with points appended.
  const std::vector<QList<QPointF>>& update(const std::vector<std::span<const QPointF>>& sets,
                                            const PixelFrame& frame, bool replaced);
  bool startedOver() const { return m_startedOver; }

 private:
  struct Choice {
    std::uint64_t hash = ~std::uint64_t(0);
    std::uint32_t set = 0;
    std::uint32_t index = 0;
  };
  PixelFrame m_frame;
  bool m_started = false;
  bool m_startedOver = false;
  std::vector<std::size_t> m_consumed;
  std::vector<Choice> m_cells;
  std::vector<QList<QPointF>> m_points;
};

}  // namespace grazelab::ui
