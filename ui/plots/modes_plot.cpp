// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/modes_plot.h"

#include "ui/plots/csv_table.h"

#include <QChart>
#include <QScatterSeries>

#include <cmath>
#include <limits>

#include "ui/pictures/modes_picture.h"
#include "ui/plots/plot_style.h"

namespace grazelab::ui {

namespace {

int impactClass(int impacts) { return impacts == 1 ? 0 : impacts == 2 ? 1 : impacts == 4 ? 2 : 3; }

// short: the legend shares a small card with the picture (k as in the scene's text: the
// motion repeats after k impacts)
QString impactsText(int cls) {
  switch (cls) {
    case 0: return ModesPlot::tr("k = 1");
    case 1: return ModesPlot::tr("k = 2");
    case 2: return ModesPlot::tr("k = 4");
    default: return ModesPlot::tr("k ≥ 8");
  }
}

QPointF picturePoint(double energy, double period) {
  return {std::log10(energy), 2 * M_PI / period};
}

}  // namespace

ModesPlot::ModesPlot(QWidget* parent)
    : PlotView(tr("Modes: frequency against energy"), tr("log₁₀ E"), tr("frequency 2π/T"), parent) {
  // the legend names the colours once; rings say "unstable" in an entry of their own
  for (int cls = 0; cls < 4; ++cls) {
    const QColor colour = pictures::modesColor(cls == 0 ? 1 : cls == 1 ? 2 : cls == 2 ? 4 : 8);
    auto* stable = makeScatter(impactsText(cls), colour, 5.5);
    useLightMarker(stable);
    m_dots[cls][0] = addEntry(stable, Decimation::Scatter);
    auto* unstable = makeScatter(QString(), colour, 6);
    unstable->setColor(Qt::white);
    unstable->setPen(QPen(colour, 1.5));
    useLightMarker(unstable, QPen(colour, 1.5));
    m_dots[cls][1] = addEntry(unstable, Decimation::Scatter);
    setCsvName(m_dots[cls][0], tr("%1, stable").arg(impactsText(cls)));
    setCsvName(m_dots[cls][1], tr("%1, unstable").arg(impactsText(cls)));
  }
  auto* ring = makeScatter(tr("○ unstable"), Qt::white, 6);
  ring->setPen(QPen(Qt::darkGray, 1.5));
  useLightMarker(ring, QPen(Qt::darkGray, 1.5));
  m_unstableKey = addEntry(ring, Decimation::None, false);
  setInLegend(ring, true);
  auto* flips = makeScatter(tr("flip"), colors::kReference, 11);
  flips->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
  flips->setColor(Qt::transparent);
  flips->setPen(QPen(colors::kReference, 2));
  useLightMarker(flips, QPen(colors::kReference, 2));
  m_flips = addEntry(flips, Decimation::None);
  // a flip whose family the search did not find: drawn apart, never as if a family were there
  auto* orphans = makeScatter(tr("flip, no family found"), colors::kReference, 11);
  orphans->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
  orphans->setColor(colors::kReference);
  orphans->setPen(QPen(colors::kReference, 2));
  useLightMarker(orphans, QPen(colors::kReference, 2));
  m_orphanFlips = addEntry(orphans, Decimation::None);
  auto* ends = makeScatter(tr("grazing end"), colors::kReference, 9);
  useLightMarker(ends);
  m_ends = addEntry(ends, Decimation::None);
  auto* chosen = makeScatter(tr("the orbit shown"), colors::kAccent, 16);
  chosen->setColor(Qt::transparent);
  useLightMarker(chosen, QPen(colors::kAccent, 3));
  m_chosen = addEntry(chosen, Decimation::None, false);
  setToolTip(tr("Every periodic motion with impacts that the chain has, up to 4 impacts per period, "
                "as its frequency 2π/T against its energy (log scale): one dot per computed orbit, "
                "coloured by k, its impacts per period, filled where it is stable, a ring where it is "
                "not. Squares are flips, where a family with twice the impacts is born (filled: the "
                "search found no family there, see grazelab-cli modes for why); black dots "
                "are grazing ends; the large ring is the orbit shown in the other views.\n"
                "Click a family to follow that orbit in the other views."));
  connect(this, &PlotView::clickedAt, this, &ModesPlot::choose);
}

void ModesPlot::appendCsv(CsvTable& table) const {
  const QString plot = title();
  table.describe(plot, tr("energy E"), tr("frequency 2π/T"), tr("T/T₂"));
  if (!m_atlas) return;
  const auto add = [&](const QString& series, double energy, double period) {
    table.add(plot, series, energy, 2 * M_PI / period, m_T2 > 0 ? std::optional(period / m_T2) : std::nullopt);
  };
  for (const core::ModeFamily<double>& family : m_atlas->families) {
    const QString name = tr("family %1 (%2 impacts per period)").arg(family.id).arg(family.impacts);
    for (const core::FamilyOrbit<double>& orbit : family.orbits) {
      const bool stable = orbit.stability == core::Stability::Elliptic;
      add(name + (stable ? tr(", stable") : tr(", unstable")), orbit.energy, orbit.period);
    }
    for (const core::FamilyBifurcation<double>& b : family.bifurcations) {
      QString kind = QString::fromUtf8(core::toString(b.kind).data());
      if (b.kind == core::PointKind::PeriodDoubling && b.born < 0 && !b.birthProblem.empty()) {
        kind = tr("flip, no family found");
      }
      add(name + QStringLiteral(": ") + kind, b.energy, b.T);
    }
    for (const core::FamilyEnd<double>* end : {&family.startEnd, &family.end}) {
      if (end->period > 0) {
        add(name + tr(": end (%1)").arg(QString::fromUtf8(core::toString(end->kind).data())), end->energy, end->period);
      }
    }
  }
}

void ModesPlot::show(const SimUpdate& update) {
  const SceneJob& job = update.request->job;
  if (!job.modes) return;
  if (job.modes != m_atlas) {
    m_atlas = job.modes;
    m_T2 = update.request->derived.modes.T2;
    std::vector<QPointF> dots[4][2];
    std::vector<QPointF> flips;
    std::vector<QPointF> orphanFlips;
    std::vector<QPointF> ends;
    for (const core::ModeFamily<double>& family : m_atlas->families) {
      const int cls = impactClass(family.impacts);
      for (const core::FamilyOrbit<double>& orbit : family.orbits) {
        const bool stable = orbit.stability == core::Stability::Elliptic;
        dots[cls][stable ? 0 : 1].push_back(picturePoint(orbit.energy, orbit.period));
      }
      for (const auto& b : family.bifurcations) {
        if (b.kind != core::PointKind::PeriodDoubling) continue;
        // birthProblem is empty where no search was made (beyond the impacts shown)
        (b.born < 0 && !b.birthProblem.empty() ? orphanFlips : flips).push_back(picturePoint(b.energy, b.T));
      }
      for (const core::FamilyEnd<double>* end : {&family.end, &family.startEnd}) {
        if (end->kind == core::PointKind::GrazingOrbit && end->period > 0) ends.push_back(picturePoint(end->energy, end->period));
      }
    }
    const auto& list = entries();
    for (int cls = 0; cls < 4; ++cls) {
      for (int stable = 0; stable < 2; ++stable) {
        if (stable == 0) {
          // a class is named when it has orbits at all
          setInLegend(list[std::size_t(m_dots[cls][0])].series, !dots[cls][0].empty() || !dots[cls][1].empty());
        }
        setData(m_dots[cls][stable], std::move(dots[cls][stable]));
      }
    }
    setInLegend(list[std::size_t(m_orphanFlips)].series, !orphanFlips.empty());
    setData(m_flips, std::move(flips));
    setData(m_orphanFlips, std::move(orphanFlips));
    setData(m_ends, std::move(ends));
    startNewRun();
  }
  std::vector<QPointF> chosen;
  if (job.orbit) chosen.push_back(picturePoint(job.orbit->energy, job.orbit->period));
  setData(m_chosen, std::move(chosen));
  scheduleRefresh();
}

void ModesPlot::choose(QPointF value) {
  if (!m_atlas) return;
  const QPointF clicked = chart()->mapToPosition(value);
  double best = kChoiceRadius;
  const core::FamilyOrbit<double>* found = nullptr;
  for (const core::ModeFamily<double>& family : m_atlas->families) {
    for (const core::FamilyOrbit<double>& orbit : family.orbits) {
      const QPointF at = chart()->mapToPosition(picturePoint(orbit.energy, orbit.period));
      const double distance = std::hypot(at.x() - clicked.x(), at.y() - clicked.y());
      if (distance < best) {
        best = distance;
        found = &orbit;
      }
    }
  }
  if (found) emit orbitChosen(found->state);
  else emit missed();
}

}  // namespace grazelab::ui
