// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/mass_chain_view.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ui/plots/plot_style.h"
#include "ui/widgets/param_specs.h"

namespace grazelab::ui {
namespace {

constexpr int kSliderSteps = 10000;

}  // namespace

class MassChainView::Canvas : public QWidget {
 public:
  explicit Canvas(MassChainView* view) : QWidget(view), m_view(view) {
    setMinimumSize(200, 110);
    setAttribute(Qt::WA_OpaquePaintEvent);
  }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter painter(this);
    painter.fillRect(rect(), Qt::white);
    painter.setRenderHint(QPainter::Antialiasing);
    const MassChainView& view = *m_view;
    if (!view.m_series || view.m_series->grid.empty()) {
      painter.drawText(rect().adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap,
                       view.m_emptyNote.isEmpty() ? tr("no motion to show yet") : view.m_emptyNote);
      return;
    }
    const core::MassChain& chain = view.m_series->chain;
    const int n = chain.size();
    const int s = chain.stopped() - 1;
    const std::vector<double> u = view.displacementsAt(view.m_time);
    // one length scale for displacements, gap and spacing: rest spacing R wide enough for the
    // largest displacement
    const double amplitude = view.m_amplitude;
    // and twice the most two neighbours close in, so that boxes at most 0.45 R wide never meet
    const double rest = std::max(1.6 * amplitude + 0.5 * chain.gap, 2 * view.m_squeeze);
    const double heaviest = *std::max_element(chain.masses.begin(), chain.masses.end());
    std::vector<double> box(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
      box[std::size_t(i)] = 0.45 * rest * std::cbrt(chain.masses[std::size_t(i)] / heaviest);
    const bool rightWall = chain.rightSpring > 0;
    const double stopX = (s + 1) * rest + box[std::size_t(s)] / 2 + chain.gap;
    const double span =
        std::max((n + (rightWall ? 1 : 0)) * rest + box.back() / 2, stopX) + 0.35 * rest;
    const double pad = 12;
    const double scale = (width() - 2 * pad) / span;
    const double middle = height() * 0.42;
    const auto px = [&](double x) { return pad + x * scale; };
    const double lineWidth = view.m_presentation ? 3.0 : 1.6;
    const double tallest = height() * 0.4;

    QColor flash;
    for (double contact : view.m_contactTimes) {
      const double since = view.m_time - contact;
      if (since >= 0 && since < 0.08 * view.m_rate) flash = colors::kImpact;
    }
    // walls
    painter.setPen(QPen(Qt::black, lineWidth));
    const double wallTop = middle - 0.3 * height(), wallBottom = middle + 0.3 * height();
    const auto wall = [&](double x, int side) {
      painter.drawLine(QPointF(px(x), wallTop), QPointF(px(x), wallBottom));
      for (double y = wallTop; y < wallBottom; y += 10)
        painter.drawLine(QPointF(px(x), y), QPointF(px(x) + 8 * side, y + 8));
    };
    wall(0, -1);
    const double rightWallX = (n + 1) * rest;
    if (rightWall) wall(rightWallX, +1);
    // springs, between the faces of the boxes
    painter.setPen(QPen(colors::kTrace, lineWidth));
    painter.setBrush(Qt::NoBrush);
    const double rise = std::min(0.08 * height(), 10.0) + 2;
    // as many coils as its drawn length holds apart (a short spring with seven was a solid block
    // on a projector), straight when too short for one
    const auto spring = [&](double from, double to) {
      const int coils = std::min(7, int((to - from) / (5 * lineWidth)));
      if (coils < 1) painter.drawLine(QPointF(from, middle), QPointF(to, middle));
      else painter.drawPath(springPath(from, to, middle, rise, coils));
    };
    double left = 0;
    for (int i = 0; i < n; ++i) {
      const double centre = (i + 1) * rest + u[std::size_t(i)];
      spring(px(left), px(centre - box[std::size_t(i)] / 2));
      left = centre + box[std::size_t(i)] / 2;
    }
    if (rightWall) spring(px(left), px(rightWallX));
    // the stop: a post below the chain line that a tab under the stopped mass strikes
    const double postTop = middle + tallest / 2 + 4;
    painter.setPen(QPen(flash.isValid() ? flash : QColor(Qt::black), lineWidth * 2));
    painter.drawLine(QPointF(px(stopX), postTop), QPointF(px(stopX), wallBottom));
    painter.setPen(QPen(Qt::black, 1));
    for (double y = postTop; y < wallBottom; y += 8)
      painter.drawLine(QPointF(px(stopX) + 2, y + 6), QPointF(px(stopX) + 8, y));
    // masses
    for (int i = 0; i < n; ++i) {
      const double centre = (i + 1) * rest + u[std::size_t(i)];
      const double size = box[std::size_t(i)];
      const double boxHeight = std::min(size * scale, tallest);
      const QRectF rectangle(QPointF(px(centre - size / 2), middle - boxHeight / 2),
                             QSizeF(size * scale, boxHeight));
      const bool stopped = i == s;
      painter.setPen(QPen(Qt::black, lineWidth));
      painter.setBrush(stopped ? (flash.isValid() ? flash : QColor(0x00, 0x72, 0xB2))
                               : QColor(0x44, 0x44, 0x44));
      painter.drawRect(rectangle);
      if (stopped) {  // its tab reaches down to the post's height
        const double tabX = px(centre + size / 2);
        painter.drawLine(QPointF(tabX, middle + boxHeight / 2), QPointF(tabX, postTop + 6));
      }
      // its name inside, or above it when the box is too small to hold it (a light mass was
      // left unnamed)
      const QString name = tr("m%1").arg(subscriptDigits(i + 1));
      const double nameWidth = painter.fontMetrics().horizontalAdvance(name);
      if (rectangle.width() > nameWidth + 2 && rectangle.height() > painter.fontMetrics().height()) {
        painter.setPen(Qt::white);
        painter.drawText(rectangle, Qt::AlignCenter, name);
      } else {
        painter.setPen(Qt::black);
        const double textHeight = painter.fontMetrics().height();
        painter.drawText(QRectF(rectangle.center().x() - nameWidth, rectangle.top() - textHeight - 1, 2 * nameWidth,
                                textHeight),
                         Qt::AlignHCenter | Qt::AlignBottom, name);
      }
    }
    // the gap d, from the stopped mass's face at rest to the post
    painter.setPen(QPen(Qt::black, 1));
    const double restFace = px((s + 1) * rest + box[std::size_t(s)] / 2);
    const double rulerY = postTop - 2;
    painter.drawLine(QPointF(restFace, rulerY), QPointF(px(stopX), rulerY));
    const double textHeight = painter.fontMetrics().height();  // the presentation font's too
    painter.drawText(QRectF(restFace, rulerY - textHeight - 2, px(stopX) - restFace, textHeight),
                     Qt::AlignHCenter | Qt::AlignBottom, tr("d"));
    const double unit = view.m_series->period > 0 ? view.m_series->period : 0;
    painter.drawText(
        rect().adjusted(8, 6, -8, -6), Qt::AlignLeft | Qt::AlignTop,
        unit > 0
            ? tr("t = %1  (%2 T)").arg(view.m_time, 0, 'f', 2).arg(view.m_time / unit, 0, 'f', 2)
            : tr("t = %1").arg(view.m_time, 0, 'f', 2));
  }

