// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/phase_plot.h"

#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>

#include "core/model/linear_modes.h"
#include "ui/plots/run_points.h"
#include "ui/plots/plot_style.h"

#include <QChart>
#include <QScatterSeries>

namespace grazelab::ui {

PhasePlot::PhasePlot(Mass mass, QWidget* parent)
    : PlotView(mass == Mass::Two ? tr("Phase portrait of mass 2 (u₂, v₂)")
                                 : tr("Phase portrait of mass 1 (u₁, v₁)"),
               mass == Mass::Two ? tr("u₂") : tr("u₁"), mass == Mass::Two ? tr("v₂") : tr("v₁"),
               parent),
      m_mass(mass) {
  m_path = addEntry(makeLine(tr("orbit"), colors::kTrace, 1.0), Decimation::Path);
  m_recent = addEntry(makeLine(tr("orbit, %1 T₂").arg(RunWindow::kPeriods),
                               colors::kTrace, 1.0),
                      Decimation::Path);
  setInLegend(entries()[std::size_t(m_recent)].series, false);
  if (mass == Mass::Two) {
    m_stop = addEntry(makeLine(tr("stop u₂ = d"), colors::kStop, 1.5, Qt::DashLine),
                      Decimation::None);
  }
  m_start = addEntry(makeScatter(tr("start"), colors::kImpact, 8), Decimation::None);
  setToolTip(mass == Mass::Two
                 ? tr("Velocity v₂ of mass 2 against its displacement u₂. At the stop (dashed, "
                      "u₂ = d) an impact flips v₂ to −v₂: the vertical jumps. Click on the stop "
                      "line to start a run there: mass 2 leaves the stop at the clicked speed, "
                      "mass 1 keeps its start position, on the same energy; edit any value to go back.")
                 : tr("Velocity v₁ of mass 1 against its displacement u₁. Mass 1 never touches "
                      "the stop; it feels the impacts through the spring k₂."));
}

double PhasePlot::lastTime() const {
  return m_samples == 0 ? 0 : m_run->samples[m_samples - 1].t;
}

std::optional<QPointF> PhasePlot::pointAt(double t) const {
  if (m_samples == 0) return std::nullopt;
  const auto first = m_run->samples.begin(), end = first + std::ptrdiff_t(m_samples);
  const auto after = std::lower_bound(first, end, t, [](const core::Sample& s, double time) { return s.t < time; });
  const auto point = [this](const core::State& x) {
    return m_mass == Mass::Two ? QPointF(x.u2, x.v2) : QPointF(x.u1, x.v1);
  };
  if (after == first) return point(first->state);
  if (after == end) return point((end - 1)->state);
  const core::Sample& a = *(after - 1);
  const double w = (t - a.t) / (after->t - a.t);
  return point(a.state) + w * (point(after->state) - point(a.state));
}

void PhasePlot::setTimeCursor(double t) {
  m_cursorTime = t;
  const double tLast = lastTime();
  if (!m_whole && !m_runWindow.wholeFits(tLast, m_T2) && m_runWindow.follow(t, tLast, m_T2)) {
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
  if (const std::optional<QPointF> at = pointAt(t)) m_cursor->replace({*at});
  else m_cursor->clear();
}

void PhasePlot::show(const SimUpdate& update) {
  const core::Result& result = *update.result;
  const bool grown = !m_taken.startsOver(update);
  if (!grown) {
    startNewRun();
    m_vLow = 0;
    m_vHigh = 0;
  }
  // the run's samples as they are, no copy: only the new ones widen the velocity range
  const PointSpan path = samplePoints(result, m_mass == Mass::Two ? SampleAxes::U2V2 : SampleAxes::U1V1);
  for (std::size_t index = m_taken.samples; index < path.size(); ++index) {
    m_vLow = std::min(m_vLow, path[index].y());
    m_vHigh = std::max(m_vHigh, path[index].y());
  }
  m_taken.samples = path.size();
  m_run = update.result;
  m_samples = path.size();
  showInPlace(m_path, path, update.result, grown);
  const core::State& initial = update.request->job.spec.run.initial;
  setData(m_start, {m_mass == Mass::Two ? QPointF(initial.u2, initial.v2)
                                        : QPointF(initial.u1, initial.v1)});
  if (m_stop >= 0) {
    const double gap = update.request->job.spec.model.gap;
    setData(m_stop, {QPointF(gap, m_vLow), QPointF(gap, m_vHigh)});
  }
  m_T2 = core::computeModes(update.request->job.spec.model).T2;
  placeWindow();
  scheduleRefresh();
}

void PhasePlot::placeWindow() {
  const double tLast = lastTime();
  const bool windowed = !m_whole && !m_runWindow.wholeFits(tLast, m_T2);
  if (windowed) {
    m_runWindow.follow(m_cursorTime, tLast, m_T2);
    // the window's stretch of the same samples, in place
    const auto first = m_run->samples.begin();
    const auto last = first + std::ptrdiff_t(m_samples);
    const auto byTime = [](const core::Sample& sample, double t) { return sample.t < t; };
    const auto begin = std::lower_bound(first, last, m_runWindow.from(), byTime);
    const auto end = std::upper_bound(begin, last, m_runWindow.to(),
                                      [](double t, const core::Sample& sample) { return t < sample.t; });
    const PointSpan whole = entries()[std::size_t(m_path)].points();
    showInPlace(m_recent, whole.subspan(std::size_t(begin - first), std::size_t(end - begin)), m_run, false);
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
