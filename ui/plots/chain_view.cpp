// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/chain_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QKeyEvent>
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

#include "core/model/linear_modes.h"
#include "ui/plots/plot_style.h"

namespace grazelab::ui {
namespace {

constexpr int kSliderSteps = 10000;
constexpr double kSlowMotion = 0.15;  // speed factor near a contact, when asked for

}  // namespace

/// The drawing: wall, springs, masses and stop, at the view's current time.
class ChainView::Canvas : public QWidget {
 public:
  explicit Canvas(ChainView* view) : QWidget(view), m_view(view) {
    setMinimumSize(200, 120);
    setAttribute(Qt::WA_OpaquePaintEvent);
  }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter painter(this);
    painter.fillRect(rect(), Qt::white);
    painter.setRenderHint(QPainter::Antialiasing);
    const ChainView& view = *m_view;
    if (!view.m_result || view.m_result->samples.empty()) {
      painter.drawText(rect(), Qt::AlignCenter, tr("no motion to show yet"));
      return;
    }
    const core::Model& model = view.m_model;
    const core::State state = view.stateAt(view.m_time);
    const double gap = model.gap;
    // lengths: rest spacing R between wall, mass 1 and mass 2, wide enough for the largest
    // displacement; every length (displacements, gap) on one scale
    const double amplitude = view.m_amplitude;
    // and twice the most the masses close in, so that boxes at most 0.45 R wide never meet (a
    // heavy mass 2, m2 = 1.37, swings against mass 1 and they were drawn on top of each other)
    const double rest = std::max(1.6 * amplitude + 0.5 * gap, 2 * view.m_squeeze);
    const double heaviest = std::max(model.m1, model.m2);
    const double box1 = 0.45 * rest * std::cbrt(model.m1 / heaviest);
    const double box2 = 0.45 * rest * std::cbrt(model.m2 / heaviest);
    const double span = 2 * rest + box2 / 2 + gap + 0.35 * rest;
    const double pad = 12;
    const double scale = (width() - 2 * pad) / span;
    const double middle = height() * 0.45;
    auto px = [&](double x) { return pad + x * scale; };
    const double lineWidth = view.m_presentation ? 3.0 : 1.6;

    const double x1 = rest + state.u1;  // centres
    const double x2 = 2 * rest + state.u2;
    const double stopX = 2 * rest + box2 / 2 + gap;
    const double height1 = std::min(box1 * scale, height() * 0.5);
    const double height2 = std::min(box2 * scale, height() * 0.5);

    // a contact just passed: the stop and mass 2 flash in its colour
    QColor flash;
    for (std::size_t i = 0; i < view.m_contactTimes.size(); ++i) {
      const double since = view.m_time - view.m_contactTimes[i];
      if (since >= 0 && since < 0.06 * view.m_rate * 2) {
        flash = view.m_contactTypes[i] == core::EventType::Impact ? colors::kImpact : colors::kGrazing;
      }
    }

    // wall
    painter.setPen(QPen(Qt::black, lineWidth));
    const double wallTop = middle - 0.6 * height() * 0.5;
    const double wallBottom = middle + 0.6 * height() * 0.5;
    painter.drawLine(QPointF(px(0), wallTop), QPointF(px(0), wallBottom));
    for (double y = wallTop; y < wallBottom; y += 10) {
      painter.drawLine(QPointF(px(0), y), QPointF(px(0) - 8, y + 8));
    }
    // stop, hatched on its far side
    painter.setPen(QPen(flash.isValid() ? flash : QColor(Qt::black), lineWidth * 2));
    painter.drawLine(QPointF(px(stopX), wallTop), QPointF(px(stopX), wallBottom));
    painter.setPen(QPen(Qt::black, 1));
    for (double y = wallTop; y < wallBottom; y += 10) {
      painter.drawLine(QPointF(px(stopX) + 2, y + 8), QPointF(px(stopX) + 10, y));
    }
    // springs
    painter.setPen(QPen(colors::kTrace, lineWidth));
    painter.setBrush(Qt::NoBrush);
    const double rise = 0.12 * std::min(height1, height2) + 3;
    painter.drawPath(springPath(px(0), px(x1 - box1 / 2), middle, rise, 8));
    painter.drawPath(springPath(px(x1 + box1 / 2), px(x2 - box2 / 2), middle, rise, 8));
    // masses
    auto drawMass = [&](double centre, double size, double boxHeight, const QString& label,
                        const QColor& fill) {
      const QRectF box(QPointF(px(centre - size / 2), middle - boxHeight / 2),
                       QSizeF(size * scale, boxHeight));
      painter.setPen(QPen(Qt::black, lineWidth));
      painter.setBrush(fill);
      painter.drawRect(box);
      painter.setPen(Qt::white);
      painter.drawText(box, Qt::AlignCenter, label);
    };
    drawMass(x1, box1, height1, tr("m₁"), QColor(0x44, 0x44, 0x44));
    // the model's masses are points on springs: far enough from rest they pass each other,
    // which boxes true to scale cannot hide; mass 2 is drawn see-through and it is said
    const bool overlap = x1 + box1 / 2 > x2 - box2 / 2;
    QColor fill2 = flash.isValid() ? flash : QColor(0x00, 0x72, 0xB2);
    if (overlap) fill2.setAlpha(170);
    drawMass(x2, box2, height2, tr("m₂"), fill2);
    if (overlap) {
      painter.setPen(QColor(0xa0, 0x10, 0x10));
      painter.drawText(rect().adjusted(8, 6, -8, -6), Qt::AlignLeft | Qt::AlignBottom | Qt::TextWordWrap,
                       tr("m₁ and m₂ overlap here: the linear model lets the masses pass each other "
                          "(it has no contact between them)"));
    }
    // the gap d, measured from mass 2 at rest
    painter.setPen(QPen(Qt::black, 1));
    const double restFace = px(2 * rest + box2 / 2);
    const double rulerY = middle + std::max(height1, height2) / 2 + 14;
    painter.drawLine(QPointF(restFace, rulerY), QPointF(px(stopX), rulerY));
    painter.drawLine(QPointF(restFace, rulerY - 4), QPointF(restFace, rulerY + 4));
    painter.drawLine(QPointF(px(stopX), rulerY - 4), QPointF(px(stopX), rulerY + 4));
    painter.drawText(QRectF(restFace, rulerY + 2, px(stopX) - restFace, 40),
                     Qt::AlignHCenter | Qt::AlignTop, tr("d"));
    // the clock
    const double T2 = core::computeModes(model).T2;
    painter.drawText(rect().adjusted(8, 6, -8, -6), Qt::AlignLeft | Qt::AlignTop,
                     tr("t = %1  (%2 T₂)").arg(view.m_time, 0, 'f', 2).arg(view.m_time / T2, 0, 'f', 2));
  }

