// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/plot_grid.h"

#include <QChart>
#include <QPainter>
#include <QValueAxis>

#include <cmath>
#include <vector>

namespace grazelab::ui {

namespace {
// Qt Charts' z-value for its grid (ChartPresenter::GridZValue): above the plot area's
// background and shades, below the axes and the series
constexpr qreal kGridZ = 2;
}  // namespace

PlotGrid::PlotGrid(QChart* chart, QValueAxis* axisX, QValueAxis* axisY)
    : QGraphicsItem(chart), m_chart(chart), m_axisX(axisX), m_axisY(axisY),
      m_gridPen(axisX->gridLinePen()), m_axisPen(axisX->linePen()) {
  setZValue(kGridZ);
  for (QValueAxis* axis : {axisX, axisY}) {
    axis->setGridLineVisible(false);
    // the axis line and its ticks (Qt Charts' "arrow" items: the ticks are not drawn by the
    // light theme, so the line is all that shows)
    axis->setLineVisible(false);
  }
  m_area = chart->plotArea();
  QObject::connect(chart, &QChart::plotAreaChanged, chart, [this](const QRectF& area) {
    if (area == m_area) return;
    prepareGeometryChange();
    m_area = area;
  });
  for (QValueAxis* axis : {axisX, axisY}) {
    const auto repaint = [this] { update(); };
    QObject::connect(axis, &QValueAxis::rangeChanged, chart, repaint);
    QObject::connect(axis, &QValueAxis::tickIntervalChanged, chart, repaint);
    QObject::connect(axis, &QValueAxis::tickAnchorChanged, chart, repaint);
    QObject::connect(axis, &QValueAxis::tickTypeChanged, chart, repaint);
    QObject::connect(axis, &QValueAxis::tickCountChanged, chart, repaint);
  }
}

QRectF PlotGrid::boundingRect() const { return m_area.adjusted(-1, -1, 1, 1); }

std::vector<double> PlotGrid::tickValues(const QValueAxis& axis) {
  std::vector<double> values;
  const double low = axis.min();
  const double high = axis.max();
  if (!(high > low) || !std::isfinite(low) || !std::isfinite(high)) return values;
  if (axis.tickType() == QValueAxis::TicksDynamic) {
    // as Qt Charts does (ChartValueAxisX/Y::calculateLayout): from the anchor in whole
    // intervals to the first tick inside, then one interval at a time
    const double interval = axis.tickInterval();
    if (!(interval > 0) || (high - low) / interval > 10'000) return values;
    const double anchor = axis.tickAnchor();
    for (double value = anchor - std::floor((anchor - low) / interval) * interval; value <= high;
         value += interval) {
      values.push_back(value);
    }
    return values;
  }
  const int count = axis.tickCount();
  for (int index = 0; index < count && count > 1; ++index) {
    values.push_back(low + (high - low) * index / (count - 1));
  }
  return values;
}

void PlotGrid::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  const QRectF area = m_chart->plotArea();
  if (area.isEmpty()) return;
  painter->save();
  // one pixel, not smoothed across two: crisp, and a plain fill for the raster engine
  painter->setRenderHint(QPainter::Antialiasing, false);
  const auto pixel = [](double position) { return std::floor(position) + 0.5; };
  std::vector<QLineF> lines;
  const double xSpan = m_axisX->max() - m_axisX->min();
  for (double value : tickValues(*m_axisX)) {
    const double x = pixel(area.left() + (value - m_axisX->min()) / xSpan * area.width());
    if (x >= area.left() && x <= area.right()) lines.emplace_back(x, area.top(), x, area.bottom());
  }
  const double ySpan = m_axisY->max() - m_axisY->min();
  for (double value : tickValues(*m_axisY)) {
    const double y = pixel(area.bottom() - (value - m_axisY->min()) / ySpan * area.height());
    if (y >= area.top() && y <= area.bottom()) lines.emplace_back(area.left(), y, area.right(), y);
  }
  painter->setPen(m_gridPen);
  painter->drawLines(lines.data(), int(lines.size()));
  // the axes over the grid, where Qt Charts draws them
  const double left = pixel(area.left());
  const double bottom = pixel(area.bottom());
  const QLineF axes[] = {{left, area.top(), left, bottom}, {left, bottom, area.right(), bottom}};
  painter->setPen(m_axisPen);
  painter->drawLines(axes, 2);
  painter->restore();
}

}  // namespace grazelab::ui
