// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/multipliers_plot.h"

#include <QChart>
#include <QLineSeries>
#include <QScatterSeries>

#include <algorithm>
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
  connect(chart(), &QChart::plotAreaChanged, this, [this] { fitEqualScale(); });
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
        tr("μ, 1/μ: tr = %1, %2").arg(orbit->trace, 0, 'g', 4).arg(QString::fromUtf8(core::toString(core::decidedStability(*orbit)).data())));
  }
  m_reach = 1.15;
  for (const QPointF& mu : points) m_reach = std::max(m_reach, 1.1 * std::hypot(mu.x(), mu.y()));
  setData(m_multipliers, std::move(points));
  fitEqualScale();
  scheduleRefresh();
}

void MultipliersPlot::fitEqualScale() {
  const QRectF area = chart()->plotArea();
  if (!(area.width() > 0 && area.height() > 0)) return;
  const double wide = area.width() / area.height();
  const double x = m_reach * std::max(1.0, wide);
  const double y = m_reach * std::max(1.0, 1.0 / wide);
  const QRectF range(QPointF(-x, -y), QPointF(x, y));
  if (m_fitted && std::abs(m_fitted->width() - range.width()) <= 1e-3 * range.width() &&
      std::abs(m_fitted->height() - range.height()) <= 1e-3 * range.height()) {
    return;  // the same within a pixel: no new layout
  }
  m_fitted = range;
  setFixedRange(range);
  scheduleRefresh();
}

}  // namespace grazelab::ui
