// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/curve_plot.h"

#include <QChart>
#include <QXYSeries>

#include <algorithm>
#include <QMouseEvent>
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include "ui/plots/plot_style.h"

namespace grazelab::ui {

CurvePlot::CurvePlot(PlotKind kind, QWidget* parent)
    : PlotView(QString(), QString(), QString(), parent), m_kind(kind) {
  // to the pixels: a curve (folded families) keeps its path
  m_curve = addEntry(makeLine(QString(), colors::kTrace, 2.0), Decimation::Path);
  auto* dots = makeScatter(QString(), colors::kTrace, 5.5);
  dots->setPen(Qt::NoPen);
  m_dots = addEntry(dots, Decimation::Scatter);
  m_reference = addEntry(makeLine(QString(), colors::kReference, 1.5, Qt::DashLine), Decimation::None);
  // a one-point reference is a ring (a zero-length dashed line drew nothing)
  auto* ring = makeScatter(QString(), colors::kReference, 14);
  ring->setColor(Qt::transparent);
  ring->setPen(QPen(colors::kReference, 2.5));
  useLightMarker(ring, QPen(colors::kReference, 2.5));
  m_referencePoint = addEntry(ring, Decimation::None);
  auto* marker = makeScatter(QString(), colors::kImpact, 12);
  marker->setPen(QPen(Qt::white, 1.5));
  useLightMarker(marker, QPen(Qt::white, 1.5));
  // (one to a marker's cell: the hundreds of contacts of a whole run drew as a faint band)
  m_marker = addEntry(marker, Decimation::Scatter);
}

void CurvePlot::show(const SimUpdate& update) {
  const auto found = update.request->job.figures.find(m_kind);
  if (found == update.request->job.figures.end()) return;
  const CurveFigure& figure = found->second;
  setTitles(figure.title, figure.xTitle, figure.yTitle);
  setToolTip(figure.toolTip);
  const auto& list = entries();
  list[std::size_t(m_curve)].series->setName(figure.dots ? QString() : figure.curveName);
  list[std::size_t(m_dots)].series->setName(figure.dots ? figure.curveName : QString());
  list[std::size_t(m_marker)].series->setName(figure.markerName);
  const bool point = figure.reference.size() == 1;
  list[std::size_t(m_reference)].series->setName(point ? QString() : figure.referenceName);
  list[std::size_t(m_referencePoint)].series->setName(point ? figure.referenceName : QString());
  setData(m_curve, figure.dots ? std::vector<QPointF>{} : figure.curve);
  setData(m_dots, figure.dots ? figure.curve : std::vector<QPointF>{});
  setData(m_marker, figure.markers);
  setEmptyNote(figure.curve.empty() && figure.markers.empty() ? figure.whyEmpty : QString());
  setData(m_reference, point ? std::vector<QPointF>{} : figure.reference);
  setData(m_referencePoint, point ? figure.reference : std::vector<QPointF>{});
  m_draggable = !figure.draggedModes.empty() && (point || figure.markers.size() == 1);
  if (m_draggable) m_ring = point ? figure.reference.front() : figure.markers.front();
  setMouseTracking(m_draggable);  // the hand over the ring
  if (figure.xMax > figure.xMin && figure.yMax > figure.yMin) {
    setFixedRange(QRectF(QPointF(figure.xMin, figure.yMin), QPointF(figure.xMax, figure.yMax)));
  } else {
    setFixedRange(std::nullopt);
  }
  scheduleRefresh();
}

bool CurvePlot::onRing(QPointF position) const {
  constexpr double kReach = 18;  // pixels: the ring is 14 across
  const QPointF ring = chart()->mapToPosition(m_ring);
  return m_draggable && QLineF(ring, position).length() <= kReach;
}

void CurvePlot::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton && !(event->modifiers() & Qt::ShiftModifier) &&
      onRing(event->position())) {
    emit activated(this);
    m_dragging = true;
    setCursor(Qt::ClosedHandCursor);
    event->accept();
    return;
  }
  PlotView::mousePressEvent(event);
}

void CurvePlot::mouseMoveEvent(QMouseEvent* event) {
  if (m_dragging) {
    const QPointF position = event->position();
    if (chart()->plotArea().contains(position)) {
      m_ring = chart()->mapToValue(position);
      emit referenceDragged(m_ring);
    }
    event->accept();
    return;
  }
  if (m_draggable && event->buttons() == Qt::NoButton) {
    if (onRing(event->position())) setCursor(Qt::OpenHandCursor);
    else unsetCursor();
  }
  PlotView::mouseMoveEvent(event);
}

void CurvePlot::mouseReleaseEvent(QMouseEvent* event) {
  if (m_dragging) {
    m_dragging = false;
    setCursor(Qt::OpenHandCursor);
    event->accept();
    return;
  }
  PlotView::mouseReleaseEvent(event);
}

}  // namespace grazelab::ui
