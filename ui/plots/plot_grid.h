// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QGraphicsItem>
#include <QPen>

#include <vector>

class QChart;
class QValueAxis;

namespace grazelab::ui {

/// The grid and the axis lines of a chart with two value axes, drawn as one item with crisp,
/// unsmoothed lines at the axes' ticks. Qt Charts draws each grid line, each axis line and each
/// tick as an item of its own, antialiased at a fractional pixel: on the default scene's six
/// plots the grid was a third of the time a repaint took after an edit, and the axis lines
/// still 7 % of the GUI thread's time (measured with `grazelab --bench` under perf). It lies
/// where Qt Charts puts its grid: above the plot area's background, below the series.
class PlotGrid : public QGraphicsItem {
 public:
  /// Hides the axes' own grid lines and axis lines and draws them instead, with their pens, as
  /// a child of `chart` (the x axis along the plot area's bottom, the y axis along its left
  /// edge, where Qt Charts puts them); follows the axes' ranges and ticks and the plot area.
  PlotGrid(QChart* chart, QValueAxis* axisX, QValueAxis* axisY);

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

  /// The values along `axis` at which it draws a tick, as Qt Charts places them.
  static std::vector<double> tickValues(const QValueAxis& axis);

 private:
  QChart* m_chart;
  QValueAxis* m_axisX;
  QValueAxis* m_axisY;
  QPen m_gridPen;
  QPen m_axisPen;
  QRectF m_area;
};

}  // namespace grazelab::ui
