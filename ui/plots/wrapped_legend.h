// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QSet>
#include <QString>
#include <QStringList>

class QChart;
class QGraphicsTextItem;
class QXYSeries;

namespace grazelab::ui {

/// A chart's legend as wrapped text under the plot: each named series' symbol in its colour
/// (its marker's shape, a dash for dashed lines, a bar for lines) and its full name, on as
/// many lines as the chart's width needs, at most 40 % of its height. Qt Charts' own legend
/// keeps one row (or one column) and cuts names to "sto…" or to bare swatches. The chart's
/// legend stays the font's source but is hidden.
class WrappedLegend {
 public:
  explicit WrappedLegend(QChart* chart);

  /// Lays the legend out again for the chart's series, size and legend font (cheap when none
  /// changed); reserves the room under the axes through the chart's bottom margin.
  void update();
  /// Leaves a series out of the legend (or takes it back).
  void setShown(QXYSeries* series, bool shown);

  const QStringList& names() const { return m_names; }
  /// Every name shows whole (false when cut to 40 % of the height, or not laid out yet).
  bool fits() const { return m_fits; }
  const QGraphicsTextItem* item() const { return m_text; }

 private:
  QChart* m_chart;
  QGraphicsTextItem* m_text;  ///< owned by the chart
  QString m_html;
  QStringList m_names;
  bool m_fits = false;
  QSet<QXYSeries*> m_leftOut;
};

}  // namespace grazelab::ui