 private:
  MassChainView* m_view;
};

MassChainView::MassChainView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  auto* title = new QLabel(tr("<b>The chain, moving</b> (true to scale)"), this);
  title->setAlignment(Qt::AlignHCenter);
  layout->addWidget(title);
  m_canvas = new Canvas(this);
  layout->addWidget(m_canvas, 1);
  auto* controls = new QHBoxLayout;
  m_play = new QToolButton(this);
  m_play->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
  m_play->setText(tr("play"));
  m_play->setObjectName(QStringLiteral("play"));
  m_play->setToolTip(tr("Play or pause the motion"));
  controls->addWidget(m_play);
  m_slider = new QSlider(Qt::Horizontal, this);
  m_slider->setRange(0, kSliderSteps);
  m_slider->setToolTip(tr("Drag to any time of the first periods"));
  controls->addWidget(m_slider, 1);
  layout->addLayout(controls);
  setToolTip(
      tr("Every mass on its springs and the stop, moving as computed over the run's first periods; "
         "the stopped mass (blue) strikes the post with its tab, flashing at each contact."));
  m_timer.setInterval(16);
  connect(&m_timer, &QTimer::timeout, this, &MassChainView::tick);
  connect(m_play, &QToolButton::clicked, this, [this] { setPlaying(!playing()); });
  connect(m_slider, &QSlider::valueChanged, this,
          [this](int position) { setTime(m_end * position / kSliderSteps); });
}

