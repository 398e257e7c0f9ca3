// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/decimate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace grazelab::ui {
namespace {

// pixel index of a coordinate; values far outside are kept finite so they compare sanely
std::int64_t cell(double value, double low, double high, int pixels) {
  const double span = high - low;
  if (!(span > 0)) return 0;
  const double position = std::floor((value - low) / span * pixels);
  return std::int64_t(std::clamp(position, -1e15, 1e15));
}

bool finitePoint(const QPointF& point) {
  return std::isfinite(point.x()) && std::isfinite(point.y());
}

// The index of the width x height cell a scatter point falls in (the right and top edges
// belong to the last cell); nothing for a point outside the frame or not finite.
std::optional<std::size_t> scatterCell(const QPointF& point, const PixelFrame& frame, int width,
                                       int height) {
  if (!finitePoint(point)) return std::nullopt;
  if (point.x() < frame.xMin || point.x() > frame.xMax || point.y() < frame.yMin ||
      point.y() > frame.yMax) {
    return std::nullopt;
  }
  const auto column = std::min<std::int64_t>(cell(point.x(), frame.xMin, frame.xMax, width), width - 1);
  const auto row = std::min<std::int64_t>(cell(point.y(), frame.yMin, frame.yMax, height), height - 1);
  return std::size_t(row) * std::size_t(width) + std::size_t(column);
}

}  // namespace

QList<QPointF> decimateTrace(PointSpan points, const PixelFrame& frame) {
  IncrementalDecimation once(IncrementalDecimation::Kind::Trace);
  return once.update(points, frame, true);
}

QList<QPointF> decimateScatter(PointSpan points, const PixelFrame& frame) {
  IncrementalDecimation once(IncrementalDecimation::Kind::Scatter);
  return once.update(points, frame, true);
}

QList<QPointF> decimatePath(PointSpan points, const PixelFrame& frame) {
  IncrementalDecimation once(IncrementalDecimation::Kind::Path);
  return once.update(points, frame, true);
}

std::vector<QList<QPointF>> decimateScatterSets(const std::vector<PointSpan>& sets,
                                                const PixelFrame& frame) {
  IncrementalScatterSets once;
  return once.update(sets, frame, true);
}

void IncrementalDecimation::restart(const PixelFrame& frame) {
  m_frame = frame;
  m_frame.width = std::max(frame.width, 1);
  m_frame.height = std::max(frame.height, 1);
  m_started = true;
  m_startedOver = true;
  m_consumed = 0;
  m_kept.clear();
  m_traceFirst = 0;
  m_openColumn = 0;
  m_taken.assign(m_kind == Kind::Scatter ? std::size_t(m_frame.width) * std::size_t(m_frame.height) : 0,
                 false);
  m_lastColumn = 0;
  m_lastRow = 0;
  m_lastKept = SIZE_MAX;
}

const QList<QPointF>& IncrementalDecimation::update(PointSpan data,
                                                    const PixelFrame& frame, bool replaced) {
  PixelFrame usable = frame;
  usable.width = std::max(frame.width, 1);
  usable.height = std::max(frame.height, 1);
  m_startedOver = false;
  if (replaced || !m_started || !(usable == m_frame) || data.size() < m_consumed) restart(usable);
  switch (m_kind) {
    case Kind::Trace: feedTrace(data); break;
    case Kind::Scatter: feedScatter(data); break;
    case Kind::Path: feedPath(data); break;
  }
  m_consumed = data.size();
  return m_points;
}

// Columns from the first visible point (one before the frame's left edge) to one past its
// right edge; the last column met may still grow, so it stays open: its points are not settled
// into m_kept, and the next update resumes at its start.
void IncrementalDecimation::feedTrace(PointSpan points) {
  const PixelFrame& frame = m_frame;
  const int width = frame.width;
  // the visible slice by binary search on x (non-decreasing), one point beyond on each side
  const auto firstNotBelow = [&points](double x) {
    std::size_t low = 0, high = points.size();
    while (low < high) {
      const std::size_t middle = low + (high - low) / 2;
      if (points[middle].x() < x) low = middle + 1;
      else high = middle;
    }
    return low;
  };
  const auto firstAbove = [&points](double x) {
    std::size_t low = 0, high = points.size();
    while (low < high) {
      const std::size_t middle = low + (high - low) / 2;
      if (x < points[middle].x()) high = middle;
      else low = middle + 1;
    }
    return low;
  };
  std::size_t firstIndex = firstNotBelow(frame.xMin);
  std::size_t lastIndex = firstAbove(frame.xMax);
  if (firstIndex != 0) --firstIndex;
  if (lastIndex != points.size()) ++lastIndex;
  // appended points moved the visible slice's start (all the data lay left of the frame)
  if (m_consumed > 0 && firstIndex != m_traceFirst) restart(m_frame);
  if (m_consumed == 0) {
    m_traceFirst = firstIndex;
    m_openColumn = firstIndex;
  }
  m_points = m_kept;
  std::size_t columnStart = m_openColumn;
  const std::size_t end = std::max(lastIndex, columnStart);
  while (columnStart < end) {
    const std::int64_t column = std::clamp<std::int64_t>(
        cell(points[columnStart].x(), frame.xMin, frame.xMax, width), -1, width);
    std::size_t lowest = columnStart;
    std::size_t highest = columnStart;
    std::size_t index = columnStart + 1;
    for (; index < end; ++index) {
      const std::int64_t next = std::clamp<std::int64_t>(
          cell(points[index].x(), frame.xMin, frame.xMax, width), -1, width);
      if (next != column) break;
      if (points[index].y() < points[lowest].y()) lowest = index;
      if (points[index].y() > points[highest].y()) highest = index;
    }
    const std::size_t columnEnd = index - 1;
    const bool open = index == end;  // the data may continue it
    QList<QPointF>& out = open ? m_points : m_kept;
    // first, extremes in their order, last; no duplicates
    const std::size_t picks[4] = {columnStart, std::min(lowest, highest), std::max(lowest, highest),
                                  columnEnd};
    std::size_t previous = SIZE_MAX;
    for (std::size_t pick : picks) {
      if (pick != previous) {
        out.append(points[pick]);
        if (!open) m_points.append(points[pick]);
      }
      previous = pick;
    }
    if (open) m_openColumn = columnStart;
    columnStart = index;
  }
}

