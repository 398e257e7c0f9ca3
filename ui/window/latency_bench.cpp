// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/window/latency_bench.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QGuiApplication>
#include <QKeyEvent>
#include <QHash>
#include <QSet>
#include <QSlider>
#include <QTextStream>
#include <QTimer>

#include <algorithm>
#include <vector>

#include "ui/window/main_window.h"
#include "ui/plots/chain_view.h"
#include "ui/widgets/parameter_panel.h"
#include "ui/plots/plot_view.h"
#include "ui/plots/poincare_plot.h"
#include "ui/compute/sim_controller.h"
#include "ui/widgets/slider_spin.h"

namespace grazelab::ui {
namespace {

// waits until the plots show the latest request's whole run (`runOnly`), or its final update
// (the Accuracy scene's sweep and the landscape's map after the run); false on timeout
bool waitForFinal(MainWindow& window, int timeoutMs, bool runOnly = false) {
  const auto done = [&window, runOnly] {
    const SimUpdate* shown = window.displayed();
    return shown && shown->id == window.controller()->latestId() &&
           (shown->final || (runOnly && shown->runDone));
  };
  QEventLoop loop;
  QTimer timeout;
  timeout.setSingleShot(true);
  QObject::connect(&timeout, &QTimer::timeout, &loop, &QEventLoop::quit);
  const auto connection = QObject::connect(&window, &MainWindow::plotsUpdated, &loop, [&] {
    if (done()) loop.quit();
  });
  timeout.start(timeoutMs);
  if (!done()) loop.exec();
  QObject::disconnect(connection);
  return done();
}

// Counts the paints of every plot's viewport: the bench waits for the paint that follows an
// update in the event loop, the one the user sees (a forced repaint would paint twice: Qt
// Charts marks its scene dirty again after a replace and paints it at the next turn anyway).
class PaintWatch : public QObject {
 public:
  /// Watches every plot of the window, or only `only`.
  explicit PaintWatch(const MainWindow& window, PlotView* only = nullptr)
      : m_plots(only ? QList<PlotView*>{only} : window.plots()) {
    for (PlotView* plot : m_plots) plot->viewport()->installEventFilter(this);
  }
  ~PaintWatch() override {
    for (PlotView* plot : m_plots) plot->viewport()->removeEventFilter(this);
  }
  void reset() {
    m_painted.clear();
    m_paints.clear();
  }
  // paints since reset() of the plot painted least often (a frame repaints all of them)
  int framesPainted() const {
    int least = -1;
    for (PlotView* plot : m_plots) {
      if (!plot->isVisible()) continue;
      const int paints = m_paints.value(plot->viewport(), 0);
      least = least < 0 ? paints : std::min(least, paints);
    }
    return std::max(0, least);
  }
  // runs the event loop until every visible plot has painted since reset(); false on timeout
  bool waitForAll(int timeoutMs) {
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < timeoutMs) {
      QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
      bool all = true;
      for (PlotView* plot : m_plots) {
        if (plot->isVisible() && !m_painted.contains(plot->viewport())) all = false;
      }
      if (all) return true;
    }
    return false;
  }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::Paint) {
      m_painted.insert(watched);
      ++m_paints[watched];
    }
    return false;
  }

 private:
  QList<PlotView*> m_plots;
  QSet<QObject*> m_painted;
  QHash<QObject*, int> m_paints;
};

// The longest the event loop went without turning, while it watches: a timer that should fire
// every 2 ms notes the largest gap between two of its ticks. A scene switch or an edit that
// computed on the GUI thread would show here (the budget: 50 ms).
class StallWatch : public QObject {
 public:
  StallWatch() {
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(2);
    connect(&m_timer, &QTimer::timeout, this, [this] {
      m_longest = std::max(m_longest, m_sinceTick.nsecsElapsed() * 1e-6);
      m_sinceTick.start();
    });
  }
  void start() {
    m_longest = 0;
    m_sinceTick.start();
    m_timer.start();
  }
  /// The longest gap since start() [ms], the last (still open) one included.
  double longest() const { return std::max(m_longest, m_sinceTick.nsecsElapsed() * 1e-6); }

 private:
  QTimer m_timer;
  QElapsedTimer m_sinceTick;
  double m_longest = 0;
};

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, std::size_t(fraction * double(values.size())))];
}

