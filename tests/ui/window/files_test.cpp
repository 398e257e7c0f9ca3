// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for ui/window/export.cpp, session.cpp and main_window_files.cpp: snapshots, CSV and
// sessions are written, carry their parameters and reopen to the same view.
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImageReader>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QXmlStreamReader>
#include <QScrollArea>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

#include "tests/ui/explorer_test_support.h"
#include "ui/window/export.h"
#include "ui/window/main_window.h"
#include "ui/widgets/number_box.h"
#include "ui/widgets/parameter_panel.h"
#include "ui/plots/plot_view.h"
#include "ui/plots/scene_view.h"
#include "ui/window/session.h"

using namespace grazelab::ui;
using grazelab::ui::testing::shownChainRun;
using grazelab::ui::testing::openTestWindow;
using grazelab::ui::testing::waitForLatestFinal;

namespace {

QByteArray readAll(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

Params changedParams(const Params& base) {
  Params params = base;
  params.lambda = 0.8125;
  params.m2 = 0.4375;
  params.gap = 2.5;
  params.perturbation = -0.03;
  params.horizon = 40;
  params.branch = grazelab::core::Branch::Lower;
  return params;
}

}  // namespace

class FilesTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    m_window = openTestWindow();
    m_window->setParams(changedParams(m_window->params()));
    QVERIFY(waitForLatestFinal(*m_window));
  }
  void cleanup() { m_window.reset(); }

  void snapshotsAreWrittenWithTheirSession_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<bool>("wholeWindow");
    QTest::newRow("window png") << "window.png" << true;
    QTest::newRow("window svg") << "window.svg" << true;
    QTest::newRow("window pdf") << "window.pdf" << true;
    QTest::newRow("plot png") << "plot.png" << false;
    QTest::newRow("plot svg") << "plot.svg" << false;
    QTest::newRow("plot pdf") << "plot.pdf" << false;
  }

  void snapshotsAreWrittenWithTheirSession() {
    QFETCH(QString, name);
    QFETCH(bool, wholeWindow);
    QTemporaryDir dir;
    const QString path = dir.filePath(name);
    QString error;
    const bool saved = wholeWindow ? m_window->saveWindowSnapshot(path, &error)
                                   : m_window->savePlotSnapshot(path, &error);
    QVERIFY2(saved, qPrintable(error));
    QVERIFY(QFileInfo(path).size() > 1000);
    const QByteArray head = readAll(path).left(8);
    if (name.endsWith(QStringLiteral(".png"))) QVERIFY(head.startsWith("\x89PNG"));
    if (name.endsWith(QStringLiteral(".pdf"))) QVERIFY(head.startsWith("%PDF"));
    if (name.endsWith(QStringLiteral(".svg"))) {
      // well-formed: Qt 6.4 writes the description unescaped, so it is escaped before
      QXmlStreamReader xml(readAll(path));
      QString description;
      while (!xml.atEnd()) {
        if (xml.readNext() == QXmlStreamReader::StartElement && xml.name() == QStringLiteral("desc")) {
          description = xml.readElementText();
        }
      }
      QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
      QString error;
      QVERIFY2(sessionFromJson(description.toUtf8(), Params{}, &error), qPrintable(error));
      // Qt 6.4's SVG has no clipping: nothing may be drawn past the picture's right edge (the
      // u2(t) stop line ran 4000 px across the neighbouring views). Every translated group's
      // path points, in the picture's coordinates:
      const QString svg = QString::fromUtf8(readAll(path));
      const QRegularExpression group(QStringLiteral(
          "transform=\"matrix\\(1,0,0,1,([-0-9.e]+),[-0-9.e]+\\)\"[^>]*>\\s*<path[^>]* d=\"([^\"]*)\""));
      const QRegularExpression pair(QStringLiteral("([-0-9.e]+),[-0-9.e]+"));
      const double width = wholeWindow ? m_window->width() : m_window->currentPlot()->width();
      double rightmost = 0;
      for (const auto& g : group.globalMatch(svg)) {
        const double tx = g.captured(1).toDouble();
        for (const auto& p : pair.globalMatch(g.captured(2))) rightmost = std::max(rightmost, tx + p.captured(1).toDouble());
      }
      QVERIFY2(rightmost <= width + 2, qPrintable(QStringLiteral("drawn to x = %1 in %2").arg(rightmost).arg(width)));
    }

    // the parameters travel beside the picture and reopen to the same values
    const QString sessionPath = sessionPathFor(path);
    QVERIFY(QFileInfo::exists(sessionPath));
    QString parseError;
    const auto session = sessionFromJson(readAll(sessionPath), Params{}, &parseError);
    QVERIFY2(session, qPrintable(parseError));
    QCOMPARE(session->scene, m_window->scene().name());
    QVERIFY(session->params == m_window->params());
  }

  // window.png, window.svg and window.csv shared (and overwrote) one window.session.json; the
  // PDF's title was a JSON blob; a plot could only be saved at its size on screen
  void savedFilesKeepTheirOwnSideFileTitleAndSize() {
    QTemporaryDir dir;
    QString error;
    QVERIFY2(m_window->saveWindowSnapshot(dir.filePath(QStringLiteral("fig.png")), &error), qPrintable(error));
    QVERIFY2(m_window->exportCsv(dir.filePath(QStringLiteral("fig.csv")), &error), qPrintable(error));
    QVERIFY(sessionPathFor(dir.filePath(QStringLiteral("fig.png"))) !=
            sessionPathFor(dir.filePath(QStringLiteral("fig.csv"))));
    QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("fig.png.session.json"))));
    QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("fig.csv.session.json"))));

    const QString pdf = dir.filePath(QStringLiteral("fig.pdf"));
    QVERIFY2(m_window->saveWindowSnapshot(pdf, &error), qPrintable(error));
    QProcess info;
    info.start(QStringLiteral("pdfinfo"), {pdf});
    QVERIFY2(info.waitForFinished(20000), "pdfinfo (poppler-utils) did not run");
    const QString title = QString::fromUtf8(info.readAllStandardOutput()).section(QLatin1Char('\n'), 0, 0);
    const QString lambda = shortestText(m_window->params().lambda);
    QVERIFY2(title.contains(QStringLiteral("λ = ") + lambda) && !title.contains(QLatin1Char('{')),
             qPrintable(title));

    const QString plot = dir.filePath(QStringLiteral("plot.png"));
    QVERIFY2(m_window->savePlotSnapshot(plot, &error, QSize(800, 600)), qPrintable(error));
    QCOMPARE(QImage(plot).size(), QSize(1600, 1200));
    // any view can be saved, not only a chart that a click made current (the map and the
    // animation start runs when clicked): here the animated chain, at a slide's size
    SceneView* chain = nullptr;
    for (SceneView* view : m_window->sceneViews()) {
      if (view->viewTitle().contains(QStringLiteral("chain"))) chain = view;
    }
    QVERIFY(chain);
    const QString chainPath = dir.filePath(QStringLiteral("chain.png"));
    QVERIFY2(m_window->savePlotSnapshot(chainPath, &error, QSize(1920, 1080), chain), qPrintable(error));
    QCOMPARE(QImage(chainPath).size(), QSize(3840, 2160));

    QVERIFY(m_window->suggestedFileName(QStringLiteral("window"), QStringLiteral(".png"))
                .startsWith(QStringLiteral("grazing-lambda") + lambda + QStringLiteral("-window")));
    QVERIFY(!m_window->saveDirectory().startsWith(QStringLiteral("/proc")));
  }

  void pngCarriesItsSessionAndDoublePixels() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("window.png"));
    QString error;
    QVERIFY2(m_window->saveWindowSnapshot(path, &error), qPrintable(error));
    QImageReader reader(path);
    const QString text = reader.text(QStringLiteral("GrazeLabSession"));
    const QImage image = reader.read();
    QCOMPARE(image.size(), m_window->size() * 2);
    const auto session = sessionFromJson(text.toUtf8(), Params{}, &error);
    QVERIFY2(session, qPrintable(error));
    QVERIFY(session->params == m_window->params());
  }

  // A PDF keeps the legends (Qt Charts' legend clip came out empty in a PDF painter: only the
  // first label showed) and carries its parameters in the document's metadata.
  void pdfKeepsItsLegendsAndCarriesItsSession() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("window.pdf"));
    QString error;
    QVERIFY2(m_window->saveWindowSnapshot(path, &error), qPrintable(error));
    QProcess pdftotext;
    pdftotext.start(QStringLiteral("pdftotext"), {path, QStringLiteral("-")});
    QVERIFY2(pdftotext.waitForFinished(20000), "pdftotext (poppler-utils) did not run");
    const QString text = QString::fromUtf8(pdftotext.readAllStandardOutput());
    // ("flights" comes out of pdftotext with an fl ligature)
    for (const char* label : {"impacts", "bound", "orbit", "start"}) {
      QVERIFY2(text.contains(QString::fromUtf8(label)), label);
    }
    // the session in the XMP description, as a reader of the metadata finds it
    const QByteArray pdf = readAll(path);
    const QByteArray open = "<dc:description><rdf:Alt><rdf:li xml:lang=\"x-default\">";
    const qsizetype begin = pdf.indexOf(open);
    QVERIFY(begin >= 0);
    const qsizetype end = pdf.indexOf("</rdf:li>", begin);
    QByteArray json = pdf.mid(begin + open.size(), end - begin - open.size());
    json.replace("&quot;", "\"").replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&");
    const auto session = sessionFromJson(json, Params{}, &error);
    QVERIFY2(session, qPrintable(error));
    QVERIFY(session->params == m_window->params());
  }

  // Qt's PDF engine did not clip the parameter panel's scroll area: its rows below the visible
  // part were drawn over the status bar. The status bar's strip of the page must be the same
  // with the panel shown (overflowing: presentation text) and hidden.
  void pdfClipsTheParameterPanelToWhatItShows() {
    m_window->setPresentation(true, 1080, false);
    m_window->resize(1920, 1080);  // the readout box then straddles the panel's lower edge
    QTest::qWait(300);
    const auto* side = m_window->findChild<QScrollArea*>();
    QVERIFY(side && side->widget());
    QVERIFY2(side->widget()->height() > side->viewport()->height(), "the panel does not overflow");
    QTemporaryDir dir;
    auto statusStrip = [&](const QString& name) {
      const QString pdf = dir.filePath(name + QStringLiteral(".pdf"));
      QString error;
      if (!m_window->saveWindowSnapshot(pdf, &error)) return QImage();
      QProcess pdftoppm;
      pdftoppm.start(QStringLiteral("pdftoppm"), {QStringLiteral("-r"), QStringLiteral("96"),
                                                  QStringLiteral("-png"), QStringLiteral("-singlefile"),
                                                  pdf, dir.filePath(name)});
      if (!pdftoppm.waitForFinished(30000)) return QImage();
      const QImage page(dir.filePath(name + QStringLiteral(".png")));
      const QRect bar(m_window->statusBar()->mapTo(m_window.get(), QPoint(0, 0)), m_window->statusBar()->size());
      return page.copy(bar).convertToFormat(QImage::Format_RGB32);
    };
    const QImage shown = statusStrip(QStringLiteral("shown"));
    m_window->setPanelVisible(false);
    QTest::qWait(300);
    const QImage hidden = statusStrip(QStringLiteral("hidden"));
    m_window->setPanelVisible(true);
    m_window->setPresentation(false, 1080, false);
    QVERIFY2(!shown.isNull() && shown.size() == hidden.size(), "pdftoppm (poppler-utils) did not run");
    qsizetype differing = 0;
    for (int y = 0; y < shown.height(); ++y) {
      for (int x = 0; x < shown.width(); ++x) {
        const QRgb a = shown.pixel(x, y), b = hidden.pixel(x, y);
        if (std::abs(qGray(a) - qGray(b)) > 48) ++differing;
      }
    }
    QVERIFY2(differing < shown.width() * shown.height() / 200,
             qPrintable(QStringLiteral("%1 status-bar pixels differ").arg(differing)));
  }

  void snapshotCarriesTheParametersOfWhatItShows() {
    // an infeasible mass ratio leaves the last valid run on screen: the snapshot's parameters
    // are that run's, not the panel's
    const Params shown = m_window->displayed()->request->params;
    Params infeasible = m_window->params();
    infeasible.m2 = 0.9;
    m_window->setParams(infeasible);
    QTRY_VERIFY(!m_window->problem().isEmpty());
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("window.png"));
    QString error;
    QVERIFY2(m_window->saveWindowSnapshot(path, &error), qPrintable(error));
    const auto session = sessionFromJson(readAll(sessionPathFor(path)), Params{}, &error);
    QVERIFY2(session, qPrintable(error));
    QVERIFY(session->params == shown);
    QCOMPARE(session->params.m2, shown.m2);
    QVERIFY(session->params.m2 != infeasible.m2);
  }

  void sessionValuesOutsideTheControlsAreRejected() {
    QString error;
    const QByteArray json = R"({"format": "grazelab-session", "version": 1, "scene": "Grazing family GLO_lambda", "params": {"contacts": 5e7}})";
    QVERIFY(!sessionFromJson(json, Params{}, &error));
    QVERIFY2(error.contains(QStringLiteral("outside")), qPrintable(error));
    const QByteArray fraction = R"({"format": "grazelab-session", "version": 1, "scene": "Grazing family GLO_lambda", "params": {"contacts": 12.5}})";
    QVERIFY(!sessionFromJson(fraction, Params{}, &error));
  }

  void sessionRoundTrip() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("session.json"));
    const Params saved = m_window->params();
    QString error;
    QVERIFY2(m_window->saveSession(path, &error), qPrintable(error));
    QVERIFY(QFileInfo(path).size() > 0);

    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("1ipp")));
    m_window->setParams(m_window->scene().defaults());
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY2(m_window->openSession(path, &error), qPrintable(error));
    QCOMPARE(m_window->sceneIndex(), 0);
    QVERIFY(m_window->params() == saved);
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY(m_window->displayed()->request->params == saved);
  }

  void csvHasEveryPlottedPoint() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("data.csv"));
    QString error;
    QVERIFY2(m_window->exportCsv(path, &error), qPrintable(error));
    const QList<QByteArray> lines = readAll(path).split('\n');
    // the parameters first, in comment lines (in words, as a session, as a command line),
    // what each plot's columns mean, then the table
    QVERIFY(lines[0].startsWith("# GrazeLab: "));
    QVERIFY(lines[1].startsWith("# session: {"));
    QVERIFY(lines[2].startsWith("# the run again: grazelab-cli simulate "));
    const qsizetype columns = lines.indexOf(QByteArray("plot,series,x,y,value"));
    QVERIFY(columns > 3);
    for (qsizetype i = 3; i < columns; ++i) QVERIFY(lines[i].startsWith("# "));
    QVERIFY(lines[3].startsWith("# columns: "));
    const auto& samples = m_window->displayed()->result->samples;
    QVERIFY(lines.size() > qsizetype(samples.size()));
    // no series without a name
    for (qsizetype i = columns + 1; i < lines.size(); ++i) QVERIFY2(!lines[i].contains("\"\",") , lines[i].constData());
    QVERIFY(QFileInfo::exists(sessionPathFor(path)));
  }

  // a run started with the mouse (on H, the stop line, the map, the modes picture): every
  // export describes that run, its session reopens it bit for bit, and the CSV's command line
  // gives the same events from the command-line tool
  void exportsOfAClickedRunReproduceIt() {
    const grazelab::core::Model model = m_window->displayed()->request->job.spec.model;
    const double middle = model.k2 * model.gap / (model.k1 + model.k2);  // inside every level
    QVERIFY(m_window->startFromSection(QPointF(middle / model.gap, 0.0)));  // (as plotted: u1 / d)
    QVERIFY(waitForLatestFinal(*m_window));
    const grazelab::core::State clicked = m_window->displayed()->request->job.spec.run.initial;
    QVERIFY(m_window->displayed()->request->clickedStart.has_value());
    QVERIFY(grazelab::core::twoMassStateOf(*m_window->displayed()->request->clickedStart) == clicked);
    const std::vector<grazelab::core::Event> events = m_window->displayed()->result->events;
    QVERIFY(events.size() > 3);

    QTemporaryDir dir;
    const QString csvPath = dir.filePath(QStringLiteral("clicked.csv"));
    QString error;
    QVERIFY2(m_window->exportCsv(csvPath, &error), qPrintable(error));
    const QList<QByteArray> lines = readAll(csvPath).split('\n');
    QVERIFY2(lines[0].contains("from the clicked start"), lines[0].constData());
    QVERIFY(!lines[0].contains("λ ="));  // the scene's start does not describe this run
    const QByteArray command = lines[2].mid(QByteArray("# the run again: ").size());
    QVERIFY(command.contains("--state " + shortestText(clicked.u1).toUtf8() + ","));

    // the session beside it opens that run again, whatever the window shows meanwhile
    m_window->setParams(m_window->scene().defaults());
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY(!(m_window->displayed()->request->job.spec.run.initial == clicked));
    QVERIFY2(m_window->openSession(sessionPathFor(csvPath), &error), qPrintable(error));
    QVERIFY(waitForLatestFinal(*m_window));
    QVERIFY(m_window->displayed()->request->job.spec.run.initial == clicked);
    const auto& again = m_window->displayed()->result->events;
    QCOMPARE(again.size(), events.size());
    for (std::size_t i = 0; i < events.size(); ++i) QCOMPARE(again[i].t, events[i].t);
    QVERIFY(m_window->parameterPanel()->clickedStartText().contains(QStringLiteral("clicked start")));

    // the command line: the same events to the last bit
    const QString cli = qEnvironmentVariable("GRAZELAB_CLI");
    if (cli.isEmpty()) QSKIP("GRAZELAB_CLI is not set (run through ctest)");
    QStringList arguments = QString::fromUtf8(command).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    QCOMPARE(arguments.takeFirst(), QStringLiteral("grazelab-cli"));
    QProcess process;
    process.start(cli, arguments);
    QVERIFY(process.waitForFinished(60000));
    QCOMPARE(process.exitCode(), 0);
    const QJsonArray printed = QJsonDocument::fromJson(process.readAllStandardOutput()).object()
                                   .value(QStringLiteral("events")).toArray();
    QCOMPARE(qsizetype(printed.size()), qsizetype(events.size()));
    for (qsizetype i = 0; i < printed.size(); ++i) {
      QCOMPARE(printed[i].toObject().value(QStringLiteral("t")).toDouble(), events[std::size_t(i)].t);
      QCOMPARE(printed[i].toObject().value(QStringLiteral("u1")).toDouble(), events[std::size_t(i)].after.u1);
    }
  }

  // a chain of N masses (issue 33): its exports say the chain in words, carry it in their
  // session (which reopens the same run), and the CSV's command line gives the same events to
  // the last bit from the command-line tool
  void anNMassExportReproducesItsRun() {
    m_window->selectScene(findScene(m_window->scenes(), QStringLiteral("three-masses")));
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    // with a right wall (designed around it) and the section on (u2, v3): the export carries both
    Params walled = m_window->params();
    walled.massChain.rightSpring = 0.3;
    walled.massChain.sectionX = 2;
    walled.massChain.sectionY = 6;
    m_window->setParams(walled);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const auto series = shownChainRun(*m_window);
    QVERIFY(series && series->run.events.size() > 100);
    QCOMPARE(series->chain.rightSpring, 0.3);
    QTemporaryDir dir;
    const QString csvPath = dir.filePath(QStringLiteral("three.csv"));
    QString error;
    QVERIFY2(m_window->exportCsv(csvPath, &error), qPrintable(error));
    const QList<QByteArray> lines = readAll(csvPath).split('\n');
    QVERIFY2(lines[0].contains("masses (1, 0.2, 0.05)") && lines[0].contains("1:2:3") &&
                 lines[0].contains("right wall's k = 0.3"),
             lines[0].constData());
    QVERIFY2(!lines[0].contains("m₂ = "), lines[0].constData());
    const QByteArray command = lines[2].mid(QByteArray("# the run again: ").size());
    QVERIFY2(command.startsWith("grazelab-cli simulate --masses 1,0.2,0.05 --springs ") &&
                 command.contains(" --right-spring 0.3"),
             command.constData());

    // the session beside it reopens the same chain and run
    Params other = m_window->params();
    other.massChain.masses = {1.0, 0.25, 0.05};
    m_window->setParams(other);
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    QVERIFY2(m_window->openSession(sessionPathFor(csvPath), &error), qPrintable(error));
    QVERIFY(waitForLatestFinal(*m_window, 60000));
    const auto again = shownChainRun(*m_window);
    QVERIFY(again);
    QCOMPARE(again->chain.rightSpring, 0.3);
    QCOMPARE(m_window->params().massChain.sectionX, 2);
    QCOMPARE(m_window->params().massChain.sectionY, 6);
    QCOMPARE(again->run.events.size(), series->run.events.size());
    for (std::size_t i = 0; i < series->run.events.size(); ++i) QCOMPARE(again->run.events[i].t, series->run.events[i].t);

    const QString cli = qEnvironmentVariable("GRAZELAB_CLI");
    if (cli.isEmpty()) QSKIP("GRAZELAB_CLI is not set (run through ctest)");
    QStringList arguments = QString::fromUtf8(command).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    QCOMPARE(arguments.takeFirst(), QStringLiteral("grazelab-cli"));
    QProcess process;
    process.start(cli, arguments);
    QVERIFY(process.waitForFinished(60000));
    QCOMPARE(process.exitCode(), 0);
    const QJsonArray printed = QJsonDocument::fromJson(process.readAllStandardOutput()).object()
                                   .value(QStringLiteral("events")).toArray();
    QCOMPARE(qsizetype(printed.size()), qsizetype(series->run.events.size()));
    for (qsizetype i = 0; i < printed.size(); ++i) {
      const QJsonObject event = printed[i].toObject();
      QCOMPARE(event.value(QStringLiteral("t")).toDouble(), series->run.events[std::size_t(i)].t);
      QCOMPARE(event.value(QStringLiteral("u1")).toDouble(), series->run.events[std::size_t(i)].u[0]);
    }
  }

  // a window picture taken while the panel holds a refused value shows the run's parameters
  // in the panel, not the refused one beside plots of another chain; the panel keeps what was
  // typed afterwards
  void aWindowSnapshotIsOneState() {
    const Params shown = m_window->displayed()->request->params;
    Params refused = shown;
    refused.m2 = 0.9 * refused.m1;  // beyond 9/16: no 1:2 design
    m_window->setParams(refused);
    QVERIFY(!m_window->problem().isEmpty());
    // the panel as a picture of the window has it (saveWindowSnapshot draws through this)
    Params inPicture;
    QString messageInPicture = QStringLiteral("unset");
    m_window->withDisplayedRunInPanel([&] {
      inPicture = m_window->parameterPanel()->params();
      messageInPicture = m_window->parameterPanel()->message();
    });
    QVERIFY(inPicture == shown);
    QVERIFY(messageInPicture.isEmpty());
    QVERIFY(m_window->parameterPanel()->params() == refused);
    QVERIFY(!m_window->parameterPanel()->message().isEmpty());
    QTemporaryDir dir;
    QString error;
    QVERIFY2(m_window->saveWindowSnapshot(dir.filePath(QStringLiteral("w.png")), &error), qPrintable(error));
    QVERIFY(m_window->parameterPanel()->params() == refused);
  }

  void failedSaveSaysWhyAndKeepsEverything() {
    const Params before = m_window->params();
    QString error;
    QVERIFY(!m_window->saveWindowSnapshot(QStringLiteral("/nonexistent-dir/x/snap.png"), &error));
    QVERIFY(!error.isEmpty());
    error.clear();
    QVERIFY(!m_window->saveWindowSnapshot(QStringLiteral("/tmp/snap.bmpx"), &error));
    QVERIFY(error.contains(QStringLiteral(".png")));
    QVERIFY(!m_window->openSession(QStringLiteral("/nonexistent-dir/s.json"), &error));
    QVERIFY(m_window->params() == before);

    // an existing file survives a failed rewrite untouched
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("keep.json"));
    QVERIFY(saveFileAtomically(path, "{\"old\": true}", &error));
    QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::ExeOwner);
    const bool rewritten = saveFileAtomically(path, "new", &error);
    QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    if (!rewritten) QCOMPARE(readAll(path), QByteArray("{\"old\": true}"));  // root may write anyway

    // a folder that cannot be made (its "parent" is a file) fails even for root, and the file
    // in the way, the window and its session are left as they were
    const QString blocker = dir.filePath(QStringLiteral("notes.txt"));
    QVERIFY(saveFileAtomically(blocker, "keep me", &error));
    error.clear();
    QVERIFY(!m_window->saveWindowSnapshot(blocker + QStringLiteral("/snap.png"), &error));
    QVERIFY(!error.isEmpty());
    QVERIFY(!m_window->exportCsv(blocker + QStringLiteral("/data.csv"), &error));
    QVERIFY(!m_window->saveSession(blocker + QStringLiteral("/s.json"), &error));
    QCOMPARE(readAll(blocker), QByteArray("keep me"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::NoDotAndDotDot).size(), 2);
    QVERIFY(m_window->params() == before);
  }

  void malformedSessionIsRejected() {
    QString error;
    QVERIFY(!sessionFromJson("not json", Params{}, &error));
    QVERIFY(!error.isEmpty());
    QVERIFY(!sessionFromJson(R"({"format": "grazelab-session", "params": {"m1": "heavy"}})",
                             Params{}, &error));
    QVERIFY(error.contains(QStringLiteral("m1")));
    // a misspelt parameter is refused, not dropped for its default (another run)
    QVERIFY(!sessionFromJson(R"({"format": "grazelab-session", "params": {"horizon": 1000000}})", Params{}, &error));
    QVERIFY(error.contains(QStringLiteral("horizon")) && error.contains(QStringLiteral("contacts")));
    // a clicked start must be four finite numbers
    QVERIFY(!sessionFromJson(R"({"format": "grazelab-session", "params": {}, "start": {"u1": 0.1, "u2": 1}})",
                             Params{}, &error));
    QVERIFY(error.contains(QStringLiteral("v1")));
  }

 private:
  std::unique_ptr<MainWindow> m_window;
};

QTEST_MAIN(FilesTest)
#include "files_test.moc"
