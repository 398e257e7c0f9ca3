// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/free_flight_plot.h"

#include "core/model/linear_modes.h"

#include <QLineSeries>
#include <QScatterSeries>

#include <algorithm>

#include "ui/plots/plot_style.h"

namespace grazelab::ui {

FreeFlightPlot::FreeFlightPlot(QWidget* parent)
    : PlotView(tr("Free-flight time at each contact"), tr("contact index"), tr("flight time / T₂"), parent) {
  auto* flights = makeScatter(tr("flights"), colors::kTrace, 5);
  flights->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
  useLightMarker(flights);
  m_flights = addEntry(flights, Decimation::Scatter);
  m_period = addEntry(makeLine(tr("bound: T₂"), colors::kImpact, 1.5, Qt::DashLine), Decimation::None);
  setAxesIndependent(true);
  setToolTip(tr("Free-flight time (FFT): the time from leaving the stop to the next contact, "
                "against the index of that contact, in units of T₂, the slow period. Theorem 2.3: FFT ≤ T₂ "
                "(dashed: FFT / T₂ = 1), with equality only on a grazing orbit."));
}

void FreeFlightPlot::show(const SimUpdate& update) {
  const core::Result& result = *update.result;
  if (m_taken.startsOver(update)) {
    startNewRun();
    setData(m_flights, {});
  }
  // T2 of the run's own chain (the model travels with the request, not in the result)
  const double T2 = core::computeModes(update.request->job.spec.model).T2;
  std::vector<QPointF> flights;
  flights.reserve(result.freeFlights.size() - m_taken.freeFlights);
  for (std::size_t index = m_taken.freeFlights; index < result.freeFlights.size(); ++index) {
    const core::FreeFlight& flight = result.freeFlights[index];
    // 1 - shortfall / T2: exact near T2, where FFT / T2 itself would round to 1
    flights.emplace_back(double(flight.contactIndex), 1.0 - flight.shortfall / T2);
  }
  m_taken.freeFlights = result.freeFlights.size();
  appendData(m_flights, flights);
  const std::vector<QPointF>& all = entries()[std::size_t(m_flights)].data;
  const double last = all.empty() ? 1.0 : std::max(1.0, all.back().x());
  // decided by the run's length, not the flights so far: a look that changed mid-run made Qt
  // Charts build every marker again (57 ms for 20 000 contacts)
  const double flightsAsked = std::max(double(all.size()), double(update.request->job.spec.run.maxContacts));
  m_dense = flightsAsked > 2.0 * std::max(1, width());
  applyMarkers();
  // the whole run's contact range from its first update: an axis that grew as the run came
  // in moved every marker each time (25-50 ms a move for 20 000 contacts)
  clearExtraBounds();
  includeInBounds(double(std::max<std::int64_t>(1, update.request->job.spec.run.maxContacts)), 1.0);
  setData(m_period, {QPointF(0, 1.0), QPointF(last, 1.0)});
  scheduleRefresh();
}

void FreeFlightPlot::setPresentation(bool on, int textPixels) {
  PlotView::setPresentation(on, textPixels);
  applyMarkers();  // the presentation look enlarges every marker: not these, when dense
}

void FreeFlightPlot::applyMarkers() {
  // many flights per pixel column: small translucent dots, so that their density shows as
  // shade instead of a solid block of overlapping squares (projected too)
  auto* series = qobject_cast<QScatterSeries*>(entries()[std::size_t(m_flights)].series);
  // dense: a 7 px dot per 5 px cell (markerCells), a sixth of the markers of 2 px cells (Qt
  // Charts builds an item per marker: 20 000 flights held the window for 57 ms; once they
  // spread over the plot's height, 4 px cells made this the slowest plot of near grazing)
  const double size = m_dense ? (presentation() ? 8.0 : 7.0) : (presentation() ? 8.0 : 5.0);
  if (series->markerSize() == size) return;
  QColor color = colors::kTrace;
  if (m_dense) color.setAlpha(110);
  series->setMarkerSize(size);
  series->setColor(color);
  useLightMarker(series);
}

}  // namespace grazelab::ui
