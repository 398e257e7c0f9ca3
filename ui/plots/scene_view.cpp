// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/scene_view.h"

#include "ui/plots/accuracy_view.h"
#include "ui/plots/chain_view.h"
#include "ui/plots/curve_plot.h"
#include "ui/plots/free_flight_plot.h"
#include "ui/plots/landscape_view.h"
#include "ui/plots/phase_plot.h"
#include "ui/plots/poincare_plot.h"
#include "ui/plots/trace_plot.h"

namespace grazelab::ui {

bool RunProgress::startsOver(const SimUpdate& update) {
  const core::Result& result = *update.result;
  const bool grown = runId == update.id && attempt == update.attempt &&
                     events <= result.events.size() &&
                     poincare <= result.poincare.size() &&
                     freeFlights <= result.freeFlights.size() && samples <= result.samples.size();
  if (grown) return false;
  *this = RunProgress{};
  runId = update.id;
  attempt = update.attempt;
  return true;
}

SceneView* makeView(PlotKind kind, QWidget* parent) {
  switch (kind) {
    case PlotKind::TraceU2: return new TracePlot(parent);
    case PlotKind::PhaseU2V2: return new PhasePlot(PhasePlot::Mass::Two, parent);
    case PlotKind::PhaseU1V1: return new PhasePlot(PhasePlot::Mass::One, parent);
    case PlotKind::Poincare: return new PoincarePlot(parent);
    case PlotKind::FreeFlight: return new FreeFlightPlot(parent);
    case PlotKind::OnePeriodicData:
    case PlotKind::ImpactSpeed:
    case PlotKind::FrequencyEnergy:
    case PlotKind::GrazingMaximum:
    case PlotKind::SpreadAgainstSize:
    case PlotKind::FlightHistogram:
    case PlotKind::DetunedFlights:
    case PlotKind::ResonantFlights: return new CurvePlot(kind, parent);
    case PlotKind::Chain: return new ChainView(parent);
    case PlotKind::WorkPrecision: return new AccuracyView(parent);
    case PlotKind::Landscape: return new LandscapeView(parent);
  }
  return nullptr;
}

}  // namespace grazelab::ui
