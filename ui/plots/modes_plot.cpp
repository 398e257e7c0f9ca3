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
  // three masses or more: where multipliers of opposite Krein signature collide and leave the circle
  auto* krein = makeScatter(tr("Krein collision"), colors::kReference, 12);
  krein->setMarkerShape(QScatterSeries::MarkerShapeTriangle);
  krein->setColor(Qt::transparent);
  krein->setPen(QPen(colors::kReference, 2));
  useLightMarker(krein, QPen(colors::kReference, 2));
  m_krein = addEntry(krein, Decimation::None);
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
                "search found no family there, see grazelab-cli modes for why); triangles (three "
                "masses or more) are Krein collisions, where two multiplier pairs of opposite "
                "signature meet on the unit circle and leave it; black dots are grazing ends; the "
                "large ring is the orbit shown in the other views.\n"
                "Click a family to follow that orbit in the other views."));
  connect(this, &PlotView::clickedAt, this, &ModesPlot::choose);
}

void ModesPlot::appendCsv(CsvTable& table) const {
  const QString plot = title();
  table.describe(plot, tr("energy E"), tr("frequency 2π/T"), tr("T/T₂"));
  if (!m_atlas) return;
  const double slow = m_atlas->slowPeriod;
  const auto add = [&](const QString& series, double energy, double period) {
    table.add(plot, series, energy, 2 * M_PI / period, slow > 0 ? std::optional(period / slow) : std::nullopt);
  };
  for (std::size_t f = 0; f < m_atlas->families.size(); ++f) {
    const AtlasFigure::Family& family = m_atlas->families[f];
    const QString name = tr("family %1 (%2 impacts per period)").arg(family.id).arg(family.impacts);
    for (const AtlasFigure::Orbit& orbit : family.orbits) {
      add(name + (orbit.stable ? tr(", stable") : tr(", unstable")), orbit.energy, orbit.period);
    }
    for (const AtlasFigure::Mark& mark : m_atlas->marks) {
      if (mark.family == int(f)) add(name + QStringLiteral(": ") + mark.label, mark.energy, mark.period);
    }
  }
}

void ModesPlot::show(const SimUpdate& update) {
  const SceneJob& job = update.request->job;
  if (!job.atlas && !m_atlas) return;
  if (!job.atlas) {
    // a chain refused before its atlas: the last chain's picture does not stay up as if it were this one's
    m_atlas.reset();
    for (int i = 0; i < int(entries().size()); ++i) setData(i, {});
    startNewRun();
    scheduleRefresh();
    return;
  }
  if (job.atlas != m_atlas) {
    m_atlas = job.atlas;
    std::vector<QPointF> dots[4][2];
    std::vector<QPointF> marks[5];
    for (const AtlasFigure::Family& family : m_atlas->families) {
      const int cls = impactClass(family.impacts);
      for (const AtlasFigure::Orbit& orbit : family.orbits) {
        dots[cls][orbit.stable ? 0 : 1].push_back(picturePoint(orbit.energy, orbit.period));
      }
    }
    for (const AtlasFigure::Mark& mark : m_atlas->marks) {
      marks[int(mark.kind)].push_back(picturePoint(mark.energy, mark.period));  // (Other: not drawn)
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
    const auto markEntry = [&](AtlasFigure::MarkKind kind) -> std::vector<QPointF>& { return marks[int(kind)]; };
    setInLegend(list[std::size_t(m_orphanFlips)].series, !markEntry(AtlasFigure::MarkKind::OrphanFlip).empty());
    setInLegend(list[std::size_t(m_krein)].series, !markEntry(AtlasFigure::MarkKind::KreinCollision).empty());
    setData(m_flips, std::move(markEntry(AtlasFigure::MarkKind::Flip)));
    setData(m_orphanFlips, std::move(markEntry(AtlasFigure::MarkKind::OrphanFlip)));
    setData(m_krein, std::move(markEntry(AtlasFigure::MarkKind::KreinCollision)));
    setData(m_ends, std::move(markEntry(AtlasFigure::MarkKind::GrazingEnd)));
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
  int family = -1, orbit = -1;
  for (std::size_t f = 0; f < m_atlas->families.size(); ++f) {
    const std::vector<AtlasFigure::Orbit>& orbits = m_atlas->families[f].orbits;
    for (std::size_t i = 0; i < orbits.size(); ++i) {
      const QPointF at = chart()->mapToPosition(picturePoint(orbits[i].energy, orbits[i].period));
      const double distance = std::hypot(at.x() - clicked.x(), at.y() - clicked.y());
      if (distance < best) {
        best = distance;
        family = int(f);
        orbit = int(i);
      }
    }
  }
  if (family >= 0) {
    emit orbitChosen(family, orbit, m_atlas->families[std::size_t(family)].orbits[std::size_t(orbit)].state);
  } else {
    emit missed();
  }
}

}  // namespace grazelab::ui
