// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/landscape_view.h"

#include "ui/plots/csv_table.h"

#include <QComboBox>

#include "ui/widgets/eliding_combo_box.h"
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolButton>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/model/two_mass_form.h"
#include "core/orbits/special_orbits.h"
#include "ui/pictures/heat_map.h"
#include "core/model/linear_modes.h"
#include "ui/plots/plot_style.h"

namespace grazelab::ui {
namespace {

constexpr int kClickSlack = 4;  // pixels a press may move and still be a click

/// The colour bar's title in words, and whether the map's values (in time) are shown in units
/// of T2, as every scene shows free-flight times ("fft_first [time]" meant nothing to a class).
struct QuantityInWords {
  QString title;
  bool overT2 = false;
};

QuantityInWords inWords(core::Quantity quantity) {
  using core::Quantity;
  switch (quantity) {
    case Quantity::FftFirst: return {LandscapeView::tr("first free flight / T₂"), true};
    case Quantity::FftMin: return {LandscapeView::tr("shortest free flight / T₂"), false};
    case Quantity::FftMax: return {LandscapeView::tr("longest free flight / T₂"), false};
    case Quantity::FftMean: return {LandscapeView::tr("mean free flight / T₂"), false};
    case Quantity::Impacts: return {LandscapeView::tr("number of impacts"), false};
    case Quantity::Grazings: return {LandscapeView::tr("number of grazings"), false};
    case Quantity::Sticks: return {LandscapeView::tr("number of stuck phases"), false};
    case Quantity::FirstImpactTime: return {LandscapeView::tr("time of the first impact / T₂"), true};
    case Quantity::Horizon: return {LandscapeView::tr("predictability horizon / T₂"), true};
  }
  return {};
}

}  // namespace

LandscapeView::LandscapeView(QWidget* parent) : QWidget(parent) {
  auto* bar = new QHBoxLayout;
  bar->setContentsMargins(6, 4, 6, 0);
  auto* label = new QLabel(tr("Show:"));
  m_quantityBox = new ElidingComboBox;
  for (const core::QuantityInfo& info : core::quantities()) {
    if (info.quantity == core::Quantity::Horizon) continue;  // the map is not estimated
    // core's words are plain text for files and terminals ("/ T2"): shown with T₂
    m_quantityBox->addItem(QString::fromUtf8(info.meaning).replace(QStringLiteral("T2"), QStringLiteral("T₂")),
                           int(info.quantity));
  }
  m_quantityBox->setToolTip(tr("The quantity of each run drawn on the map (each point is a run "
                               "of 10 contacts from that start)"));
  label->setBuddy(m_quantityBox);
  m_back = new QToolButton;
  m_back->setText(tr("Back"));
  m_back->setToolTip(tr("The region shown before the last rectangle (Alt+Left)"));
  m_back->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Left));
  m_back->setEnabled(false);
  m_status = new QLabel;
  m_status->setTextInteractionFlags(Qt::NoTextInteraction);
  m_status->setWordWrap(true);
  m_status->setContentsMargins(6, 0, 6, 0);
  bar->addWidget(label);
  bar->addWidget(m_quantityBox, 1);
  bar->addWidget(m_back);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(bar);
  layout->addWidget(m_status);
  layout->addStretch(1);
  connect(m_quantityBox, &QComboBox::currentIndexChanged, this, [this] {
    m_quantity = core::Quantity(m_quantityBox->currentData().toInt());
    update();
  });
  connect(m_back, &QToolButton::clicked, this, &LandscapeView::backRequested);
  setMouseTracking(false);
  setMinimumSize(320, 280);
  setToolTip(tr("Click: a run from that start (u₁, d, v₁, 0). Drag a rectangle: that region "
                "computed anew at full resolution. Back: the region before."));
}

void LandscapeView::setQuantity(core::Quantity quantity) {
  const int index = m_quantityBox->findData(int(quantity));
  if (index >= 0) m_quantityBox->setCurrentIndex(index);
}

