// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/multipliers_plot.h"

#include <QChart>
#include <QLineSeries>
#include <QScatterSeries>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "ui/plots/plot_style.h"

namespace grazelab::ui {

MultipliersPlot::MultipliersPlot(QWidget* parent)
    : PlotView(tr("Multipliers of the orbit shown"), tr("Re μ"), tr("Im μ"), parent) {
  m_circle = addEntry(makeLine(tr("unit circle: stable"), colors::kReference, 1.2, Qt::DashLine), Decimation::None);
  auto* multipliers = makeScatter(tr("μ, 1/μ"), colors::kImpact, 12);
  multipliers->setPen(QPen(Qt::white, 1.5));
  useLightMarker(multipliers, QPen(Qt::white, 1.5));
  m_multipliers = addEntry(multipliers, Decimation::None);
  // N masses: each multiplier on the circle by its Krein signature
  for (const auto& [entry, name, colour] : {std::tuple{&m_kreinPlus, tr("Krein +"), colors::kTrace},
                                            std::tuple{&m_kreinMinus, tr("Krein −"), colors::kOverlay}}) {
    auto* signed_ = makeScatter(name, colour, 12);
    signed_->setPen(QPen(Qt::white, 1.5));
    useLightMarker(signed_, QPen(Qt::white, 1.5));
    *entry = addEntry(signed_, Decimation::None);
  }
  std::vector<QPointF> circle;
  for (int i = 0; i <= 128; ++i) {
    const double angle = 2 * M_PI * i / 128;
    circle.emplace_back(std::cos(angle), std::sin(angle));
  }
  setData(m_circle, std::move(circle));
  connect(chart(), &QChart::plotAreaChanged, this, [this] { fitEqualScale(); });
  setToolTip(tr("The multipliers of the orbit: how a small change of it grows or shrinks after one "
                "period (two for two masses, 2N − 2 for N; the other two are 1: the flow and the "
                "energy). On the unit circle the orbit is stable; off it unstable; when a pair meets "
                "at −1 the orbit flips and a family of twice the impacts is born. Of three masses or "
                "more each multiplier on the circle has a Krein signature (+ blue, − green): two of "
                "opposite signature can meet and leave the circle as four (a Krein collision), two "
                "of the same cannot."));
}

void MultipliersPlot::show(const SimUpdate& update) {
  const std::optional<ShownOrbit>& orbit = update.request->job.orbit;
  std::vector<QPointF> points, plus, minus;
  if (orbit) {
    for (std::size_t i = 0; i < orbit->multipliers.size(); ++i) {
      const QPointF mu(orbit->multipliers[i].real(), orbit->multipliers[i].imag());
      const int krein = i < orbit->krein.size() ? orbit->krein[i] : 0;
      (krein > 0 ? plus : krein < 0 ? minus : points).push_back(mu);
    }
    entries()[std::size_t(m_multipliers)].series->setName(
        orbit->trace ? tr("μ, 1/μ: tr = %1, %2").arg(*orbit->trace, 0, 'g', 4).arg(orbit->stability)
                     : tr("μ: %1").arg(orbit->stability));
  }
  const auto& list = entries();
  setInLegend(list[std::size_t(m_kreinPlus)].series, orbit && !orbit->krein.empty());
  setInLegend(list[std::size_t(m_kreinMinus)].series, orbit && !orbit->krein.empty());
  m_reach = 1.15;
  for (const auto* set : {&points, &plus, &minus}) {
    for (const QPointF& mu : *set) m_reach = std::max(m_reach, 1.1 * std::hypot(mu.x(), mu.y()));
  }
  setData(m_multipliers, std::move(points));
  setData(m_kreinPlus, std::move(plus));
  setData(m_kreinMinus, std::move(minus));
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
