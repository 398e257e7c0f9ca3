// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QChartView>
#include <QFont>
#include <QPointF>
#include <QString>

#include "ui/pictures/colors.h"
#include "ui/pictures/log_log_picture.h"

#include <memory>
#include <optional>
#include <vector>

class QLineSeries;
class QLogValueAxis;

namespace grazelab::ui {

class WrappedLegend;

using pictures::LogLogCurve;

/// A chart with base-10 logarithmic axes on both sides, one line with markers per curve in the
/// Okabe-Ito colours with a dash pattern as a second code: the explorer's Accuracy scene
/// (`grazelab-cli report` draws the same with ui/pictures/log_log_picture.h, without widgets).
class LogLogChart : public QChartView {
  Q_OBJECT

 public:
  /// y values below this are drawn on it (an error of exactly 0, e.g. equal roundings).
  static constexpr double kFloor = pictures::kLogLogFloor;

  LogLogChart(const QString& title, const QString& xTitle, const QString& yTitle,
              QWidget* parent = nullptr);
  ~LogLogChart() override;

  /// The names the legend shows, and whether each shows whole.
  QStringList legendNames() const;
  bool legendFits() const;

  /// Replaces every curve.
  void setCurves(const std::vector<LogLogCurve>& curves);
  /// Adds a point to curve `index` (created empty by setCurves or addCurve).
  void addPoint(int index, QPointF point);
  /// Adds an empty curve; returns its index.
  int addCurve(const QString& name);
  int curveCount() const { return int(m_series.size()); }
  /// Removes every curve.
  void clear();

 /// Presentation mode: text of `textPixels`, lines of 3.5 px (off: the desk look).
  void setPresentation(bool on, int textPixels);

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  void fitAxes();
  double lineWidth() const { return m_presentation ? 3.5 : 2.0; }

  bool m_presentation = false;
  std::optional<QFont> m_deskFont;
  std::optional<QFont> m_deskTitleFont;  ///< the chart title's, bold as every plot's
  QLogValueAxis* m_axisX = nullptr;
  QLogValueAxis* m_axisY = nullptr;
  std::vector<QLineSeries*> m_series;
  std::unique_ptr<WrappedLegend> m_legend;
};

using pictures::curveColor;
using pictures::curveDash;

}  // namespace grazelab::ui