void LandscapeView::setBackEnabled(bool enabled) { m_back->setEnabled(enabled); }

void LandscapeView::show(const SimUpdate& update) {
  // a map being computed again for the same region (a new run's request) is the one shown
  const bool sameAsShown = update.map && m_map && m_map->complete && m_map->spec == update.map->spec;
  if (update.map && !sameAsShown) {
    m_map = update.map;
    const auto& spec = update.map->spec;
    const QString cost = update.map->complete
                             ? tr("%1 × %2 runs of %3 contacts in %4 s")
                                   .arg(spec.x.count)
                                   .arg(spec.y.count)
                                   .arg(spec.contacts)
                                   .arg(update.map->seconds, 0, 'f', 2)
                             : tr("computing: %1 of %2 rows")
                                   .arg(update.map->rowsDone)
                                   .arg(spec.y.count);
    m_cost = cost;
  }
  const SimRequest& request = *update.request;
  m_gap = request.job.spec.model.gap;
  // the grazing family and its two modes, from the run's chain
  const core::TwoMassFormOrProblem<double> formed = core::makeTwoMassForm(request.job.spec.model);
  m_family.clear();
  m_T2 = core::computeModes(request.job.spec.model).T2;
  if (formed.chain && formed.chain->resonant) {
    for (int step = 0; step <= 64; ++step) {
      const core::State data = core::gloData(*formed.chain, 4.0 / 3.0 * step / 64);
      m_family.emplace_back(data.u1, data.v1);
    }
    const core::State fast = core::glomData(*formed.chain, core::Mode::Fast);
    const core::State slow = core::glomData(*formed.chain, core::Mode::Slow);
    m_glom1 = QPointF(fast.u1, fast.v1);
    m_glom2 = QPointF(slow.u1, slow.v1);
  }
  m_section.clear();
  for (const core::PoincarePoint& point : update.result->poincare) m_section.emplace_back(point.u1, point.v1);
  const core::State& start = request.job.spec.run.initial;
  m_start.reset();
  if (start.u2 == m_gap && start.v2 == 0) m_start = QPointF(start.u1, start.v1);
  // the key of the marks over the map (the start's only when the run starts on this plane,
  // where the cross is drawn), and what the map cost
  const QString startKey = m_start ? tr("<span style=\"color:%1\">✚</span> its start · ").arg(colors::kAccent.name())
                                   : QString();
  m_status->setText(tr("<span style=\"color:%1\">●</span> the run's (u₁, v₁) at each contact · %2"
                       "╍ GLO(λ), λ in [0, 4/3] · %3")
                        .arg(colors::kImpact.name(), startKey, m_cost));
  QWidget::update();
}

void LandscapeView::setPresentation(bool on, int textPixels) {
  m_textPixels = on ? textPixels : 0;
  QFont font = this->font();
  if (on) {
    font.setPixelSize(textPixels);
  } else {
    font = QFont();
  }
  setFont(font);
  update();
}

QRectF LandscapeView::mapArea() const {
  const double top = m_status->geometry().bottom() + 4;
  return QRectF(0, top, width(), height() - top);
}

QRectF LandscapeView::plotRect() const { return pictures::heatMapPlotArea(mapArea(), font(), m_data); }

std::optional<QPointF> LandscapeView::valueAt(QPointF position) const {
  if (!m_map) return std::nullopt;
  const QRectF plot = plotRect();
  if (!plot.contains(position)) return std::nullopt;
  const auto& spec = m_map->spec;
  const auto [x0, x1] = pictures::cellExtent(spec.x.from, spec.x.to, spec.x.count);
  const auto [y0, y1] = pictures::cellExtent(spec.y.from, spec.y.to, spec.y.count);
  return QPointF(x0 + (position.x() - plot.left()) / plot.width() * (x1 - x0),
                 y0 + (plot.bottom() - position.y()) / plot.height() * (y1 - y0));
}

QPointF LandscapeView::positionOf(QPointF value) const { return positionIn(plotRect(), value); }