 private:
  ChainView* m_view;
};

ChainView::ChainView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  auto* title = new QLabel(tr("<b>The chain, moving</b> (true to scale)"), this);
  title->setAlignment(Qt::AlignHCenter);
  title->setWordWrap(true);
  layout->addWidget(title);
  m_canvas = new Canvas(this);
  layout->addWidget(m_canvas, 1);

  auto* controls = new QHBoxLayout;
  auto button = [this, controls](QStyle::StandardPixmap icon, const QString& name,
                                 const QString& tip) {
    auto* b = new QToolButton(this);
    b->setIcon(style()->standardIcon(icon));
    b->setText(name);  // read by screen readers and shown where the style has no icon
    b->setObjectName(name);
    b->setToolTip(tip);
    controls->addWidget(b);
    return b;
  };
  m_previous = button(QStyle::SP_MediaSkipBackward, tr("previous contact"),
                      tr("Back to the previous contact ([)"));
  m_play = button(QStyle::SP_MediaPlay, tr("play"), tr("Play or pause the motion (Space)"));
  m_next = button(QStyle::SP_MediaSkipForward, tr("next contact"), tr("On to the next contact (])"));
  m_speed = new QComboBox(this);
  for (double speed : {0.1, 0.25, 0.5, 1.0, 2.0, 4.0}) {
    m_speed->addItem(tr("%1×").arg(speed), speed);
  }
  m_speed->setCurrentIndex(3);
  m_speed->setToolTip(tr("Playing speed; at 1× one slow period T₂ takes two seconds."));
  controls->addWidget(m_speed);
  m_slowNearContacts = new QCheckBox(tr("slow at contacts"), this);
  m_slowNearContacts->setChecked(true);
  m_slowNearContacts->setToolTip(tr("Play at %1× of the speed within T₂/40 of a contact, so "
                                    "that the impact can be seen.").arg(kSlowMotion));
  controls->addStretch(1);
  layout->addLayout(controls);
  // the time slider on a row of its own, the whole width: the view stays narrow enough for a
  // third of a small screen (beside the check box it shrank to a bare handle in presentation)
  layout->addWidget(m_slowNearContacts);
  m_slider = new QSlider(Qt::Horizontal, this);
  m_slider->setRange(0, kSliderSteps);
  m_slider->setMinimumWidth(40);
  m_slider->setToolTip(tr("Drag to any time of the motion"));
  layout->addWidget(m_slider);

  setFocusPolicy(Qt::StrongFocus);
  setToolTip(tr("The two masses on their springs and the rigid stop, moving as computed. The "
                "time shown is marked on the u₂(t) trace and the phase portraits. Space: "
                "play / pause; [ and ]: previous / next contact."));
  m_timer.setInterval(16);  // a 60 Hz display
  connect(&m_timer, &QTimer::timeout, this, &ChainView::tick);
  connect(m_play, &QToolButton::clicked, this, [this] { setPlaying(!playing()); });
  connect(m_previous, &QToolButton::clicked, this, [this] { stepContact(-1); });
  connect(m_next, &QToolButton::clicked, this, [this] { stepContact(+1); });
  connect(m_slider, &QSlider::valueChanged, this, [this](int position) {
    setTime(m_end * position / kSliderSteps);
  });
}

