// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/plot_view.h"

#include <QChart>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QScatterSeries>
#include <QValueAxis>
#include <QWheelEvent>
#include <QXYSeries>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ui/decimate.h"

namespace grazelab::ui {
namespace {

// a range that is never empty, padded by 2 % on each side
std::pair<double, double> padded(double low, double high) {
  if (!(low <= high)) return {-1.0, 1.0};
  double span = high - low;
  if (span <= 1e-300) span = std::max(std::abs(low) * 0.1, 1e-9);
  return {low - 0.02 * span, high + 0.02 * span};
}

}  // namespace

PlotView::PlotView(const QString& title, const QString& xTitle, const QString& yTitle,
                   QWidget* parent)
    : QChartView(new QChart, parent) {
  QChart* chart = this->chart();
  chart->setTitle(title);
  chart->setTheme(QChart::ChartThemeLight);
  chart->setAnimationOptions(QChart::NoAnimation);
  chart->setMargins(QMargins(4, 4, 4, 4));
  chart->legend()->setAlignment(Qt::AlignBottom);
  QFont titleFont = chart->titleFont();
  titleFont.setBold(true);
  chart->setTitleFont(titleFont);

  m_axisX = new QValueAxis;
  m_axisY = new QValueAxis;
  m_axisX->setTitleText(xTitle);
  m_axisY->setTitleText(yTitle);
  m_axisX->setLabelFormat(QStringLiteral("%.4g"));
  m_axisY->setLabelFormat(QStringLiteral("%.4g"));
  chart->addAxis(m_axisX, Qt::AlignBottom);
  chart->addAxis(m_axisY, Qt::AlignLeft);

  setRenderHint(QPainter::Antialiasing);
  setRubberBand(QChartView::RectangleRubberBand);
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(240, 180);

  m_refreshTimer.setSingleShot(true);
  m_refreshTimer.setInterval(0);
  connect(&m_refreshTimer, &QTimer::timeout, this, &PlotView::refresh);
}

int PlotView::addEntry(QXYSeries* series, Decimation decimation, bool inBounds) {
  chart()->addSeries(series);
  series->attachAxis(m_axisX);
  series->attachAxis(m_axisY);
  m_entries.push_back({series, {}, decimation, inBounds});
  return int(m_entries.size()) - 1;
}

void PlotView::setData(int index, std::vector<QPointF> data) {
  m_entries[std::size_t(index)].data = std::move(data);
}

void PlotView::includeInBounds(double x, double y) { m_extraBounds.push_back({x, y}); }
void PlotView::clearExtraBounds() { m_extraBounds.clear(); }

void PlotView::scheduleRefresh() {
  if (!m_refreshTimer.isActive()) m_refreshTimer.start();
}

void PlotView::refreshNow() {
  m_refreshTimer.stop();
  refresh();
}

void PlotView::resetView() {
  m_followData = true;
  refreshNow();
}

void PlotView::userMovedView() {
  m_followData = false;
  scheduleRefresh();
}

QString PlotView::title() const { return chart()->title(); }

qsizetype PlotView::drawnPointCount() const {
  qsizetype count = 0;
  for (const Entry& entry : m_entries) count += entry.series->count();
  return count;
}

void PlotView::appendCsv(QString& csv) const {
  auto quote = [](QString text) {
    text.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + text + QLatin1Char('"');
  };
  const QString plot = quote(title());
  for (const Entry& entry : m_entries) {
    const QString quoted = plot + QLatin1Char(',') + quote(entry.series->name());
    for (const QPointF& point : entry.data) {
      csv += quoted + QLatin1Char(',') + QString::number(point.x(), 'g', 17) + QLatin1Char(',') +
             QString::number(point.y(), 'g', 17) + QLatin1Char('\n');
    }
  }
}

void PlotView::fitAxes() {
  double xLow = std::numeric_limits<double>::infinity();
  double xHigh = -xLow;
  double yLow = xLow;
  double yHigh = -xLow;
  auto take = [&](const QPointF& point) {
    if (!std::isfinite(point.x()) || !std::isfinite(point.y())) return;
    xLow = std::min(xLow, point.x());
    xHigh = std::max(xHigh, point.x());
    yLow = std::min(yLow, point.y());
    yHigh = std::max(yHigh, point.y());
  };
  for (const Entry& entry : m_entries) {
    if (!entry.inBounds) continue;
    for (const QPointF& point : entry.data) take(point);
  }
  for (const QPointF& point : m_extraBounds) take(point);
  const auto [x0, x1] = padded(xLow, xHigh);
  const auto [y0, y1] = padded(yLow, yHigh);
  m_axisX->setRange(x0, x1);
  m_axisY->setRange(y0, y1);
  // round tick values (0, 100, 200 rather than -21.02, 120.9)
  m_axisX->applyNiceNumbers();
  m_axisY->applyNiceNumbers();
}

void PlotView::refresh() {
  if (m_followData) fitAxes();
  const QRectF area = chart()->plotArea();
  PixelFrame frame{m_axisX->min(), m_axisX->max(), m_axisY->min(), m_axisY->max(),
                   std::max(1, int(area.width())), std::max(1, int(area.height()))};
  for (Entry& entry : m_entries) {
    QList<QPointF> points;
    switch (entry.decimation) {
      case Decimation::None:
        points = QList<QPointF>(entry.data.begin(), entry.data.end());
        break;
      case Decimation::Trace:
        points = decimateTrace(entry.data, frame);
        break;
      case Decimation::Path:
        points = decimatePath(entry.data, frame);
        break;
      case Decimation::Scatter: {
        // one marker per marker-sized cell: more would overdraw the same pixels
        const auto* scatter = qobject_cast<QScatterSeries*>(entry.series);
        const int cell = scatter ? std::max(1, int(scatter->markerSize() / 2)) : 1;
        PixelFrame coarse = frame;
        coarse.width = std::max(1, frame.width / cell);
        coarse.height = std::max(1, frame.height / cell);
        points = decimateScatter(entry.data, coarse);
        break;
      }
    }
    // one bulk replace per series: Qt Charts redraws once instead of once per point
    entry.series->replace(points);
  }
  emit refreshed();
}

void PlotView::mousePressEvent(QMouseEvent* event) {
  emit activated(this);
  const bool pan = event->button() == Qt::MiddleButton ||
                   (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier));
  if (pan) {
    m_panning = true;
    m_lastPanPosition = event->position().toPoint();
    setCursor(Qt::ClosedHandCursor);
    event->accept();
    return;
  }
  QChartView::mousePressEvent(event);
}