QPointF LandscapeView::positionIn(const QRectF& plot, QPointF value) const {
  if (!m_map) return {};
  const auto& spec = m_map->spec;
  const auto [x0, x1] = pictures::cellExtent(spec.x.from, spec.x.to, spec.x.count);
  const auto [y0, y1] = pictures::cellExtent(spec.y.from, spec.y.to, spec.y.count);
  return QPointF(plot.left() + (value.x() - x0) / (x1 - x0) * plot.width(),
                 plot.bottom() - (value.y() - y0) / (y1 - y0) * plot.height());
}

void LandscapeView::appendCsv(CsvTable& table) const {
  if (!m_map) return;
  const pictures::HeatMapData data = heatMapDataOf(*m_map);
  table.describe(data.title, data.xTitle, data.yTitle, data.valueTitle);
  const auto at = [](double from, double to, std::int64_t count, std::int64_t i) {
    return count > 1 ? from + (to - from) * double(i) / double(count - 1) : from;
  };
  const std::int64_t ready = data.rowsReady < 0 ? data.rows : data.rowsReady;
  for (std::int64_t row = 0; row < ready; ++row) {
    for (std::int64_t column = 0; column < data.columns; ++column) {
      table.add(data.title, tr("map"), at(data.xFrom, data.xTo, data.columns, column),
                at(data.yFrom, data.yTo, data.rows, row), data.values[std::size_t(row * data.columns + column)]);
    }
  }
  for (const QPointF& p : m_family) table.add(data.title, tr("grazing family GLO_λ, λ in [0, 4/3]"), p.x(), p.y());
}

pictures::HeatMapData LandscapeView::heatMapDataOf(const MapProgress& map) const {
  pictures::HeatMapData data;
  data.columns = map.spec.x.count;
  data.rows = map.spec.y.count;
  // only the rows the worker has finished: it may be writing the others right now
  const std::size_t ready = std::size_t(map.rowsDone * data.columns);
  data.values.assign(std::size_t(data.columns * data.rows), std::numeric_limits<double>::quiet_NaN());
  const QuantityInWords words = inWords(m_quantity);
  const double scale = words.overT2 && m_T2 > 0 ? 1 / m_T2 : 1.0;
  for (std::size_t i = 0; i < ready; ++i) data.values[i] = core::valueOf((*map.points)[i], m_quantity) * scale;
  data.rowsReady = map.rowsDone;
  data.xFrom = map.spec.x.from;
  data.xTo = map.spec.x.to;
  data.yFrom = map.spec.y.from;
  data.yTo = map.spec.y.to;
  // short enough to stand over the map whole; the combo box above says it in a sentence
  data.title = tr("%1, for each start").arg(words.title);
  data.title[0] = data.title[0].toUpper();
  data.xTitle = tr("u₁ of the start (u₂ = d, v₂ = 0)");
  data.yTitle = tr("v₁ of the start");
  data.valueTitle = words.title;
  return data;
}

