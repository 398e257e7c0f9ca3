// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/phase_plot.h"

#include <QChart>
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>

#include "ui/plots/plot_style.h"
#include "ui/widgets/param_specs.h"

namespace grazelab::ui {
namespace {

// The first of the first `end` samples at or after time t (`after`: the first after it).
std::size_t firstAtOrAfter(const StateSpan& samples, std::size_t end, double t,
                           bool after = false) {
  std::size_t low = 0, high = end;
  while (low < high) {
    const std::size_t middle = low + (high - low) / 2;
    if (samples.t(middle) < t || (after && samples.t(middle) == t))
      low = middle + 1;
    else
      high = middle;
  }
  return low;
}

}  // namespace

PhasePlot::PhasePlot(Mass mass, QWidget* parent)
    : PlotView(mass == Mass::Chosen ? tr("Phase portrait of mass 2 (u₂, v₂)")
                                    : tr("Phase portrait of mass 1 (u₁, v₁)"),
               mass == Mass::Chosen ? tr("u₂ / d") : tr("u₁ / d"),
               mass == Mass::Chosen ? tr("v₂ / (d ω₁)") : tr("v₁ / (d ω₁)"), parent),
      m_mass(mass) {
  m_path = addEntry(makeLine(tr("orbit"), colors::kTrace, 1.0), Decimation::Path);
  m_recent = addEntry(makeLine(tr("orbit, %1 periods").arg(RunWindow::kPeriods), colors::kTrace, 1.0),
                      Decimation::Path);
  setInLegend(entries()[std::size_t(m_recent)].series, false);
  m_stop = addEntry(makeLine(QString(), colors::kStop, 1.5, Qt::DashLine), Decimation::None);
  m_start = addEntry(makeScatter(tr("start"), colors::kImpact, 8), Decimation::None);
  auto* contacts = makeScatter(QString(), colors::kOverlay, 6);
  contacts->setPen(Qt::NoPen);
  m_contacts = addEntry(contacts, Decimation::Scatter);
}

void PhasePlot::nameFor(const ShownRun& run, int index) {
  const QString mass = subscriptDigits(index + 1);
  const bool stopped = index == run.stopped;
  setTitles(tr("Phase portrait of mass %1 (u%2, v%2)").arg(index + 1).arg(mass),
            tr("u%1 / d").arg(mass), tr("v%1 / (d ω₁)").arg(mass));
  entries()[std::size_t(m_recent)].series->setName(
      tr("orbit, %1 %2").arg(RunWindow::kPeriods).arg(run.unit.name));
  entries()[std::size_t(m_stop)].series->setName(stopped ? tr("stop u%1 = d").arg(mass)
                                                         : QString());
  entries()[std::size_t(m_contacts)].series->setName(stopped ? QString() : tr("at contacts"));
  QString tip;
  if (stopped) {
    tip = tr("Velocity of mass %1 against its displacement, over d and d ω₁ (ω₁ the fastest frequency). At "
             "the stop (dashed, u = d) an impact flips the velocity: the vertical jumps. Click on the stop "
             "line to start a run there: mass %1 leaves the stop at the clicked speed, %2; edit any value to "
             "go back.")
              .arg(index + 1)
              .arg(run.twoMass ? tr("mass 1 keeps its start position, on the same energy")
                               : tr("the others as at the start shown"));
  } else if (m_mass == Mass::First && run.twoMass) {
    tip = tr(
        "Velocity v₁ of mass 1 against its displacement u₁, over d and d ω₁. Mass 1 never touches the stop; "
        "it feels the impacts through the spring k₂ (the dots: its state at each contact).");
  } else {
    tip = tr("Mass %1's velocity against its displacement, over d and d ω₁ (the panel's 'phase of' chooses "
             "the mass); the dots are its state at each contact of the stopped mass.")
              .arg(index + 1);
  }
  setToolTip(tip +
             tr("\nA long run shows a few periods at the animation's time; W shows all of it."));
}

double PhasePlot::lastTime() const {
  return !m_run || m_samplesTaken == 0 ? 0 : m_run->samples.t(m_samplesTaken - 1);
}

std::optional<QPointF> PhasePlot::pointAt(double t) const {
  if (!m_run || m_samplesTaken == 0) return std::nullopt;
  const StateSpan& samples = m_run->samples;
  const auto point = [&](std::size_t k) {
    return QPointF(samples.value(k, samples.displacementField(m_index)) / m_run->gap,
                   samples.value(k, samples.velocityField(m_index)) / m_run->speed);
  };
  const std::size_t after = firstAtOrAfter(samples, m_samplesTaken, t);
  if (after == 0) return point(0);
  if (after == m_samplesTaken) return point(m_samplesTaken - 1);
  const double w = (t - samples.t(after - 1)) / (samples.t(after) - samples.t(after - 1));
  return point(after - 1) + w * (point(after) - point(after - 1));
}

void PhasePlot::setTimeCursor(double t) {
  m_cursorTime = t;
  const double toPeriods = m_run ? 1 / m_run->unit.length : 1.0;
  const double tLast = lastTime() * toPeriods;
  if (!m_whole && !m_runWindow.wholeFits(tLast) && m_runWindow.follow(t * toPeriods, tLast)) {
    placeWindow();
    scheduleRefresh();
  }
  if (!m_cursor) {
    // a ring: the start marker (and the orbit) show through it at t = 0
    auto* dot = makeScatter(QString(), colors::kAccent, 14);
    dot->setColor(Qt::transparent);
    useLightMarker(dot, QPen(colors::kAccent, 2.5));  // the marker's picture, drawn again hollow
    chart()->addSeries(dot);
    dot->attachAxis(m_axisX);
    dot->attachAxis(m_axisY);
    setInLegend(dot, false);
    m_cursor = dot;
  }
  if (const std::optional<QPointF> at = pointAt(t))
    m_cursor->replace({*at});
  else
    m_cursor->clear();
}

void PhasePlot::show(const SimUpdate& update) {
  std::optional<ShownRun> run = shownRun(update);
  if (!run) return;
  const int index = m_mass == Mass::First ? 0 : run->chosen;
  const bool grown = m_run && run->continues(*m_run) && index == m_index;
  if (!grown) {
    startNewRun();
    m_vLow = 0;
    m_vHigh = 0;
    m_samplesTaken = 0;
    m_eventsTaken = 0;
    setData(m_contacts, {});
    if (!m_run || !run->wordedAlike(*m_run) || index != m_index) nameFor(*run, index);
  }
  // the run's samples as they are, no copy: only the new ones widen the velocity range
  const StateSpan& samples = run->samples;
  const PointSpan path =
      samples.points(samples.displacementField(index), samples.velocityField(index))
          .scaled(1 / run->gap, 1 / run->speed);
  for (std::size_t k = m_samplesTaken; k < path.size(); ++k) {
    m_vLow = std::min(m_vLow, path[k].y());
    m_vHigh = std::max(m_vHigh, path[k].y());
  }
  m_samplesTaken = path.size();
  showInPlace(m_path, path, run->owner, grown);
  setData(m_start, {QPointF(run->start.u[index] / run->gap, run->start.v[index] / run->speed)});
  if (index == run->stopped) {
    setData(m_stop, {QPointF(1, m_vLow), QPointF(1, m_vHigh)});
  } else {
    // its state at each contact within the samples' span (the velocity before the contact)
    setData(m_stop, {});
    const double tLast = run->drawnUntil();
    std::vector<QPointF> marks;
    std::size_t next = m_eventsTaken;
    for (; next < run->eventCount() && run->eventTime(next) <= tLast; ++next) {
      if (!core::isContact(run->eventType(next))) continue;
      marks.emplace_back(run->eventU(next, index) / run->gap,
                         run->eventVBefore(next, index) / run->speed);
    }
    m_eventsTaken = next;
    appendData(m_contacts, marks);
  }
  m_run = std::move(run);
  m_index = index;
  placeWindow();
  scheduleRefresh();
}

void PhasePlot::placeWindow() {
  const double period = m_run ? m_run->unit.length : 1.0;
  const double tLast = lastTime() * (1 / period);
  const bool windowed = m_run && !m_whole && !m_runWindow.wholeFits(tLast);
  if (windowed) {
    m_runWindow.follow(m_cursorTime * (1 / period), tLast);
    // the window's stretch of the same samples, in place
    const std::size_t begin =
        firstAtOrAfter(m_run->samples, m_samplesTaken, m_runWindow.from() * period);
    const std::size_t end =
        firstAtOrAfter(m_run->samples, m_samplesTaken, m_runWindow.to() * period, true);
    const PointSpan whole = entries()[std::size_t(m_path)].points();
    showInPlace(m_recent, whole.subspan(begin, end - begin), m_run->owner, false);
  } else if (m_windowed) {
    setData(m_recent, {});
  }
  if (windowed == m_windowed) return;
  // the whole run still sets the axes (they do not jump as the window moves) but is not drawn:
  // sixty turns of a quasi-periodic orbit fill a disc, and cost a stroked point each
  m_windowed = windowed;
  QXYSeries* path = entries()[std::size_t(m_path)].series;
  path->setVisible(!windowed);
  setInLegend(path, !windowed);
  setInLegend(entries()[std::size_t(m_recent)].series, windowed);
}

void PhasePlot::setWholeRun(bool whole) {
  m_whole = whole;
  placeWindow();
  scheduleRefresh();
}

}  // namespace grazelab::ui
