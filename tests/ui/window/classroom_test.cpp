// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// What a first trial of the explorer in front of a class tripped over (issue 9, "Fix first"):
// each problem found there has a test here that fails if it comes back.
#include <QAction>
#include <QGroupBox>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QMenuBar>
#include <QProcess>
#include <QScatterSeries>
#include <QSlider>
#include <QTemporaryDir>
#include <QFontInfo>
#include <QTest>
#include <QValueAxis>
#include <QXYSeries>

#include <algorithm>
#include <numbers>

#include "core/model/two_mass_form.h"
#include "core/orbits/modes_atlas.h"
#include "core/model/linear_modes.h"
#include "core/orbits/special_orbits.h"
#include "core/model/resonance.h"
#include "tests/ui/explorer_test_support.h"
#include "ui/window/main_window.h"
#include "ui/widgets/readout_panel.h"
#include "ui/widgets/number_box.h"
#include "ui/widgets/parameter_panel.h"
#include "ui/plots/log_log_chart.h"
#include "ui/plots/plot_view.h"
#include "ui/window/session.h"
#include "ui/compute/sim_worker.h"
#include "ui/compute/derived.h"
#include "ui/widgets/slider_spin.h"

using namespace grazelab::ui;
using grazelab::ui::testing::openTestWindow;
using grazelab::ui::testing::waitForLatestFinal;

namespace {

PlotView* plotTitled(const MainWindow& window, const QString& start) {
  for (PlotView* plot : window.plots()) {
    if (plot->title().startsWith(start)) return plot;
  }
  return nullptr;
}

const PlotView::Entry* seriesNamed(const PlotView& plot, const QString& start) {
  for (const PlotView::Entry& entry : plot.entries()) {
    if (entry.series->name().startsWith(start)) return &entry;
  }
  return nullptr;
}

QValueAxis* axis(const PlotView& plot, Qt::Orientation orientation) {
  return qobject_cast<QValueAxis*>(plot.chart()->axes(orientation).first());
}

int sceneIndex(const MainWindow& window, const QString& alias) {
  return findScene(window.scenes(), alias);
}

}  // namespace

class ClassroomTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    m_window = openTestWindow();
    QVERIFY(waitForLatestFinal(*m_window));
  }
  void cleanup() { m_window.reset(); }

  // "u2 (off the plane: impacts)" gave no impacts and blank plots: a run without contacts
  // draws its free orbit, and the direction says what it does
  void aStartBelowTheStopDrawsItsFreeOrbit() {
    Params params = m_window->params();
    params.direction = PerturbDirection::U2;
    params.perturbation = -0.05;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    const SimUpdate* shown = m_window->displayed();
    QCOMPARE(shown->result->cost.contacts, std::int64_t(0));
    PlotView* trace = plotTitled(*m_window, QStringLiteral("Displacement"));
    QVERIFY(trace);
    const auto& data = trace->entries().front().points().toVector();
    QVERIFY(data.size() > 100);
    const double T2 = grazelab::core::computeModes(shown->request->job.spec.model).T2;
    // (the trace's time in slow periods T2) at least a whole slow period, not a +-4e-7 axis
    QVERIFY(T2 > 0);
    QVERIFY(data.back().x() > 0.99);
    QVERIFY(axis(*trace, Qt::Horizontal)->max() - axis(*trace, Qt::Horizontal)->min() > 1);
    QVERIFY(m_window->statusText().contains(QStringLiteral("no further contact")));
    auto* direction = m_window->parameterPanel()->findChild<QComboBox*>(QStringLiteral("directionCombo"));
    const QString label = direction->itemText(direction->findData(int(PerturbDirection::U2)));
    QVERIFY2(!label.contains(QStringLiteral("impacts")), qPrintable(label));
  }

  // sessions and snapshots recorded k2 = 0.5 while the design made 0.5513... (m2 = 0.3);
  // unticking the design went back to that stale value
  void theDesignedStiffnessIsRecordedAndKeptWhenUnticked() {
    Params params = m_window->params();
    params.m2 = 0.3;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    const double designed = *grazelab::core::resonantK2(1.0, 0.3, 1.0, grazelab::core::Branch::Upper);
    QVERIFY(std::abs(designed - 0.5) > 0.05);
    QCOMPARE(m_window->params().k2, designed);
    QCOMPARE(m_window->displayed()->request->params.k2, designed);  // what snapshots record
    QString error;
    const auto session = sessionFromJson(sessionToJson(m_window->displayedSession()), Params{}, &error);
    QVERIFY2(session, qPrintable(error));
    QCOMPARE(session->params.k2, designed);
    auto* design = m_window->parameterPanel()->findChild<QCheckBox*>(QStringLiteral("designCheck"));
    design->click();
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY(!m_window->params().resonantDesign);
    QCOMPARE(m_window->params().k2, designed);
    QCOMPARE(m_window->displayed()->request->job.spec.model.k2, designed);
  }

  // the T/T2 slider began at 0.5, itself a period without a 1IPP orbit
  void thePeriodSliderStartsOnAnAdmissiblePeriod() {
    m_window->selectScene(sceneIndex(*m_window, QStringLiteral("1ipp")));
    QVERIFY(waitForLatestFinal(*m_window));
    SliderSpin* period = m_window->parameterPanel()->control(ParamKey::Period);
    period->slider()->setValue(period->slider()->minimum());
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY2(m_window->problem().isEmpty(), qPrintable(m_window->problem()));
    const double lowEnd = grazelab::core::onePeriodicLowerEnd(
        m_window->displayed()->request->job.spec.model,
        grazelab::core::computeModes(m_window->displayed()->request->job.spec.model));
    const double T2 = grazelab::core::computeModes(m_window->displayed()->request->job.spec.model).T2;
    QVERIFY(m_window->params().periodFraction > lowEnd / T2);
    QVERIFY(m_window->params().periodFraction < lowEnd / T2 + 0.002);
    // other masses, another end: the slider follows the chain
    Params params = m_window->params();
    params.m2 = 0.05;
    params.periodFraction = 0.99;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    period->slider()->setValue(period->slider()->minimum());
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY2(m_window->problem().isEmpty(), qPrintable(m_window->problem()));
  }

  // the 1IPP Poincaré axes rescaled for every T and the impact speed was shown nowhere
  void theOnePeriodicFamilyIsOnFixedAxesWithItsImpactSpeed() {
    m_window->selectScene(sceneIndex(*m_window, QStringLiteral("1ipp")));
    QVERIFY(waitForLatestFinal(*m_window));
    PlotView* data = plotTitled(*m_window, QStringLiteral("Impact data"));
    PlotView* speed = plotTitled(*m_window, QStringLiteral("Impact speed"));
    QVERIFY(data && speed);
    const double xMin = axis(*data, Qt::Horizontal)->min();
    const double yMin = axis(*data, Qt::Vertical)->min();
    const double yMax = axis(*data, Qt::Vertical)->max();
    auto markerSpeed = [&] { return seriesNamed(*speed, QStringLiteral("|V|"))->data.front().y(); };
    const double farSpeed = markerSpeed();
    Params params = m_window->params();
    params.periodFraction = 0.995;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    QCOMPARE(axis(*data, Qt::Horizontal)->min(), xMin);
    QCOMPARE(axis(*data, Qt::Vertical)->min(), yMin);
    QCOMPARE(axis(*data, Qt::Vertical)->max(), yMax);
    // V(T) -> 0 and the data -> GLO(lambda*) as T -> T2
    QVERIFY(markerSpeed() < 0.2 * farSpeed);
    const double u1 = seriesNamed(*data, QStringLiteral("T/T"))->data.front().y();
    const double star = seriesNamed(*data, QStringLiteral("GLO"))->data.front().y();
    const double u1Far = seriesNamed(*data, QStringLiteral("1IPP"))->data.front().y();
    QVERIFY(std::abs(u1 - star) < 0.1 * std::abs(u1Far - star) + 1e-12);
  }

  // issue 10: the family's frequency-energy curve with the current T on it, ending at the
  // grazing orbit GLO(lambda*): energy of its data, frequency w2
  void theFrequencyEnergyCurveEndsAtTheGrazingOrbit() {
    m_window->selectScene(sceneIndex(*m_window, QStringLiteral("1ipp")));
    QVERIFY(waitForLatestFinal(*m_window));
    const CurveFigure& figure = m_window->displayed()->request->job.figures.at(PlotKind::FrequencyEnergy);
    QVERIFY(figure.curve.size() > 100);
    const DerivedModel derived = deriveModel(m_window->params());
    const grazelab::core::State star = grazelab::core::gloData(derived.model, derived.modes, derived.lambdaStar);
    const QPointF end(std::log10(grazelab::core::energy(derived.model, star)), derived.modes.omegaSlow);
    QCOMPARE(figure.reference.size(), std::size_t(1));
    QVERIFY(std::abs(figure.reference[0].x() - end.x()) < 1e-12);
    // the curve's point nearest T2 is within 1e-3 of the end (T = T2 (1 - 1e-6) there)
    const QPointF last = *std::max_element(figure.curve.begin(), figure.curve.end(),
                                           [](QPointF a, QPointF b) { return a.y() > b.y(); });
    QVERIFY2(std::abs(last.x() - end.x()) < 1e-3 && std::abs(last.y() - end.y()) < 1e-3 * end.y(),
             qPrintable(QStringLiteral("(%1, %2) against (%3, %4)").arg(last.x()).arg(last.y()).arg(end.x()).arg(end.y())));
    // the marker is the current T's orbit
    const double T = m_window->params().periodFraction * derived.modes.T2;
    const auto orbit = grazelab::core::onePeriodicOrbit(derived.model, derived.modes, T);
    QVERIFY(std::abs(figure.markers.at(0).x() - std::log10(grazelab::core::energy(derived.model, orbit.postImpact))) < 1e-12);
    QVERIFY(std::abs(figure.markers.at(0).y() - 2 * std::numbers::pi / T) < 1e-12);
    // the family's energy falls towards the grazing end as T grows (the frequency falls)
    QVERIFY(figure.curve.front().x() > last.x());
  }

  // legends were cut to "sto...", "imp..." (or to bare swatches) on a 1280x720 screen: each
  // plot's legend now wraps and names every named series in full
  void legendsNameEverySeriesInFullAt1280x720() {
    m_window->resize(1280, 720);
    for (int scene = 0; scene < int(m_window->scenes().size()); ++scene) {
      m_window->selectScene(scene);
      QVERIFY(waitForLatestFinal(*m_window, 60000));
      QTest::qWait(20);  // laid out at the window's size
      for (PlotView* plot : m_window->plots()) {
        plot->refreshNow();
        QVERIFY2(plot->legendFits(), qPrintable(plot->title()));
        for (const PlotView::Entry& entry : plot->entries()) {
          const QString name = entry.series->name();
          // a hidden series (the whole run behind a window) is not in the legend either
          if (name.isEmpty() || entry.points().empty() || !entry.series->isVisible()) continue;
          QVERIFY2(plot->legendNames().contains(name), qPrintable(plot->title() + QStringLiteral(": ") + name));
        }
      }
    }
  }

  // Qt Charts cut long titles to "...": "Free-flight time at each contact" in three columns at
  // 1920x1080 presentation, the 1IPP scene's "|V| (speed of mass 2 at impact)"
  void noTitleOrLabelIsCutOnAnySceneAtDeskOrProjectorSize() {
    for (const auto& [width, height, presentation] : {std::tuple{1280, 720, false}, std::tuple{1920, 1080, true}}) {
      m_window->setPresentation(presentation, height, false);
      m_window->resize(width, height);
      for (int scene = 0; scene < int(m_window->scenes().size()); ++scene) {
        m_window->selectScene(scene);
        QVERIFY(waitForLatestFinal(*m_window, 60000));
        QTest::qWait(20);  // laid out at the window's size
        for (PlotView* plot : m_window->plots()) plot->refreshNow();
        QTest::qWait(30);  // the charts laid out again with the wrapped titles
        for (PlotView* plot : m_window->plots()) {
          QVERIFY2(plot->cutTexts().isEmpty(),
                   qPrintable(QStringLiteral("%1x%2: %3").arg(width).arg(height).arg(plot->cutTexts().join(" | "))));
        }
        // the Accuracy scene's log-log chart: its legend (Qt's cut "moreau-jean-the...") names
        // every method in full
        for (const LogLogChart* chart : m_window->findChildren<LogLogChart*>()) {
          if (!chart->isVisible() || chart->curveCount() == 0) continue;
          QVERIFY2(chart->legendFits(), qPrintable(QStringLiteral("%1x%2").arg(width).arg(height)));
          QCOMPARE(chart->legendNames().size(), chart->curveCount());
        }
      }
    }
    m_window->setPresentation(false, 1080, false);
  }

  // the last colour bin covered the others and the legend named two bins of five
  void everyPoincareBinIsNamedAndShows() {
    m_window->selectScene(sceneIndex(*m_window, QStringLiteral("near-grazing")));
    QVERIFY(waitForLatestFinal(*m_window));
    PlotView* poincare = plotTitled(*m_window, QStringLiteral("Poincaré"));
    QVERIFY(poincare);
    // the plots are laid out after the scene switch: wait for the refresh at their size
    auto drawnTotal = [&] {
      qsizetype total = 0;
      for (const PlotView::Entry& entry : poincare->entries()) total += entry.series->count();
      return total;
    };
    // alone over the plot area: enough cells on the ring for the shares to be measured
    m_window->toggleEnlarged(poincare);
    QTRY_VERIFY(drawnTotal() > 20);
    QTest::qWait(50);
    poincare->refreshNow();  // at the laid-out size
    int named = 0;
    int fairBins = 0;
    for (const PlotView::Entry& entry : poincare->entries()) {
      if (entry.points().empty() || entry.series->name().startsWith(QStringLiteral("GLO"))) continue;
      if (poincare->legendNames().contains(entry.series->name())) ++named;
      // 10 000 contacts fill the same ring: each fifth of the run keeps about a fifth of it
      if (entry.series->count() > drawnTotal() / 10) ++fairBins;
    }
    QCOMPARE(named, 5);
    QCOMPARE(fairBins, 5);
  }

  // m2 set in one scene was back to 0.5 in the next: the chain and start belong to the session
  void theChainCarriesAcrossScenesAndSessions() {
    Params params = m_window->params();
    params.m2 = 0.3;
    params.gap = 2.0;
    params.lambda = 0.75;
    params.horizon = 33;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    const QByteArray saved = sessionToJson(m_window->session());
    m_window->selectScene(sceneIndex(*m_window, QStringLiteral("near-grazing")));
    QVERIFY(waitForLatestFinal(*m_window));
    QCOMPARE(m_window->params().m2, 0.3);
    QCOMPARE(m_window->params().gap, 2.0);
    // the start and the run's length are the scene's own
    QCOMPARE(m_window->params().lambda, m_window->scenes()[std::size_t(m_window->sceneIndex())]->defaults().lambda);
    QVERIFY(m_window->params().horizon != 33);
    // a session saved in one scene restores its chain, and the next scene keeps it
    Params other = m_window->params();
    other.m2 = 0.2;
    m_window->setParams(other);
    QString error;
    const auto session = sessionFromJson(saved, Params{}, &error);
    QVERIFY2(session && m_window->applySession(*session, &error), qPrintable(error));
    QCOMPARE(m_window->sceneIndex(), 0);
    QCOMPARE(m_window->params().horizon, 33.0);
    m_window->selectScene(sceneIndex(*m_window, QStringLiteral("1ipp")));
    QCOMPARE(m_window->params().m2, 0.3);
    QCOMPARE(m_window->params().gap, 2.0);
  }

  // the trial: Ctrl+5 (Sticking, lambda = 1.9) then Ctrl+6 ran Detuned at lambda = 1.9, saved it,
  // and brought it back after a restart
  void sceneSettingsStayInTheirScene() {
    const int sticking = sceneIndex(*m_window, QStringLiteral("sticking"));
    QTest::keyClick(m_window.get(), Qt::Key_1 + sticking, Qt::ControlModifier);
    QCOMPARE(m_window->sceneIndex(), sticking);
    QCOMPARE(m_window->params().lambda, 1.9);
    QVERIFY(waitForLatestFinal(*m_window));
    for (const char* alias : {"detuned", "near-grazing", "grazing"}) {
      const int index = sceneIndex(*m_window, QString::fromLatin1(alias));
      QTest::keyClick(m_window.get(), Qt::Key_1 + index, Qt::ControlModifier);
      QCOMPARE(m_window->sceneIndex(), index);
      QCOMPARE(m_window->params().lambda, m_window->scenes()[std::size_t(index)]->defaults().lambda);
      QVERIFY(m_window->params().lambda != 1.9);
      QVERIFY(waitForLatestFinal(*m_window));
      QString error;
      const auto saved = sessionFromJson(sessionToJson(m_window->session()), Params{}, &error);
      QVERIFY2(saved, qPrintable(error));
      QCOMPARE(saved->params.lambda, m_window->params().lambda);
    }
    // a scene's own edit stays in it when the user comes back; the chain follows the user
    Params grazing = m_window->params();
    grazing.lambda = 0.25;
    grazing.m2 = 0.4;
    m_window->setParams(grazing);
    QTest::keyClick(m_window.get(), Qt::Key_1 + sticking, Qt::ControlModifier);
    QCOMPARE(m_window->params().lambda, 1.9);
    QCOMPARE(m_window->params().m2, 0.4);
    QTest::keyClick(m_window.get(), Qt::Key_1, Qt::ControlModifier);
    QCOMPARE(m_window->params().lambda, 0.25);
    // Reset to scene defaults: everything, the chain included
    QTest::keyClick(m_window.get(), Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(m_window->params() == m_window->scenes()[0]->defaults());
    QCOMPARE(m_window->parameterPanel()->control(ParamKey::Lambda)->value(), 0.5);
  }

  // typed "-1" became 1, "1e300" 13, "99999" 99, and -1e-5 became 0 (four decimals): a typed
  // value is taken exactly or refused with a reason, never changed
  void typedValuesAreTakenExactlyOrRefused() {
    const auto type = [this](ParamKey key, const QString& text) {
      NumberBox* box = m_window->parameterPanel()->control(key)->spinBox();
      box->setFocus();
      box->selectAll();
      QTest::keyClicks(box, text);
      QTest::keyClick(box, Qt::Key_Return);
      return box;
    };
    const auto refusal = [this] { return m_window->parameterPanel()->refusal(); };
    NumberBox* push = type(ParamKey::Perturbation, QStringLiteral("-1e-5"));
    QCOMPARE(m_window->params().perturbation, -1e-5);
    QCOMPARE(push->text(), QStringLiteral("-1e-05"));
    QVERIFY(refusal().isEmpty());
    type(ParamKey::Perturbation, QStringLiteral("-3.0000000000000001e-9"));
    QCOMPARE(m_window->params().perturbation, -3e-9);
    QCOMPARE(readNumber(QStringLiteral(" −0.5e-3 ")).value_or(0), -0.5e-3);  // a copied minus sign
    type(ParamKey::Perturbation, QStringLiteral("-0.0123456789012345"));
    QCOMPARE(m_window->params().perturbation, -0.0123456789012345);
    // the exact value is what a saved session records
    QString error;
    auto saved = sessionFromJson(sessionToJson(m_window->session()), Params{}, &error);
    QVERIFY2(saved, qPrintable(error));
    QCOMPARE(saved->params.perturbation, -0.0123456789012345);

    const Params before = m_window->params();
    type(ParamKey::M2, QStringLiteral("-1"));
    QCOMPARE(m_window->params().m2, before.m2);
    QVERIFY2(refusal().contains(QStringLiteral("-1")), qPrintable(refusal()));
    QVERIFY(m_window->statusText().contains(QStringLiteral("refused")));
    type(ParamKey::M2, QStringLiteral("1e300"));
    QCOMPARE(m_window->params().m2, before.m2);
    QVERIFY(refusal().contains(QStringLiteral("1e300")));
    type(ParamKey::Horizon, QStringLiteral("0"));
    QCOMPARE(m_window->params().horizon, before.horizon);
    QVERIFY(!refusal().isEmpty());
    type(ParamKey::Horizon, QStringLiteral("2.5"));
    QCOMPARE(m_window->params().horizon, before.horizon);
    QVERIFY(refusal().contains(QStringLiteral("whole")));
    {
      // the defaults again (Ctrl+Shift+R) answer an old refusal: it no longer describes the
      // panel (issue 30, item 10); the scene's own values come back for the rest of the test
      const Params typed = m_window->params();
      m_window->resetToSceneDefaults();
      QVERIFY(refusal().isEmpty());
      m_window->setParams(typed);
      type(ParamKey::Horizon, QStringLiteral("2.5"));
      QVERIFY(!refusal().isEmpty());
    }
    type(ParamKey::Horizon, QStringLiteral("99999"));
    QCOMPARE(m_window->params().horizon, 99999.0);
    QVERIFY(refusal().isEmpty());
    type(ParamKey::M1, QStringLiteral("2.5e0"));
    QCOMPARE(m_window->params().m1, 2.5);
    QVERIFY(waitForLatestFinal(*m_window));
    // an arrow key steps to a short decimal (0.3 + 0.025, not 0.32500000000000001)
    NumberBox* lambda = type(ParamKey::Lambda, QStringLiteral("0.3"));
    QTest::keyClick(lambda, Qt::Key_Up);
    QCOMPARE(lambda->text(), QStringLiteral("0.325"));
    QCOMPARE(m_window->params().lambda, 0.325);
    // a dragged value is a short decimal
    QSlider* slider = m_window->parameterPanel()->control(ParamKey::Lambda)->slider();
    slider->setValue(301);
    const double dragged = m_window->params().lambda;
    QCOMPARE(QString::number(dragged, 'g', 17).size() <= 7, true);
  }

  // Ctrl+E and Space did nothing while a spin box had the focus; Esc did not leave presentation
  void shortcutsWorkWhileTypingAndEscLeavesPresentation() {
    NumberBox* box = m_window->parameterPanel()->control(ParamKey::Lambda)->spinBox();
    box->setFocus();
    QTest::keyClick(box, Qt::Key_PageDown);
    QCOMPARE(m_window->sceneIndex(), 1);
    QVERIFY(waitForLatestFinal(*m_window));
    // the scenes of N masses after the note's: Alt+1 ... Alt+4
    QTest::keyClick(m_window.get(), Qt::Key_2, Qt::AltModifier);
    QCOMPARE(m_window->scene().alias(), QStringLiteral("grazing-sets"));
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    QTest::keyClick(m_window.get(), Qt::Key_1, Qt::ControlModifier);
    QVERIFY(waitForLatestFinal(*m_window));
    box = m_window->parameterPanel()->control(ParamKey::Lambda)->spinBox();
    box->setFocus();
    // the line edit inside claims Ctrl+E and Space unless the box gives them to the window
    QKeyEvent overrideCtrlE(QEvent::ShortcutOverride, Qt::Key_E, Qt::ControlModifier);
    overrideCtrlE.ignore();
    QApplication::sendEvent(box, &overrideCtrlE);
    QVERIFY(!overrideCtrlE.isAccepted());
    QKeyEvent overrideSpace(QEvent::ShortcutOverride, Qt::Key_Space, Qt::NoModifier, QStringLiteral(" "));
    overrideSpace.ignore();
    QApplication::sendEvent(box, &overrideSpace);
    QVERIFY(!overrideSpace.isAccepted());
    QKeyEvent overrideDigit(QEvent::ShortcutOverride, Qt::Key_5, Qt::NoModifier, QStringLiteral("5"));
    overrideDigit.ignore();
    QApplication::sendEvent(box, &overrideDigit);
    QVERIFY(overrideDigit.isAccepted());  // typing digits stays typing
    // W (the whole run) and R (reset the views) went into the box as text
    for (const auto& [key, text] : {std::pair{Qt::Key_W, "w"}, std::pair{Qt::Key_R, "r"}}) {
      QKeyEvent overrideLetter(QEvent::ShortcutOverride, key, Qt::NoModifier, QString::fromLatin1(text));
      overrideLetter.ignore();
      QApplication::sendEvent(box, &overrideLetter);
      QVERIFY2(!overrideLetter.isAccepted(), text);
    }
    m_window->setPresentation(true, 720, false);
    QVERIFY(m_window->presentation());
    QTest::keyClick(m_window.get(), Qt::Key_Escape);
    QVERIFY(!m_window->presentation());
    QVERIFY(QApplication::font().pixelSize() < 720 / 50);  // the desk font, in points (-1 px)
  }

  // "trust: unreliable (error ≈ 140)" on ordinary settings, FFT in time units in one scene and
  // in T2 in another, an empty "Start" box, no list of shortcuts
  void wordsAClassUnderstands() {
    Params params = m_window->params();
    params.lambda = 0.25;  // chaotic within the scene's 60 contacts
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    QTRY_VERIFY_WITH_TIMEOUT(m_window->statusText().contains(QStringLiteral("chaotic")), 20000);
    QVERIFY2(m_window->statusText().contains(QStringLiteral("the statistics shown still hold")),
             qPrintable(m_window->statusText()));
    QVERIFY(!m_window->statusText().contains(QStringLiteral("unreliable")));
    PlotView* flights = plotTitled(*m_window, QStringLiteral("Free-flight"));
    QVERIFY(axis(*flights, Qt::Vertical)->titleText().contains(QStringLiteral("T₂")));
    for (const QPointF& point : seriesNamed(*flights, QStringLiteral("flights"))->data) QVERIFY(point.y() <= 1.0);
    m_window->selectScene(sceneIndex(*m_window, QStringLiteral("random-starts")));
    for (const QGroupBox* box : m_window->parameterPanel()->findChildren<QGroupBox*>()) {
      if (!box->isVisibleTo(m_window.get())) continue;
      bool shows = false;
      for (const QWidget* child : box->findChildren<QWidget*>()) shows |= child->isVisibleTo(box);
      QVERIFY2(shows, qPrintable(box->title()));
    }
    const QString keys = m_window->shortcutsText();
    for (const char* key : {"Ctrl+Shift+R", "Space", "F5", "Esc", "PgDown", "Ctrl+9"}) {
      QVERIFY2(keys.contains(QString::fromLatin1(key)), key);
    }
  }

  // the explorer made its starts itself and said nothing when a push vanished in rounding; it
  // now takes them from core's makeStart, as the command line does, with the same notes
  void aPushLostInRoundingIsSaid() {
    Params params = m_window->params();
    params.direction = PerturbDirection::U2;
    params.perturbation = -1e-20;  // u2 = d = 1: far below one ulp
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY2(m_window->parameterPanel()->notes().contains(QStringLiteral("below one ulp")),
             qPrintable(m_window->parameterPanel()->notes()));
    params.perturbation = -1e-3;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY(m_window->parameterPanel()->notes().isEmpty());
  }

  // after a zoom, a parameter change kept it and the plot could go blank with no hint; a stale
  // result after an infeasible edit was not marked on the plots
  void aParameterChangeRefitsAndAStaleResultIsMarked() {
    PlotView* trace = m_window->plots().first();
    trace->chart()->zoom(8.0);
    QTest::keyClick(trace, Qt::Key_Plus);
    QVERIFY(!trace->followsData());
    Params params = m_window->params();
    params.lambda = 0.3;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY(trace->followsData());
    for (const PlotView* plot : m_window->plots()) QVERIFY(!plot->isStale());
    m_window->resize(1100, 640);  // narrow plots: the note wraps to three lines
    QTest::qWait(50);
    params.m2 = 0.9;  // no 1:2 chain
    m_window->setParams(params);
    QVERIFY(!m_window->problem().isEmpty());
    for (const PlotView* plot : m_window->plots()) {
      QVERIFY(plot->isStale());
      const QLabel* note = plot->findChild<QLabel*>(QStringLiteral("staleNote"));
      QVERIFY(note->isVisible());
      // tall enough for its wrapped lines (a third line was cut in a narrow plot)
      QVERIFY2(note->height() >= note->heightForWidth(note->width()),
               qPrintable(QStringLiteral("%1 < %2").arg(note->height()).arg(note->heightForWidth(note->width()))));
    }
    params.m2 = 0.4;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    for (const PlotView* plot : m_window->plots()) QVERIFY(!plot->isStale());
  }

  // traces showed the first ~3000 time units with no note; the contact-index axis read
  // "0.0002" then "2e+05"
  void longRunsSayWhatTheTraceShowsAndCountInWholeNumbers() {
    m_window->selectScene(sceneIndex(*m_window, QStringLiteral("near-grazing")));
    Params params = m_window->params();
    params.horizon = 200000;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    PlotView* trace = plotTitled(*m_window, QStringLiteral("Displacement"));
    // a window of three slow periods of the samples' stretch, then (W) all the samples; every
    // number a time in the axis' unit T₂, the run's end among them (it said "3 T₂ of 3.55e+03"
    // where W said "first 3.55e+03 of 8.76e+05"), and no number in a code ("3.55e+03": "3554",
    // "8.8×10⁵")
    const double T2 = grazelab::core::computeModes(m_window->displayed()->request->job.spec.model).T2;
    const QString windowTitle = axis(*trace, Qt::Horizontal)->titleText().replace(QStringLiteral("<br>"), QStringLiteral(" "));
    const QString tFinal = timeText(m_window->displayed()->result->tFinal / T2);
    const QString tSampled = timeText(m_window->displayed()->result->samples.back().t / T2);
    QVERIFY2(windowTitle.startsWith(QStringLiteral("t / T₂ (")) &&
                 windowTitle.contains(QStringLiteral("of %1 sampled)").arg(tSampled)) &&
                 !windowTitle.contains(QStringLiteral("e+")),
             qPrintable(windowTitle));
    QCOMPARE(timeText(3554.4), QStringLiteral("3554"));
    QCOMPARE(timeText(876000), QStringLiteral("8.8×10⁵"));
    QCOMPARE(timeText(26.66), QStringLiteral("26.7"));
    QCOMPARE(timeText(0.534), QStringLiteral("0.534"));
    QCOMPARE(timeText(0.00123), QStringLiteral("0.00123"));
    QCOMPARE(timeText(2.5e-4), QStringLiteral("2.5×10⁻⁴"));
    QCOMPARE(timeText(0), QStringLiteral("0"));
    QVERIFY(axis(*trace, Qt::Horizontal)->max() - axis(*trace, Qt::Horizontal)->min() <= 3 * (1 + 1e-9));
    QTest::keyClick(m_window.get(), Qt::Key_W);
    trace->refreshNow();
    QVERIFY(axis(*trace, Qt::Horizontal)->titleText().contains(QStringLiteral("sampled to")));
    QVERIFY(axis(*trace, Qt::Horizontal)->titleText().contains(tFinal));
    QVERIFY(axis(*trace, Qt::Horizontal)->max() - axis(*trace, Qt::Horizontal)->min() > 4);
    PlotView* flights = plotTitled(*m_window, QStringLiteral("Free-flight"));
    QValueAxis* index = axis(*flights, Qt::Horizontal);
    QVERIFY(index->max() > 1.9e5);
    QCOMPARE(index->labelFormat(), QStringLiteral("%.0f"));
    // the flight-time axis spans the flights and their bound, not a unit around them (its
    // least span once followed the contact axis's 10^5: the flights merged with the bound)
    double lowest = 1;
    for (const QPointF& p : flights->entries().front().points().toVector()) lowest = std::min(lowest, p.y());
    QVERIFY(lowest < 1);
    const QValueAxis* fft = axis(*flights, Qt::Vertical);
    QVERIFY2(fft->max() - fft->min() < 2 * (1 - lowest) + 1e-9,
             qPrintable(QStringLiteral("%1 to %2 for flights from %3").arg(fft->min()).arg(fft->max()).arg(lowest)));
  }

  // "GLO_λ" showed its underscore in menus, texts and legends
  void noLiteralUnderscoreInWhatIsShown() {
    for (QAction* action : m_window->menuBar()->actions()) {
      if (!action->menu()) continue;
      for (QAction* item : action->menu()->actions()) {
        QVERIFY2(!item->text().contains(QStringLiteral("GLO_")), qPrintable(item->text()));
      }
    }
    for (int index = 0; index < int(m_window->scenes().size()); ++index) {
      m_window->selectScene(index);
      QVERIFY(!m_window->windowTitle().contains(QStringLiteral("GLO_")));
      for (QLabel* label : m_window->findChildren<QLabel*>()) {
        QVERIFY2(!label->text().contains(QStringLiteral("GLO_")), qPrintable(label->text()));
      }
      for (const PlotView* plot : m_window->plots()) {
        for (const PlotView::Entry& entry : plot->entries()) {
          QVERIFY2(!entry.series->name().contains(QStringLiteral("GLO_")),
                   qPrintable(entry.series->name()));
        }
      }
    }
  }

  // a bad --session was silently ignored: it is said on stderr at once (the window then shows
  // a dialog, which this test does not wait for)
  void aBadSessionIsSaidOnStandardError() {
    const QString app = qEnvironmentVariable("GRAZELAB_APP");
    if (app.isEmpty()) QSKIP("GRAZELAB_APP is not set (run through ctest)");
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{ not json");
    file.close();
    QProcess process;
    process.start(app, {QStringLiteral("--session"), path});
    QVERIFY(process.waitForStarted(10000));
    QByteArray err;
    for (int i = 0; i < 200 && !err.contains("bad.json"); ++i) {
      process.waitForReadyRead(100);
      err += process.readAllStandardError();
    }
    process.kill();
    process.waitForFinished(5000);
    QVERIFY2(err.contains("bad.json"), err.constData());
  }

  // the Nonlinear modes scene: the atlas and the 1IPP orbit of the slider at first; a click on a
  // dot of a 2-impact family follows that orbit (its multipliers shown, the run repeating after
  // 2 impacts); a click on no family says how near to click
  void aClickOnTheModesPictureFollowsThatOrbit() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("modes")));
    QVERIFY(waitForLatestFinal(*m_window));
    const auto first = m_window->displayed()->request;  // held: a click replaces what is shown
    const SceneJob& job = first->job;
    QVERIFY(job.ok);
    QVERIFY(job.atlas && job.atlas->families.size() >= 4);
    QVERIFY(job.orbit && job.orbit->impacts == 1);
    {
      // its CSV holds the atlas: every orbit of every family, named, with T/T2 (issue 30)
      const QStringList rows = m_window->plottedDataCsv().split(QLatin1Char('\n'));
      std::size_t orbits = 0;
      for (const auto& family : job.atlas->families) orbits += family.orbits.size();
      const double T2 = first->derived.modes.T2;
      qsizetype atlasRows = 0;
      for (const QString& row : rows) {
        if (!row.startsWith(QStringLiteral("\"Modes")) || !row.contains(QStringLiteral("\"family "))) continue;
        ++atlasRows;
        const QStringList cells = row.split(QLatin1Char(','));
        const double period = 2 * M_PI / cells[cells.size() - 2].toDouble();
        QVERIFY2(std::abs(cells.last().toDouble() - period / T2) < 1e-12 * period / T2, qPrintable(row));
      }
      QVERIFY(atlasRows >= qsizetype(orbits));
    }
    PlotView* modes = plotTitled(*m_window, QStringLiteral("Modes"));
    PlotView* multipliers = plotTitled(*m_window, QStringLiteral("Multipliers"));
    QVERIFY(modes && multipliers);
    QCOMPARE(multipliers->entries()[1].points().size(), std::size_t(2));
    // a 2-impact orbit in the middle of its family, where the picture has it
    const AtlasFigure::Family* two = nullptr;
    for (const auto& family : job.atlas->families) {
      if (family.impacts == 2 && !two) two = &family;
    }
    QVERIFY(two && two->orbits.size() > 10);
    const auto target = two->orbits[two->orbits.size() / 2];
    const QPointF value(std::log10(target.energy), 2 * std::numbers::pi / target.period);
    QTRY_VERIFY(modes->drawnPointCount() > 0);
    const QPoint at = modes->chart()->mapToPosition(value).toPoint();
    // the orbit drawn nearest the click, as the picture stands when it is clicked (two
    // families may share those pixels)
    double nearestDistance = 1e9;
    double nearestEnergy = 0;
    for (const auto& family : job.atlas->families) {
      for (const auto& orbit : family.orbits) {
        const QPointF p = modes->chart()->mapToPosition(QPointF(std::log10(orbit.energy), 2 * std::numbers::pi / orbit.period));
        const double d = std::hypot(p.x() - at.x(), p.y() - at.y());
        if (d < nearestDistance) nearestDistance = d, nearestEnergy = orbit.energy;
      }
    }
    QTest::mouseClick(modes->viewport(), Qt::LeftButton, {}, at);
    QTRY_VERIFY(m_window->displayed()->request->job.orbit && m_window->displayed()->request->job.orbit->impacts == 2);
    QVERIFY(waitForLatestFinal(*m_window));
    const SimUpdate& shown = *m_window->displayed();
    QCOMPARE(shown.request->job.orbit->impacts, 2);
    QVERIFY2(std::abs(shown.request->job.orbit->energy - nearestEnergy) < 1e-9 * nearestEnergy,
             qPrintable(QStringLiteral("%1 vs %2").arg(shown.request->job.orbit->energy).arg(nearestEnergy)));
    // the run repeats: after 2 impacts it is back where it started
    const auto& events = shown.result->events;
    QVERIFY(events.size() >= 4);
    QVERIFY(std::abs(events[1].after.u1 - shown.request->job.spec.run.initial.u1) < 1e-8);
    QVERIFY(std::abs(events[3].t - 2 * events[1].t) < 1e-8 * events[3].t);
    // a click far from every family changes nothing and says why
    const std::uint64_t before = shown.id;
    const QRectF area = modes->chart()->plotArea();
    QPoint empty;
    double farthest = 0;
    for (int i = 1; i < 20; ++i) {
      for (int j = 1; j < 20; ++j) {
        const QPointF candidate(area.left() + area.width() * i / 20, area.top() + area.height() * j / 20);
        double nearest = 1e9;
        for (const auto& family : job.atlas->families) {
          for (const auto& orbit : family.orbits) {
            const QPointF p = modes->chart()->mapToPosition(QPointF(std::log10(orbit.energy), 2 * std::numbers::pi / orbit.period));
            nearest = std::min(nearest, std::hypot(p.x() - candidate.x(), p.y() - candidate.y()));
          }
        }
        if (nearest > farthest) farthest = nearest, empty = candidate.toPoint();
      }
    }
    QVERIFY(farthest > 30);
    QTest::mouseClick(modes->viewport(), Qt::LeftButton, {}, empty);
    QTRY_VERIFY(m_window->statusText().contains(QStringLiteral("pixels of a family")));
    QCOMPARE(m_window->displayed()->id, before);
  }

  // Modes of three masses (issue 49): the atlas of a 3:2:1 chain with its Krein collisions
  // marked; the energy slider moves the orbit along its family: between a collision pair its
  // four multipliers are a complex quadruplet (no signature), just past either end they are back
  // on the circle as two pairs of opposite signature; the run is that orbit (its impacts a period
  // apart); a click on a dot of the picture moves the family and the slider to that orbit
  void theModesOfThreeMassesShowKreinCollisionsAlongTheEnergySlider() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("modes-three")));
    QVERIFY(waitForLatestFinal(*m_window));
    const auto first = m_window->displayed()->request;
    QVERIFY(first->job.ok);
    const AtlasFigure& atlas = *first->job.atlas;
    QVERIFY(atlas.families.size() >= 4);
    // the family with two Krein collisions, and their energies
    int family = -1;
    std::vector<double> collisions;
    for (std::size_t f = 0; f < atlas.families.size() && family < 0; ++f) {
      collisions.clear();
      for (const AtlasFigure::Mark& mark : atlas.marks) {
        if (mark.family == int(f) && mark.kind == AtlasFigure::MarkKind::KreinCollision) collisions.push_back(mark.energy);
      }
      if (collisions.size() == 2) family = int(f);
    }
    QVERIFY(family >= 0);
    std::sort(collisions.begin(), collisions.end());
    const AtlasFigure::Family& chosen = atlas.families[std::size_t(family)];
    const auto orbitAt = [&](double energy) {
      Params params = m_window->params();
      params.modeFamily = family;
      params.modeEnergy = energyPosition(chosen, energy);
      m_window->setParams(params);
      [[maybe_unused]] const bool done = waitForLatestFinal(*m_window);
      return m_window->displayed()->request->job.orbit;
    };
    const std::optional<ShownOrbit> between = orbitAt(std::sqrt(collisions[0] * collisions[1]));
    QVERIFY(between && between->multipliers.size() == 4);
    QCOMPARE(between->stability, QStringLiteral("complex-quadruplet"));
    for (int krein : between->krein) QCOMPARE(krein, 0);
    for (const double outside : {collisions[0] * 0.98, collisions[1] * 1.02}) {
      const std::optional<ShownOrbit> on = orbitAt(outside);
      QVERIFY(on && on->multipliers.size() == 4);
      QCOMPARE(on->stability, QStringLiteral("elliptic"));
      int plus = 0, minus = 0;
      for (std::size_t i = 0; i < 4; ++i) {
        QVERIFY(std::abs(std::abs(on->multipliers[i]) - 1) < 1e-6);
        plus += on->krein[i] > 0 ? 1 : 0;
        minus += on->krein[i] < 0 ? 1 : 0;
      }
      QCOMPARE(plus, 2);
      QCOMPARE(minus, 2);
      // the run is the orbit: its impacts a period apart
      const auto& events = m_window->displayed()->chains.front()->run.events;
      QVERIFY(events.size() >= 2);
      QVERIFY(std::abs(events[1].t - events[0].t - on->period) < 1e-8 * on->period);
    }
    // a click on a dot of another family follows it, and the sliders move to it
    PlotView* modes = plotTitled(*m_window, QStringLiteral("Modes"));
    QVERIFY(modes);
    const int other = family == 0 ? 1 : 0;
    const AtlasFigure::Orbit& target = atlas.families[std::size_t(other)].orbits[atlas.families[std::size_t(other)].orbits.size() / 2];
    QTRY_VERIFY(modes->drawnPointCount() > 0);
    const QPoint at = modes->chart()->mapToPosition(QPointF(std::log10(target.energy), 2 * std::numbers::pi / target.period)).toPoint();
    double nearest = 1e9;
    int nearestFamily = -1;
    for (std::size_t f = 0; f < atlas.families.size(); ++f) {
      for (const AtlasFigure::Orbit& orbit : atlas.families[f].orbits) {
        const QPointF p = modes->chart()->mapToPosition(QPointF(std::log10(orbit.energy), 2 * std::numbers::pi / orbit.period));
        const double d = std::hypot(p.x() - at.x(), p.y() - at.y());
        if (d < nearest) nearest = d, nearestFamily = int(f);
      }
    }
    QTest::mouseClick(modes->viewport(), Qt::LeftButton, {}, at);
    QTRY_COMPARE(int(m_window->params().modeFamily), nearestFamily);
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY(m_window->displayed()->request->job.orbit);
  }

  // the atlas is computed in the worker and shown family by family: partial updates carry
  // the families so far, each one more than the last, before the run's final update
  void theModesAtlasArrivesFamilyByFamily() {
    const std::vector<std::unique_ptr<Scene>> scenes = grazelab::ui::makeScenes();
    const Scene& scene = *scenes[std::size_t(findScene(scenes, QStringLiteral("modes")))];
    Params params = scene.defaults();
    params.m2 = 0.45;  // a chain no atlas was computed for yet (the scene keeps the last one)
    const DerivedModel derived = grazelab::ui::deriveModel(params);
    QVERIFY(derived.ok);
    SimRequest request;
    request.id = 7;
    request.params = params;
    request.sceneName = scene.name();
    request.derived = derived;
    request.prepare = [&scene, params, derived](std::stop_token stop, const grazelab::ui::ScenePartial& partial) {
      return scene.build(params, derived, stop, std::nullopt, partial);
    };
    std::vector<std::size_t> partials;
    std::optional<SimUpdate> last;
    SimWorker::run(request, {}, 0.030, [&](const SimUpdate& update) {
      if (update.scenePartial) {
        QVERIFY(update.request->job.atlas);
        QVERIFY(update.result && update.result->events.empty());
        partials.push_back(update.request->job.atlas->families.size());
      } else if (update.final && !update.trustPending) {
        last = update;
      }
    });
    QVERIFY(last && last->request->job.ok);
    const std::size_t families = last->request->job.atlas->families.size();
    QCOMPARE(partials.size(), families);
    for (std::size_t i = 0; i < partials.size(); ++i) QCOMPARE(partials[i], i + 1);
  }

  // click a point of the section H: a run starts there, on the same energy, leaving the stop
  void aClickOnTheSectionStartsARunThere() {
    PlotView* poincare = plotTitled(*m_window, QStringLiteral("Poincaré"));
    QVERIFY(poincare);
    QTRY_VERIFY(poincare->entries().front().series->count() > 0);
    const grazelab::core::Model model = m_window->displayed()->request->job.spec.model;  // a copy: the click replaces what is shown
    const double level = grazelab::core::energy(model, m_window->displayed()->request->job.spec.run.initial);
    // half-way from a point the run reached (on the energy level, by conservation) to the
    // middle of the level's ellipse (v1 = 0, the springs' least energy): well inside the level,
    // so that a click rounded to a pixel stays on it
    const QPointF reached = poincare->entries().front().points().toVector().at(3);
    // (as plotted: u1 / d, v1 / (d w1))
    const double middle = model.k2 / (model.k1 + model.k2);
    const QPointF target = 0.5 * (reached + QPointF(middle, 0.0));
    const QPoint at = poincare->chart()->mapToPosition(target).toPoint();
    QTest::mouseClick(poincare->viewport(), Qt::LeftButton, {}, at);
    QTRY_VERIFY(!poincare->clickPending());
    QVERIFY(waitForLatestFinal(*m_window));
    const grazelab::core::State start = m_window->displayed()->request->job.spec.run.initial;
    QCOMPARE(start.u2, model.gap);
    QVERIFY(start.v2 <= 0);
    const double pixel = (axis(*poincare, Qt::Horizontal)->max() - axis(*poincare, Qt::Horizontal)->min()) / 100;
    QVERIFY2(std::abs(start.u1 / model.gap - target.x()) < pixel, qPrintable(m_window->statusText()));
    QVERIFY(std::abs(grazelab::core::energy(model, start) - level) < 1e-12 * level);
    // a point outside the energy level is refused with a reason, nothing recomputed
    const std::uint64_t before = m_window->displayed()->id;
    QVERIFY(!m_window->startFromSection(QPointF(100, 0)));
    QVERIFY(m_window->statusText().contains(QStringLiteral("No state of this energy")));
    QCOMPARE(m_window->displayed()->id, before);
    // an edit goes back to the scene's own start
    Params params = m_window->params();
    params.horizon = 30;
    m_window->setParams(params);
    QVERIFY(waitForLatestFinal(*m_window));
    const auto glo = grazelab::core::gloData(model, grazelab::core::computeModes(model), params.lambda);
    QCOMPARE(m_window->displayed()->request->job.spec.run.initial.u1, glo.u1);
  }

  // the (u2, v2) portrait: a click on the stop line starts mass 2 from the stop at the
  // clicked speed, mass 1 where the run started, on the same energy
  void aClickOnTheStopLineStartsARunThere() {
    PlotView* phase = plotTitled(*m_window, QStringLiteral("Phase portrait of mass 2"));
    QVERIFY(phase);
    QTRY_VERIFY(!phase->entries().front().points().empty());
    const grazelab::core::Model model = m_window->displayed()->request->job.spec.model;
    const grazelab::core::State shown = m_window->displayed()->request->job.spec.run.initial;
    const double level = grazelab::core::energy(model, shown);
    // (the portrait's units: u2 / d, v2 / (d w1))
    const double speedUnit = model.gap * grazelab::core::computeModes(model).omegaFast;
    // a speed the run itself reached at the stop: the largest |v2| of its path there
    double speed = 0;
    for (const QPointF& point : phase->entries().front().points().toVector()) {
      if (std::abs(point.x() - 1) < 1e-9) speed = std::max(speed, std::abs(point.y()));
    }
    QVERIFY(speed > 0);
    const QPointF target(1, -0.5 * speed);
    // 12 px off: a hand on a projector's remote misses a thin line by that much
    const QPoint at = phase->chart()->mapToPosition(target).toPoint() + QPoint(-12, 0);
    QTest::mouseClick(phase->viewport(), Qt::LeftButton, {}, at);
    QTRY_VERIFY(!phase->clickPending());
    QVERIFY(waitForLatestFinal(*m_window));
    const grazelab::core::State start = m_window->displayed()->request->job.spec.run.initial;
    QCOMPARE(start.u2, model.gap);
    QCOMPARE(start.u1, shown.u1);
    const double pixel = (axis(*phase, Qt::Vertical)->max() - axis(*phase, Qt::Vertical)->min()) / 100;
    QVERIFY(std::abs(start.v2 / speedUnit - target.y()) < pixel);
    QVERIFY(std::abs(grazelab::core::energy(model, start) - level) < 1e-12 * level);
    QVERIFY(m_window->displayed()->result->cost.contacts > 0);
    // the panel says that this start is not its own
    QVERIFY(m_window->parameterPanel()->clickedStartText().contains(QStringLiteral("clicked start")));
    // off the line, or a speed beyond the energy: refused with a reason, nothing recomputed
    const std::uint64_t before = m_window->displayed()->id;
    QVERIFY(!m_window->startFromStopLine(QPointF(0.5, -0.5 * speed), 0.01));
    QVERIFY(m_window->statusText().contains(QStringLiteral("pixels of the stop line")));
    QVERIFY(!m_window->startFromStopLine(QPointF(1, -100 * speed), 0.01));
    QVERIFY(m_window->statusText().contains(QStringLiteral("No state of this energy")));
    QCOMPARE(m_window->displayed()->id, before);
    // an edit goes back to the panel's start, and the note goes
    m_window->setParams(m_window->params());
    QVERIFY(m_window->parameterPanel()->clickedStartText().isEmpty());
  }

  // presentation mode: text of at least 1/50 of the screen height, lines of 3 px or more, the
  // scenes in the order of the note on PageDown / PageUp, a plot enlarged by a double-click
  // the readout's values are fixed-size labels (a changing size re-laid out the whole side
  // panel on every update): under a projector's font the longest number they print still fits
  void readoutValuesGrowWithTheirFont() {
    ReadoutPanel* readout = m_window->readoutPanel();
    QFont large = readout->font();
    large.setPixelSize(40);
    readout->setFont(large);
    int values = 0;
    for (const QLabel* value : readout->findChildren<QLabel*>()) {
      if (value->objectName().isEmpty()) continue;
      ++values;
      QCOMPARE(QFontInfo(value->font()).pixelSize(), 40);
      QVERIFY2(value->width() >= value->fontMetrics().horizontalAdvance(QStringLiteral("-8.8888888e-188")),
               qPrintable(value->objectName()));
      QCOMPARE(value->minimumSize(), value->maximumSize());
    }
    QCOMPARE(values, 7);
  }

  void presentationModeIsReadableAndSteppable() {
    const int deskLabels = QFontInfo(axis(*m_window->plots().first(), Qt::Horizontal)->labelsFont()).pixelSize();
    m_window->setPresentation(true, 1080, false);
    QVERIFY(QApplication::font().pixelSize() >= 1080 / 50);
    for (const PlotView* plot : m_window->plots()) {
      QVERIFY(plot->chart()->legend()->font().pixelSize() >= 1080 / 50);
      QVERIFY(axis(*plot, Qt::Horizontal)->labelsFont().pixelSize() >= 1080 / 50);
      for (const PlotView::Entry& entry : plot->entries()) {
        if (!qobject_cast<QScatterSeries*>(entry.series)) QVERIFY(entry.series->pen().widthF() >= 3.0);
      }
    }
    // a scene opened in presentation mode gets the look too
    QTest::keyClick(m_window.get(), Qt::Key_PageDown);
    QCOMPARE(m_window->sceneIndex(), 1);
    QVERIFY(waitForLatestFinal(*m_window));
    for (const PlotView* plot : m_window->plots()) {
      QVERIFY(plot->chart()->legend()->font().pixelSize() >= 1080 / 50);
    }
    QTest::keyClick(m_window.get(), Qt::Key_PageUp);
    QTest::keyClick(m_window.get(), Qt::Key_PageUp);
    QCOMPARE(m_window->sceneIndex(), int(m_window->scenes().size()) - 1);  // wraps
    QTest::keyClick(m_window.get(), Qt::Key_PageDown);
    QCOMPARE(m_window->sceneIndex(), 0);
    QVERIFY(waitForLatestFinal(*m_window));
    // double-click: that plot alone; again: all back
    PlotView* plot = m_window->plots().last();
    QTest::mouseDClick(plot->viewport(), Qt::LeftButton, {}, plot->viewport()->rect().center());
    QCOMPARE(m_window->enlargedView(), plot);
    for (const PlotView* other : m_window->plots()) QCOMPARE(other->isVisibleTo(m_window.get()), other == plot);
    QTest::mouseDClick(plot->viewport(), Qt::LeftButton, {}, plot->viewport()->rect().center());
    QVERIFY(!m_window->enlargedView());
    // a double-click on a plot that starts runs when clicked (H) enlarges it and starts none
    PlotView* poincare = plotTitled(*m_window, QStringLiteral("Poincaré"));
    QVERIFY(poincare);
    const std::uint64_t shownId = m_window->displayed()->id;
    QTest::mouseDClick(poincare->viewport(), Qt::LeftButton, {}, poincare->viewport()->rect().center());
    QCOMPARE(m_window->enlargedView(), poincare);
    QTest::qWait(QApplication::doubleClickInterval() + 100);
    QVERIFY(!poincare->clickPending());
    QCOMPARE(m_window->displayed()->id, shownId);
    QVERIFY(m_window->parameterPanel()->clickedStartText().isEmpty());
    QTest::mouseDClick(poincare->viewport(), Qt::LeftButton, {}, poincare->viewport()->rect().center());
    QVERIFY(!m_window->enlargedView());
    for (const PlotView* other : m_window->plots()) QVERIFY(other->isVisibleTo(m_window.get()));
    // the panel hides and comes back (F9)
    QTest::keyClick(m_window.get(), Qt::Key_F9);
    QVERIFY(!m_window->parameterPanel()->isVisibleTo(m_window.get()));
    QTest::keyClick(m_window.get(), Qt::Key_F9);
    QVERIFY(m_window->parameterPanel()->isVisibleTo(m_window.get()));
    m_window->setPresentation(false, 1080, false);
    QVERIFY(QApplication::font().pixelSize() < 1080 / 50);
    // the scenes were switched while presenting: their plots come back to the desk's text too
    // (made under the large font, they once kept it); made again one per turn, they draw the
    // run they showed
    QTRY_COMPARE(m_window->sceneViews().size(), m_window->scene().plots().size());
    QTRY_VERIFY(!m_window->plots().first()->entries().front().points().empty());
    for (const PlotView* plot : m_window->plots()) {
      QCOMPARE(QFontInfo(axis(*plot, Qt::Horizontal)->labelsFont()).pixelSize(), deskLabels);
      for (const PlotView::Entry& entry : plot->entries()) {
        if (!qobject_cast<QScatterSeries*>(entry.series)) QVERIFY(entry.series->pen().widthF() < 3.0);
      }
    }
  }

 private:
  std::unique_ptr<MainWindow> m_window;
};

QTEST_MAIN(ClassroomTest)
#include "classroom_test.moc"
