// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/modes_plot.h"
#include "ui/plots/multipliers_plot.h"
#include "ui/plots/scene_view.h"

#include <algorithm>

#include "ui/plots/accuracy_view.h"
#include "ui/plots/chain_view.h"
#include "ui/plots/contrast_flights_plot.h"
#include "ui/plots/curve_plot.h"
#include "ui/plots/free_flight_plot.h"
#include "ui/plots/landscape_view.h"
#include "ui/plots/phase_plot.h"
#include "ui/plots/poincare_plot.h"
#include "ui/plots/trace_plot.h"

namespace grazelab::ui {

SceneView* makeView(PlotKind kind, QWidget* parent) {
  switch (kind) {
    case PlotKind::Trace: return new TracePlot(parent);
    case PlotKind::Phase: return new PhasePlot(PhasePlot::Mass::Chosen, parent);
    case PlotKind::PhaseU1V1: return new PhasePlot(PhasePlot::Mass::First, parent);
    case PlotKind::Poincare: return new PoincarePlot(parent);
    case PlotKind::FreeFlight: return new FreeFlightPlot(parent);
    case PlotKind::OnePeriodicData:
    case PlotKind::ImpactSpeed:
    case PlotKind::FrequencyEnergy:
    case PlotKind::GrazingMaximum:
    case PlotKind::SpreadAgainstSize:
    case PlotKind::FlightHistogram:
    case PlotKind::GrazingSet: return new CurvePlot(kind, parent);
    case PlotKind::Chain: return new ChainView(parent);
    case PlotKind::ContrastFlights: return new ContrastFlightsPlot(parent);
    case PlotKind::WorkPrecision: return new AccuracyView(parent);
    case PlotKind::Landscape: return new LandscapeView(parent);
    case PlotKind::ModesAtlas: return new ModesPlot(parent);
    case PlotKind::Multipliers: return new MultipliersPlot(parent);
  }
  return nullptr;
}

bool RunWindow::follow(double cursor, double tLast) {
  const double width = kPeriods;
  const double last = std::max(0.0, tLast - width);  // the latest start the window can have
  if (m_to - m_from == width && m_from <= last) {
    // kept while the time is in its middle half, or beyond it on a side where the run ends
    const bool lowSide = cursor >= m_from + width / 4 || m_from <= 0;
    const bool highSide = cursor <= m_to - width / 4 || m_from >= last;
    if (lowSide && highSide) return false;
  }
  const double from = std::clamp(cursor - width / 2, 0.0, last);
  if (from == m_from && from + width == m_to) return false;
  m_from = from;
  m_to = from + width;
  return true;
}

}  // namespace grazelab::ui