void IncrementalDecimation::feedScatter(PointSpan points) {
  for (std::size_t index = m_consumed; index < points.size(); ++index) {
    const auto slot = scatterCell(points[index], m_frame, m_frame.width, m_frame.height);
    if (!slot || m_taken[*slot]) continue;
    m_taken[*slot] = true;
    m_kept.append(points[index]);
  }
  m_points = m_kept;
}

// Each point that falls in the same cell as the point kept before it is dropped; the last
// point is always drawn (kept aside: a later point may follow it).
void IncrementalDecimation::feedPath(PointSpan points) {
  for (std::size_t index = m_consumed; index < points.size(); ++index) {
    const QPointF& point = points[index];
    if (!finitePoint(point)) continue;
    const std::int64_t column = cell(point.x(), m_frame.xMin, m_frame.xMax, m_frame.width);
    const std::int64_t row = cell(point.y(), m_frame.yMin, m_frame.yMax, m_frame.height);
    if (m_lastKept == SIZE_MAX || column != m_lastColumn || row != m_lastRow) {
      m_kept.append(point);
      m_lastColumn = column;
      m_lastRow = row;
      m_lastKept = index;
    }
  }
  m_points = m_kept;
  const std::size_t lastIndex = points.size() - 1;
  if (!points.empty() && lastIndex != m_lastKept && finitePoint(points[lastIndex])) {
    m_points.append(points[lastIndex]);
  }
}

const std::vector<QList<QPointF>>& IncrementalScatterSets::update(
    const std::vector<PointSpan>& sets, const PixelFrame& frame, bool replaced) {
  PixelFrame usable = frame;
  usable.width = std::max(frame.width, 1);
  usable.height = std::max(frame.height, 1);
  bool shrunk = m_consumed.size() != sets.size();
  for (std::size_t set = 0; set < sets.size() && !shrunk; ++set) {
    shrunk = sets[set].size() < m_consumed[set];
  }
  m_startedOver = replaced || !m_started || !(usable == m_frame) || shrunk;
  if (m_startedOver) {
    const std::size_t cells = std::size_t(usable.width) * std::size_t(usable.height);
    if (m_cells.size() == cells) {
      forEachUsedCell([this](std::size_t cell) { m_cells[cell] = Choice{}; });
      std::fill(m_used.begin(), m_used.end(), 0);
    } else {
      m_cells.assign(cells, Choice{});
      m_used.assign((cells + 63) / 64, 0);
    }
    m_frame = usable;
    m_started = true;
    m_consumed.assign(sets.size(), 0);
  }
  auto mix = [](std::uint64_t x) {  // splitmix64: a fixed, well-spread hash
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
  };
  // per cell: the point with the smallest hash so far, as (hash, set, index)
  for (std::size_t set = 0; set < sets.size(); ++set) {
    for (std::size_t index = m_consumed[set]; index < sets[set].size(); ++index) {
      const auto found = scatterCell(sets[set][index], m_frame, m_frame.width, m_frame.height);
      if (!found) continue;
      Choice& slot = m_cells[*found];
      const std::uint64_t hash = mix((std::uint64_t(set) << 40) ^ std::uint64_t(index));
      if (hash < slot.hash) slot = {hash, std::uint32_t(set), std::uint32_t(index)};
      m_used[*found / 64] |= std::uint64_t(1) << (*found % 64);
    }
    m_consumed[set] = sets[set].size();
  }
  // in cell order (row by row), as a walk over every cell would give
  m_points.assign(sets.size(), QList<QPointF>());
  forEachUsedCell([this, &sets](std::size_t cell) {
    const Choice& choice = m_cells[cell];
    m_points[choice.set].append(sets[choice.set][choice.index]);
  });
  return m_points;
}

}  // namespace grazelab::ui
