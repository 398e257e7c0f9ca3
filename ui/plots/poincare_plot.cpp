// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/poincare_plot.h"

#include <QChart>
#include <QScatterSeries>

#include <algorithm>

#include "ui/plots/plot_style.h"
#include "ui/plots/run_points.h"

namespace grazelab::ui {

PoincarePlot::PoincarePlot(QWidget* parent)
    : PlotView(tr("Poincaré points on H (u₂ = d)"),
               tr("u₁ at contact"), tr("v₁"), parent) {
  for (int bin = 0; bin < kBins; ++bin) {
    // squares: Qt Charts draws them far faster than circles, which matters for 10^5 points
    auto* series = makeScatter(QString(), kViridis[bin], 4);
    series->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
    useLightMarker(series);
    m_bins[bin] = addEntry(series, Decimation::Scatter);
  }
  // the bins are one cloud: the last one drawn must not cover the others
  joinScatters(std::vector<int>(std::begin(m_bins), std::end(m_bins)));
  auto* reference = makeScatter(tr("reference"), colors::kReference, 11);
  reference->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
  reference->setColor(Qt::transparent);
  reference->setPen(QPen(colors::kReference, 2));
  useLightMarker(reference, QPen(colors::kReference, 2));
  m_reference = addEntry(reference, Decimation::None);
  setToolTip(tr("Each dot is the state (u₁, v₁) of mass 1 at a contact of mass 2 with the stop "
                "(the section H: u₂ = d). Colours run from early contacts (purple) to late ones "
                "(yellow); where many fall on one spot, the colour shown is one of them drawn at "
                "random, so every stretch of the run shows in proportion. The square marks the "
                "reference grazing orbit's data. Click a point of the plane to start a run there, on "
                "the same energy (mass 2 leaving the stop); edit any value to go back."));
}

void PoincarePlot::show(const SimUpdate& update) {
  const core::Result& result = *update.result;
  const auto count = std::int64_t(result.poincare.size());
  // equal-width bins over the contact index: while the run goes on, over the contacts asked
  // for (so that a point keeps its bin and the bins only grow); at the end over those made
  const std::int64_t asked = update.request->job.spec.run.maxContacts;
  const std::int64_t planned =
      update.final || asked <= 0 || asked > std::int64_t(1) << 40 ? count : std::max(asked, count);
  const std::int64_t per = std::max<std::int64_t>(1, (planned + kBins - 1) / kBins);
  bool grown = !m_taken.startsOver(update);
  if (!grown || per != m_perBin) {
    m_taken = RunProgress{};
    m_taken.runId = update.id;
    m_taken.attempt = update.attempt;
    m_perBin = per;
    startNewRun();
    grown = false;
  }
  // each bin is a stretch of contacts: the run's points as they are, no copy (the last bin
  // holds the rest)
  const PointSpan points = sectionPoints(result);
  m_taken.poincare = std::size_t(count);
  const auto& entryList = entries();
  for (int bin = 0; bin < kBins; ++bin) {
    const std::int64_t from = std::min<std::int64_t>(bin * per, count);
    const std::int64_t to = bin == kBins - 1 ? count : std::min<std::int64_t>((bin + 1) * per, count);
    showInPlace(m_bins[bin], points.subspan(std::size_t(from), std::size_t(to - from)), update.result, grown);
    const std::int64_t first = bin * per;
    const std::int64_t last = std::min(planned, first + per) - 1;
    const bool shown = to > from;
    // every bin is named in the legend (an empty one is left out); set only on a change:
    // each new name lays the chart out again
    QXYSeries* series = entryList[std::size_t(m_bins[bin])].series;
    const QString range = tr("%1–%2").arg(first).arg(last);
    const QString name = last < first ? QString() : bin == 0 ? tr("contacts %1").arg(range) : range;
    if (series->name() != name) series->setName(name);
    setInLegend(series, shown);
  }
  std::vector<QPointF> reference;
  clearExtraBounds();
  if (update.request->job.reference) {
    const core::State& data = *update.request->job.reference;
    reference.emplace_back(data.u1, data.v1);
    // points that coincide (a 1IPP orbit hits the same spot every period) still get a window
    // of a few percent of the gap around them, not one zoomed into round-off; and the square
    // marking the data is whole where it is the section's outermost point
    const double margin = 0.05 * update.request->params.gap;
    includeInBounds(data.u1, data.v1 - margin);
    includeInBounds(data.u1, data.v1 + margin);
    includeInBounds(data.u1 - margin, data.v1);
    includeInBounds(data.u1 + margin, data.v1);
  }
  QXYSeries* referenceSeries = entryList[std::size_t(m_reference)].series;
  if (referenceSeries->name() != update.request->job.referenceLabel) {
    referenceSeries->setName(update.request->job.referenceLabel);
  }
  setData(m_reference, std::move(reference));
  scheduleRefresh();
}

}  // namespace grazelab::ui