void PlotView::mouseMoveEvent(QMouseEvent* event) {
  if (m_panning) {
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - m_lastPanPosition;
    m_lastPanPosition = position;
    chart()->scroll(-delta.x(), delta.y());
    userMovedView();
    event->accept();
    return;
  }
  QChartView::mouseMoveEvent(event);
}

void PlotView::mouseReleaseEvent(QMouseEvent* event) {
  if (m_panning) {
    m_panning = false;
    unsetCursor();
    event->accept();
    return;
  }
  // a rubber-band zoom (left) or zoom-out (right) shows up as changed ranges
  const QPointF before(m_axisX->min(), m_axisX->max());
  const QPointF beforeY(m_axisY->min(), m_axisY->max());
  QChartView::mouseReleaseEvent(event);
  if (before != QPointF(m_axisX->min(), m_axisX->max()) ||
      beforeY != QPointF(m_axisY->min(), m_axisY->max())) {
    userMovedView();
  }
}

void PlotView::wheelEvent(QWheelEvent* event) {
  chart()->zoom(event->angleDelta().y() > 0 ? 1.25 : 0.8);
  userMovedView();
  event->accept();
}

void PlotView::keyPressEvent(QKeyEvent* event) {
  switch (event->key()) {
    case Qt::Key_R: resetView(); break;
    case Qt::Key_Plus:
    case Qt::Key_Equal: chart()->zoom(1.25); break;
    case Qt::Key_Minus: chart()->zoom(0.8); break;
    case Qt::Key_Left: chart()->scroll(-20, 0); break;
    case Qt::Key_Right: chart()->scroll(20, 0); break;
    case Qt::Key_Up: chart()->scroll(0, 20); break;
    case Qt::Key_Down: chart()->scroll(0, -20); break;
    default: QChartView::keyPressEvent(event); return;
  }
  if (event->key() != Qt::Key_R) userMovedView();
  event->accept();
}

void PlotView::resizeEvent(QResizeEvent* event) {
  QChartView::resizeEvent(event);
  scheduleRefresh();
}

void PlotView::focusInEvent(QFocusEvent* event) {
  QChartView::focusInEvent(event);
  emit activated(this);
}

}  // namespace grazelab::ui
