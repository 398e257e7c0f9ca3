// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for ui/scenes/: every scene opens with its views and asks only for what they draw, and
// each picture agrees with the result of the theory it illustrates.
#include <QTest>
#include <QXYSeries>

#include <algorithm>

#include "core/modes.h"
#include "tests/ui/explorer_test_support.h"
#include "ui/main_window.h"
#include "ui/plots/chain_view.h"
#include "ui/plots/plot_view.h"

using namespace grazelab::ui;
using grazelab::ui::testing::openTestWindow;
using grazelab::ui::testing::waitForLatestFinal;

namespace {

bool shows(const Scene& scene, PlotKind kind) { return scene.plots().contains(kind); }

const CurveFigure& figure(const MainWindow& window, PlotKind kind) {
  return window.displayed()->request->figures.at(kind);
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
      const auto& needs = m_window->displayed()->request->request.needs;
      const bool dense = shows(scene, PlotKind::TraceU2) || shows(scene, PlotKind::PhaseU2V2) ||
                         shows(scene, PlotKind::PhaseU1V1) || shows(scene, PlotKind::Chain);
      QVERIFY2((needs.samples.spacing > 0) == dense, qPrintable(name));
      QVERIFY2(needs.poincare == shows(scene, PlotKind::Poincare), qPrintable(name));
      QVERIFY2(needs.freeFlights == shows(scene, PlotKind::FreeFlight), qPrintable(name));
      QVERIFY2(needs.events == (shows(scene, PlotKind::TraceU2) || shows(scene, PlotKind::Chain)),
               qPrintable(name));
      QVERIFY2(bool(m_window->chainView()) == shows(scene, PlotKind::Chain), qPrintable(name));
      // every view it lists is on screen, each curve view with its figure
      const qsizetype views = m_window->plots().size() + (m_window->accuracyView() ? 1 : 0) +
                              (m_window->chainView() ? 1 : 0);
      QCOMPARE(views, scene.plots().size());
      for (PlotKind kind : scene.plots()) {
        const bool curve = kind == PlotKind::OnePeriodicData || kind == PlotKind::ImpactSpeed ||
                           kind == PlotKind::GrazingMaximum || kind == PlotKind::SpreadAgainstSize ||
                           kind == PlotKind::FlightHistogram || kind == PlotKind::DetunedFlights ||
                           kind == PlotKind::ResonantFlights;
        if (curve) QVERIFY2(m_window->displayed()->request->figures.count(kind), qPrintable(name));
      }
      QVERIFY2(!scene.description().isEmpty(), qPrintable(name));
    }
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

  // off 1:2 the free-flight time passes T2; in resonance it never does
  void detunedFlightsPassT2AndResonantOnesDoNot() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("detuned")));
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const CurveFigure& detuned = figure(*m_window, PlotKind::DetunedFlights);
    const CurveFigure& resonant = figure(*m_window, PlotKind::ResonantFlights);
    QVERIFY(!detuned.curve.empty() && !resonant.curve.empty());
    const auto highest = [](const CurveFigure& f) {
      double top = 0;
      for (const QPointF& point : f.curve) top = std::max(top, point.y());
      return top;
    };
    QVERIFY(highest(detuned) > 1.05);
    QVERIFY(highest(resonant) <= 1.0);
    const auto& model = m_window->displayed()->request->model;
    const auto modes = grazelab::core::computeModes(model);
    QVERIFY(std::abs(modes.omegaFast / modes.omegaSlow - m_window->params().frequencyRatio) < 1e-9);
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
    QVERIFY(std::abs(chain->stateAt(chain->time()).u2 - m_window->params().gap) < 1e-3);
    // the trace's cursor line stands at that time
    PlotView* trace = m_window->plots().first();
    QXYSeries* cursor = nullptr;
    for (QAbstractSeries* series : trace->chart()->series()) {
      auto* xy = qobject_cast<QXYSeries*>(series);
      if (xy && xy->count() == 2 && xy->at(0).x() == xy->at(1).x() && xy->at(0).x() == chain->time()) cursor = xy;
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
