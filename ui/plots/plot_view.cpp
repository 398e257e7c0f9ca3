// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/plot_view.h"

#include <QChart>
#include <QKeyEvent>
#include <QLegend>
#include <QLabel>
#include <QMouseEvent>
#include <QScatterSeries>
#include <QValueAxis>
#include <QWheelEvent>
#include <QXYSeries>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ui/decimate.h"
#include "ui/plots/plot_style.h"

namespace grazelab::ui {
namespace {

// a range that is never empty, padded by 2 % on each side; a spread below 1e-3 of the plot's
// scale (round-off around a constant) is shown as flat rather than blown up
std::pair<double, double> padded(double low, double high, double scale) {
  if (!(low <= high)) return {-1.0, 1.0};
  double span = high - low;
  const double least = std::max(1e-3 * scale, 1e-12);
  if (span < least) {
    const double middle = 0.5 * (low + high);
    low = middle - 0.5 * least;
    high = middle + 0.5 * least;
    span = least;
  }
  return {low - 0.02 * span, high + 0.02 * span};
}

// Ticks at round values (0, 100, 200 rather than -21.02, 120.9) without widening the range,
// labelled with as many decimals as the step needs. (A QCategoryAxis gives exact labels too,
// but relayouting it costs ~3 ms per axis and update, too much for a live drag.)
double niceStep(double low, double high) {
  const double span = high - low;
  if (!(span > 0) || !std::isfinite(span)) return 0;
  const double rough = span / 4.0;  // four to eight ticks: labels stay apart on a projector
  const double magnitude = std::pow(10.0, std::floor(std::log10(rough)));
  const double ratio = rough / magnitude;
  return (ratio < 1.5 ? 1.0 : ratio < 3.5 ? 2.0 : ratio < 7.5 ? 5.0 : 10.0) * magnitude;
}

// Sets range and tick interval together. The order matters: Qt Charts lays the ticks out on
// each change, and a small interval over a large range would create millions of tick items.
void setRangeWithTicks(QValueAxis* axis, double low, double high) {
  const double step = niceStep(low, high);
  if (step <= 0) {
    axis->setRange(low, high);
    return;
  }
  // whole steps print as whole numbers up to a billion (a contact-index axis to 10^6 read
  // "0.0002, 2e+05": the anchor below, printed by %g); fractions as decimals below a million
  const double largest = std::max(std::abs(low), std::abs(high));
  const bool plain = (step >= 1e-9 && largest < 1e6) || (step >= 1 && largest < 1e9);
  const int decimals = std::max(0, int(std::ceil(-std::log10(step) - 1e-9)));
  const QString format = plain ? QStringLiteral("%.%1f").arg(decimals) : QStringLiteral("%.3g");
  if (axis->labelFormat() != format) axis->setLabelFormat(format);
  if (axis->tickType() != QValueAxis::TicksDynamic) {
    axis->setTickInterval(std::max(step, axis->max() - axis->min()));
    axis->setTickType(QValueAxis::TicksDynamic);
  }
  // Qt Charts accumulates the tick values, so the one at zero lands at about -1e-17 and reads
  // "-0.0" (or "-1.4e-20"); anchoring the ticks a billionth of a step above zero keeps that
  // tick on the positive side, invisibly
  const double anchor = 1e-9 * step;
  if (axis->tickAnchor() != anchor) axis->setTickAnchor(anchor);
  if (step >= axis->tickInterval()) {
    axis->setTickInterval(step);
    axis->setRange(low, high);
  } else {
    axis->setRange(low, high);
    axis->setTickInterval(step);
  }
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
  const auto* scatter = qobject_cast<QScatterSeries*>(series);
  const double base = scatter ? scatter->markerSize() : series->pen().widthF();
  m_entries.push_back({series, {}, decimation, inBounds, base});
  if (m_presentation) {
    m_presentation = false;  // applies the look to the new series too
    setPresentation(true, chart()->legend()->font().pixelSize());
  }
  return int(m_entries.size()) - 1;
}

void PlotView::setTimeCursor(double, const core::State&) {}

void PlotView::setPresentation(bool on, int textPixels) {
  QChart* chart = this->chart();
  if (!m_deskFonts) {
    m_deskFonts = Fonts{chart->titleFont(), m_axisX->labelsFont(), m_axisX->titleFont(),
                        chart->legend()->font()};
  }
  auto sized = [&](QFont font, double factor) {
    font.setPixelSize(std::max(1, int(std::lround(textPixels * factor))));
    return font;
  };
  const Fonts fonts = on ? Fonts{sized(m_deskFonts->title, 1.15), sized(m_deskFonts->labels, 1.0),
                                 sized(m_deskFonts->axisTitles, 1.0), sized(m_deskFonts->legend, 1.0)}
                         : *m_deskFonts;
  chart->setTitleFont(fonts.title);
  chart->legend()->setFont(fonts.legend);
  for (QValueAxis* axis : {m_axisX, m_axisY}) {
    axis->setLabelsFont(fonts.labels);
    axis->setTitleFont(fonts.axisTitles);
  }
  // a white page with no rounded, shaded card: what a projector shows best
  chart->setBackgroundRoundness(on ? 0 : 4);
  chart->setDropShadowEnabled(!on);
  for (Entry& entry : m_entries) {
    if (auto* scatter = qobject_cast<QScatterSeries*>(entry.series)) {
      scatter->setMarkerSize(on ? std::max(8.0, 1.5 * entry.baseWidth) : entry.baseWidth);
      useLightMarker(scatter, scatter->property("grazelabOutline").value<QPen>());
    } else {
      QPen pen = entry.series->pen();
      pen.setWidthF(on ? std::max(3.0, 2.0 * entry.baseWidth) : entry.baseWidth);
      entry.series->setPen(pen);
    }
  }
  m_presentation = on;
  scheduleRefresh();
}

void PlotView::setData(int index, std::vector<QPointF> data) {
  m_entries[std::size_t(index)].data = std::move(data);
}

void PlotView::joinScatters(std::vector<int> indices) { m_joinedScatters = std::move(indices); }

void PlotView::includeInBounds(double x, double y) { m_extraBounds.push_back({x, y}); }
void PlotView::clearExtraBounds() { m_extraBounds.clear(); }
void PlotView::setFixedRange(std::optional<QRectF> range) { m_fixedRange = range; }

void PlotView::scheduleRefresh() {
  if (!m_refreshTimer.isActive()) m_refreshTimer.start();
}

void PlotView::refreshNow() {
  m_refreshTimer.stop();
  refresh();
}

void PlotView::setStale(bool stale) {
  if (stale == m_stale) return;
  m_stale = stale;
  if (!m_staleNote) {
    m_staleNote = new QLabel(tr("stale: the last valid result, not the panel's values"), this);
    m_staleNote->setObjectName(QStringLiteral("staleNote"));
    m_staleNote->setStyleSheet(QStringLiteral(
        "QLabel { background: #fff3cd; color: #7a1010; border: 1px solid #7a1010; padding: 2px; }"));
    m_staleNote->setAttribute(Qt::WA_TransparentForMouseEvents);
  }
  m_staleNote->adjustSize();
  m_staleNote->move(width() - m_staleNote->width() - 8, 4);
  m_staleNote->setVisible(stale);
  chart()->setPlotAreaBackgroundBrush(QColor(0xe8, 0xe8, 0xe8));
  chart()->setPlotAreaBackgroundVisible(stale);
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
  if (m_fixedRange) {
    setRangeWithTicks(m_axisX, m_fixedRange->left(), m_fixedRange->right());
    setRangeWithTicks(m_axisY, m_fixedRange->top(), m_fixedRange->bottom());
    return;
  }
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
  // each axis is padded on its own scale (an FFT axis near 8.9 must not inherit the 20 000 of
  // its contact-index axis), but never below 1e-3 of the plot's overall scale, so that a
  // coordinate that is zero up to round-off stays a flat line
  const double scaleX = std::max({std::abs(xLow), std::abs(xHigh), xHigh - xLow});
  const double scaleY = std::max({std::abs(yLow), std::abs(yHigh), yHigh - yLow});
  const double overall = std::max(scaleX, scaleY);
  auto usable = [&](double scale) {
    const double floored = std::max(scale, 1e-3 * overall);
    return std::isfinite(floored) && floored > 0 ? floored : 1.0;
  };
  const auto [x0, x1] = padded(xLow, xHigh, usable(scaleX));
  const auto [y0, y1] = padded(yLow, yHigh, usable(scaleY));
  setRangeWithTicks(m_axisX, x0, x1);
  setRangeWithTicks(m_axisY, y0, y1);
}

void PlotView::refresh() {
  // empty the line series first: every axis change makes Qt Charts recompute and re-stroke the
  // path of every point a line holds, and the old points are about to be replaced anyway.
  // Scatter series keep theirs: Qt Charts reuses their marker items across a replace().
  for (Entry& entry : m_entries) {
    if (entry.series->count() > 0 && !qobject_cast<QScatterSeries*>(entry.series)) {
      entry.series->replace(QList<QPointF>());
    }
  }
  if (m_followData) fitAxes();
  // after a zoom or pan by the user: new ticks for the new range
  setRangeWithTicks(m_axisX, m_axisX->min(), m_axisX->max());
  setRangeWithTicks(m_axisY, m_axisY->min(), m_axisY->max());
  const QRectF area = chart()->plotArea();
  PixelFrame frame{m_axisX->min(), m_axisX->max(), m_axisY->min(), m_axisY->max(),
                   std::max(1, int(area.width())), std::max(1, int(area.height()))};
  if (!m_joinedScatters.empty()) {
    const auto* first = qobject_cast<QScatterSeries*>(m_entries[std::size_t(m_joinedScatters[0])].series);
    const int cell = first ? std::max(1, int(first->markerSize() * 0.75)) : 1;
    PixelFrame coarse = frame;
    coarse.width = std::max(1, frame.width / cell);
    coarse.height = std::max(1, frame.height / cell);
    std::vector<std::span<const QPointF>> sets;
    for (int index : m_joinedScatters) sets.emplace_back(m_entries[std::size_t(index)].data);
    std::vector<QList<QPointF>> reduced = decimateScatterSets(sets, coarse);
    for (std::size_t set = 0; set < reduced.size(); ++set) {
      m_entries[std::size_t(m_joinedScatters[set])].series->replace(reduced[set]);
    }
  }
  for (std::size_t index = 0; index < m_entries.size(); ++index) {
    Entry& entry = m_entries[index];
    if (std::find(m_joinedScatters.begin(), m_joinedScatters.end(), int(index)) !=
        m_joinedScatters.end()) {
      continue;
    }
    QList<QPointF> points;
    switch (entry.decimation) {
      case Decimation::None:
        points = QList<QPointF>(entry.data.begin(), entry.data.end());
        break;
      case Decimation::Trace:
        points = decimateTrace(entry.data, frame);
        break;
      case Decimation::Path: {
        // 2-pixel cells: Qt Charts strokes a hover shape for every line point, so each point
        // costs; a 1.2 px antialiased line looks the same
        PixelFrame coarse = frame;
        coarse.width = std::max(1, frame.width / 2);
        coarse.height = std::max(1, frame.height / 2);
        points = decimatePath(entry.data, coarse);
        break;
      }
      case Decimation::Scatter: {
        // one marker per marker-sized cell: more would overdraw the same pixels
        const auto* scatter = qobject_cast<QScatterSeries*>(entry.series);
        const int cell = scatter ? std::max(1, int(scatter->markerSize() * 0.75)) : 1;
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
  m_pressPosition = event->position().toPoint();
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
    return;
  }
  // a click, not a rubber band: where, in the data's coordinates
  const QPoint position = event->position().toPoint();
  if (event->button() == Qt::LeftButton && (position - m_pressPosition).manhattanLength() < 4 &&
      chart()->plotArea().contains(position)) {
    emit clickedAt(chart()->mapToValue(position));
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
  if (m_staleNote) m_staleNote->move(width() - m_staleNote->width() - 8, 4);
  scheduleRefresh();
}

void PlotView::mouseDoubleClickEvent(QMouseEvent* event) {
  emit enlargeRequested(this);
  event->accept();
}

void PlotView::focusInEvent(QFocusEvent* event) {
  QChartView::focusInEvent(event);
  emit activated(this);
}

}  // namespace grazelab::ui
