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

#include "ui/plots/plot_style.h"
#include "ui/widgets/param_specs.h"

namespace grazelab::ui {
namespace {

constexpr int kSliderSteps = 10000;
constexpr double kSlowMotion = 0.15;  // speed factor near a contact, when asked for

}  // namespace

/// The drawing: walls, springs, masses and stop, at the view's current time.
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
    const std::vector<double> u = view.displacementsAt(view.m_time);
    if (u.empty()) {
      painter.drawText(rect().adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap,
                       view.m_emptyNote.isEmpty() ? tr("no motion to show yet") : view.m_emptyNote);
      return;
    }
    const core::MassChain& chain = view.m_run->chain;
    const int n = chain.size();
    const int s = chain.stopped() - 1;
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

    // a contact just passed: the stop and the stopped mass flash in its colour
    QColor flash;
    for (std::size_t i = 0; i < view.m_contactTimes.size(); ++i) {
      const double since = view.m_time - view.m_contactTimes[i];
      if (since >= 0 && since < 0.12 * view.m_rate) {
        flash = view.m_contactTypes[i] == core::EventType::Impact ? colors::kImpact : colors::kGrazing;
      }
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
    // masses; the model's masses are points on springs: far enough from rest neighbours pass
    // each other, which boxes true to scale cannot hide: the later one is drawn see-through and
    // it is said
    int overlap = -1;
    for (int i = 0; i < n; ++i) {
      const double centre = (i + 1) * rest + u[std::size_t(i)];
      const double size = box[std::size_t(i)];
      const double boxHeight = std::min(size * scale, tallest);
      const QRectF rectangle(QPointF(px(centre - size / 2), middle - boxHeight / 2),
                             QSizeF(size * scale, boxHeight));
      const bool stopped = i == s;
      QColor fill = stopped ? (flash.isValid() ? flash : QColor(0x00, 0x72, 0xB2)) : QColor(0x44, 0x44, 0x44);
      if (i > 0 && (i + 1) * rest + u[std::size_t(i)] - size / 2 <
                       i * rest + u[std::size_t(i - 1)] + box[std::size_t(i - 1)] / 2) {
        overlap = i;
        fill.setAlpha(170);
      }
      painter.setPen(QPen(Qt::black, lineWidth));
      painter.setBrush(fill);
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
    if (overlap > 0) {
      painter.setPen(QColor(0xa0, 0x10, 0x10));
      painter.drawText(rect().adjusted(8, 6, -8, -6), Qt::AlignLeft | Qt::AlignBottom | Qt::TextWordWrap,
                       tr("m%1 and m%2 overlap here: the linear model lets the masses pass each other "
                          "(it has no contact between them)")
                           .arg(subscriptDigits(overlap), subscriptDigits(overlap + 1)));
      painter.setPen(Qt::black);
    }
    // the clock, also in the unit of the other views' time axes
    const TimeUnit& unit = view.m_run->unit;
    painter.drawText(rect().adjusted(8, 6, -8, -6), Qt::AlignLeft | Qt::AlignTop,
                     tr("t = %1  (%2 %3)")
                         .arg(view.m_time, 0, 'f', 2)
                         .arg(view.m_time / unit.length, 0, 'f', 2)
                         .arg(unit.name));
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
  QToolButton* previous =
      button(QStyle::SP_MediaSkipBackward, tr("previous contact"), tr("Back to the previous contact ([)"));
  m_play = button(QStyle::SP_MediaPlay, tr("play"), tr("Play or pause the motion (Space)"));
  QToolButton* next = button(QStyle::SP_MediaSkipForward, tr("next contact"), tr("On to the next contact (])"));
  m_speed = new QComboBox(this);
  for (double speed : {0.1, 0.25, 0.5, 1.0, 2.0, 4.0}) {
    m_speed->addItem(tr("%1×").arg(speed), speed);
  }
  m_speed->setCurrentIndex(3);
  m_speed->setToolTip(tr("Playing speed; at 1× the slowest mode's period takes two seconds."));
  controls->addWidget(m_speed);
  m_slowNearContacts = new QCheckBox(tr("slow at contacts"), this);
  m_slowNearContacts->setChecked(true);
  m_slowNearContacts->setToolTip(tr("Play at %1× of the speed within 1/40 of the slowest period of a "
                                    "contact, so that the impact can be seen.")
                                     .arg(kSlowMotion));
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
  setToolTip(tr("Every mass on its springs and the rigid stop, moving as computed; the stopped mass "
                "(blue) strikes the post with its tab, flashing at each contact. The time shown is "
                "marked on the trace and the phase portraits. Space: play / pause; [ and ]: "
                "previous / next contact."));
  m_timer.setInterval(16);  // a 60 Hz display
  connect(&m_timer, &QTimer::timeout, this, &ChainView::tick);
  connect(m_play, &QToolButton::clicked, this, [this] { setPlaying(!playing()); });
  connect(previous, &QToolButton::clicked, this, [this] { stepContact(-1); });
  connect(next, &QToolButton::clicked, this, [this] { stepContact(+1); });
  connect(m_slider, &QSlider::valueChanged, this, [this](int position) {
    setTime(m_end * position / kSliderSteps);
  });
}

void ChainView::setEmptyNote(const QString& why) {
  m_emptyNote = why;
  m_canvas->update();
}

void ChainView::widen(std::size_t from) {
  const StateSpan& motion = m_run->samples;
  const int n = motion.masses();
  for (std::size_t k = from; k < motion.size(); ++k) {
    for (int i = 0; i < n; ++i) {
      m_amplitude = std::max(m_amplitude, std::abs(motion.u(k, i)));
      if (i + 1 < n) m_squeeze = std::max(m_squeeze, motion.u(k, i) - motion.u(k, i + 1));
    }
  }
}

// Only what the run added since the last update when it is the same run grown; else from its
// start (its scales and contacts anew).
void ChainView::show(const SimUpdate& update) {
  std::optional<ShownRun> run = shownRun(update);
  const bool grown = run && m_run && run->continues(*m_run);
  const std::size_t samplesTaken = grown ? m_run->samples.size() : 0;
  if (!grown) {
    m_eventsTaken = 0;
    m_contactTimes.clear();
    m_contactTypes.clear();
    if (run) {
      m_rate = run->slowestPeriod / 2;
      m_nearContact = run->slowestPeriod / 40;
      m_amplitude = run->gap;
      m_squeeze = 0;
    }
  }
  m_run = std::move(run);
  m_end = 0;
  if (m_run) {
    const StateSpan& motion = m_run->samples;
    widen(samplesTaken);
    if (!motion.empty()) m_end = motion.t(motion.size() - 1);
    // contacts within the samples' span; later ones wait for the samples that reach them
    std::size_t next = m_eventsTaken;
    for (; next < m_run->eventCount() && m_run->eventTime(next) <= m_end; ++next) {
      const core::EventType type = m_run->eventType(next);
      if (!core::isContact(type)) continue;
      m_contactTimes.push_back(m_run->eventTime(next));
      m_contactTypes.push_back(type);
    }
    m_eventsTaken = next;
  }
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

std::vector<double> ChainView::displacementsAt(double t) const {
  if (!m_run || m_run->samples.empty()) return {};
  const StateSpan& motion = m_run->samples;
  // the neighbours of t among the motion's times, and their displacements
  std::size_t low = 0, high = motion.size();  // the first record after t: in [low, high]
  while (low < high) {
    const std::size_t middle = low + (high - low) / 2;
    if (motion.t(middle) < t) low = middle + 1;
    else high = middle;
  }
  const std::size_t after = low;
  std::vector<double> u(std::size_t(motion.masses()));
  if (after == 0 || after == motion.size()) {
    for (int i = 0; i < motion.masses(); ++i) u[std::size_t(i)] = motion.u(after == 0 ? 0 : after - 1, i);
    return u;
  }
  const double w = (t - motion.t(after - 1)) / (motion.t(after) - motion.t(after - 1));
  for (int i = 0; i < motion.masses(); ++i) {
    const double a = motion.u(after - 1, i), b = motion.u(after, i);
    u[std::size_t(i)] = a + w * (b - a);
  }
  return u;
}

void ChainView::setTime(double t) {
  m_time = std::clamp(t, 0.0, m_end);
  {
    const QSignalBlocker block(m_slider);
    m_slider->setValue(m_end > 0 ? int(std::lround(m_time / m_end * kSliderSteps)) : 0);
  }
  m_canvas->update();
  emit timeChanged(m_time);
}

void ChainView::setPlaying(bool on) {
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
  const double seconds = std::min(0.1, m_clock.restart() / 1000.0);
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
