// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/phase_plot.h"

#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>

#include "ui/plots/plot_style.h"

#include <QChart>
#include <QLegend>
#include <QLegendMarker>
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
                      "u₂ = d) an impact flips v₂ to −v₂: the vertical jumps.")
                 : tr("Velocity v₁ of mass 1 against its displacement u₁. Mass 1 never touches "
                      "the stop; it feels the impacts through the spring k₂."));
}

void PhasePlot::setTimeCursor(double, const core::State& state) {
  if (!m_cursor) {
    auto* dot = makeScatter(QString(), colors::kAccent, 12);
    chart()->addSeries(dot);
    dot->attachAxis(m_axisX);
    dot->attachAxis(m_axisY);
    for (QLegendMarker* marker : chart()->legend()->markers(dot)) marker->setVisible(false);
    m_cursor = dot;
  }
  m_cursor->replace({m_mass == Mass::Two ? QPointF(state.u2, state.v2) : QPointF(state.u1, state.v1)});
}

void PhasePlot::show(const SimUpdate& update) {
  const core::Result& result = *update.result;
  std::vector<QPointF> path;
  path.reserve(result.samples.size());
  double vLow = 0;
  double vHigh = 0;
  for (const core::Sample& sample : result.samples) {
    const core::State& state = sample.state;
    path.push_back(m_mass == Mass::Two ? QPointF(state.u2, state.v2) : QPointF(state.u1, state.v1));
    vLow = std::min(vLow, path.back().y());
    vHigh = std::max(vHigh, path.back().y());
  }
  const core::State& initial = update.request->request.initial;
  setData(m_start, {m_mass == Mass::Two ? QPointF(initial.u2, initial.v2)
                                        : QPointF(initial.u1, initial.v1)});
  setData(m_path, std::move(path));
  if (m_stop >= 0) {
    const double gap = update.request->model.gap;
    setData(m_stop, {QPointF(gap, vLow), QPointF(gap, vHigh)});
  }
  scheduleRefresh();
}

}  // namespace grazelab::ui