void ChainView::show(const SimUpdate& update) {
  m_result = update.result;
  const core::Result& result = *m_result;
  if (m_taken.startsOver(update)) {
    m_model = update.request->job.spec.model;
    const double T2 = core::computeModes(m_model).T2;
    m_rate = T2 / 2;
    m_nearContact = T2 / 40;
    m_amplitude = m_model.gap;
    m_squeeze = 0;
    m_contactTimes.clear();
    m_contactTypes.clear();
  }
  // only what the run added since the last update
  for (std::size_t index = m_taken.samples; index < result.samples.size(); ++index) {
    const core::State& state = result.samples[index].state;
    m_amplitude = std::max({m_amplitude, std::abs(state.u1), std::abs(state.u2)});
    m_squeeze = std::max(m_squeeze, state.u1 - state.u2);
  }
  m_taken.samples = result.samples.size();
  m_end = result.samples.empty() ? 0 : result.samples.back().t;
  // contacts within the samples' window; later ones wait for the samples that reach them
  std::size_t next = m_taken.events;
  for (; next < result.events.size() && result.events[next].t <= m_end; ++next) {
    const core::Event& event = result.events[next];
    if (!core::isContact(event.type)) continue;
    m_contactTimes.push_back(event.t);
    m_contactTypes.push_back(event.type);
  }
  m_taken.events = next;
  setTime(std::min(m_time, m_end));
}

void ChainView::setPresentation(bool on, int textPixels) {
  m_presentation = on;
  // the whole view (its title and controls too: an enlarged export is drawn off the window,
  // whose presentation font it does not share); off: the application's font again
  QFont font;
  if (on) font.setPixelSize(textPixels);
  setFont(font);
  m_canvas->update();
}

core::State ChainView::stateAt(double t) const {
  if (!m_result || m_result->samples.empty()) return {};
  const auto& samples = m_result->samples;
  const auto after = std::lower_bound(samples.begin(), samples.end(), t,
                                      [](const core::Sample& s, double time) { return s.t < time; });
  if (after == samples.begin()) return samples.front().state;
  if (after == samples.end()) return samples.back().state;
  const core::Sample& b = *after;
  const core::Sample& a = *(after - 1);
  const double w = (t - a.t) / (b.t - a.t);
  auto mix = [w](double x, double y) { return x + w * (y - x); };
  return {mix(a.state.u1, b.state.u1), mix(a.state.u2, b.state.u2), mix(a.state.v1, b.state.v1),
          mix(a.state.v2, b.state.v2)};
}

void ChainView::setTime(double t) {
  m_time = std::clamp(t, 0.0, m_end);
  {
    const QSignalBlocker block(m_slider);
    m_slider->setValue(m_end > 0 ? int(std::lround(m_time / m_end * kSliderSteps)) : 0);
  }
  m_canvas->update();
  emit timeChanged(m_time, stateAt(m_time));
}

void ChainView::setPlaying(bool on) {
  if (on == playing()) return;
  if (on) {
    if (m_time >= m_end) m_time = 0;
    m_clockTimer.start();
    m_timer.start();
  } else {
    m_timer.stop();
  }
  m_play->setIcon(style()->standardIcon(on ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

void ChainView::stepContact(int direction) {
  setPlaying(false);
  const double slack = 1e-9 * std::max(1.0, m_end);
  if (direction > 0) {
    const auto next = std::upper_bound(m_contactTimes.begin(), m_contactTimes.end(), m_time + slack);
    if (next != m_contactTimes.end()) setTime(*next);
  } else {
    const auto before = std::lower_bound(m_contactTimes.begin(), m_contactTimes.end(), m_time - slack);
    if (before != m_contactTimes.begin()) setTime(*(before - 1));
  }
}

double ChainView::speedFactor() const {
  double factor = m_speed->currentData().toDouble();
  if (m_slowNearContacts->isChecked()) {
    const auto next = std::lower_bound(m_contactTimes.begin(), m_contactTimes.end(), m_time);
    const bool near = (next != m_contactTimes.end() && *next - m_time < m_nearContact) ||
                      (next != m_contactTimes.begin() && m_time - *(next - 1) < m_nearContact);
    if (near) factor *= kSlowMotion;
  }
  return factor;
}

void ChainView::tick() {
  ++m_framesPlayed;
  // wall time since the last frame (a late frame does not make the motion jump far)
  const double seconds = std::min(0.1, m_clockTimer.restart() / 1000.0);
  double t = m_time + seconds * m_rate * speedFactor();
  if (t > m_end) t = 0;  // loops
  setTime(t);
}

void ChainView::keyPressEvent(QKeyEvent* event) {
  switch (event->key()) {
    // Space is the window's play / pause shortcut (it works wherever the focus is)
    case Qt::Key_BracketRight: stepContact(+1); break;
    case Qt::Key_BracketLeft: stepContact(-1); break;
    default: QWidget::keyPressEvent(event); return;
  }
  event->accept();
}

}  // namespace grazelab::ui