// the slider a scene's drag moves: the first of lambda, the period, the chain's period and the
// push the scene shows, else its first (a hidden slider's change computes, but nobody sees it)
QSlider* dragSlider(MainWindow& window) {
  const QList<ParamKey> keys = window.scene().parameters();
  if (keys.isEmpty()) return window.parameterPanel()->control(ParamKey::Gap)->slider();
  ParamKey key = keys.front();
  for (ParamKey preferred : {ParamKey::Perturbation, ParamKey::ChainPeriod, ParamKey::Period, ParamKey::Lambda}) {
    if (keys.contains(preferred)) key = preferred;
  }
  return window.parameterPanel()->control(key)->slider();
}

}  // namespace

int runLatencyBenchmark(QTextStream& out, const QString& onlyScene) {
  out << "GrazeLab explorer latency (platform " << QGuiApplication::platformName() << ")\n";
  out << QStringLiteral("%1 | %2 | %3 | %4 | %7 | %5 | %6 | %8 | %9 | %11 | %10\n")
             .arg(QStringLiteral("scene"), -40)
             .arg(QStringLiteral("median ms"), 9)
             .arg(QStringLiteral("p90 ms"), 7)
             .arg(QStringLiteral("compute ms"), 10)
             .arg(QStringLiteral("drag fps"), 8)
             .arg(QStringLiteral("frames/changes"), 14)
             .arg(QStringLiteral("paint ms"), 8)
             .arg(QStringLiteral("animation fps"), 13)
             .arg(QStringLiteral("edit stall ms"), 13)
             .arg(QStringLiteral("slowest view (ms to take an update)"))
             .arg(QStringLiteral("switch stall ms"), 15);
  MainWindow window({.synchronous = false, .useSettings = false});
  window.resize(1600, 1000);
  window.show();
  const int only = onlyScene.isEmpty() ? -1 : findScene(window.scenes(), onlyScene);
  if (!onlyScene.isEmpty() && only < 0) {
    out << "unknown scene: " << onlyScene << '\n';
    return 2;
  }
  for (int sceneIndex = 0; sceneIndex < int(window.scenes().size()); ++sceneIndex) {
    if (only >= 0 && sceneIndex != only) continue;
    // from the switch on: every turn of the event loop is timed (switch, edits, drag)
    StallWatch stalls;
    stalls.start();
    window.selectScene(sceneIndex);
    // each scene on its own defaults, as on a class's first visit (the chain and the start
    // would otherwise carry over from the scene before)
    window.setParams(window.scene().defaults());
    waitForFinal(window, 60'000);
    // the switch (new views built, the first run drawn) apart from the edits and the drag
    const double switchStall = stalls.longest();
    stalls.start();
    QSlider* slider = dragSlider(window);
    const int base = slider->value();

    // single changes: value change -> final result drawn
    std::vector<double> latencies;
    std::vector<double> compute;
    std::vector<double> paint;
    QHash<const QWidget*, double> viewCost;
    int viewSteps = 0;
    PaintWatch watch(window);
    for (int step = 0; step < 21; ++step) {
      QElapsedTimer clock;
      clock.start();
      slider->setValue(base + (step % 2 == 0 ? 3 : -3));
      // the run drawn: a sweep or map after it goes on, its points appearing as they come
      if (!waitForFinal(window, 60'000, true)) break;
      const double drawn = clock.nsecsElapsed() * 1e-6;
      // the paint that the update scheduled
      watch.reset();
      if (!watch.waitForAll(5'000)) break;
      if (step == 0) continue;  // warm-up
      latencies.push_back(clock.nsecsElapsed() * 1e-6);
      paint.push_back(clock.nsecsElapsed() * 1e-6 - drawn);
      // (an N-mass scene's runs carry no wall time: 0)
      compute.push_back(window.displayed()->result ? window.displayed()->result->cost.wallSeconds * 1e3 : 0.0);
      for (auto it = window.viewCosts().begin(); it != window.viewCosts().end(); ++it) {
        viewCost[it.key()] += it.value();
      }
      ++viewSteps;
    }
    // the view that took longest to take in an update, on average
    QString slowest = QStringLiteral("-");
    double slowestMs = 0;
    for (auto it = viewCost.begin(); it != viewCost.end(); ++it) {
      if (it.value() / std::max(1, viewSteps) <= slowestMs) continue;
      slowestMs = it.value() / std::max(1, viewSteps);
      const auto* plot = qobject_cast<const PlotView*>(it.key());
      slowest = plot ? plot->title().section(QLatin1Char(':'), 0, 0).left(24)
                     : QString::fromLatin1(it.key()->metaObject()->className()).section(QStringLiteral("::"), -1);
    }

    // a drag: one slider step every 8 ms for 2 s; a frame is one paint of every plot
    int changes = 0;
    watch.reset();
    QTimer drag;
    drag.setInterval(8);
    QObject::connect(&drag, &QTimer::timeout, &window, [&] {
      ++changes;
      slider->setValue(base + (changes % 200 < 100 ? changes % 100 : 100 - changes % 100));
    });
    // the animation plays meanwhile, where the scene shows it: its frames per second
    ChainView* chain = window.chainView();
    const std::int64_t chainFramesBefore = chain ? chain->framesPlayed() : 0;
    if (chain) chain->setPlaying(true);
    QElapsedTimer dragClock;
    dragClock.start();
    drag.start();
    QEventLoop loop;
    QTimer::singleShot(2000, &loop, &QEventLoop::quit);
    loop.exec();
    drag.stop();
    const double seconds = dragClock.nsecsElapsed() * 1e-9;
    const int frames = watch.framesPainted();
    const double chainFps = chain ? double(chain->framesPlayed() - chainFramesBefore) / seconds : 0;
    if (chain) chain->setPlaying(false);
    waitForFinal(window, 60'000);
    const double longestStall = stalls.longest();

    out << QStringLiteral("%1 | %2 | %3 | %4 | %7 | %5 | %6 | %8 | %9 | %11 | %10\n")
               .arg(window.scene().name(), -40)
               .arg(percentile(latencies, 0.5), 9, 'f', 1)
               .arg(percentile(latencies, 0.9), 7, 'f', 1)
               .arg(percentile(compute, 0.5), 10, 'f', 2)
               .arg(frames / seconds, 8, 'f', 1)
               .arg(QStringLiteral("%1/%2").arg(frames).arg(changes), 14)
               .arg(percentile(paint, 0.5), 8, 'f', 1)
               .arg(chain ? QString::number(chainFps, 'f', 1) : QStringLiteral("-"), 13)
               .arg(longestStall, 13, 'f', 1)
               .arg(QStringLiteral("%1 %2").arg(slowest).arg(slowestMs, 0, 'f', 2))
               .arg(switchStall, 15, 'f', 1);
    if (latencies.empty()) {
      // (the grazing sets are drawn in units of the gap, its only slider)
      out << "  (" << window.scene().name() << ": its slider changes nothing drawn, so no view repaints: "
          << "nothing to time)\n";
    }
    out.flush();
  }

  // 10^6 Poincaré points: a pan of the section, from the key press to the repainted plot
  if (only >= 0 && only != findScene(window.scenes(), QStringLiteral("near-grazing"))) return 0;
  window.selectScene(findScene(window.scenes(), QStringLiteral("near-grazing")));
  Params params = window.scene().defaults();
  params.horizon = 1'000'000;
  window.setParams(params);
  waitForFinal(window, 300'000);
  PlotView* section = nullptr;
  for (PlotView* plot : window.plots()) {
    if (qobject_cast<PoincarePlot*>(plot)) section = plot;
  }
  if (!section) return 0;
  std::size_t held = 0;    // points the view copied
  std::size_t inPlace = 0;  // points it reads where the run keeps them
  for (const PlotView::Entry& entry : section->entries()) {
    held += entry.data.size();
    if (entry.owner) inPlace += entry.inPlace.size();
  }
  std::vector<double> pans;
  PaintWatch panWatch(window, section);
  for (int step = 0; step < 21; ++step) {
    QElapsedTimer clock;
    clock.start();
    QKeyEvent key(QEvent::KeyPress, step % 2 == 0 ? Qt::Key_Right : Qt::Key_Left, Qt::NoModifier);
    panWatch.reset();
    QCoreApplication::sendEvent(section, &key);
    if (!panWatch.waitForAll(5'000)) break;
    if (step > 0) pans.push_back(clock.nsecsElapsed() * 1e-6);  // the first warms up
  }
  out << QStringLiteral("%1 Poincaré points read in place and %2 copied by the view (near "
                        "grazing, %3 contacts), %4 drawn: a pan takes %5 ms (median), %6 ms "
                        "(slowest 10 %)\n")
             .arg(inPlace)
             .arg(held)
             .arg(window.displayed()->result->cost.contacts)
             .arg(section->drawnPointCount())
             .arg(percentile(pans, 0.5), 0, 'f', 1)
             .arg(percentile(pans, 0.9), 0, 'f', 1);
  return 0;
}

}  // namespace grazelab::ui
