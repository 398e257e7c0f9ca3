// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for app/grazelab/main.cpp and ui/window/headless.cpp: the executable lists scenes and renders
// each one to a picture without a display.
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QTest>

#include "ui/compute/params.h"
#include "ui/window/session.h"

using namespace grazelab::ui;

namespace {

struct Run {
  int exitCode = -1;
  QByteArray out;
  QByteArray err;
};

Run runApp(const QStringList& arguments) {
  QProcess process;
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
  process.setProcessEnvironment(environment);
  process.start(qEnvironmentVariable("GRAZELAB_APP"), arguments);
  if (!process.waitForFinished(120'000)) return {};
  return {process.exitCode(), process.readAllStandardOutput(), process.readAllStandardError()};
}

QStringList listScenes() {
  const Run run = runApp({QStringLiteral("--list-scenes")});
  return QString::fromUtf8(run.out).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

// the first word of each line: what --scene takes
QStringList listSceneIds() {
  QStringList ids;
  for (const QString& line : listScenes()) ids.append(line.section(QLatin1Char(' '), 0, 0));
  return ids;
}

}  // namespace

class HeadlessTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { QVERIFY2(!qEnvironmentVariableIsEmpty("GRAZELAB_APP"), "set GRAZELAB_APP"); }

  // the list printed the long names, which --scene also takes but nobody types: it prints the
  // ids --scene takes, with the titles as the menu shows them
  void listsScenesOnePerLine() {
    const QStringList lines = listScenes();
    QCOMPARE(lines.size(), qsizetype(15));  // the note's ten, then the five of N masses
    QVERIFY2(lines.first().startsWith(QStringLiteral("grazing ")), qPrintable(lines.first()));
    QVERIFY(lines.first().contains(QStringLiteral("Ctrl+1")));
    QVERIFY(lines[8].contains(QStringLiteral("Accuracy: methods against the exact solver")));
    QVERIFY2(lines[9].startsWith(QStringLiteral("modes ")) && lines[9].contains(QStringLiteral("Ctrl+M")),
             qPrintable(lines[9]));
    QVERIFY2(lines.last().startsWith(QStringLiteral("modes-three ")) && lines.last().contains(QStringLiteral("Alt+5")),
             qPrintable(lines.last()));
    const QStringList ids = listSceneIds();
    for (const char* id : {"grazing", "1ipp", "perturbations", "random-starts", "sticking",
                           "detuned", "near-grazing", "landscape", "accuracy", "modes",
                           "three-masses", "grazing-sets", "chain-1ipp", "eight-masses", "modes-three"}) {
      QVERIFY2(ids.contains(QString::fromLatin1(id)), id);
    }
  }

  void rendersEveryScene_data() {
    QTest::addColumn<bool>("presentation");
    QTest::newRow("desk") << false;
    QTest::newRow("presentation") << true;
  }

  void rendersEveryScene() {
    QFETCH(bool, presentation);
    QTemporaryDir dir;
    int index = 0;
    for (const QString& scene : listSceneIds()) {
      const QString path = dir.filePath(QStringLiteral("scene%1.png").arg(index++));
      QStringList arguments{QStringLiteral("--scene"), scene, QStringLiteral("--snapshot"), path,
                            QStringLiteral("--size"), QStringLiteral("1200x800")};
      if (presentation) arguments << QStringLiteral("--presentation");
      const Run run = runApp(arguments);
      QVERIFY2(run.exitCode == 0, run.err.constData());
      QVERIFY2(!run.err.contains("QFont"), run.err.constData());
      const QImage image(path);
      QCOMPARE(image.size(), QSize(2400, 1600));
      QVERIFY(QFileInfo::exists(sessionPathFor(path)));
    }
  }

  void rendersVectorFormats() {
    QTemporaryDir dir;
    for (const QString& name : {QStringLiteral("a.svg"), QStringLiteral("a.pdf")}) {
      const Run run = runApp({QStringLiteral("--scene"), QStringLiteral("grazing"),
                              QStringLiteral("--snapshot"), dir.filePath(name)});
      QVERIFY2(run.exitCode == 0, run.err.constData());
      QVERIFY(QFileInfo(dir.filePath(name)).size() > 1000);
    }
  }

  void sessionDecidesTheParameters() {
    QTemporaryDir dir;
    Session session;
    session.scene = QStringLiteral("Grazing family GLO_lambda");
    session.params.lambda = 1.25;
    session.params.gap = 0.5;
    session.params.horizon = 25;
    QFile file(dir.filePath(QStringLiteral("in.json")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(sessionToJson(session));
    file.close();
    const QString out = dir.filePath(QStringLiteral("out.png"));
    const Run run = runApp({QStringLiteral("--session"), file.fileName(),
                            QStringLiteral("--snapshot"), out});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QFile written(sessionPathFor(out));
    QVERIFY(written.open(QIODevice::ReadOnly));
    QString error;
    const auto reread = sessionFromJson(written.readAll(), Params{}, &error);
    QVERIFY2(reread, qPrintable(error));
    QVERIFY(reread->params == session.params);
  }

  void unknownSceneFails() {
    QTemporaryDir dir;
    const Run run = runApp({QStringLiteral("--scene"), QStringLiteral("no such scene"),
                            QStringLiteral("--snapshot"), dir.filePath(QStringLiteral("x.png"))});
    QVERIFY(run.exitCode != 0);
    QVERIFY(run.err.contains("unknown scene"));
    QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("x.png"))));
  }
};

QTEST_GUILESS_MAIN(HeadlessTest)
#include "headless_test.moc"