void MassChainView::setEmptyNote(const QString& why) {
  m_emptyNote = why;
  m_canvas->update();
}

void MassChainView::show(const SimUpdate& update) {
  m_series = update.chains.empty() ? nullptr : update.chains.front();
  m_contactTimes.clear();
  m_end = 0;
  if (m_series && !m_series->grid.empty()) {
    m_end = m_series->grid.back().t;
    m_amplitude = m_series->chain.gap;
    m_squeeze = 0;
    for (const core::experiments::ChainGridPoint& point : m_series->grid) {
      for (double x : point.u) m_amplitude = std::max(m_amplitude, std::abs(x));
      for (std::size_t i = 0; i + 1 < point.u.size(); ++i) m_squeeze = std::max(m_squeeze, point.u[i] - point.u[i + 1]);
    }
    for (const core::ChainEvent& event : m_series->run.events) {
      if (event.t > m_end) break;
      if (core::isContact(event.type)) m_contactTimes.push_back(event.t);
    }
    m_rate = 2 * std::numbers::pi / m_series->modes.omega.minCoeff() / 2;
  }
  setTime(std::min(m_time, m_end));
}

void MassChainView::setPresentation(bool on, int textPixels) {
  m_presentation = on;
  QFont font;
  if (on) font.setPixelSize(textPixels);
  setFont(font);
  m_canvas->update();
}

std::vector<double> MassChainView::displacementsAt(double t) const {
  if (!m_series || m_series->grid.empty()) return {};
  const auto& grid = m_series->grid;
  const auto after = std::lower_bound(
      grid.begin(), grid.end(), t,
      [](const core::experiments::ChainGridPoint& p, double time) { return p.t < time; });
  if (after == grid.begin()) return grid.front().u;
  if (after == grid.end()) return grid.back().u;
  const auto& b = *after;
  const auto& a = *(after - 1);
  const double w = (t - a.t) / (b.t - a.t);
  std::vector<double> u(a.u.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = a.u[i] + w * (b.u[i] - a.u[i]);
  return u;
}

void MassChainView::setTime(double t) {
  m_time = std::clamp(t, 0.0, m_end);
  const QSignalBlocker block(m_slider);
  m_slider->setValue(m_end > 0 ? int(std::lround(m_time / m_end * kSliderSteps)) : 0);
  m_canvas->update();
  emit timeChanged(m_time);
}

void MassChainView::setPlaying(bool on) {
  if (on == playing()) return;
  if (on) {
    if (m_time >= m_end) m_time = 0;
    m_clock.start();
    m_timer.start();
  } else {
    m_timer.stop();
  }
  m_play->setIcon(style()->standardIcon(on ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

void MassChainView::tick() {
  const double seconds = std::min(0.1, m_clock.restart() / 1000.0);
  double t = m_time + seconds * m_rate;
  if (t > m_end) t = 0;
  setTime(t);
}

}  // namespace grazelab::ui
