// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/trace_plot.h"

#include <QChart>
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include "ui/compute/time_text.h"
#include "ui/plots/plot_style.h"
#include "ui/plots/run_points.h"
#include "ui/widgets/param_specs.h"

namespace grazelab::ui {

TracePlot::TracePlot(QWidget* parent)
    : PlotView(tr("Displacement u₂ / d"), tr("t / T₂"), tr("u / d"), parent) {
  m_trace = addEntry(makeLine(tr("u₂ / d"), colors::kTrace, 1.0), Decimation::Trace);
  m_other = addEntry(makeLine(QString(), colors::kOverlay, 1.5), Decimation::Trace);
  m_stop = addEntry(makeLine(tr("stop"), colors::kStop, 1.5, Qt::DashLine), Decimation::None);
  m_impacts = addEntry(makeScatter(tr("impacts"), colors::kImpact, 6), Decimation::Scatter, false);
  auto* touches = makeScatter(tr("grazings / sticks"), colors::kGrazing, 8);
  touches->setMarkerShape(QScatterSeries::MarkerShapeTriangle);
  useLightMarker(touches);
  m_grazings = addEntry(touches, Decimation::Scatter, false);
}

void TracePlot::nameFor(const ShownRun& run, const ViewWords* words) {
  const QString stopped = subscriptDigits(run.stopped + 1);
  const QString trace = tr("u%1 / d").arg(stopped);
  entries()[std::size_t(m_trace)].series->setName(trace);
  const bool other = run.chosen != run.stopped;
  entries()[std::size_t(m_other)].series->setName(
      other ? tr("u%1 / d").arg(subscriptDigits(run.chosen + 1)) : QString());
  const QString title =
      other ? tr("Mass %1 at the stop and mass %2: u / d")
                  .arg(run.stopped + 1)
                  .arg(run.chosen + 1)
      : run.twoMass ? tr("Displacement u₂ / d")
                    : tr("Mass %1 at the stop: %2").arg(run.stopped + 1).arg(trace);
  // the scene's words for this run, over the view's own (the 1IPP orbit's period)
  setTitles(words ? words->title : title, tr("t / %1").arg(run.unit.name), tr("u / d"));
  if (words) {
    setToolTip(words->toolTip);
    return;
  }
  setToolTip(
      tr("The displacement of mass %1, which meets the stop, over the gap d, against time over %2; the "
         "dashed line is the stop (u = d). Dots mark the contacts (impacts: vermillion circles; grazing "
         "touches and sticks: orange triangles).%3\nA long run shows a few periods at the animation's time; "
         "W shows all of it.\nDrag to zoom, Shift+drag or middle button to pan, wheel to zoom, R to reset.")
          .arg(run.stopped + 1)
          .arg(run.unit.inWords)
          .arg(other
                   ? tr(" The other line is mass %1, the one 'phase of' names.").arg(run.chosen + 1)
                   : QString()));
}

void TracePlot::show(const SimUpdate& update) {
  std::optional<ShownRun> run = shownRun(update);
  if (!run) return;
  const bool grown = m_run && run->continues(*m_run);
  if (!grown) {
    startNewRun();
    setData(m_impacts, {});
    setData(m_grazings, {});
    m_eventsTaken = 0;
    const auto& words = update.request->job.viewWords;
    const auto found = words.find(PlotKind::Trace);
    const ViewWords* given = found != words.end() ? &found->second : nullptr;
    const QString title = given ? given->title : QString();
    if (!m_run || !run->wordedAlike(*m_run) || title != m_wordsTitle) nameFor(*run, given);
    m_wordsTitle = title;
  }
  // the run's samples as they are, no copy (the view holds the run while it shows it), in the
  // chain's units
  const double toTime = 1 / run->unit.length, toLength = 1 / run->gap;
  const StateSpan& samples = run->samples;
  showInPlace(m_trace,
              samples.points(StateSpan::timeField(), samples.displacementField(run->stopped))
                  .scaled(toTime, toLength),
              run->owner, grown);
  if (run->chosen != run->stopped) {
    showInPlace(m_other,
                samples.points(StateSpan::timeField(), samples.displacementField(run->chosen))
                    .scaled(toTime, toLength),
                run->owner, grown);
  } else {
    setData(m_other, {});
  }
  const double tLast = run->drawnUntil();
  // contacts within the trace's window; later ones wait for the samples that reach them
  std::vector<QPointF> impacts;
  std::vector<QPointF> others;
  std::size_t next = m_eventsTaken;
  for (; next < run->eventCount() && run->eventTime(next) <= tLast; ++next) {
    const core::EventType type = run->eventType(next);
    if (type == core::EventType::Impact)
      impacts.emplace_back(run->eventTime(next) * toTime, 1.0);
    else if (core::isContact(type))
      others.emplace_back(run->eventTime(next) * toTime, 1.0);
  }
  m_eventsTaken = next;
  appendData(m_impacts, impacts);
  appendData(m_grazings, others);
  setData(m_stop, {QPointF(0, 1), QPointF(tLast * toTime, 1)});
  m_window = tLast * toTime;
  m_tFinal = std::max(run->tFinal, tLast) * toTime;
  m_run = std::move(run);
  placeWindow();
  drawOverlay();
  scheduleRefresh();
}

std::vector<QPointF> TracePlot::contacts() const {
  std::vector<QPointF> all = entries()[std::size_t(m_impacts)].points().toVector();
  const std::vector<QPointF> others = entries()[std::size_t(m_grazings)].points().toVector();
  all.insert(all.end(), others.begin(), others.end());
  return all;
}

void TracePlot::placeWindow() {
  // the samples may cover only the run's first periods: the title says so when the run goes on
  const QString axis = tr("t / %1").arg(m_run ? m_run->unit.name : tr("T₂"));
  if (m_whole || m_runWindow.wholeFits(m_window)) {
    setXWindow(std::nullopt);
    setXTitle(runAxisTitle(axis, std::nullopt, m_window, m_tFinal));
    return;
  }
  m_runWindow.follow(cursorOnAxis(), m_window);
  const std::pair shown(m_runWindow.from(), m_runWindow.to());
  setXWindow(shown);
  setXTitle(runAxisTitle(axis, shown, m_window, m_tFinal));
}

void TracePlot::setWholeRun(bool whole) {
  m_whole = whole;
  placeWindow();
  scheduleRefresh();
}

void TracePlot::setTimeCursor(double time) {
  m_cursorTime = time;
  const double t = cursorOnAxis();
  if (!m_whole && !m_runWindow.wholeFits(m_window) && m_runWindow.follow(t, m_window)) {
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
    // from the axis' bottom to its top as they are once fitted, zoomed or panned
    connect(m_axisY, &QValueAxis::rangeChanged, this, [this] { placeCursor(); });
  }
  placeCursor();
}

void TracePlot::placeCursor() {
  const double t = cursorOnAxis();
  m_cursor->replace({QPointF(t, m_axisY->min()), QPointF(t, m_axisY->max())});
}

void TracePlot::setOverlay(std::shared_ptr<const core::Result> run, const QString& name) {
  m_overlayRun = std::move(run);
  if (m_overlayRun && m_overlayTrace < 0) {
    // created on first use: scenes without an overlay keep their legend as it was
    m_overlayTrace =
        addEntry(makeLine(name, colors::kOverlay, 1.5, Qt::DashLine), Decimation::Trace);
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
  if (m_overlayRun && m_run) {
    // (the note's chain's methods: in the exact run's units)
    const double toTime = 1 / m_run->unit.length, toLength = 1 / m_run->gap;
    for (const core::Sample& sample : m_overlayRun->samples) {
      if (sample.t * toTime > m_window) break;
      trace.emplace_back(sample.t * toTime, sample.state.u2 * toLength);
    }
    for (const core::Event& event : m_overlayRun->events) {
      if (event.t * toTime > m_window) break;
      // drawn a little above the stop, so that they sit beside the exact contacts
      if (core::isContact(event.type)) contacts.emplace_back(event.t * toTime, 1.03);
    }
  }
  setData(m_overlayTrace, std::move(trace));
  setData(m_overlayContacts, std::move(contacts));
}

}  // namespace grazelab::ui
