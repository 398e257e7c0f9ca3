// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/free_flight_plot.h"

#include <QLineSeries>
#include <QScatterSeries>

#include <algorithm>

#include "ui/plots/plot_style.h"

namespace grazelab::ui {

FreeFlightPlot::FreeFlightPlot(QWidget* parent)
    : PlotView(tr("Free-flight time at each contact"), tr("contact index"), tr("flight time / T₂"),
               parent) {
  auto* flights = makeScatter(tr("flights"), colors::kTrace, 5);
  flights->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
  useLightMarker(flights);
  m_flights = addEntry(flights, Decimation::Scatter);
  m_period =
      addEntry(makeLine(tr("bound: T₂"), colors::kImpact, 1.5, Qt::DashLine), Decimation::None);
  setAxesIndependent(true);
}

void FreeFlightPlot::nameFor(const ShownRun& run) {
  const QString unit = run.unit.name;
  entries()[std::size_t(m_period)].series->setName(run.flightsBounded ? tr("bound: %1").arg(unit)
                                                                      : QString());
  if (run.twoMass) {
    setTitles(tr("Free-flight time at each contact"), tr("contact index"),
              tr("flight time / %1").arg(unit));
    setToolTip(
        tr("Free-flight time (FFT): the time from leaving the stop to the next contact, against the index of "
           "that contact, in units of T₂, the slow period. Theorem 2.3: FFT ≤ T₂ (dashed: FFT / T₂ = 1), "
           "with equality only on a grazing orbit."));
    return;
  }
  setTitles(run.flightsBounded ? tr("Free flights from the stop / %1 (≤ 1)").arg(unit)
                               : tr("Free flights / %1 (no common period: no bound)").arg(unit),
            tr("contact index"), tr("flight / %1").arg(unit));
  setToolTip(tr("Each free flight from the stop (after an impact, a grazing or a release), over %1, against "
                "the index of the contact that ends it. A resonant chain's free motion repeats after its "
                "common period T, so no flight from the stop lasts longer (Theorem 2.3 for any N); a chain "
                "with no common period has no such bound.")
                 .arg(run.unit.inWords));
}

void FreeFlightPlot::show(const SimUpdate& update) {
  std::optional<ShownRun> run = shownRun(update);
  if (!run) return;
  if (!(m_run && run->continues(*m_run))) {
    startNewRun();
    setData(m_flights, {});
    m_taken = 0;
    if (!m_run || !run->wordedAlike(*m_run)) nameFor(*run);
  }
  const double period = run->unit.length;
  std::vector<QPointF> flights;
  for (; m_taken < run->flightCount(); ++m_taken) {
    const std::optional<ShownRun::Flight> flight = run->flightAt(m_taken);
    if (!flight) continue;  // (not from the stop)
    // 1 - shortfall / period: exact near the period, where FFT / period itself would round to 1
    flights.emplace_back(double(flight->contact), run->unitIsPeriod
                                                      ? 1.0 - flight->shortfall / period
                                                      : flight->duration / period);
  }
  appendData(m_flights, flights);
  const std::vector<QPointF>& all = entries()[std::size_t(m_flights)].data;
  const double last = all.empty() ? 1.0 : std::max(1.0, all.back().x());
  // decided by the run's length, not the flights so far: a look that changed mid-run made Qt
  // Charts build every marker again (57 ms for 20 000 contacts)
  const double flightsAsked = std::max(double(all.size()), double(run->contactsAsked));
  m_dense = flightsAsked > 2.0 * std::max(1, width());
  applyMarkers();
  // the whole run's contact range from its first update: an axis that grew as the run came
  // in moved every marker each time (25-50 ms a move for 20 000 contacts)
  clearExtraBounds();
  includeInBounds(double(std::max<std::int64_t>(1, run->contactsAsked)), 1.0);
  setData(m_period, run->flightsBounded ? std::vector<QPointF>{QPointF(0, 1.0), QPointF(last, 1.0)}
                                        : std::vector<QPointF>{});
  setEmptyNote(all.empty() && run->whole
                   ? tr("No free flight from the stop in this run: nothing to draw.")
                   : QString());
  m_run = std::move(run);
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
