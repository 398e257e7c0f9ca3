// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/phase_plot.h"

#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>

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

void PhasePlot::setTimeCursor(double, const core::State& state) {
  if (!m_cursor) {
    auto* dot = makeScatter(QString(), colors::kAccent, 12);
    chart()->addSeries(dot);
    dot->attachAxis(m_axisX);
    dot->attachAxis(m_axisY);
    setInLegend(dot, false);
    m_cursor = dot;
  }
  m_cursor->replace({m_mass == Mass::Two ? QPointF(state.u2, state.v2) : QPointF(state.u1, state.v1)});
}

void PhasePlot::show(const SimUpdate& update) {
  const core::Result& result = *update.result;
  if (m_taken.startsOver(update)) {
    startNewRun();
    setData(m_path, {});
    m_vLow = 0;
    m_vHigh = 0;
  }
  std::vector<QPointF> path;
  path.reserve(result.samples.size() - m_taken.samples);
  for (std::size_t index = m_taken.samples; index < result.samples.size(); ++index) {
    const core::State& state = result.samples[index].state;
    path.push_back(m_mass == Mass::Two ? QPointF(state.u2, state.v2) : QPointF(state.u1, state.v1));
    m_vLow = std::min(m_vLow, path.back().y());
    m_vHigh = std::max(m_vHigh, path.back().y());
  }
  m_taken.samples = result.samples.size();
  appendData(m_path, path);
  const core::State& initial = update.request->job.request.initial;
  setData(m_start, {m_mass == Mass::Two ? QPointF(initial.u2, initial.v2)
                                        : QPointF(initial.u1, initial.v1)});
  if (m_stop >= 0) {
    const double gap = update.request->job.model.gap;
    setData(m_stop, {QPointF(gap, m_vLow), QPointF(gap, m_vHigh)});
  }
  scheduleRefresh();
}

}  // namespace grazelab::ui