void LandscapeView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), Qt::white);
  if (!m_map) {
    painter.drawText(mapArea(), Qt::AlignCenter, tr("computing the map…"));
    return;
  }
  const MapProgress& map = *m_map;
  // the cells' values and picture are made again only when the map, its finished rows or the
  // quantity change (65 536 cells: most of a repaint's time otherwise)
  const CacheKey key{map.points.get(), map.spec, map.rowsDone, m_quantity};
  if (!(key == m_cacheKey)) {
    m_cacheKey = key;
    m_data = heatMapDataOf(map);
    m_image = pictures::heatMapImage(m_data);
  }
  painter.setFont(font());
  pictures::paintHeatMap(painter, mapArea(), m_data, &m_image);

  // over the cells: the grazing family, its modes, the run's section and its start
  const QRectF plot = plotRect();
  painter.save();
  painter.setClipRect(plot);
  painter.setRenderHint(QPainter::Antialiasing, true);
  const double line = m_textPixels > 0 ? 3.0 : 2.0;
  if (!m_family.empty()) {
    QPainterPath family;
    family.moveTo(positionIn(plot, m_family.front()));
    for (const QPointF& p : m_family) family.lineTo(positionIn(plot, p));
    painter.setPen(QPen(Qt::white, line + 2));
    painter.drawPath(family);
    painter.setPen(QPen(Qt::black, line, Qt::DashLine));
    painter.drawPath(family);
    const QFontMetricsF metrics(font());
    QRectF taken;  // the first label's box: the second goes below its point if they would meet
    for (const auto& [value, name] : {std::pair{m_glom1, QStringLiteral("GLOM₁")}, std::pair{m_glom2, QStringLiteral("GLOM₂")}}) {
      const QPointF at = positionIn(plot, value);
      // a mode outside a zoomed region is not on the map: no label pinned to its edge
      if (!plot.contains(at)) continue;
      painter.setPen(QPen(Qt::black, 1.5));
      painter.setBrush(Qt::white);
      painter.drawEllipse(at, 5 + line, 5 + line);
      const QSizeF size(metrics.horizontalAdvance(name) + 6, metrics.height() + 2);
      QRectF box(at + QPointF(-size.width() / 2, -2.4 * metrics.height()), size);
      if (box.intersects(taken)) box.moveTop(at.y() + 1.2 * metrics.height());
      // whole inside the map (the painter clips to it)
      box.moveLeft(std::clamp(box.left(), plot.left(), std::max(plot.left(), plot.right() - box.width())));
      taken = box;
      painter.fillRect(box, QColor(255, 255, 255, 210));
      painter.drawText(box, Qt::AlignCenter, name);
    }
  }
  painter.setPen(Qt::NoPen);
  painter.setBrush(colors::kImpact);
  for (const QPointF& p : m_section) painter.drawEllipse(positionIn(plot, p), 2.0 + line / 2, 2.0 + line / 2);
  if (m_start) {
    const QPointF at = positionIn(plot, *m_start);
    painter.setPen(QPen(Qt::white, line + 2));
    painter.drawLine(at + QPointF(-8, 0), at + QPointF(8, 0));
    painter.drawLine(at + QPointF(0, -8), at + QPointF(0, 8));
    painter.setPen(QPen(colors::kAccent, line));
    painter.drawLine(at + QPointF(-8, 0), at + QPointF(8, 0));
    painter.drawLine(at + QPointF(0, -8), at + QPointF(0, 8));
  }
  if (m_pressAt && (m_dragTo - *m_pressAt).manhattanLength() > kClickSlack) {
    painter.setPen(QPen(Qt::white, 1.5, Qt::DashLine));
    painter.setBrush(QColor(255, 255, 255, 50));
    painter.drawRect(QRectF(*m_pressAt, m_dragTo).normalized());
  }
  painter.restore();
}

void LandscapeView::mousePressEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton || !valueAt(event->position())) {
    QWidget::mousePressEvent(event);
    return;
  }
  m_pressAt = event->position();
  m_dragTo = *m_pressAt;
  event->accept();
}

void LandscapeView::mouseMoveEvent(QMouseEvent* event) {
  if (!m_pressAt) return;
  const QRectF plot = plotRect();
  m_dragTo = QPointF(std::clamp(event->position().x(), plot.left(), plot.right()),
                     std::clamp(event->position().y(), plot.top(), plot.bottom()));
  update();
}

void LandscapeView::mouseReleaseEvent(QMouseEvent* event) {
  if (!m_pressAt || event->button() != Qt::LeftButton) return;
  const QPointF pressed = *m_pressAt;
  m_pressAt.reset();
  update();
  const auto from = valueAt(pressed);
  if (!from) return;
  if ((m_dragTo - pressed).manhattanLength() <= kClickSlack) {
    emit startRequested(core::State{from->x(), m_gap, from->y(), 0});
    return;
  }
  const auto to = valueAt(m_dragTo);
  if (!to) return;
  emit regionRequested(QRectF(*from, *to).normalized());
}

}  // namespace grazelab::ui
