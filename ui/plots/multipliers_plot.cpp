// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/multipliers_plot.h"

#include <QLineSeries>
#include <QScatterSeries>

#include <cmath>

#include "ui/plots/plot_style.h"

namespace grazelab::ui {

MultipliersPlot::MultipliersPlot(QWidget* parent)
    : PlotView(tr("Multipliers of the orbit shown"), tr("Re μ"), tr("Im μ"), parent) {
  m_circle = addEntry(makeLine(tr("unit circle: stable"), colors::kReference, 1.2, Qt::DashLine), Decimation::None);
  auto* multipliers = makeScatter(tr("μ, 1/μ"), colors::kImpact, 12);
  multipliers->setPen(QPen(Qt::white, 1.5));
  useLightMarker(multipliers, QPen(Qt::white, 1.5));
  m_multipliers = addEntry(multipliers, Decimation::None);
  std::vector<QPointF> circle;
  for (int i = 0; i <= 128; ++i) {
    const double angle = 2 * M_PI * i / 128;
    circle.emplace_back(std::cos(angle), std::sin(angle));
  }
  setData(m_circle, std::move(circle));
  setToolTip(tr("The two multipliers μ and 1/μ of the orbit: how a small change of it grows or "
                "shrinks after one period (its other two are 1: the flow and the energy). On the "
                "unit circle the orbit is stable; a real pair off it is unstable; when they meet "
                "at −1 the orbit flips and a family of twice the impacts is born."));
}

void MultipliersPlot::show(const SimUpdate& update) {
  const auto& orbit = update.request->job.orbit;
  std::vector<QPointF> points;
  if (orbit) {
    for (const auto& mu : orbit->multipliers) points.emplace_back(mu[0], mu[1]);
    entries()[std::size_t(m_multipliers)].series->setName(
        tr("μ, 1/μ: tr = %1, %2").arg(orbit->trace, 0, 'g', 4).arg(QString::fromUtf8(core::toString(orbit->stability).data())));
  }
  setData(m_multipliers, std::move(points));
  scheduleRefresh();
}

}  // namespace grazelab::ui
