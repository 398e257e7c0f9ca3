// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The explorer: argument parsing and wiring only (ui/ does the work).
#include <QApplication>
#include <QMessageBox>
#include <QScreen>
#include <QCommandLineParser>
#include <QTextStream>

#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "core/version.h"
#include "ui/window/headless.h"
#include "ui/window/latency_bench.h"
#include "ui/window/main_window.h"

namespace {

// QGuiApplication takes "-session"/"--session" for X11 session management and removes it from
// the arguments, so ours is renamed before Qt sees it.
std::vector<std::string> renameSessionOption(int argc, char* argv[]) {
  std::vector<std::string> arguments(argv, argv + argc);
  for (std::string& argument : arguments) {
    for (const char* prefix : {"--session", "-session"}) {
      const std::string_view text(argument);
      const std::size_t length = std::strlen(prefix);
      if (text.substr(0, length) == prefix && (text.size() == length || text[length] == '=')) {
        argument = "--session-file" + argument.substr(length);
        break;
      }
    }
  }
  return arguments;
}

// True when the arguments ask for headless work (a snapshot, the scene list, the help or the
// version: none of them needs a display, and on a machine without one they must still answer).
bool headlessRequested(int argc, char* argv[]) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument(argv[i]);
    for (std::string_view option : {"--snapshot", "-snapshot", "--list-scenes", "-list-scenes"}) {
      if (argument.substr(0, option.size()) == option) return true;
    }
    for (std::string_view option : {"--help", "-help", "-h", "-?", "--help-all", "--version", "-v"}) {
      if (argument == option) return true;
    }
  }
  return false;
}

}  // namespace

int main(int argc, char* argv[]) {
  // headless work needs no display: render offscreen unless the user chose a platform
  if (headlessRequested(argc, argv) && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
  }
  std::vector<std::string> arguments = renameSessionOption(argc, argv);
  std::vector<char*> pointers;
  for (std::string& argument : arguments) pointers.push_back(argument.data());
  pointers.push_back(nullptr);
  int count = argc;
  QApplication app(count, pointers.data());
  QApplication::setOrganizationName(QStringLiteral("GrazeLab"));
  QApplication::setApplicationName(QStringLiteral("grazelab"));
  QApplication::setApplicationDisplayName(QStringLiteral("GrazeLab"));
  QApplication::setApplicationVersion(QString::fromUtf8(grazelab::kVersion));

  QCommandLineParser parser;
  parser.setApplicationDescription(QApplication::translate(
      "main", "Explore chains of masses against a rigid stop: the two-mass chain in 1:2 internal "
              "resonance, and chains of N masses in any resonance."));
  parser.addHelpOption();
  parser.addVersionOption();
  const QCommandLineOption listScenes(QStringLiteral("list-scenes"),
                                      QApplication::translate("main", "Print the scenes, one per line: the id --scene takes, "
                                                                      "its shortcut and its title."));
  const QCommandLineOption scene(QStringLiteral("scene"),
                                 QApplication::translate("main", "Scene to open or render."),
                                 QStringLiteral("NAME"));
  const QCommandLineOption session(QStringList{QStringLiteral("session"), QStringLiteral("session-file")},
                                   QApplication::translate("main", "Session file (JSON) to open."),
                                   QStringLiteral("FILE"));
  const QCommandLineOption snapshot(
      QStringLiteral("snapshot"),
      QApplication::translate("main", "Render the scene to a .png, .svg or .pdf file and exit."),
      QStringLiteral("FILE"));
  const QCommandLineOption size(QStringLiteral("size"),
                                QApplication::translate("main", "Snapshot size in pixels, WxH."),
                                QStringLiteral("WxH"), QStringLiteral("1600x1000"));
  const QCommandLineOption bench(QStringLiteral("bench"),
                                 QApplication::translate("main", "Measure plot latency and drag frame rate (of every "
                                                                 "scene, or of the one named by --scene)."));
  const QCommandLineOption presentation(
      QStringLiteral("presentation"),
      QApplication::translate("main", "Open in presentation mode (full screen, large text; F5 "
                                      "toggles it); with --snapshot, render that look."));
  parser.addOptions({listScenes, scene, session, snapshot, size, bench, presentation});
  parser.process(app);

  QTextStream out(stdout);
  QTextStream err(stderr);
  if (parser.isSet(listScenes)) {
    for (const QString& line : grazelab::ui::sceneList()) out << line << '\n';
    return 0;
  }
  if (parser.isSet(bench)) return grazelab::ui::runLatencyBenchmark(out, parser.value(scene));
  if (parser.isSet(snapshot)) {
    const QStringList parts = parser.value(size).split(QLatin1Char('x'));
    const QSize pixels = parts.size() == 2 ? QSize(parts[0].toInt(), parts[1].toInt()) : QSize();
    if (pixels.width() < 200 || pixels.height() < 150) {
      err << "grazelab: --size must be WxH with W >= 200 and H >= 150\n";
      return 2;
    }
    if (!parser.isSet(scene) && !parser.isSet(session)) {
      err << "grazelab: --snapshot needs --scene NAME or --session FILE\n";
      return 2;
    }
    QString error;
    if (!grazelab::ui::renderSceneSnapshot(parser.value(scene), parser.value(session),
                                           parser.value(snapshot), pixels, &error,
                                           parser.isSet(presentation))) {
      err << "grazelab: " << error << '\n';
      return 1;
    }
    return 0;
  }

  grazelab::ui::MainWindow window({});
  // a session or scene the window cannot open is said on stderr at once (the stream is flushed
  // here, not at exit) and in a dialog over the window, which opens on what it had
  QStringList problems;
  QString error;
  if (parser.isSet(session) && !window.openSession(parser.value(session), &error)) {
    problems << QApplication::translate("main", "Cannot open the session: %1").arg(error);
  }
  if (parser.isSet(scene)) {
    const int index = grazelab::ui::findScene(window.scenes(), parser.value(scene));
    if (index < 0) {
      problems << QApplication::translate("main", "Unknown scene \"%1\" (see --list-scenes)")
                      .arg(parser.value(scene));
    } else {
      window.selectScene(index);
    }
  }
  for (const QString& problem : problems) err << "grazelab: " << problem << Qt::endl;
  window.show();
  if (parser.isSet(presentation)) {
    const QScreen* screen = window.screen();
    window.setPresentation(true, screen ? screen->geometry().height() : 1080, true);
  }
  if (!problems.isEmpty()) {
    QMessageBox::warning(&window, QApplication::translate("main", "GrazeLab"),
                         problems.join(QStringLiteral("\n\n")));
  }
  return app.exec();
}
