// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QList>
#include <QPointF>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace grazelab::ui {

/// Points read where they are: a list of QPointF, or two double fields of larger records (a
/// run's samples: (t, u2), (u2, v2), ...), so that a view draws a run without a copy of it.
/// Holds no memory: the records must outlive it and stay where they are while it is used.
class PointSpan {
 public:
  PointSpan() = default;
  PointSpan(std::span<const QPointF> points)  // NOLINT: a list of points is a span of points
      : m_first(reinterpret_cast<const std::byte*>(points.data())),
        m_count(points.size()),
        m_stride(sizeof(QPointF)),
        m_x(0),
        m_y(sizeof(qreal)) {}
  PointSpan(const std::vector<QPointF>& points)  // NOLINT: as the span of its points
      : PointSpan(std::span<const QPointF>(points)) {}

  /// x and y are the doubles at `xOffset` and `yOffset` bytes into each of `count` records of
  /// `stride` bytes from `first` (offsets taken from a record: fieldOffset()).
  static PointSpan ofRecords(const void* first, std::size_t count, std::size_t stride,
                             std::size_t xOffset, std::size_t yOffset) {
    PointSpan span;
    span.m_first = static_cast<const std::byte*>(first);
    span.m_count = count;
    span.m_stride = stride;
    span.m_x = xOffset;
    span.m_y = yOffset;
    return span;
  }
  /// Bytes from the start of `record` to its double `field`.
  template <typename Record>
  static std::size_t fieldOffset(const Record& record, const double& field) {
    return std::size_t(reinterpret_cast<const std::byte*>(&field) -
                       reinterpret_cast<const std::byte*>(&record));
  }

  /// The same points in other units: x times `xScale`, y times `yScale` (a run's t over its
  /// period, u over the gap), read so, not copied.
  PointSpan scaled(double xScale, double yScale) const {
    PointSpan span = *this;
    span.m_xScale *= xScale;
    span.m_yScale *= yScale;
    return span;
  }

  QPointF operator[](std::size_t index) const {
    const std::byte* record = m_first + index * m_stride;
    double x = 0;
    double y = 0;
    std::memcpy(&x, record + m_x, sizeof x);
    std::memcpy(&y, record + m_y, sizeof y);
    return {x * m_xScale, y * m_yScale};
  }
  std::size_t size() const { return m_count; }
  bool empty() const { return m_count == 0; }
  QPointF back() const { return (*this)[m_count - 1]; }
  std::vector<QPointF> toVector() const {
    std::vector<QPointF> points(m_count);
    for (std::size_t index = 0; index < m_count; ++index) points[index] = (*this)[index];
    return points;
  }
  /// The `count` points from `first` (clamped to the span).
  PointSpan subspan(std::size_t first, std::size_t count) const {
    PointSpan part = *this;
    first = std::min(first, m_count);
    part.m_first = m_first + first * m_stride;
    part.m_count = std::min(count, m_count - first);
    return part;
  }

 private:
  const std::byte* m_first = nullptr;
  std::size_t m_count = 0;
  std::size_t m_stride = sizeof(QPointF);
  std::size_t m_x = 0;
  std::size_t m_y = sizeof(qreal);
  double m_xScale = 1;
  double m_yScale = 1;
};

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
QList<QPointF> decimateTrace(PointSpan points, const PixelFrame& frame);

/// Reduces a scatter to at most one point per pixel cell (the first one found); points outside
/// the frame and non-finite points are dropped.
QList<QPointF> decimateScatter(PointSpan points, const PixelFrame& frame);

/// Reduces several scatters drawn over each other (colour classes of one cloud) jointly to at
/// most one point per pixel cell, chosen at random (a fixed hash of its set and index) among
/// every point of every set in that cell: each class shows in proportion to its share of the
/// cell, and none hides the others by being drawn last. Returns one list per set.
std::vector<QList<QPointF>> decimateScatterSets(const std::vector<PointSpan>& sets,
                                                const PixelFrame& frame);

/// Reduces a polyline with any x order (a phase portrait) by dropping each point that falls in
/// the same pixel cell as the point kept before it. The first and last points are kept.
QList<QPointF> decimatePath(PointSpan points, const PixelFrame& frame);

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
  const QList<QPointF>& update(PointSpan data, const PixelFrame& frame, bool replaced);
  /// Whether the last update went over all the data (the frame or the data changed).
  bool startedOver() const { return m_startedOver; }

 private:
  void restart(const PixelFrame& frame);
  void feedTrace(PointSpan data);
  void feedScatter(PointSpan data);
  void feedPath(PointSpan data);

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
  const std::vector<QList<QPointF>>& update(const std::vector<PointSpan>& sets,
                                            const PixelFrame& frame, bool replaced);
  bool startedOver() const { return m_startedOver; }

 private:
  /// Calls `visit(cell)` for each cell that holds a choice, in increasing cell order.
  template <typename Visit>
  void forEachUsedCell(const Visit& visit) const {
    for (std::size_t word = 0; word < m_used.size(); ++word) {
      for (std::uint64_t bits = m_used[word]; bits != 0; bits &= bits - 1) {
        visit(word * 64 + std::size_t(std::countr_zero(bits)));
      }
    }
  }

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
  /// one bit per cell, set when the cell holds a choice: a restart clears and the output walks
  /// only the cells in use (a plot's frame has ~10^5..10^6 cells; a run fills a few percent)
  std::vector<std::uint64_t> m_used;
  std::vector<QList<QPointF>> m_points;
};

}  // namespace grazelab::ui
