// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/decimate.h"

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

QList<QPointF> decimateTrace(std::span<const QPointF> points, const PixelFrame& frame) {
  QList<QPointF> out;
  if (points.empty()) return out;
  const int width = std::max(frame.width, 1);
  out.reserve(std::min<std::size_t>(points.size(), std::size_t(4 * width + 2)));

  // the visible slice, widened by one point on each side
  const auto byX = [](const QPointF& point, double x) { return point.x() < x; };
  auto first = std::lower_bound(points.begin(), points.end(), frame.xMin, byX);
  auto last = std::upper_bound(points.begin(), points.end(), frame.xMax,
                               [](double x, const QPointF& point) { return x < point.x(); });
  if (first != points.begin()) --first;
  if (last != points.end()) ++last;

  std::size_t columnStart = std::size_t(first - points.begin());
  const std::size_t end = std::size_t(last - points.begin());
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
    // first, extremes in their order, last; no duplicates
    std::size_t picks[4] = {columnStart, std::min(lowest, highest), std::max(lowest, highest),
                            columnEnd};
    std::size_t previous = SIZE_MAX;
    for (std::size_t pick : picks) {
      if (pick != previous) out.append(points[pick]);
      previous = pick;
    }
    columnStart = index;
  }
  return out;
}

QList<QPointF> decimateScatter(std::span<const QPointF> points, const PixelFrame& frame) {
  QList<QPointF> out;
  const int width = std::max(frame.width, 1);
  const int height = std::max(frame.height, 1);
  std::vector<bool> taken(std::size_t(width) * std::size_t(height), false);
  for (const QPointF& point : points) {
    const auto slot = scatterCell(point, frame, width, height);
    if (!slot || taken[*slot]) continue;
    taken[*slot] = true;
    out.append(point);
  }
  return out;
}

std::vector<QList<QPointF>> decimateScatterSets(const std::vector<std::span<const QPointF>>& sets,
                                                const PixelFrame& frame) {
  const int width = std::max(frame.width, 1);
  const int height = std::max(frame.height, 1);
  // per cell: the point with the smallest hash so far, as (hash, set, index)
  struct Choice {
    std::uint64_t hash = ~std::uint64_t(0);
    std::uint32_t set = 0;
    std::uint32_t index = 0;
  };
  std::vector<Choice> cells(std::size_t(width) * std::size_t(height));
  auto mix = [](std::uint64_t x) {  // splitmix64: a fixed, well-spread hash
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
  };
  for (std::size_t set = 0; set < sets.size(); ++set) {
    for (std::size_t index = 0; index < sets[set].size(); ++index) {
      const auto found = scatterCell(sets[set][index], frame, width, height);
      if (!found) continue;
      Choice& slot = cells[*found];
      const std::uint64_t hash = mix((std::uint64_t(set) << 40) ^ std::uint64_t(index));
      if (hash < slot.hash) slot = {hash, std::uint32_t(set), std::uint32_t(index)};
    }
  }
  std::vector<QList<QPointF>> out(sets.size());
  for (const Choice& choice : cells) {
    if (choice.hash != ~std::uint64_t(0)) out[choice.set].append(sets[choice.set][choice.index]);
  }
  return out;
}

QList<QPointF> decimatePath(std::span<const QPointF> points, const PixelFrame& frame) {
  QList<QPointF> out;
  if (points.empty()) return out;
  const int width = std::max(frame.width, 1);
  const int height = std::max(frame.height, 1);
  std::int64_t lastColumn = 0;
  std::int64_t lastRow = 0;
  bool any = false;
  for (std::size_t index = 0; index < points.size(); ++index) {
    const QPointF& point = points[index];
    if (!finitePoint(point)) continue;
    const std::int64_t column = cell(point.x(), frame.xMin, frame.xMax, width);
    const std::int64_t row = cell(point.y(), frame.yMin, frame.yMax, height);
    const bool isLast = index + 1 == points.size();
    if (!any || column != lastColumn || row != lastRow || isLast) {
      out.append(point);
      lastColumn = column;
      lastRow = row;
      any = true;
    }
  }
  return out;
}

}  // namespace grazelab::ui
