// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/log_log_chart.h"

#include <QLineSeries>
#include <QLegend>
#include <QFontMetricsF>
#include <QLogValueAxis>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ui/plots/wrapped_legend.h"

namespace grazelab::ui {

namespace {

/// At most this many labelled ticks on an axis, fewer where its labels would touch: a range
/// of many decades ticks every 2, 3, ... decades (a log axis ticks at each power of its base).
constexpr int kMaxTicks = 7;

/// Whole powers of the base at both ends, so that every label is a power of ten.
void setLogRange(QLogValueAxis* axis, double low, double high, int maxTicks) {
  // a marker within a tenth of a decade of an end would be cut in half by the frame: the end
  // moves out by a power
  low /= std::pow(10.0, 0.1);
  high *= std::pow(10.0, 0.1);
  const double decades = std::max(1.0, std::ceil(std::log10(high) + 1e-9) - std::floor(std::log10(low)));
  const int step = std::max(1, int(std::ceil(decades / maxTicks)));
  const double base = std::pow(10.0, step);
  axis->setBase(base);
  const double first = std::floor(std::log10(low) / step) * step;
  const double last = std::max(first + step, std::ceil(std::log10(high) / step - 1e-9) * step);
  axis->setRange(std::pow(10.0, first), std::pow(10.0, last));
}

}  // namespace

LogLogChart::LogLogChart(const QString& title, const QString& xTitle, const QString& yTitle,
                         QWidget* parent)
    : QChartView(parent) {
  auto* chart = new QChart;
  // the look of every other plot (ui/plots/plot_view.cpp): its theme, margins and bold title
  chart->setTheme(QChart::ChartThemeLight);
  chart->setAnimationOptions(QChart::NoAnimation);
  chart->setMargins(QMargins(4, 4, 4, 4));
  QFont titleFont = chart->titleFont();
  titleFont.setBold(true);
  chart->setTitleFont(titleFont);
  chart->setTitle(title);
  m_axisX = new QLogValueAxis;
  m_axisX->setTitleText(xTitle);
  m_axisX->setBase(10);
  m_axisX->setLabelFormat("%.0e");
  m_axisX->setMinorTickCount(0);
  m_axisY = new QLogValueAxis;
  m_axisY->setTitleText(yTitle);
  m_axisY->setBase(10);
  m_axisY->setLabelFormat("%.0e");
  m_axisY->setMinorTickCount(0);
  chart->addAxis(m_axisX, Qt::AlignBottom);
  chart->addAxis(m_axisY, Qt::AlignLeft);
  setChart(chart);
  m_legend = std::make_unique<WrappedLegend>(chart);
  setRenderHint(QPainter::Antialiasing);
}

LogLogChart::~LogLogChart() = default;

QStringList LogLogChart::legendNames() const { return m_legend->names(); }
bool LogLogChart::legendFits() const { return m_legend->fits(); }

void LogLogChart::resizeEvent(QResizeEvent* event) {
  QChartView::resizeEvent(event);
  m_legend->update();
  fitAxes();
  // and once the chart is laid out at this size (the ticks depend on the plot area)
  QTimer::singleShot(0, this, [this] { fitAxes(); });
}

void LogLogChart::clear() {
  for (QLineSeries* series : m_series) {
    chart()->removeSeries(series);
    delete series;
  }
  m_series.clear();
  m_legend->update();
}

void LogLogChart::setPresentation(bool on, int textPixels) {
  if (!m_deskFont) m_deskFont = chart()->legend()->font();
  if (!m_deskTitleFont) m_deskTitleFont = chart()->titleFont();
  QFont font = *m_deskFont;
  if (on) font.setPixelSize(textPixels);
  QFont title = font;
  title.setBold(true);
  QFont chartTitle = *m_deskTitleFont;
  if (on) chartTitle.setPixelSize(std::max(1, int(std::lround(textPixels * 1.15))));  // as PlotView's
  chart()->setTitleFont(chartTitle);
  chart()->setBackgroundRoundness(on ? 0 : 4);
  chart()->setDropShadowEnabled(!on);
  chart()->legend()->setFont(font);
  for (QAbstractAxis* axis : {static_cast<QAbstractAxis*>(m_axisX), static_cast<QAbstractAxis*>(m_axisY)}) {
    axis->setLabelsFont(font);
    axis->setTitleFont(title);
  }
  m_presentation = on;
  for (QLineSeries* series : m_series) {
    QPen pen = series->pen();
    pen.setWidthF(lineWidth());
    series->setPen(pen);
  }
  fitAxes();  // the legend and the ticks for the new font
}

int LogLogChart::addCurve(const QString& name) {
  const int index = int(m_series.size());
  auto* series = new QLineSeries;
  series->setName(name);
  QPen pen(curveColor(index));
  pen.setWidthF(lineWidth());
  pen.setStyle(curveDash(index));
  series->setPen(pen);
  series->setPointsVisible(true);
  series->setMarkerSize(7);
  chart()->addSeries(series);
  series->attachAxis(m_axisX);
  series->attachAxis(m_axisY);
  m_series.push_back(series);
  m_legend->update();
  return index;
}

void LogLogChart::addPoint(int index, QPointF point) {
  if (index < 0 || index >= int(m_series.size())) return;
  if (!std::isfinite(point.x()) || !std::isfinite(point.y()) || !(point.x() > 0)) return;
  point.setY(std::max(point.y(), kFloor));
  m_series[std::size_t(index)]->append(point);
  fitAxes();
}

void LogLogChart::setCurves(const std::vector<LogLogCurve>& curves) {
  // the series are kept and their points replaced: removing and re-adding them on every update
  // left stale markers on screen (Qt Charts repaints only what it knows has changed)
  while (m_series.size() > curves.size()) {
    chart()->removeSeries(m_series.back());
    delete m_series.back();
    m_series.pop_back();
  }
  for (std::size_t index = 0; index < curves.size(); ++index) {
    if (index >= m_series.size()) addCurve(curves[index].name);
    QLineSeries* series = m_series[index];
    series->setName(curves[index].name);
    QList<QPointF> points;
    for (const QPointF& point : curves[index].points) {
      if (!std::isfinite(point.x()) || !std::isfinite(point.y()) || !(point.x() > 0)) continue;
      points.append(QPointF(point.x(), std::max(point.y(), kFloor)));
    }
    series->replace(points);
  }
  fitAxes();
  viewport()->update();
}

void LogLogChart::fitAxes() {
  double xMin = std::numeric_limits<double>::infinity(), xMax = 0;
  double yMin = std::numeric_limits<double>::infinity(), yMax = 0;
  for (const QLineSeries* series : m_series) {
    for (const QPointF& p : series->points()) {
      xMin = std::min(xMin, p.x());
      xMax = std::max(xMax, p.x());
      yMin = std::min(yMin, p.y());
      yMax = std::max(yMax, p.y());
    }
  }
  m_legend->update();
  if (!(xMax > 0)) return;
  // as many ticks as labels fit side by side (x) or one above the other (y)
  const QFontMetricsF metrics(m_axisX->labelsFont());
  const QRectF area = chart()->plotArea();
  const double labelWidth = 1.5 * metrics.horizontalAdvance(QStringLiteral("1e-05"));
  const double labelHeight = 1.8 * metrics.height();
  const int xTicks = area.width() > 0 ? std::clamp(int(area.width() / labelWidth), 2, kMaxTicks) : kMaxTicks;
  const int yTicks = area.height() > 0 ? std::clamp(int(area.height() / labelHeight), 2, kMaxTicks) : kMaxTicks;
  setLogRange(m_axisX, xMin, xMax, xTicks);
  setLogRange(m_axisY, yMin, yMax, yTicks);
}

}  // namespace grazelab::ui
