// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/poincare_plot.h"

#include <QChart>
#include <QScatterSeries>

#include <algorithm>

#include "ui/plots/plot_style.h"
#include "ui/plots/run_points.h"
#include "ui/widgets/param_specs.h"

namespace grazelab::ui {

PoincarePlot::PoincarePlot(QWidget* parent)
    : PlotView(tr("Poincaré points on H: (u₁, v₁)"), tr("u₁ / d"), tr("v₁ / (d ω₁)"), parent) {
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
}

void PoincarePlot::nameFor(const ShownRun& run) {
  const QString x = run.coordinateName(run.sectionX), y = run.coordinateName(run.sectionY);
  setTitles(tr("Poincaré points on H: (%1, %2)").arg(x, y), run.coordinateAxis(run.sectionX),
            run.coordinateAxis(run.sectionY));
  const QString colours =
      tr("Colours run from early contacts (purple) to late ones (yellow); where many fall on one spot, the "
         "colour shown is one of them drawn at random, so every stretch of the run shows in proportion.");
  if (run.twoMass) {
    setToolTip(tr("Each dot is the state (u₁, v₁) of mass 1 at a contact of mass 2 with the stop (the "
                  "section H: u₂ = d), over d and d ω₁. %1 The square marks the reference grazing orbit's "
                  "data. Click a point of the plane to start a run there, on the same energy (mass 2 leaving "
                  "the stop); edit any value to go back.")
                   .arg(colours));
    return;
  }
  setToolTip(tr("The chain's state at each contact of mass %1 with the stop (the section H: u%2 = d), on the "
                "two coordinates chosen in the panel's 'section on' (velocities just before the contact), "
                "over d and d ω₁. A resonant chain's points lie on few curves; a chaotic run fills a region. "
                "%3 Click to start a run there: those two coordinates as clicked, the others as at the "
                "nearest contact, mass %1 leaving the stop at the speed that keeps the energy.")
                 .arg(run.stopped + 1)
                 .arg(subscriptDigits(run.stopped + 1), colours));
}

std::vector<QPointF> PoincarePlot::points() const {
  std::vector<QPointF> all;
  for (int bin = 0; bin < kBins; ++bin) {
    const std::vector<QPointF> some = entries()[std::size_t(m_bins[bin])].points().toVector();
    all.insert(all.end(), some.begin(), some.end());
  }
  return all;
}

void PoincarePlot::show(const SimUpdate& update) {
  std::optional<ShownRun> run = shownRun(update);
  if (!run) return;
  // (one mass has no section: its state on H is one point, said instead)
  const PointSpan points = run->masses() == 1 ? PointSpan() : run->sectionPoints();
  const auto count = std::int64_t(points.size());
  // equal-width bins over the contact index: while the run goes on, over the contacts asked
  // for (so that a point keeps its bin and the bins only grow); at the end over those made
  const std::int64_t asked = run->contactsAsked;
  const std::int64_t planned =
      run->whole || asked <= 0 || asked > std::int64_t(1) << 40 ? count : std::max(asked, count);
  const std::int64_t per = std::max<std::int64_t>(1, (planned + kBins - 1) / kBins);
  bool grown = m_run && run->continues(*m_run) && run->sectionX == m_run->sectionX &&
               run->sectionY == m_run->sectionY && per == m_perBin;
  if (!grown) {
    m_perBin = per;
    startNewRun();
    if (!m_run || !run->wordedAlike(*m_run)) nameFor(*run);
  }
  // one mass: on H its place is the stop and its speed the energy's, a single point
  setEmptyNote(run->masses() == 1
                   ? tr("One mass: on H its place is the stop and its speed the energy's; no section to draw.")
               : count == 0 && run->whole
                   ? tr("No contact with the stop in this run: no point on H to draw.")
                   : QString());
  // each bin is a stretch of contacts: the run's points as they are, no copy (the last bin
  // holds the rest)
  const auto& entryList = entries();
  for (int bin = 0; bin < kBins; ++bin) {
    const std::int64_t from = std::min<std::int64_t>(bin * per, count);
    const std::int64_t to =
        bin == kBins - 1 ? count : std::min<std::int64_t>((bin + 1) * per, count);
    showInPlace(m_bins[bin], points.subspan(std::size_t(from), std::size_t(to - from)), run->owner,
                grown);
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
  if (update.request->job.reference && run->twoMass) {
    const core::State& data = *update.request->job.reference;
    const QPointF at(data.u1 / run->gap, data.v1 / run->speed);
    reference.push_back(at);
    // points that coincide (a 1IPP orbit hits the same spot every period) still get a window
    // of a few percent of the gap around them, not one zoomed into round-off; and the square
    // marking the data is whole where it is the section's outermost point
    const double margin = 0.05;
    includeInBounds(at.x(), at.y() - margin);
    includeInBounds(at.x(), at.y() + margin);
    includeInBounds(at.x() - margin, at.y());
    includeInBounds(at.x() + margin, at.y());
  }
  QXYSeries* referenceSeries = entryList[std::size_t(m_reference)].series;
  if (referenceSeries->name() != update.request->job.referenceLabel) {
    referenceSeries->setName(update.request->job.referenceLabel);
  }
  setData(m_reference, std::move(reference));
  m_run = std::move(run);
  scheduleRefresh();
}

}  // namespace grazelab::ui
