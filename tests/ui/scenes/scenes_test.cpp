// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for ui/scenes/: every scene opens with its views and asks only for what they draw, and
// each picture agrees with the result of the theory it illustrates.
#include <QApplication>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QTest>
#include <QTimer>
#include <QDeadlineTimer>
#include <QJsonArray>
#include <QLabel>
#include <QValueAxis>
#include <QXYSeries>

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/model/linear_modes.h"
#include "tests/ui/explorer_test_support.h"
#include "ui/window/main_window.h"
#include "ui/plots/chain_view.h"
#include "ui/plots/contrast_flights_plot.h"
#include "ui/plots/curve_plot.h"
#include "ui/pictures/heat_map.h"
#include "ui/plots/landscape_view.h"
#include "ui/plots/phase_plot.h"
#include "ui/plots/free_flight_plot.h"
#include "ui/plots/plot_view.h"
#include "ui/plots/poincare_plot.h"
#include "ui/plots/trace_plot.h"
#include "ui/widgets/chain_editor.h"
#include "ui/widgets/parameter_panel.h"

using namespace grazelab::ui;
using grazelab::ui::testing::openTestWindow;
using grazelab::ui::testing::shownChainRun;
using grazelab::ui::testing::waitForLatestFinal;

namespace {

bool shows(const Scene& scene, PlotKind kind) { return scene.plots().contains(kind); }

// The window's flights from the stop.
const FreeFlightPlot& flightPlot(const MainWindow& window) {
  for (FreeFlightPlot* plot : window.findChildren<FreeFlightPlot*>()) {
    if (!plot->isVisible()) continue;
    plot->refreshNow();
    return *plot;
  }
  qFatal("no flights shown");
}

// The window's (first) portrait of the chosen mass.
const PhasePlot& phasePlot(const MainWindow& window) {
  for (PhasePlot* plot : window.findChildren<PhasePlot*>()) {
    if (plot->mass() != PhasePlot::Mass::Chosen || !plot->isVisible()) continue;
    plot->refreshNow();
    return *plot;
  }
  qFatal("no portrait of the chosen mass");
}

// The window's trace of the run (the one view of every chain's run).
const TracePlot& tracePlot(const MainWindow& window) {
  QList<TracePlot*> plots = window.findChildren<TracePlot*>();
  plots.removeIf([](const TracePlot* plot) { return !plot->isVisible(); });
  if (plots.size() != 1) qFatal("one trace shown expected, %d found", int(plots.size()));
  plots.front()->refreshNow();
  return *plots.front();
}

const CurveFigure& figure(const MainWindow& window, PlotKind kind) {
  return window.displayed()->request->job.figures.at(kind);
}

}  // namespace

class ScenesTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    m_window = openTestWindow();
    QVERIFY(waitForLatestFinal(*m_window));
  }
  void cleanup() { m_window.reset(); }

  // a scene computes what its views draw and nothing else (dense samples are the costly part)
  void everySceneAsksOnlyForWhatItsViewsUse() {
    for (int index = 0; index < int(m_window->scenes().size()); ++index) {
      m_window->selectScene(index);
      QVERIFY2(waitForLatestFinal(*m_window, 60000), qPrintable(m_window->scene().name()));
      const Scene& scene = m_window->scene();
      const QString name = scene.name();
      QVERIFY2(m_window->problem().isEmpty(), qPrintable(name + ": " + m_window->problem()));
      // a scene runs chains (every N-mass scene, and the two-mass detuned contrast) or the note's
      // run, never both, and nothing empty beside them
      const SimUpdate& shown = *m_window->displayed();
      const bool chains = !shown.request->job.spec.chains.empty();
      QVERIFY2(chains || !scene.massChain(), qPrintable(name));
      QVERIFY2(bool(shown.result) != chains, qPrintable(name));
      QVERIFY2(shown.chains.size() == shown.request->job.spec.chains.size(), qPrintable(name));
      const auto& needs = shown.request->job.spec.run.needs;
      // (a scene of chains runs no two-mass run: it asks it for nothing)
      const bool dense = !chains && (shows(scene, PlotKind::Trace) || shows(scene, PlotKind::Phase) ||
                                     shows(scene, PlotKind::PhaseU1V1) || shows(scene, PlotKind::Chain));
      QVERIFY2((needs.samples.spacing > 0) == dense, qPrintable(name));
      QVERIFY2(needs.poincare == (!chains && (shows(scene, PlotKind::Poincare) || shows(scene, PlotKind::Landscape))),
               qPrintable(name));
      QVERIFY2(m_window->displayed()->request->job.spec.map.has_value() == shows(scene, PlotKind::Landscape),
               qPrintable(name));
      QVERIFY2(needs.freeFlights == (!chains && shows(scene, PlotKind::FreeFlight)), qPrintable(name));
      QVERIFY2(chains || needs.events == (shows(scene, PlotKind::Trace) || shows(scene, PlotKind::Chain)),
               qPrintable(name));
      QVERIFY2(bool(m_window->chainView()) == shows(scene, PlotKind::Chain), qPrintable(name));
      // every view it lists is on screen, each curve view with its figure
      const qsizetype views = m_window->plots().size() + (m_window->accuracyView() ? 1 : 0) +
                              (m_window->chainView() ? 1 : 0) + (m_window->landscapeView() ? 1 : 0);
      QCOMPARE(views, scene.plots().size());
      QCOMPARE(m_window->sceneViews().size(), scene.plots().size());
      for (PlotKind kind : scene.plots()) {
        const bool curve = kind == PlotKind::OnePeriodicData || kind == PlotKind::ImpactSpeed ||
                           kind == PlotKind::FrequencyEnergy ||
                           kind == PlotKind::GrazingMaximum || kind == PlotKind::SpreadAgainstSize ||
                           kind == PlotKind::FlightHistogram || kind == PlotKind::GrazingSet;
        if (curve) QVERIFY2(m_window->displayed()->request->job.figures.count(kind), qPrintable(name));
      }
      QVERIFY2(!scene.description().isEmpty(), qPrintable(name));
    }
  }

  // the landscape (issue 10): the map is computed in the worker on all cores while the window
  // stays live, and it is the core's map; the grazing set flies T2 exactly
  void landscapeIsComputedOffTheWindowAndIsTheCoresMap() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("landscape")));
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    // a chain whose map nobody computed yet (the worker keeps the last complete one)
    Params params = m_window->params();
    params.m2 = 0.4125;
    QElapsedTimer clock;
    qint64 last = 0, longestGap = 0;
    QTimer ticker;
    ticker.setInterval(5);
    connect(&ticker, &QTimer::timeout, this, [&] {
      longestGap = std::max(longestGap, clock.elapsed() - last);
      last = clock.elapsed();
    });
    clock.start();
    ticker.start();
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    ticker.stop();
    const SimUpdate& shown = *m_window->displayed();
    QVERIFY(shown.map && shown.map->complete);
    const MapProgress& map = *shown.map;
    QCOMPARE(map.spec.model.m2, 0.4125);
    QCOMPARE(map.spec.x.count, 256);
    // the event loop kept turning while the map was computed (a map on the GUI thread would
    // have held it for the whole computation)
    qInfo("map %.3f s, longest pause of the event loop %lld ms", map.seconds, longestGap);
    // (relative to the map's own time: a loaded machine pauses any event loop now and then)
    QVERIFY2(double(longestGap) < std::max(100.0, 0.5e3 * map.seconds),
             qPrintable(QStringLiteral("the window stood still for %1 ms of the map's %2 s")
                            .arg(longestGap)
                            .arg(map.seconds)));
    QVERIFY(m_window->landscapeView()->map().has_value());
    // the cells are core::mapPoint's, bit for bit
    for (const auto& [column, row] : {std::pair{0, 0}, std::pair{128, 128}, std::pair{255, 17}, std::pair{40, 200}}) {
      const grazelab::core::PointSummary expected = grazelab::core::mapPoint(map.spec, column, row);
      const grazelab::core::PointSummary& got = (*map.points)[std::size_t(row * 256 + column)];
      QCOMPARE(std::bit_cast<std::uint64_t>(got.fftFirst), std::bit_cast<std::uint64_t>(expected.fftFirst));
      QCOMPARE(got.impacts, expected.impacts);
    }
    // FFT = T2 somewhere (the grazing set), never above it
    const grazelab::core::TwoMassFormOrProblem<double> formed = grazelab::core::makeTwoMassForm(map.spec.model);
    const double T2 = grazelab::core::twoPi<double>() / formed.chain->omegaSlow;
    int atT2 = 0;
    for (const auto& point : *map.points) {
      if (std::isfinite(point.fftFirst)) QVERIFY(point.fftFirst <= T2);
      atT2 += point.fftFirst == T2;
    }
    QVERIFY(atT2 > 1000);
    // the CSV holds the map, cell by cell, with the value its colour shows (issue 30)
    const QStringList rows = m_window->plottedDataCsv().split(QLatin1Char('\n'));
    const qsizetype cells = std::count_if(rows.begin(), rows.end(), [](const QString& row) {
      return row.contains(QStringLiteral(",\"map\","));
    });
    QCOMPARE(cells, qsizetype(map.spec.x.count * map.spec.y.count));
  }

  // a click runs from that point of the plane; a dragged rectangle is computed anew at the
  // same resolution; Back returns to the region before
  void landscapeClickRunsFromThePointAndARectangleZooms() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("landscape")));
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    LandscapeView* view = m_window->landscapeView();
    QVERIFY(view && view->map() && view->map()->complete);
    const double gap = m_window->displayed()->request->job.spec.model.gap;
    // one pixel in value units, either way
    const QPointF a = *view->valueAt(view->positionOf(QPointF(0, 0)) + QPointF(1, 1));
    const QPointF b = *view->valueAt(view->positionOf(QPointF(0, 0)));
    const QPointF pixel(std::abs(a.x() - b.x()), std::abs(a.y() - b.y()));

    QTest::mouseClick(view, Qt::LeftButton, {}, view->positionOf(QPointF(0.3, 0.2)).toPoint());
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const grazelab::core::State start = m_window->displayed()->request->job.spec.run.initial;
    QCOMPARE(start.u2, gap);
    QCOMPARE(start.v2, 0.0);
    QVERIFY(std::abs(start.u1 - 0.3) <= 1.5 * pixel.x());
    QVERIFY(std::abs(start.v1 - 0.2) <= 1.5 * pixel.y());
    QVERIFY(!m_window->displayed()->result->poincare.empty());  // its contacts, over the map

    const Params::MapRegion before = m_window->params().mapRegion;
    const QPoint from = view->positionOf(QPointF(0.0, -0.5)).toPoint();
    const QPoint to = view->positionOf(QPointF(0.8, 0.5)).toPoint();
    QTest::mousePress(view, Qt::LeftButton, {}, from);
    QMouseEvent move(QEvent::MouseMove, QPointF(to), view->mapToGlobal(QPointF(to)), Qt::NoButton,
                     Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(view, &move);
    QTest::mouseRelease(view, Qt::LeftButton, {}, to);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const auto& spec = m_window->displayed()->map->spec;
    QVERIFY(std::abs(spec.x.from - 0.0) <= 1.5 * pixel.x());
    QVERIFY(std::abs(spec.x.to - 0.8) <= 1.5 * pixel.x());
    QVERIFY(std::abs(spec.y.from + 0.5) <= 1.5 * pixel.y());
    QVERIFY(std::abs(spec.y.to - 0.5) <= 1.5 * pixel.y());
    QCOMPARE(spec.x.count, 256);  // computed at full resolution, not a zoom of pixels
    QVERIFY(m_window->displayed()->map->complete);
    QVERIFY(!(m_window->params().mapRegion == before));

    QVERIFY(m_window->mapRegionBack());
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    QVERIFY(m_window->params().mapRegion == before);
    QVERIFY(!m_window->mapRegionBack());  // nothing further back
  }

  // a map a few ulps wide (zoomed eight times) made the tick loop spin forever: t += step did
  // not move t
  void heatMapTicksEndOnASpanOfAFewUlps() {
    const double lo = 1.0;
    const double hi = std::nextafter(std::nextafter(lo, 2.0), 2.0);
    const std::vector<double> ticks = grazelab::pictures::niceTicks(lo, hi);
    QVERIFY(!ticks.empty() && ticks.size() <= 64);
  }

  // Lemma 2.1: max u2/d of GLO(lambda) is 1 exactly on [0, 4/3], above 1 outside
  void grazingFamilyCurveIsOneOnTheGrazingRange() {
    const CurveFigure& lemma = figure(*m_window, PlotKind::GrazingMaximum);
    for (const QPointF& point : lemma.curve) {
      const bool grazing = point.x() >= 0 && point.x() <= 4.0 / 3.0;
      if (grazing) QCOMPARE(point.y(), 1.0);
      else if (std::abs(point.x()) > 1e-9 && std::abs(point.x() - 4.0 / 3.0) > 1e-9) QVERIFY(point.y() > 1.0);
    }
    QCOMPARE(lemma.markers.front().x(), m_window->params().lambda);
  }

  // Theorem 2.2: the shortfall of FFT below T2 shrinks with the push
  void perturbationSpreadShrinksWithThePush() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("perturbations")));
    QVERIFY(waitForLatestFinal(*m_window));
    const CurveFigure& spread = figure(*m_window, PlotKind::SpreadAgainstSize);
    QVERIFY(spread.curve.size() > 10);
    QVERIFY(spread.curve.front().y() < spread.curve.back().y() - 2);  // orders of magnitude
    for (const QPointF& point : spread.curve) QVERIFY(point.y() < 0);  // FFT < T2
    const auto& flights = m_window->displayed()->result->freeFlights;
    QVERIFY(!flights.empty());
    for (const auto& flight : flights) QVERIFY(flight.shortfall >= 0);
  }

  // Theorem 2.3: no contact or contacts to the end; no flight longer than T2
  void randomStartsNeverFlyLongerThanT2() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("random-starts")));
    QVERIFY(waitForLatestFinal(*m_window));
    const CurveFigure& histogram = figure(*m_window, PlotKind::FlightHistogram);
    double total = 0;
    for (std::size_t i = 1; i < histogram.curve.size(); i += 4) {
      total += histogram.curve[i].y();
      if (histogram.curve[i].x() >= 1.0) QCOMPARE(histogram.curve[i].y(), 0.0);
    }
    QVERIFY(total > 1000);
    // the legend counts: every start either never touches or reaches the end
    QVERIFY2(histogram.toolTip.contains(QStringLiteral(", 0 stop earlier")), qPrintable(histogram.toolTip));
  }

  // a start pressed on the stop sticks, then is released and impacts
  void stickingSceneSticksAndReleases() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("sticking")));
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY(m_window->params().lambda > 4.0 / 3.0);
    const auto& events = m_window->displayed()->result->events;
    const auto has = [&](grazelab::core::EventType type) {
      return std::any_of(events.begin(), events.end(), [&](const auto& e) { return e.type == type; });
    };
    QVERIFY(has(grazelab::core::EventType::Stick));
    QVERIFY(has(grazelab::core::EventType::Release));
    QVERIFY(has(grazelab::core::EventType::Impact));
  }

  // off 1:2 the free-flight time passes T2; in resonance it never does: one experiment of two
  // runs from the same start, read from the views that draw them
  void detunedFlightsPassT2AndResonantOnesDoNot() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("detuned")));
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const std::vector<QPointF> resonant = flightPlot(*m_window).flights().toVector();
    QVERIFY(resonant.size() > 100);
    for (const QPointF& point : resonant) QVERIFY2(point.y() <= 1.0, qPrintable(QString::number(point.y())));
    auto* contrast = m_window->findChild<ContrastFlightsPlot*>();
    QVERIFY(contrast);
    double longest = 0;
    for (const QPointF& point : contrast->below().toVector()) longest = std::max(longest, point.y());
    for (const QPointF& point : contrast->past().toVector()) longest = std::max(longest, point.y());
    QVERIFY2(longest > 1.05, qPrintable(QString::number(longest)));
    // the runs are the two chains: the 1:2 design, and k2 for the slider's ratio
    const auto& chains = m_window->displayed()->chains;
    QCOMPARE(chains.size(), std::size_t(2));
    const auto ratio = [](const grazelab::core::experiments::ChainSeries& series) {
      return series.modes.omega.maxCoeff() / series.modes.omega.minCoeff();
    };
    QVERIFY(std::abs(ratio(*chains[0]) - 2) < 1e-12);
    QVERIFY(std::abs(ratio(*chains[1]) - m_window->params().frequencyRatio) < 1e-9);
    QCOMPARE(chains[0]->start.u, chains[1]->start.u);
    QCOMPARE(chains[0]->start.v, chains[1]->start.v);
  }

  // a chain of N masses (issue 33): designed for 1:2:3 its frequencies are in the ratio and no
  // flight from the stop outlasts T (Theorem 2.3 for N = 3), while the same chain detuned has
  // flights past T; an impossible resonance for the masses is refused with a sentence; four
  // masses in 1:2:3:4 are designed and run the same way; the chain travels in the session
  void threeMassesStayBelowTheirPeriodAndImpossibleResonancesAreRefused() {
    // a two-mass chain with no 1:2 design, left in a two-mass scene, does not refuse the
    // N-mass scene (which never runs it)
    Params infeasible = m_window->params();
    infeasible.m2 = 0.9;
    m_window->setParams(infeasible);
    QVERIFY(!m_window->problem().isEmpty());
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("three-masses")));
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    QVERIFY2(m_window->problem().isEmpty(), qPrintable(m_window->problem()));
    const SceneJob* job = &m_window->displayed()->request->job;
    QVERIFY2(job->ok, qPrintable(job->message));
    QVERIFY2(job->chain.summary.contains(QStringLiteral("3 : 2 : 1")), qPrintable(job->chain.summary));
    QVERIFY2(m_window->statusText().contains(QStringLiteral("200 contacts")), qPrintable(m_window->statusText()));
    QCOMPARE(job->chain.designs, 6);
    const std::vector<QPointF> flights = flightPlot(*m_window).flights().toVector();
    QVERIFY(flights.size() > 150);
    for (const QPointF& point : flights) QVERIFY2(point.y() <= 1.0 + 1e-12, qPrintable(QString::number(point.y())));
    double longest = 0;
    auto* contrast = m_window->findChild<ContrastFlightsPlot*>();
    QVERIFY(contrast);
    for (const QPointF& point : contrast->below().toVector()) longest = std::max(longest, point.y());
    for (const QPointF& point : contrast->past().toVector()) longest = std::max(longest, point.y());  // past 3 T
    QVERIFY2(longest > 1.01, qPrintable(QString::number(longest)));
    // the trace stays at or below the stop, and touches it at each contact
    const PointSpan trace = tracePlot(*m_window).stoppedMass();
    QVERIFY(trace.size() > 100);
    for (std::size_t k = 0; k < trace.size(); ++k) QVERIFY(trace[k].y() <= 1.0 + 1e-12);
    for (const QPointF& contact : tracePlot(*m_window).contacts()) QCOMPARE(contact.y(), 1.0);
    // the chain moving starts at the orbit's touch and has the stopped mass on the stop at each
    // contact (its grid interpolated: to 1 % of d)
    ChainView* moving = m_window->chainView();
    QVERIFY(moving);
    QVERIFY(shownChainRun(*m_window));
    const auto& series = *shownChainRun(*m_window);
    QCOMPARE(moving->displacementsAt(0).size(), std::size_t(3));
    QCOMPARE(moving->displacementsAt(0)[2], series.chain.gap);
    int seen = 0;
    for (const auto& event : series.run.events) {
      if (event.t > series.grid.lastTime()) break;
      QVERIFY(std::abs(moving->displacementsAt(event.t)[2] - series.chain.gap) < 0.01 * series.chain.gap);
      ++seen;
    }
    QVERIFY(seen >= 3);
    // the same view as for two masses: [ and ] step from contact to contact
    moving->setTime(0);
    moving->stepContact(+1);
    QCOMPARE(moving->time(), series.run.events[0].t);
    moving->stepContact(+1);
    QCOMPARE(moving->time(), series.run.events[1].t);
    moving->stepContact(-1);
    QCOMPARE(moving->time(), series.run.events[0].t);
    // Space plays and pauses it, as it does the two-mass chain
    QTest::keyClick(m_window.get(), Qt::Key_Space);
    QVERIFY(moving->playing());
    QTest::keyClick(m_window.get(), Qt::Key_Space);
    QVERIFY(!moving->playing());
    // the animation's time is a line on the trace (t over T) and a ring on the phase portrait
    // (the stopped mass's state then: at the first contact, on the stop)
    const double period = series.period;
    // as shown (the animation at its start, the axes fitted after the line was placed): the line
    // at t = 0 spans the fitted axis
    QTest::qWait(100);  // the plots' deferred refresh
    double when = moving->time();
    const auto seriesOf = [this](const QString& title) {
      std::vector<std::vector<QPointF>> all;
      for (PlotView* plot : m_window->plots()) {
        if (!plot->title().startsWith(title)) continue;
        for (QAbstractSeries* item : plot->chart()->series()) {
          if (auto* xy = qobject_cast<QXYSeries*>(item)) {
            const QList<QPointF> list = xy->points();
            all.emplace_back(list.begin(), list.end());
          }
        }
      }
      return all;
    };
    const auto lineSpansTheAxis = [&] {
      bool line = false;
      for (PlotView* plot : m_window->plots()) {
        if (!plot->title().startsWith(QStringLiteral("Mass 3"))) continue;
        const auto* y = qobject_cast<QValueAxis*>(plot->chart()->axes(Qt::Vertical).value(0));
        for (const auto& points : seriesOf(QStringLiteral("Mass 3"))) {
          // at t / T, from the axis' bottom to its top as fitted
          line = line || (points.size() == 2 && points[0].x() == when / period && points[1].x() == when / period &&
                          points[0].y() == y->min() && points[1].y() == y->max());
        }
      }
      return line;
    };
    QVERIFY(lineSpansTheAxis());
    when = series.run.events.front().t;
    moving->setTime(when);
    QVERIFY(lineSpansTheAxis());
    // the ring on the portrait: at the first contact on the stop, and between two samples the
    // interpolated state (the start marker, named "start", is not it)
    const auto ringAt = [&](QPointF expected, double tolerance) {
      for (PlotView* plot : m_window->plots()) {
        if (!plot->title().startsWith(QStringLiteral("Phase portrait"))) continue;
        for (QAbstractSeries* candidate : plot->chart()->series()) {
          auto* xy = qobject_cast<QXYSeries*>(candidate);
          // (a NaN y: only x is asked for)
          if (xy && xy->name().isEmpty() && xy->count() == 1 && std::abs(xy->at(0).x() - expected.x()) < tolerance &&
              (std::isnan(expected.y()) || std::abs(xy->at(0).y() - expected.y()) < tolerance)) {
            return true;
          }
        }
      }
      return false;
    };
    const double speed = series.chain.gap * series.modes.omega.maxCoeff();
    // (on the stop: its velocity there is the grid's interpolation across the impact's jump)
    QVERIFY(ringAt(QPointF(1.0, std::nan("")), 0.01));
    const std::size_t k = series.grid.size() / 3;
    when = 0.5 * (series.grid.t(k) + series.grid.t(k + 1));
    moving->setTime(when);
    const QPointF between(0.5 * (series.grid.u(k, 2) + series.grid.u(k + 1, 2)) / series.chain.gap,
                          0.5 * (series.grid.v(k, 2) + series.grid.v(k + 1, 2)) / speed);
    QVERIFY(ringAt(between, 1e-9));

    // another mass's phase portrait: its state at each contact marked on it
    Params params = m_window->params();
    params.massChain.shownMass = 1;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    {
      const PhasePlot& phase = phasePlot(*m_window);
      QVERIFY2(phase.title().contains(QStringLiteral("mass 1")), qPrintable(phase.title()));
      QVERIFY(shownChainRun(*m_window));
      const auto& shownSeries = *shownChainRun(*m_window);
      QVERIFY(!phase.atContacts().empty());
      QCOMPARE(phase.atContacts()[0].x(), shownSeries.run.events.front().u[0] / shownSeries.chain.gap);
      const double speed = shownSeries.chain.gap * shownSeries.modes.omega.maxCoeff();
      QCOMPARE(phase.atContacts()[0].y(), shownSeries.run.events.front().vBefore[0] / speed);
      QVERIFY(std::abs(phase.path()[0].x() - shownSeries.start.u[0] / shownSeries.chain.gap) < 1e-12);
      // and its trace beside the stopped mass's, on the same grid
      const TracePlot& trace = tracePlot(*m_window);
      QCOMPARE(trace.chosenMass().size(), trace.stoppedMass().size());
      QCOMPARE(trace.chosenMass()[0].y(), shownSeries.grid.u(0, 0) / shownSeries.chain.gap);
      QVERIFY2(trace.legendNames().contains(QStringLiteral("u₁ / d")), qPrintable(trace.legendNames().join(',')));
      QVERIFY2(trace.title().contains(QStringLiteral("mass 1")), qPrintable(trace.title()));
    }
    // the Poincaré points on H on the chosen pair (u2, v3): every contact's state there, the
    // velocity the one before the contact, scaled as the phase portrait is
    params.massChain.sectionX = 2;
    params.massChain.sectionY = 6;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    {
      PoincarePlot* plot = nullptr;
      for (PoincarePlot* candidate : m_window->findChildren<PoincarePlot*>()) {
        if (candidate->isVisible()) plot = candidate;
      }
      QVERIFY(plot);
      plot->refreshNow();
      const std::vector<QPointF> section = plot->points();
      const auto& run = shownChainRun(*m_window);
      QVERIFY2(plot->title().contains(QStringLiteral("(u₂, v₃)")), qPrintable(plot->title()));
      QCOMPARE(qsizetype(section.size()), qsizetype(run->run.contacts));
      const double speed = run->chain.gap * run->modes.omega.maxCoeff();
      // in contact order: the first contact's and the last's
      QCOMPARE(section.front().x(), run->run.events.front().u[1] * (1 / run->chain.gap));
      QCOMPARE(section.front().y(), run->run.events.front().vBefore[2] * (1 / speed));
      QCOMPARE(section.back().x(), run->section.u(run->section.size() - 1, 1) * (1 / run->chain.gap));
    }
    params.massChain.sectionX = params.massChain.sectionY = 0;
    params.massChain.shownMass = 0;
    params.massChain.masses = {1.0, 1.0, 1.0};
    m_window->setParams(params);
    // refused: the window says why (status line and panel), the last chain stays drawn
    QDeadlineTimer deadline(60000);
    while (m_window->problem().isEmpty() && !deadline.hasExpired()) QTest::qWait(5);
    const QString refusal = QStringLiteral("No chain with these masses has the frequencies in the ratio 1:2:3");
    QVERIFY2(m_window->problem().contains(refusal), qPrintable(m_window->problem()));
    QVERIFY2(m_window->parameterPanel()->chainEditor()->summary().contains(refusal),
             qPrintable(m_window->parameterPanel()->chainEditor()->summary()));

    params.massChain = MassChainParams{}.resized(4);
    params.massChain.masses = {1.0, 0.6, 0.36, 0.216};
    params.massChain.harmonics = {4, 3, 2, 1};
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    job = &m_window->displayed()->request->job;
    QVERIFY2(job->ok, qPrintable(job->message));
    QVERIFY2(job->chain.summary.contains(QStringLiteral("4 : 3 : 2 : 1")), qPrintable(job->chain.summary));
    const std::vector<QPointF> bounded = flightPlot(*m_window).flights().toVector();
    QVERIFY(bounded.size() > 10);
    for (const QPointF& point : bounded) QVERIFY(point.y() <= 1.0 + 1e-12);

    // the whole chain is part of the parameters a session saves, and reads back the same
    QString error;
    const auto back = paramsFromJson(toJson(m_window->params()), Params{}, &error);
    QVERIFY2(back.has_value(), qPrintable(error));
    QVERIFY(back->massChain == m_window->params().massChain);
    QJsonObject bad = toJson(m_window->params());
    QJsonObject chain = bad.value(QStringLiteral("massChain")).toObject();
    chain.insert(QStringLiteral("weights"), QJsonArray{0.5, 0.5, 0.5, 0.5});
    bad.insert(QStringLiteral("massChain"), chain);
    QVERIFY(!paramsFromJson(bad, Params{}, &error));
    QVERIFY2(error.contains(QStringLiteral("sum")), qPrintable(error));
  }

  // Lemma 2.1 for other resonances (issue 33): the grazing set the scene draws for 1:2, 1:3 and
  // 2:3 is the exact one (1:n: [0, n^2/(n^2 - 1)]; 2:3 by brute force here: the top of GLO over
  // 20 000 phases, bisected on lambda), the panel's weights get a verdict, and three modes give
  // a region whose boundary grazes just so
  void grazingSetsAreTheExactOnes() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("grazing-sets")));
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const auto top = [](const std::vector<int>& n, const std::vector<double>& w) {
      double highest = -1e300;
      for (int k = 0; k < 20000; ++k) {
        const double theta = 2 * M_PI * k / 20000;
        double sum = 0;
        for (std::size_t j = 0; j < n.size(); ++j) sum += w[j] * std::cos(n[j] * theta);
        highest = std::max(highest, sum);
      }
      return highest;
    };
    struct Case {
      std::vector<double> masses;
      std::vector<int> harmonics;
    };
    for (const Case& each : {Case{{1.0, 0.5}, {2, 1}}, Case{{1.0, 0.3}, {3, 1}}, Case{{1.0, 0.1}, {3, 2}}}) {
      Params params = m_window->params();
      params.massChain = MassChainParams{}.resized(2);
      params.massChain.masses = each.masses;
      params.massChain.harmonics = each.harmonics;
      params.massChain.weights = {0.5, 0.5};
      m_window->setParams(params);
      QVERIFY(waitForLatestFinal(*m_window, 60000));
      const SceneJob& job = m_window->displayed()->request->job;
      QVERIFY2(job.ok, qPrintable(job.message));
      const CurveFigure& set = figure(*m_window, PlotKind::GrazingSet);
      QCOMPARE(set.reference.size(), std::size_t(2));
      const double low = set.reference[0].x(), high = set.reference[1].x();
      const int n1 = each.harmonics[0], n2 = each.harmonics[1];
      // the upper end by bisection on the brute-force top (above 1 + 1e-9: crosses)
      double in = 1, out = 3;
      for (int step = 0; step < 50; ++step) {
        const double mid = (in + out) / 2;
        (top({n1, n2}, {1 - mid, mid}) > 1 + 1e-9 ? out : in) = mid;
      }
      if (n2 == 1) QVERIFY2(std::abs(high - double(n1 * n1) / (n1 * n1 - 1)) < 1e-12, qPrintable(QString::number(high)));
      // (a top flat at its end, as at 1:n, rises as the square of the distance past it: 1e-4)
      QVERIFY2(std::abs(high - in) < 1e-4, qPrintable(QStringLiteral("%1 against %2").arg(high).arg(in)));
      QVERIFY2(std::abs(low) < 1e-12, qPrintable(QString::number(low)));
      QVERIFY2(job.status.contains(QStringLiteral("grazes")), qPrintable(job.status));
      // the panel's weights past the set's end: the verdict says it crosses
      params.massChain.weights = {1 - (high + 0.2), high + 0.2};
      m_window->setParams(params);
      QVERIFY(waitForLatestFinal(*m_window, 60000));
      QVERIFY2(m_window->displayed()->request->job.status.contains(QStringLiteral("crosses")),
               qPrintable(m_window->displayed()->request->job.status));
    }
    // three modes: 1:2:3, each boundary point grazes just so (its brute-force top is 1)
    Params params = m_window->params();
    params.massChain = MassChainParams{};  // 1, 0.2, 0.05 in 1:2:3
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const CurveFigure& region = figure(*m_window, PlotKind::GrazingSet);
    QVERIFY(region.curve.size() > 40);
    for (const QPointF& point : region.curve) {
      const double lambda2 = point.x(), lambda3 = point.y();
      QVERIFY(std::abs(top({3, 2, 1}, {1 - lambda2 - lambda3, lambda2, lambda3}) - 1) < 1e-6);
    }
  }

  // the ring of the panel's weights in the (λ2, λ3) plane is dragged: the weights follow it (the
  // first balancing), the orbit and its verdict are the new weights'; a click elsewhere moves it
  // there; the two-mode dot moves λ along its axis
  void grazingSetPointIsDraggedInThePlane() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("grazing-sets")));
    Params params = m_window->params();
    params.massChain = MassChainParams{};  // 1:2:3, weights (0.5, 0.3, 0.2)
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    CurvePlot* plot = nullptr;
    for (CurvePlot* candidate : m_window->findChildren<CurvePlot*>()) {
      if (candidate->isVisible() && candidate->draggable()) plot = candidate;
    }
    QVERIFY(plot);
    const auto at = [plot](QPointF value) { return plot->mapFromScene(plot->chart()->mapToPosition(value)); };
    const QPoint ring = at(QPointF(0.3, 0.2));
    // past the boundary where it is nearest the simplex's centre: outside the set, inside the plot
    const QPointF centre(1.0 / 3, 1.0 / 3);
    QPointF nearest = figure(*m_window, PlotKind::GrazingSet).curve.front();
    for (const QPointF& point : figure(*m_window, PlotKind::GrazingSet).curve) {
      if (QLineF(centre, point).length() < QLineF(centre, nearest).length()) nearest = point;
    }
    const QPointF beyond = centre + 1.2 * (nearest - centre);
    const QPoint target = at(beyond);
    // a pixel in weight units: the drag lands within one or two of the target
    const double pixel = std::abs(plot->chart()->mapToValue(QPointF(101, 0)).x() - plot->chart()->mapToValue(QPointF(100, 0)).x());
    QTest::mousePress(plot->viewport(), Qt::LeftButton, {}, ring);
    for (int step = 1; step <= 4; ++step) {
      const QPointF through = QPointF(ring) + (QPointF(target) - QPointF(ring)) * (step / 4.0);
      QMouseEvent move(QEvent::MouseMove, through, plot->viewport()->mapToGlobal(through), Qt::LeftButton,
                       Qt::LeftButton, Qt::NoModifier);
      QApplication::sendEvent(plot->viewport(), &move);
    }
    QTest::mouseRelease(plot->viewport(), Qt::LeftButton, {}, target);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const std::vector<double> weights = m_window->params().massChain.weights;
    QVERIFY2(std::abs(weights[1] - beyond.x()) <= 2 * pixel + 1e-3, qPrintable(QString::number(weights[1])));
    QVERIFY2(std::abs(weights[2] - beyond.y()) <= 2 * pixel + 1e-3, qPrintable(QString::number(weights[2])));
    QVERIFY(std::abs(weights[0] + weights[1] + weights[2] - 1) < 1e-12);
    const CurveFigure& region = figure(*m_window, PlotKind::GrazingSet);
    QCOMPARE(region.reference.front(), QPointF(weights[1], weights[2]));
    // and the orbit drawn passes the stop (its linear motion, not a run held by the stop)
    double top = 0;
    const PointSpan orbit = tracePlot(*m_window).stoppedMass();
    for (std::size_t k = 0; k < orbit.size(); ++k) top = std::max(top, orbit[k].y());
    QVERIFY2(tracePlot(*m_window).title().contains(QStringLiteral("GLO")), qPrintable(tracePlot(*m_window).title()));
    QVERIFY2(top > 1.0 + 1e-3, qPrintable(QString::number(top)));
    QVERIFY2(m_window->displayed()->request->job.status.contains(QStringLiteral("crosses")),
             qPrintable(m_window->displayed()->request->job.status));

    // the two-mode set: dragging the dot moves λ (the slow mode's weight), the fast one balancing
    params = m_window->params();
    params.massChain = m_window->scene().defaults().massChain;  // 1:3, λ = 0.5
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const CurveFigure& set = figure(*m_window, PlotKind::GrazingSet);
    QVERIFY(plot->draggable());
    const QPoint dot = at(set.markers.front());
    const QPoint right = at(QPointF(1.0, set.markers.front().y()));
    QTest::mousePress(plot->viewport(), Qt::LeftButton, {}, dot);
    QMouseEvent move(QEvent::MouseMove, QPointF(right), plot->viewport()->mapToGlobal(QPointF(right)), Qt::LeftButton,
                     Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(plot->viewport(), &move);
    QTest::mouseRelease(plot->viewport(), Qt::LeftButton, {}, right);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const std::vector<double> two = m_window->params().massChain.weights;
    const double pixel2 = std::abs(plot->chart()->mapToValue(QPointF(101, 0)).x() - plot->chart()->mapToValue(QPointF(100, 0)).x());
    QVERIFY2(std::abs(two[1] - 1.0) <= 2 * pixel2 + 1e-3, qPrintable(QString::number(two[1])));
    QCOMPARE(two[0] + two[1], 1.0);
  }

  // Theorem 2.1 for N = 3 (issue 33): the 1IPP family's data tend to the grazing limit the
  // theorem gives and its impact speed to 0 as T -> T*; the slider's orbit is periodic (its
  // exact run meets the stop at T, 2T, 3T)
  void chainOnePeriodicOrbitsTendToTheirGrazingLimit() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("chain-1ipp")));
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const SceneJob& job = m_window->displayed()->request->job;
    QVERIFY2(job.ok, qPrintable(job.message));
    const CurveFigure& data = figure(*m_window, PlotKind::OnePeriodicData);
    const CurveFigure& speed = figure(*m_window, PlotKind::ImpactSpeed);
    QCOMPARE(data.reference.size(), std::size_t(1));
    QVERIFY(data.curve.size() > 50);
    // the family's last orbits, T within 1e-6 of T*: the data at the limit's, the speed near 0
    const QPointF nearest = data.curve.back();
    QVERIFY(nearest.x() > 1 - 1e-6);
    QVERIFY2(std::abs(nearest.y() - data.reference[0].y()) < 1e-4,
             qPrintable(QStringLiteral("%1 against %2").arg(nearest.y()).arg(data.reference[0].y())));
    QVERIFY(speed.curve.back().y() < 1e-4);
    // (on the trace over the orbit's own period)
    const std::vector<QPointF> contacts = tracePlot(*m_window).contacts();
    for (const QPointF& contact : contacts) {
      QVERIFY2(std::abs(contact.x() - std::round(contact.x())) < 1e-9, qPrintable(QString::number(contact.x(), 'g', 17)));
    }
    QCOMPARE(contacts.size(), std::size_t(3));
    // the weights are not this scene's: hidden
    const auto* firstWeight = m_window->parameterPanel()->chainEditor()->findChild<QLabel*>(QStringLiteral("chainFirstWeight"));
    QVERIFY(firstWeight && !firstWeight->isVisibleTo(m_window.get()));
  }

  // a string of eight masses (issue 33): the stop inside it (mass 5), its slowest mode pushed:
  // every contact asked for is found, the stopped mass on the stop at each (u5 = d, from the
  // grid to 1 % of d), no flight bound drawn for a chain with no common period, and no error
  // estimate claimed where none was made
  void eightMassesRunWithTheStopInside() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("eight-masses")));
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const SceneJob& job = m_window->displayed()->request->job;
    QVERIFY2(job.ok, qPrintable(job.message));
    QCOMPARE(m_window->displayed()->chains.size(), std::size_t(1));
    QVERIFY(shownChainRun(*m_window));
    const auto& series = *shownChainRun(*m_window);
    QCOMPARE(series.chain.size(), 8);
    QCOMPARE(series.chain.stopped(), 5);
    QCOMPARE(series.run.contacts, 100L);
    QVERIFY(!series.ratios.commensurate);
    QVERIFY2(!flightPlot(*m_window).legendNames().join(',').contains(QStringLiteral("bound")),
             qPrintable(flightPlot(*m_window).legendNames().join(',')));
    QVERIFY(flightPlot(*m_window).title().contains(QStringLiteral("no bound")));
    QVERIFY(series.trust.verdict == grazelab::core::Verdict::Unchecked);
    QVERIFY2(m_window->statusText().contains(QStringLiteral("no error estimate")), qPrintable(m_window->statusText()));
    ChainView* moving = m_window->chainView();
    QVERIFY(moving);
    for (const auto& event : series.run.events) {
      QCOMPARE(event.u[4], 1.0);  // on the stop exactly at its contacts
      if (event.t <= series.grid.lastTime()) QVERIFY(std::abs(moving->displacementsAt(event.t)[4] - 1) < 0.01);
    }
  }

  // a long run of N masses is drawn as it grows (issue 47): partial reports of the streamed run
  // reach the plots before the final one, each a prefix of it, the status saying it computes
  void longChainRunsAreDrawnAsTheyGrow() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("three-masses")));
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    Params params = m_window->params();
    params.horizon = 300000;
    m_window->setParams(params);
    long partialContacts = -1;
    QDeadlineTimer deadline(120000);
    while (!deadline.hasExpired()) {
      const SimUpdate* shown = m_window->displayed();
      if (shown && shown->id == m_window->controller()->latestId() && !shown->final && !shown->chains.empty()) {
        partialContacts = shown->chains.front()->run.contacts;
        const auto& partial = shown->chains.front()->flights;
        QCOMPARE(qsizetype(flightPlot(*m_window).flights().size()),
                 qsizetype(std::count_if(partial.begin(), partial.end(), [](const auto& f) { return f.fromStop; })));
        QVERIFY2(m_window->statusText().contains(QStringLiteral("computing")), qPrintable(m_window->statusText()));
        break;
      }
      QTest::qWait(2);
    }
    QVERIFY2(partialContacts >= 0, "no partial run was drawn");
    QVERIFY(partialContacts < 300000);
    QVERIFY(waitForLatestFinal(*m_window, 120000));
    QCOMPARE(shownChainRun(*m_window)->run.contacts, 300000L);
  }

  // the animated chain: plays forward at its rate, steps from contact to contact, and its time
  // is the cursor of the trace and the phase portrait
  void chainAnimationPlaysStepsAndMovesTheCursors() {
    ChainView* chain = m_window->chainView();
    QVERIFY(chain);  // the default scene shows it
    const auto& events = m_window->displayed()->result->events;
    QVERIFY(events.size() > 3);
    chain->setTime(0);
    chain->stepContact(+1);
    QCOMPARE(chain->time(), events[0].t);
    chain->stepContact(+1);
    QCOMPARE(chain->time(), events[1].t);
    chain->stepContact(-1);
    QCOMPARE(chain->time(), events[0].t);
    // at a contact the state shown is on the stop
    QVERIFY(std::abs(chain->displacementsAt(chain->time())[1] - m_window->params().gap) < 1e-3);
    // the trace's cursor line stands at that time (in slow periods T2, as its axis)
    PlotView* trace = m_window->plots().first();
    const double T2 = grazelab::core::computeModes(m_window->displayed()->request->job.spec.model).T2;
    QXYSeries* cursor = nullptr;
    for (QAbstractSeries* series : trace->chart()->series()) {
      auto* xy = qobject_cast<QXYSeries*>(series);
      if (xy && xy->count() == 2 && xy->at(0).x() == xy->at(1).x() && xy->at(0).x() == chain->time() / T2) cursor = xy;
    }
    QVERIFY(cursor);
    // playing moves time forward, about at the rate asked (generous: a loaded machine)
    chain->setTime(0);
    chain->setPlaying(true);
    QTest::qWait(400);
    chain->setPlaying(false);
    QVERIFY(chain->time() > 0.1 * 0.4 * chain->rate());
    QVERIFY(chain->time() < 3 * 0.4 * chain->rate());
  }

 private:
  std::unique_ptr<MainWindow> m_window;
};

QTEST_MAIN(ScenesTest)
#include "scenes_test.moc"
