// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for ui/compute/sim_controller.cpp and sim_worker.cpp, through ui/window/main_window.cpp: the live loop
// from a slider to the plots, latest wins, infeasible input, long runs.
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QLabel>
#include <QPointer>
#include <QTemporaryDir>
#include <QVBoxLayout>
#include <QElapsedTimer>
#include <QGuiApplication>
#include <QHelpEvent>
#include <QScreen>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <QTimer>
#include <QToolTip>
#include <QValueAxis>
#include <QXYSeries>

#include <algorithm>
#include <optional>
#include <random>

#include "core/model/two_mass_form.h"
#include "core/orbits/special_orbits.h"
#include "tests/ui/explorer_test_support.h"
#include "core/model/linear_modes.h"
#include "ui/compute/derived.h"
#include "ui/window/main_window.h"
#include "ui/widgets/batched_layout.h"
#include "ui/widgets/number_box.h"
#include "ui/widgets/parameter_panel.h"
#include "ui/plots/accuracy_view.h"
#include "ui/plots/free_flight_plot.h"
#include "ui/plots/poincare_plot.h"
#include "ui/plots/log_log_chart.h"
#include "ui/plots/plot_grid.h"
#include "ui/plots/plot_view.h"
#include "ui/widgets/readout_panel.h"
#include "ui/compute/sim_controller.h"
#include "ui/compute/sim_worker.h"
#include "ui/widgets/slider_spin.h"

using namespace grazelab::ui;
using grazelab::ui::testing::openTestWindow;
using grazelab::ui::testing::waitForLatestFinal;

namespace {

// the data of the first series of the first plot (the u2 trace on the default scene)
std::vector<QPointF> firstSeries(const MainWindow& window) {
  return window.plots().first()->entries().front().points().toVector();
}

// the reference square on the Poincaré plot: the GLO_lambda data the run started from
QPointF poincareReference(const MainWindow& window) {
  for (const PlotView* plot : window.plots()) {
    for (const PlotView::Entry& entry : plot->entries()) {
      if (entry.series->name().startsWith(QStringLiteral("GLO")) && !entry.points().empty()) {
        return entry.points()[0];
      }
    }
  }
  return {qQNaN(), qQNaN()};
}

}  // namespace

class ExplorerTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    m_window = openTestWindow();
    QVERIFY(waitForLatestFinal(*m_window));
  }
  void cleanup() { m_window.reset(); }

  void opensOnTheDefaultSceneWithAllPlots() {
    QCOMPARE(m_window->sceneIndex(), 0);
    QCOMPARE(m_window->scene().name(), QStringLiteral("Grazing family GLO_lambda"));
    QCOMPARE(m_window->plots().size(), qsizetype(5));
    for (const PlotView* plot : m_window->plots()) {
      QVERIFY2(plot->drawnPointCount() > 0, qPrintable(plot->title()));
    }
    const SimUpdate* shown = m_window->displayed();
    QVERIFY(shown->result->cost.impacts > 0);  // the default scene impacts
    QCOMPARE(m_window->readoutPanel()->text(QStringLiteral("k2")), QStringLiteral("0.5"));
  }

  void sliderChangeRecomputesAndUpdatesSeries() {
    const std::uint64_t before = m_window->displayed()->id;
    const std::vector<QPointF> oldTrace = firstSeries(*m_window);
    QSlider* slider = m_window->parameterPanel()->control(ParamKey::Lambda)->slider();
    QSignalSpy spy(m_window.get(), &MainWindow::plotsUpdated);
    slider->setValue(slider->value() + 150);
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY(spy.count() >= 1);
    QVERIFY(m_window->displayed()->id > before);
    const double lambda = m_window->parameterPanel()->control(ParamKey::Lambda)->value();
    QCOMPARE(m_window->displayed()->request->params.lambda, lambda);
    QVERIFY(firstSeries(*m_window) != oldTrace);
  }

  void spinBoxMovesSliderAndBack() {
    SliderSpin* control = m_window->parameterPanel()->control(ParamKey::Lambda);
    control->spinBox()->setValue(1.0);
    QCOMPARE(control->slider()->value(), 600);  // 1 on the slider's -0.5 ... 2, 0..1000
    control->slider()->setValue(500);
    QCOMPARE(control->spinBox()->value(), 0.75);
    QVERIFY(waitForLatestFinal(*m_window));
    QCOMPARE(m_window->displayed()->request->params.lambda, 0.75);
  }

  void burstOfChangesEndsWithTheLastValue() {
    QSlider* slider = m_window->parameterPanel()->control(ParamKey::Lambda)->slider();
    QSignalSpy spy(m_window.get(), &MainWindow::plotsUpdated);
    for (int step = 0; step < 200; ++step) {
      slider->setValue(100 + (step * 37) % 800);
      // a real drag lets the event loop turn now and then
      if (step % 10 == 0) QCoreApplication::processEvents();
    }
    slider->setValue(612);
    QVERIFY(waitForLatestFinal(*m_window));
    const double lambda = m_window->parameterPanel()->control(ParamKey::Lambda)->value();
    QCOMPARE(m_window->displayed()->request->params.lambda, lambda);
    // the plots themselves show the last value: the reference point is GLO_lambda's data
    const DerivedModel derived = deriveModel(m_window->params());
    const grazelab::core::State expected =
        grazelab::core::gloData(derived.model, derived.modes, lambda);
    QCOMPARE(poincareReference(*m_window).x(), expected.u1 / derived.model.gap);  // (in units of d)
    // far fewer redraws than changes: stale results were dropped
    QVERIFY(spy.count() < 200);
  }

  void infeasibleMassRatioKeepsLastResult() {
    const SimUpdate before = *m_window->displayed();
    const std::vector<QPointF> trace = firstSeries(*m_window);
    m_window->parameterPanel()->control(ParamKey::M2)->spinBox()->setValue(0.7);  // m2/m1 > 9/16
    QTest::qWait(100);
    QVERIFY(m_window->problem().contains(QStringLiteral("9/16")));
    QVERIFY(m_window->parameterPanel()->message().contains(QStringLiteral("9/16")));
    QCOMPARE(m_window->displayed()->id, before.id);
    QCOMPARE(m_window->displayed()->request->params.m2, 0.5);
    QVERIFY(firstSeries(*m_window) == trace);
    // no silent clamping: the typed value stays
    QCOMPARE(m_window->params().m2, 0.7);
    // and back to a feasible value computes again
    m_window->parameterPanel()->control(ParamKey::M2)->spinBox()->setValue(0.4);
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY(m_window->problem().isEmpty());
    QCOMPARE(m_window->displayed()->request->params.m2, 0.4);
  }

  void invalidStateFromTheCoreIsShownNotCrashed() {
    Params params = m_window->params();
    params.direction = PerturbDirection::U2;
    params.perturbation = 0.1;  // past the stop
    const std::uint64_t shown = m_window->displayed()->id;
    m_window->setParams(params);
    QTRY_VERIFY(!m_window->problem().isEmpty());
    QCOMPARE(m_window->displayed()->id, shown);
  }

  void longRunStreamsAndStaysResponsive() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("near-grazing")));
    QVERIFY(waitForLatestFinal(*m_window));
    Params params = m_window->params();
    params.horizon = 1e6;
    int ticks = 0;
    QTimer heartbeat;
    connect(&heartbeat, &QTimer::timeout, [&] { ++ticks; });
    heartbeat.start(10);
    QSignalSpy spy(m_window.get(), &MainWindow::plotsUpdated);
    QElapsedTimer clock;
    clock.start();
    m_window->setParams(params);
    // partial results arrive while the worker runs
    QTRY_VERIFY_WITH_TIMEOUT(spy.count() >= 2, 10000);
    QVERIFY(!spy.last().at(1).toBool() || spy.count() > 2);
    QTest::qWait(300);
    m_window->controller()->cancel();
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY(m_window->displayed()->result->stop == grazelab::core::StopReason::Cancelled);
    QVERIFY(m_window->statusText().contains(QStringLiteral("cancelled")));
    // the event loop kept turning: at least a third of the 10 ms heartbeats fired
    QVERIFY2(ticks >= clock.elapsed() / 30, qPrintable(QString::number(ticks)));
  }

  void scenesChangePlotsAndParameters() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("1ipp")));
    QVERIFY(waitForLatestFinal(*m_window));
    QCOMPARE(m_window->plots().size(), qsizetype(4));
    QVERIFY(m_window->chainView());
    QVERIFY(!m_window->parameterPanel()->control(ParamKey::Lambda)->isVisibleTo(m_window.get()));
    QVERIFY(m_window->parameterPanel()->control(ParamKey::Period)->isVisibleTo(m_window.get()));
    // one impact per period: the impacts are T apart
    const SimUpdate* shown = m_window->displayed();
    const double period = m_window->params().periodFraction * grazelab::core::computeModes(shown->request->job.spec.model).T2;
    QVERIFY(shown->result->events.size() > 2);
    for (std::size_t i = 1; i < shown->result->events.size(); ++i) {
      QVERIFY(std::abs(shown->result->events[i].t - shown->result->events[i - 1].t - period) < 1e-6);
    }
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("near-grazing")));
    QVERIFY(waitForLatestFinal(*m_window));
    QCOMPARE(m_window->plots().size(), qsizetype(3));
  }

  void accuracySceneMeasuresEveryMethodAndOverlaysTheChosenOne() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("accuracy")));
    QCOMPARE(m_window->scene().alias(), QStringLiteral("accuracy"));
    QVERIFY(waitForLatestFinal(*m_window, 120000));
    const SimUpdate* shown = m_window->displayed();
    QVERIFY(shown->accuracy);
    QCOMPARE(shown->accuracy->points.size(), shown->accuracy->total);
    AccuracyView* view = m_window->accuracyView();
    QVERIFY(view);
    // every method has a curve, and the exact solver is the most accurate of them
    QCOMPARE(view->chart()->curveCount(), 8);
    double exactError = 1, bestOther = 1;
    for (const AccuracyPoint& point : shown->accuracy->points) {
      const auto& p = point.point;
      if (p.status != grazelab::core::methods::RunStatus::Completed) continue;
      if (p.setting.kind == grazelab::core::methods::MethodKind::Exact) {
        if (p.setting.precision == grazelab::core::Precision::Double) exactError = p.errors.state;
      } else {
        bestOther = std::min(bestOther, p.errors.state);
      }
    }
    QVERIFY(exactError < 1e-9);
    QVERIFY(exactError < bestOther);
    {
      // the CSV holds the chart: one row per finished setting, its run time and errors (issue 30)
      const QStringList rows = m_window->plottedDataCsv().split(QLatin1Char('\n'));
      const auto completed = std::count_if(shown->accuracy->points.begin(), shown->accuracy->points.end(),
                                           [](const AccuracyPoint& p) {
                                             return p.point.status == grazelab::core::methods::RunStatus::Completed;
                                           });
      const auto chartRows = std::count_if(rows.begin(), rows.end(), [](const QString& row) {
        return row.startsWith(QStringLiteral("\"Error against run time\","));
      });
      QCOMPARE(qsizetype(chartRows), qsizetype(completed));
    }
    // the overlay: the chosen run's u2 appears on the trace, and changes with the choice
    auto overlayData = [this]() {
      for (const PlotView::Entry& entry : m_window->plots().first()->entries()) {
        // named in words, as the overlay picker says them
        if (entry.series->name().startsWith(QStringLiteral("Moreau–Jean")) ||
            entry.series->name().startsWith(QStringLiteral("Dormand–Prince"))) {
          return entry.points().toVector();
        }
      }
      return std::vector<QPointF>{};
    };
    QVERIFY(!overlayData().empty());
    int dopri = -1;
    for (int i = 0; i < int(shown->accuracy->points.size()); ++i) {
      if (shown->accuracy->points[std::size_t(i)].point.setting.kind ==
          grazelab::core::methods::MethodKind::Dopri5Events) {
        dopri = i;
        break;
      }
    }
    QVERIFY(dopri >= 0);
    const std::vector<QPointF> before = overlayData();
    view->chooseOverlay(dopri);
    m_window->plots().first()->refreshNow();
    QVERIFY(overlayData() != before);
    QVERIFY(m_window->statusText().contains(QStringLiteral("settings measured")));
  }

  void opensWithinTheScreenAndWrapsItsToolTips() {
    // a window larger than a small screen hid its status bar (a classroom's 1280x720)
    MainWindow fresh(MainWindow::Options{.synchronous = false, .useSettings = false});
    const QSize available = QGuiApplication::primaryScreen()->availableGeometry().size();
    QVERIFY(fresh.width() <= available.width());
    QVERIFY(fresh.height() <= available.height());
    // a plain-text tooltip is shown as a paragraph, which Qt wraps (it was one 1400-px line)
    QWidget* control = m_window->parameterPanel()->control(ParamKey::Perturbation)->slider();
    QVERIFY(control->toolTip().size() > 100);
    const QPoint local(5, 5);
    QHelpEvent help(QEvent::ToolTip, local, control->mapToGlobal(local));
    QApplication::sendEvent(control, &help);
    QTRY_VERIFY(QToolTip::isVisible());
    QVERIFY(QToolTip::text().startsWith(QStringLiteral("<p>")));
    QToolTip::hideText();
  }

  // the plots get the final result before its error estimate (the long-double shadow took 7/8
  // of a 20 000-contact run); the estimate follows on the same result, without a redraw
  void finalResultComesBeforeItsTrustEstimate() {
    QList<SimUpdate> finals;
    connect(m_window->controller(), &SimController::updated, this,
            [&](const SimUpdate& update) { if (update.final) finals.append(update); });
    QSignalSpy drawn(m_window.get(), &MainWindow::plotsUpdated);
    Params params = m_window->params();
    params.lambda = 0.61;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    QCOMPARE(finals.size(), 2);
    QVERIFY(finals[0].trustPending && !finals[0].trust);
    QVERIFY(!finals[1].trustPending && finals[1].trust);
    QCOMPARE(finals[1].result, finals[0].result);  // the same run, not computed again
    int finalDraws = 0;
    for (const QList<QVariant>& call : drawn) finalDraws += call.at(1).toBool() ? 1 : 0;
    QCOMPARE(finalDraws, 1);
    QVERIFY(m_window->displayed()->trust);
    QVERIFY(m_window->statusText().contains(QStringLiteral("trust: ok")));
    QVERIFY(!m_window->statusText().contains(QStringLiteral("estimating")));
  }

  // a scene of N masses hands on its run whole before its error estimate (the shadow run costs
  // about as much again: the window shows the run and "trust: estimating…" when it gets there
  // first); the estimate follows on the same run, which is drawn once as final
  void aChainRunComesBeforeItsTrustEstimate() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("chain-1ipp")));
    QVERIFY(waitForLatestFinal(*m_window));
    QList<SimUpdate> whole;  // the updates with the shown run whole
    connect(m_window->controller(), &SimController::updated, this,
            [&](const SimUpdate& update) { if (update.runDone) whole.append(update); });
    QSignalSpy drawn(m_window.get(), &MainWindow::plotsUpdated);
    Params params = m_window->params();
    params.chainPeriodFraction *= 0.99;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY(whole.size() >= 2);
    const SimUpdate& before = whole.front();
    const SimUpdate& after = whole.back();
    QVERIFY(before.trustPending && !before.final);
    QVERIFY(before.chains.front()->trust.verdict == grazelab::core::Verdict::Unchecked);
    QVERIFY(after.final && !after.trustPending);
    QVERIFY(after.chains.front()->trust.verdict != grazelab::core::Verdict::Unchecked);
    QCOMPARE(after.chains.front()->run.events.size(), before.chains.front()->run.events.size());
    int finalDraws = 0;
    for (const QList<QVariant>& call : drawn) finalDraws += call.at(1).toBool() ? 1 : 0;
    QCOMPARE(finalDraws, 1);
    QVERIFY2(m_window->statusText().contains(QStringLiteral("trust:")), qPrintable(m_window->statusText()));
    QVERIFY(!m_window->statusText().contains(QStringLiteral("estimating")));
  }

  // A scene switch makes, lays out and paints one view per turn of the event loop (all at once
  // stalled the window for 40-66 ms); the run is drawn once every view is up, the old views go,
  // and a file saved right after the switch still holds every view.
  void aSceneSwitchShowsItsViewsOneByOneThenTheRun() {
    // each in its cell: together they tile the plots' area (a view put in its cell without a
    // new layout kept the 200 x 160 it was made with)
    const auto viewsTileTheirArea = [this] {
      const QWidget* area = m_window->sceneViews().first()->widget()->parentWidget();
      double covered = 0;
      for (SceneView* view : m_window->sceneViews()) {
        covered += double(view->widget()->width()) * view->widget()->height();
      }
      return covered > 0.8 * area->width() * area->height();
    };
    QVERIFY(viewsTileTheirArea());  // the first scene's, built before the window was shown
    QList<QPointer<QWidget>> old;
    for (SceneView* view : m_window->sceneViews()) old.append(view->widget());
    const auto visibleViews = [this] {
      int visible = 0;
      for (SceneView* view : m_window->sceneViews()) visible += view->widget()->isVisible() ? 1 : 0;
      return visible;
    };
    QList<int> visibleAtDraw;
    connect(m_window.get(), &MainWindow::plotsUpdated, this, [&] { visibleAtDraw.append(visibleViews()); });
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("near-grazing")));
    const int views = int(m_window->scene().plots().size());
    QVERIFY(views >= 3);
    QCOMPARE(m_window->sceneViews().size(), 0);  // each made at a turn of its own
    QVERIFY(waitForLatestFinal(*m_window));
    QCOMPARE(visibleViews(), views);
    QVERIFY(viewsTileTheirArea());
    QVERIFY(!visibleAtDraw.isEmpty());
    for (int visible : visibleAtDraw) QCOMPARE(visible, views);
    for (const QPointer<QWidget>& view : old) QTRY_VERIFY(view.isNull());

    // saved at once: the window picture is taken with every view shown
    m_window->selectScene(0);
    QCOMPARE(m_window->sceneViews().size(), 0);
    QTemporaryDir dir;
    QString error;
    QVERIFY2(m_window->saveWindowSnapshot(dir.filePath(QStringLiteral("switch.png")), &error), qPrintable(error));
    QCOMPARE(m_window->sceneViews().size(), m_window->scene().plots().size());
    QCOMPARE(visibleViews(), int(m_window->scene().plots().size()));
  }

  // Showing a batch of widgets inside a BatchedLayout lays them out once, to the same geometry
  // as showing them one by one (each of which lays out every ancestor).
  void aBatchedLayoutEndsWhereSeparateShowsDo() {
    const auto build = [](QWidget& top, QList<QLabel*>& labels) {
      auto* column = new QVBoxLayout(&top);
      auto* group = new QGroupBox(QStringLiteral("group"));
      auto* inner = new QVBoxLayout(group);
      for (int index = 0; index < 6; ++index) {
        auto* label = new QLabel(QStringLiteral("a label that wraps over lines at this width, number %1").arg(index));
        label->setWordWrap(true);
        label->hide();
        inner->addWidget(label);
        labels.append(label);
      }
      column->addWidget(group);
      column->addStretch();
      top.resize(220, 700);
      top.show();
    };
    QWidget separate;
    QWidget batched;
    QList<QLabel*> separateLabels;
    QList<QLabel*> batchedLabels;
    build(separate, separateLabels);
    build(batched, batchedLabels);
    QVERIFY(QTest::qWaitForWindowExposed(&separate));
    QVERIFY(QTest::qWaitForWindowExposed(&batched));
    for (int index : {0, 2, 3, 5}) separateLabels[index]->show();
    {
      const BatchedLayout once(batchedLabels[0]->parentWidget());
      for (int index : {0, 2, 3, 5}) batchedLabels[index]->show();
      QVERIFY(!batchedLabels[0]->parentWidget()->layout()->isEnabled());  // held while batched
    }
    QVERIFY(batchedLabels[0]->parentWidget()->layout()->isEnabled());
    QVERIFY(batched.layout()->isEnabled());
    for (int index = 0; index < 6; ++index) {
      QCOMPARE(batchedLabels[index]->isVisible(), separateLabels[index]->isVisible());
      QCOMPARE(batchedLabels[index]->geometry(), separateLabels[index]->geometry());
    }
    QVERIFY(separateLabels[5]->height() > separateLabels[5]->fontMetrics().height());  // wrapped
  }

  // A drag whose every value costs more than the time between two values: a job younger than
  // the grace runs to its end and its whole run is drawn (marked superseded, with its own
  // parameters) while the newest value computes; values in between are never run; without a
  // grace the older job stops and only the newest is drawn.
  void aDragShowsYoungJobsButNeverOverANewerOne() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("near-grazing")));
    QVERIFY(waitForLatestFinal(*m_window));
    QList<SimUpdate> runs;  // every whole run handed to the window
    bool firstRunning = false;  // a part of the first value's run has come
    const auto connection = connect(m_window->controller(), &SimController::updated, this,
                                    [&](const SimUpdate& update) {
                                      if (update.runDone) runs.append(update);
                                      if (update.request && update.request->params.lambda == 0.60 && !update.runDone) {
                                        firstRunning = true;
                                      }
                                    });
    Params params = m_window->params();
    m_window->controller()->setGrace(60'000);
    // the order is made, not timed, so that no machine's speed changes it: the next values
    // come while the first run is going (once a part of it has come: 500 000 contacts, a
    // quarter of a second at the fastest), and their run is four times as long, so that the
    // first ends first (timed alone, the first run ended before the next value on a fast
    // machine, or after the newest on a loaded one)
    params.lambda = 0.60;
    params.horizon = 500'000;
    m_window->setParams(params);
    QTRY_VERIFY_WITH_TIMEOUT(firstRunning, 20000);
    params.horizon = 2'000'000;
    for (const double lambda : {0.62, 0.64}) {
      params.lambda = lambda;
      m_window->setParams(params);
    }
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    QVERIFY(runs.size() >= 2);
    QVERIFY(runs.front().superseded);
    QCOMPARE(runs.front().request->params.lambda, 0.60);
    QVERIFY(runs.front().result->stop == grazelab::core::StopReason::ContactLimit);
    for (const SimUpdate& run : runs) QVERIFY(run.request->params.lambda != 0.62);
    QVERIFY(!runs.back().superseded);
    QCOMPARE(runs.back().request->params.lambda, 0.64);
    QVERIFY(!m_window->displayed()->superseded);
    QCOMPARE(m_window->displayed()->request->params.lambda, 0.64);

    // no grace: a long job is stopped by the next value and never drawn
    runs.clear();
    m_window->controller()->setGrace(0);
    params.horizon = 1e6;
    params.lambda = 0.55;
    m_window->setParams(params);
    params.horizon = 20000;
    params.lambda = 0.57;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    for (const SimUpdate& run : runs) QVERIFY(!run.superseded && run.request->params.lambda == 0.57);
    QCOMPARE(m_window->displayed()->request->params.lambda, 0.57);
    m_window->controller()->setGrace(SimController::kDefaultGraceMs);
    disconnect(connection);
  }

  // A drag over a scene of N masses whose runs outlast the grace: a superseded job's runs so far
  // are shown as they come (marked superseded), never after a newer job's; the newest is shown
  // last, not superseded. (They were dropped: the eight-mass scene drew no frame in a drag.)
  void aDragShowsTheRunsSoFarOfSupersededChainJobs() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("eight-masses")));
    QVERIFY(waitForLatestFinal(*m_window));
    Params params = m_window->params();
    // the first run: 200 000 contacts, every one an impact (a second's work here, in chunks of
    // 30 ms); the next value is set at the turn of the event loop that shows a part of it, so the
    // first run goes on making contacts within its grace after it on a machine several times
    // faster, or a GUI thread slower to answer. (A run that ends on a long contactless search
    // makes no chunk during it: pushed by -0.05, its last part came within ms of its first, and a
    // loaded machine showed both before the next value was set.)
    const double first = -2;
    // every update handed to the window, by what the test reads of it (not the updates: each
    // holds its run so far, up to 200 000 contacts)
    struct Shown {
      double perturbation = 0;
      bool superseded = false;
      bool runDone = false;
    };
    QList<Shown> shown;
    qsizetype before = -1;  // updates shown when the next value was set
    bool asked = false;
    Params next = params;
    next.perturbation = -3e-4;
    next.horizon = 20;
    const auto connection = connect(m_window->controller(), &SimController::updated, this,
                                    [&](const SimUpdate& update) {
                                      shown.append({update.request ? update.request->params.perturbation : 0.0,
                                                    update.superseded, update.runDone});
                                      if (!asked && update.request && update.request->params.perturbation == first &&
                                          !update.runDone && !update.chains.empty()) {
                                        asked = true;
                                        QTimer::singleShot(0, this, [&] {
                                          before = shown.size();
                                          m_window->setParams(next);
                                        });
                                      }
                                    });
    m_window->controller()->setGrace(60'000);
    params.perturbation = first;
    params.horizon = 200000;
    m_window->setParams(params);
    QTRY_VERIFY_WITH_TIMEOUT(before >= 0, 20000);
    QVERIFY(waitForLatestFinal(*m_window, 120000));
    bool supersededSoFar = false;
    bool newerSeen = false;
    for (qsizetype i = before; i < shown.size(); ++i) {
      const Shown& update = shown[i];
      const bool older = update.perturbation == first;
      if (older) {
        QVERIFY(update.superseded);
        QVERIFY(!newerSeen);  // never after the newer job's
        if (!update.runDone) supersededSoFar = true;
      } else {
        newerSeen = true;
      }
    }
    QVERIFY(supersededSoFar);
    QVERIFY(!m_window->displayed()->superseded);
    QCOMPARE(m_window->displayed()->request->params.perturbation, -3e-4);
    m_window->controller()->setGrace(SimController::kDefaultGraceMs);
    disconnect(connection);
  }

  // A touch double cannot decide (GLOM1 pushed by 3e-9: the crossing at T1 rises ~1e-17 above
  // the stop) is decided again in a higher precision by the worker, as --precision auto does:
  // impacts, not grazings, and the views are told to start over.
  void theWorkerRaisesARunWhoseTouchDoubleCannotDecide() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("near-grazing")));
    QVERIFY(waitForLatestFinal(*m_window));
    SimRequest request = *m_window->displayed()->request;
    const grazelab::core::TwoMassForm<double> chain = *grazelab::core::makeTwoMassForm(request.job.spec.model).chain;
    request.job.spec.run.initial = grazelab::core::gloData(chain, 0.0);
    request.job.spec.run.initial.v2 -= 3e-9;
    request.job.spec.run.maxContacts = 20;
    std::optional<SimUpdate> last;
    SimWorker::run(request, {}, 0.002, [&](const SimUpdate& update) {
      if (update.final && !update.trustPending) last = update;
    });
    QVERIFY(last);
    QVERIFY2(last->attempt > 0, "not raised");
    QCOMPARE(last->result->cost.impacts, std::int64_t(20));
    QVERIFY(last->trust);
    QVERIFY(QString::fromStdString(last->precisionNote).contains(QStringLiteral("contact 1")));
  }

  // The views read a run's items where the controller keeps them: appending a piece never moves
  // an item a view holds (the run is copied with room to grow when it has none), and copies are
  // few (amortised).
  void aRunGrowsWithoutMovingWhatAViewReads() {
    auto run = std::make_shared<grazelab::core::Result>();
    std::shared_ptr<const grazelab::core::Result> held = run;  // what a view holds
    const grazelab::core::Sample* heldData = nullptr;
    std::size_t heldCount = 0;
    int copies = 0;
    for (int chunk = 0; chunk < 200; ++chunk) {
      grazelab::core::Result piece;
      for (int i = 0; i < 37; ++i) piece.samples.push_back({double(chunk * 37 + i), {}});
      const auto before = run;
      run = appendChunkInPlace(run, piece);
      if (run != before) ++copies;
      // what the view holds is where it was, with its values
      QCOMPARE(held->samples.data(), heldData);
      for (std::size_t k = 0; k < heldCount; ++k) QCOMPARE(heldData[k].t, double(k));
      held = run;
      heldData = run->samples.data();
      heldCount = run->samples.size();
    }
    QCOMPARE(run->samples.size(), std::size_t(200 * 37));
    QVERIFY2(copies <= 16, qPrintable(QString::number(copies)));
  }

  // The worker hands over only what is new; the pieces, appended, are the whole run.
  void aLongRunIsHandedOverInPieces() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("near-grazing")));
    QVERIFY(waitForLatestFinal(*m_window));
    SimRequest request = *m_window->displayed()->request;
    request.job.spec.run.maxContacts = 100'000;
    grazelab::core::Result assembled;
    std::shared_ptr<const grazelab::core::Result> whole;
    int pieces = 0;
    std::size_t carried = 0;
    SimWorker::run(request, {}, 0.002, [&](const SimUpdate& update) {
      if (update.final) {
        if (!whole) whole = update.result;
        return;
      }
      QVERIFY(update.chunk && !update.result);
      ++pieces;
      carried += update.chunk->events.size();
      appendChunk(assembled, *update.chunk);
    });
    QVERIFY(whole);
    QVERIFY2(pieces >= 5, qPrintable(QString::number(pieces)));
    // every event crossed once (the pieces never repeat what was sent)
    QVERIFY(carried <= whole->events.size());
    QCOMPARE(assembled.events.size(), carried);
    auto sameEvents = [](const auto& a, const auto& b) { return a.t == b.t && a.type == b.type; };
    QVERIFY(std::equal(assembled.events.begin(), assembled.events.end(), whole->events.begin(), sameEvents));
    auto samePoints = [](const auto& a, const auto& b) {
      return a.t == b.t && a.u1 == b.u1 && a.v1 == b.v1 && a.v2 == b.v2;
    };
    QVERIFY(assembled.poincare.size() <= whole->poincare.size());
    QVERIFY(std::equal(assembled.poincare.begin(), assembled.poincare.end(), whole->poincare.begin(), samePoints));
    auto sameFlights = [](const auto& a, const auto& b) {
      return a.contactIndex == b.contactIndex && a.duration == b.duration;
    };
    QVERIFY(std::equal(assembled.freeFlights.begin(), assembled.freeFlights.end(),
                       whole->freeFlights.begin(), sameFlights));
    auto sameSamples = [](const auto& a, const auto& b) {
      return a.t == b.t && a.state.u1 == b.state.u1 && a.state.u2 == b.state.u2 &&
             a.state.v1 == b.state.v1 && a.state.v2 == b.state.v2;
    };
    QVERIFY(std::equal(assembled.samples.begin(), assembled.samples.end(), whole->samples.begin(), sameSamples));
  }

  // A plot fed a growing run update after update draws what it would draw of the whole run
  // shown once, and decimates from scratch only when its axes widen (a few times), not at
  // every update.
  void plotsAppendWhatIsNewAndDrawAsTheWholeRun() {
    auto request = std::make_shared<SimRequest>(*m_window->displayed()->request);
    request->job.spec.run.maxContacts = 100'000;
    const double T2 = grazelab::core::computeModes(request->job.spec.model).T2;
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto run = std::make_shared<grazelab::core::Result>();
    FreeFlightPlot growing;
    FreeFlightPlot once;
    PoincarePlot growingSection;
    PoincarePlot onceSection;
    for (PlotView* plot : std::initializer_list<PlotView*>{&growing, &once, &growingSection, &onceSection}) {
      plot->resize(500, 350);
      plot->QWidget::show();
    }
    QVERIFY(QTest::qWaitForWindowExposed(&onceSection));
    SimUpdate update;
    update.id = 77;
    update.request = request;
    update.result = run;
    const int updates = 100;
    std::normal_distribution<double> spread(0.0, 0.02);
    for (int step = 0; step < updates; ++step) {
      for (int i = 0; i < 1000; ++i) {
        const auto index = std::int64_t(run->poincare.size());
        // flights a little shorter than T2, as near a grazing orbit
        const double shortfall = T2 * std::abs(spread(random));
        run->freeFlights.push_back({index, T2 - shortfall, shortfall});
        const double angle = 6.283 * unit(random);
        run->poincare.push_back({double(index), std::cos(angle), 0.5 * std::sin(angle), -0.1});
      }
      update.final = step + 1 == updates;
      for (PlotView* plot : std::initializer_list<PlotView*>{&growing, &growingSection}) {
        static_cast<SceneView*>(plot)->show(update);
        plot->setGrowing(!update.final);
        plot->refreshNow();
      }
      QCoreApplication::processEvents();  // the paint between updates, as in the window
    }
    for (PlotView* plot : std::initializer_list<PlotView*>{&once, &onceSection}) {
      static_cast<SceneView*>(plot)->show(update);
      plot->refreshNow();
    }
    // the charts lay out their new ticks in the event loop; then every plot draws on its
    // settled plot area
    QCoreApplication::processEvents();
    for (PlotView* plot : std::initializer_list<PlotView*>{&growing, &once, &growingSection, &onceSection}) {
      plot->refreshNow();
    }
    for (auto [appended, whole] : {std::pair<PlotView*, PlotView*>{&growing, &once},
                                   std::pair<PlotView*, PlotView*>{&growingSection, &onceSection}}) {
      QCOMPARE(appended->entries().size(), whole->entries().size());
      for (std::size_t i = 0; i < whole->entries().size(); ++i) {
        QCOMPARE(appended->entries()[i].points().toVector(), whole->entries()[i].points().toVector());
        QCOMPARE(appended->entries()[i].series->points(), whole->entries()[i].series->points());
      }
      // the contact-index axis widens by a quarter of its span each side when it must: a
      // score of fresh decimations over 100 updates at most (17 measured), the section fewer
      QVERIFY2(appended->decimationsFromScratch() <= 20,
               qPrintable(QString::number(appended->decimationsFromScratch())));
    }
    QVERIFY(growingSection.decimationsFromScratch() <= 5);
  }

  // a scene's own computation runs on the worker; a window closed meanwhile freed the scene it
  // was reading (a crash a few times in ten, in the next test)
  void aWindowClosedDuringASceneComputationLeavesNothingRunning() {
    for (int round = 0; round < 5; ++round) {
      m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("random-starts")));
      Params params = m_window->params();
      params.horizon = 200;  // the survey: 300 starts of 200 contacts
      m_window->setParams(params);
      QTest::qWait(2);
      m_window.reset();  // while the worker is in the survey
      m_window = openTestWindow();
    }
    QVERIFY(waitForLatestFinal(*m_window));
  }

  // the grid is drawn by one item of ours (PlotGrid), not by Qt Charts: its lines must stand
  // where the axes put their ticks, inside the plot area, and nowhere in between
  void gridLinesStandOnTheAxisTicks() {
    QVERIFY(waitForLatestFinal(*m_window, 10'000));
    for (PlotView* plot : m_window->plots()) {
      auto* axisX = qobject_cast<QValueAxis*>(plot->chart()->axes(Qt::Horizontal).value(0));
      auto* axisY = qobject_cast<QValueAxis*>(plot->chart()->axes(Qt::Vertical).value(0));
      QVERIFY(axisX && axisY);
      QVERIFY(!axisX->isGridLineVisible() && !axisY->isGridLineVisible());  // not drawn twice
      // the grid alone: the series (a dashed stop line lies on a grid line) out of the way
      for (QAbstractSeries* series : plot->chart()->series()) series->setVisible(false);
      const QImage image = plot->viewport()->grab().toImage();
      const QRectF area =
          plot->viewportTransform().map(plot->chart()->mapToScene(plot->chart()->plotArea())).boundingRect();
      const QRgb grid = axisX->gridLinePen().color().rgb();
      // the share of grid-coloured pixels down a column (or along a row) of the plot area
      auto share = [&](bool column, int at) {
        int hits = 0, count = 0;
        const int first = int(column ? area.top() : area.left()) + 3;
        const int last = int(column ? area.bottom() : area.right()) - 3;
        for (int along = first; along < last; ++along) {
          const QPoint pixel = column ? QPoint(at, along) : QPoint(along, at);
          hits += image.pixel(pixel) == grid ? 1 : 0;
          ++count;
        }
        return count > 0 ? double(hits) / count : 0.0;
      };
      for (const bool vertical : {true, false}) {
        const QValueAxis& axis = vertical ? *axisX : *axisY;
        const std::vector<double> ticks = PlotGrid::tickValues(axis);
        QVERIFY2(ticks.size() >= 2, qPrintable(plot->title()));
        const double span = axis.max() - axis.min();
        auto position = [&](double value) {
          return vertical ? area.left() + (value - axis.min()) / span * area.width()
                          : area.bottom() - (value - axis.min()) / span * area.height();
        };
        for (std::size_t index = 0; index < ticks.size(); ++index) {
          QVERIFY(ticks[index] >= axis.min() && ticks[index] <= axis.max());
          if (index > 0) QCOMPARE_LT(std::abs(ticks[index] - ticks[index - 1] - axis.tickInterval()), 1e-9 * span);
          const double at = position(ticks[index]);
          if (at < (vertical ? area.left() : area.top()) + 2 || at > (vertical ? area.right() : area.bottom()) - 2) continue;
          QVERIFY2(share(vertical, int(std::floor(at))) > 0.5,
                   qPrintable(QStringLiteral("%1: no grid line at %2").arg(plot->title()).arg(ticks[index])));
          // and none halfway to the next tick
          if (index + 1 < ticks.size()) {
            const int between = int(std::floor(position(0.5 * (ticks[index] + ticks[index + 1]))));
            QVERIFY2(share(vertical, between) < 0.1,
                     qPrintable(QStringLiteral("%1: a grid line between ticks").arg(plot->title())));
          }
        }
      }
    }
  }

  void resetViewFollowsDataAgain() {
    PlotView* plot = m_window->plots().first();
    plot->chart()->zoom(2.0);
    QTest::keyClick(plot, Qt::Key_Plus);
    QVERIFY(!plot->followsData());
    m_window->resetViews();
    QVERIFY(plot->followsData());
  }

 private:
  std::unique_ptr<MainWindow> m_window;
};

QTEST_MAIN(ExplorerTest)
#include "explorer_test.moc"
