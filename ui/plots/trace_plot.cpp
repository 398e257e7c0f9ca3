// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/trace_plot.h"

#include <QChart>
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include "core/model/linear_modes.h"
#include "ui/plots/run_points.h"
#include "ui/plots/plot_style.h"

namespace grazelab::ui {

TracePlot::TracePlot(QWidget* parent)
    : PlotView(tr("Displacement of mass 2: u₂(t)"), tr("time t"), tr("u₂"), parent) {
  m_trace = addEntry(makeLine(tr("u₂(t)"), colors::kTrace, 1.0), Decimation::Trace);
  m_stop = addEntry(makeLine(tr("stop u₂ = d"), colors::kStop, 1.5, Qt::DashLine), Decimation::None);
  m_impacts = addEntry(makeScatter(tr("impacts"), colors::kImpact, 6), Decimation::Scatter, false);
  auto* touches = makeScatter(tr("grazings / sticks"), colors::kGrazing, 8);
  touches->setMarkerShape(QScatterSeries::MarkerShapeTriangle);
  useLightMarker(touches);
  m_grazings = addEntry(touches, Decimation::Scatter, false);
  setToolTip(tr("Displacement u₂ of mass 2 against time. The dashed line is the stop u₂ = d; "
                "dots mark the contacts (impacts: vermillion circles; grazing touches and sticks: orange triangles).\n"
                "A long run shows three slow periods at the animation's time; W shows all of it.\n"
                "Drag to zoom, Shift+drag or middle button to pan, wheel to zoom, R to reset."));
}

void TracePlot::show(const SimUpdate& update) {
  const core::Result& result = *update.result;
  const double gap = update.request->job.spec.model.gap;
  const bool grown = !m_taken.startsOver(update);
  if (!grown) {
    startNewRun();
    setData(m_impacts, {});
    setData(m_grazings, {});
  }
  // the run's samples as they are, no copy (the view holds the run while it shows it)
  const PointSpan drawn = samplePoints(result, SampleAxes::TimeU2);
  m_taken.samples = drawn.size();
  showInPlace(m_trace, drawn, update.result, grown);
  const double tLast = drawn.empty() ? result.tFinal : drawn.back().x();
  // contacts within the trace's window; later ones wait for the samples that reach them
  std::vector<QPointF> impacts;
  std::vector<QPointF> others;
  std::size_t next = m_taken.events;
  for (; next < result.events.size() && result.events[next].t <= tLast; ++next) {
    const core::Event& event = result.events[next];
    if (event.type == core::EventType::Impact) impacts.emplace_back(event.t, gap);
    else if (core::isContact(event.type)) others.emplace_back(event.t, gap);
  }
  m_taken.events = next;
  appendData(m_impacts, impacts);
  appendData(m_grazings, others);
  setData(m_stop, {QPointF(0, gap), QPointF(tLast, gap)});
  m_gap = gap;
  m_window = tLast;
  m_T2 = core::computeModes(update.request->job.spec.model).T2;
  m_tFinal = result.tFinal;
  placeWindow();
  drawOverlay();
  scheduleRefresh();
}

void TracePlot::placeWindow() {
  // the samples may cover only the run's first periods: the title says so when the run goes on
  if (m_whole || m_runWindow.wholeFits(m_window, m_T2)) {
    setXWindow(std::nullopt);
    setXTitle(runAxisTitle(tr("time t"), std::nullopt, m_window, m_tFinal));
    return;
  }
  m_runWindow.follow(m_cursorTime, m_window, m_T2);
  const std::pair shown(m_runWindow.from(), m_runWindow.to());
  setXWindow(shown);
  setXTitle(runAxisTitle(tr("time t"), shown, m_window, m_tFinal));
}

void TracePlot::setWholeRun(bool whole) {
  m_whole = whole;
  placeWindow();
  scheduleRefresh();
}

void TracePlot::setTimeCursor(double t) {
  m_cursorTime = t;
  if (!m_whole && !m_runWindow.wholeFits(m_window, m_T2) && m_runWindow.follow(t, m_window, m_T2)) {
    placeWindow();
    scheduleRefresh();
  }
  if (!m_cursor) {
    // not an entry: it never counts for the axes, the CSV or the decimation
    // see-through: a contact at the cursor's time (a stick at t = 0) shows under it
    QColor through = colors::kAccent;
    through.setAlpha(120);
    m_cursor = makeLine(QString(), through, 2.0);
    chart()->addSeries(m_cursor);
    m_cursor->attachAxis(m_axisX);
    m_cursor->attachAxis(m_axisY);
    setInLegend(m_cursor, false);
  }
  m_cursor->replace({QPointF(t, m_axisY->min()), QPointF(t, m_axisY->max())});
}

void TracePlot::setOverlay(std::shared_ptr<const core::Result> run, const QString& name) {
  m_overlayRun = std::move(run);
  if (m_overlayRun && m_overlayTrace < 0) {
    // created on first use: scenes without an overlay keep their legend as it was
    m_overlayTrace = addEntry(makeLine(name, colors::kOverlay, 1.5, Qt::DashLine), Decimation::Trace);
    auto* crosses = makeScatter(tr("its contacts"), colors::kOverlay, 9);
    crosses->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
    useLightMarker(crosses);
    m_overlayContacts = addEntry(crosses, Decimation::Scatter, false);
  }
  if (m_overlayTrace >= 0) entries()[std::size_t(m_overlayTrace)].series->setName(name);
  drawOverlay();
  scheduleRefresh();
}

void TracePlot::drawOverlay() {
  if (m_overlayTrace < 0) return;
  std::vector<QPointF> trace;
  std::vector<QPointF> contacts;
  if (m_overlayRun) {
    for (const core::Sample& sample : m_overlayRun->samples) {
      if (sample.t > m_window) break;
      trace.emplace_back(sample.t, sample.state.u2);
    }
    for (const core::Event& event : m_overlayRun->events) {
      if (event.t > m_window) break;
      // drawn a little above the stop, so that they sit beside the exact contacts
      if (core::isContact(event.type)) contacts.emplace_back(event.t, m_gap * 1.03);
    }
  }
  setData(m_overlayTrace, std::move(trace));
  setData(m_overlayContacts, std::move(contacts));
}

}  // namespace grazelab::ui
