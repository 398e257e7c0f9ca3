// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// grazelab-cli: `info`, `simulate`, `report` and `stability` (docs/design.md "Command line").
// Exit 0 on success, 2 on invalid input with one line on stderr and nothing on stdout; an
// interrupted run (SIGINT, SIGTERM) ends its output cleanly and exits 130.
#if GRAZELAB_CLI_PICTURES
#include <QApplication>
#endif
#include <QCommandLineParser>
#include <QCoreApplication>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <cstring>
#include <memory>
#include <thread>

#include <signal.h>

#include "cli_input.h"
#include "cli_output.h"
#include "core/trust.h"
#include "family_command.h"
#include "orbit_command.h"
#include "map_command.h"
#include "modes_command.h"
#include "report_command.h"
#include "simulate_command.h"

namespace {

constexpr int kInvalidInput = 2;
constexpr int kInterrupted = 130;

int fail(const QString& message) {
  std::fprintf(stderr, "grazelab-cli: %s\n", qPrintable(message.simplified()));
  return kInvalidInput;
}

// The end of a command that writes files: one line for invalid input (exit 2), a note for an
// interrupt (130: nothing written), the reason of a failed write.
int ended(int code, const QString& error) {
  if (code == kInvalidInput) return fail(error);
  if (code == kInterrupted) {
    std::fprintf(stderr, "grazelab-cli: interrupted: nothing written\n");
  } else if (code != 0) {
    std::fprintf(stderr, "grazelab-cli: %s\n", qPrintable(error));
  }
  return code;
}

void write(const QByteArray& bytes) { std::fwrite(bytes.constData(), 1, bytes.size(), stdout); }

// SIGINT and SIGTERM are blocked in every thread and taken by this watcher with sigtimedwait:
// no code runs in a signal handler, and the run is stopped through its stop token between
// contacts, so the output ends with complete records.
class InterruptWatcher {
 public:
  InterruptWatcher() {
    sigemptyset(&m_signals);
    sigaddset(&m_signals, SIGINT);
    sigaddset(&m_signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &m_signals, nullptr);
    m_thread = std::jthread([this](std::stop_token done) {
      const timespec poll{0, 50'000'000};
      while (!done.stop_requested()) {
        if (sigtimedwait(&m_signals, nullptr, &poll) > 0) {
          m_interrupted = true;
          m_source.request_stop();
          return;
        }
      }
    });
  }
  std::stop_token token() const { return m_source.get_token(); }
  bool interrupted() const { return m_interrupted; }

 private:
  sigset_t m_signals;
  std::stop_source m_source;
  std::atomic<bool> m_interrupted = false;
  std::jthread m_thread;
};

template <typename S>
int info(const QCommandLineParser& parser) {
  const auto model = grazelab::cli::parseModel<S>(parser);
  if (!model.value) return fail(model.error);
  write(QByteArray::fromStdString(grazelab::cli::infoJson(*model.value)));
  return 0;
}

}  // namespace

// `report` draws its pictures with Qt Charts, which needs a QApplication; without a display it
// renders off screen. The other commands need Qt Core only.
bool drawsPictures(int argc, char* argv[]) {
  for (int i = 1; i < argc; ++i) {
    for (const char* command : {"report", "map", "merge", "family", "modes"}) {
      if (std::strcmp(argv[i], command) == 0) return true;
    }
  }
  return false;
}

// The off-screen platform's chatter (XDG_RUNTIME_DIR not set, size hints) would break the
// contract of one line on stderr for an error: only Qt's critical messages get through.
void quietQtMessages(QtMsgType type, const QMessageLogContext&, const QString& message) {
  if (type == QtCriticalMsg || type == QtFatalMsg) {
    std::fprintf(stderr, "grazelab-cli: Qt: %s\n", qPrintable(message));
  }
}

int main(int argc, char* argv[]) {
  InterruptWatcher watcher;  // first: its signal mask is inherited by every later thread
  std::unique_ptr<QCoreApplication> application;
#if GRAZELAB_CLI_PICTURES
  if (drawsPictures(argc, argv)) {
    qInstallMessageHandler(quietQtMessages);
    if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr &&
        std::getenv("QT_QPA_PLATFORM") == nullptr) {
      setenv("QT_QPA_PLATFORM", "offscreen", 1);
    }
    application = std::make_unique<QApplication>(argc, argv);
  }
#endif
  if (!application) application = std::make_unique<QCoreApplication>(argc, argv);
  QCoreApplication::setApplicationName("grazelab-cli");
  QCoreApplication::setApplicationVersion("0.2.0");

  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Exact event-driven simulation of a 2-dof chain against a rigid stop in 1:2 internal "
      "resonance.\nCommands: info (the model and its derived quantities), simulate (a run), "
      "report (every method against the exact solver: error against run time, --out DIR), "
      "stability (every method on stiff and extreme cases, --out DIR), map (a 2-D grid of runs "
      "reduced to summaries: --x, --y, --out PREFIX), merge (join a map's stripes: --out PREFIX "
      "PART1 ... PARTN), family --onepp (the 1IPP family: --out PREFIX), orbit (one periodic impacting orbit with its "
      "exact multipliers: --onepp --period T, or --impacts K --energy E --guess U1,V1), modes (the "
      "atlas of the chain's periodic impacting families up to --max-impacts K: --out PREFIX).");
  parser.addPositionalArgument("command", "info | simulate | report | stability | map | merge | family | orbit | modes");
  const QCommandLineOption help = parser.addHelpOption();
  const QCommandLineOption version = parser.addVersionOption();
  grazelab::cli::addOptions(parser);
  grazelab::cli::addReportOptions(parser);
  grazelab::cli::addMapOptions(parser);
  grazelab::cli::addOrbitOptions(parser);
  grazelab::cli::addModesOptions(parser);

  // `family --onepp` and `orbit --onepp` name the family: the option takes no period there
  QStringList arguments = QCoreApplication::arguments();
  for (const QString& command : {QStringLiteral("family"), QStringLiteral("orbit")}) {
    if (!arguments.contains(command)) continue;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
      const bool bare = arguments[i] == "--onepp" &&
                        (i + 1 == arguments.size() || arguments[i + 1].startsWith("--") ||
                         arguments[i + 1] == command);
      if (bare) arguments[i] = "--onepp=" + command;
    }
  }
  if (!parser.parse(arguments)) return fail(parser.errorText());
  if (parser.isSet(help)) {
    write(parser.helpText().toUtf8());
    return 0;
  }
  if (parser.isSet(version)) {
    write("grazelab-cli 0.2.0\n");
    return 0;
  }
  const QStringList repeated = grazelab::cli::repeatedOptions(parser);
  if (!repeated.isEmpty()) {
    return fail(repeated.join(", ") + " given more than once: give each option once");
  }
  const QStringList positional = parser.positionalArguments();
  if (!positional.isEmpty() && positional.first() == "merge") {
    QString error;
    return ended(grazelab::cli::runMerge(parser, positional.mid(1), watcher.token(), error), error);
  }
  if (positional.size() != 1) {
    return fail("expected one command: info, simulate, report, stability, map, merge, family, orbit or modes (see --help)");
  }
  const QString command = positional.first();
  if (command == "modes") {
    QString error;
    return ended(grazelab::cli::runModes(parser, watcher.token(), error), error);
  }
  if (command == "orbit") {
    QString error;
    const int code = grazelab::cli::runOrbit(parser, watcher.token(), error);
    if (code == kInvalidInput) return fail(error);
    return code;
  }
  const QStringList orbitOnly = grazelab::cli::orbitOnlyOptionsSet(parser);
  if (!orbitOnly.isEmpty()) return fail(orbitOnly.join(", ") + " only apply to 'orbit'");
  if (command == "map") {
    QString error;
    return ended(grazelab::cli::runMap(parser, watcher.token(), error), error);
  }
  if (command == "family") {
    QString error;
    return ended(grazelab::cli::runFamily(parser, watcher.token(), error), error);
  }
  const QStringList mapOnly = grazelab::cli::mapOnlyOptionsSet(parser);
  if (!mapOnly.isEmpty()) return fail(mapOnly.join(", ") + " only apply to 'map' (--count to 'family')");
  if (command == "report" || command == "stability") {
    QString error;
    const int code = command == "report" ? grazelab::cli::runReport(parser, watcher.token(), error)
                                         : grazelab::cli::runStability(parser, watcher.token(), error);
    if (code == grazelab::cli::kExitInvalidInput) return fail(error);
    if (code == grazelab::cli::kExitInterrupted) {
      std::fprintf(stderr, "grazelab-cli: interrupted: nothing written\n");
    }
    if (code != 0 && !error.isEmpty()) std::fprintf(stderr, "grazelab-cli: %s\n", qPrintable(error));
    return watcher.interrupted() ? kInterrupted : code;
  }
  const QStringList reportOnly = grazelab::cli::reportOnlyOptionsSet(parser);
  if (!reportOnly.isEmpty()) {
    return fail(reportOnly.join(", ") + " only apply to 'report' and 'stability'");
  }
  QString error;
  const auto precision = grazelab::cli::parsePrecisionOption(parser, error);
  if (!precision) return fail(error);
  const auto trust = grazelab::cli::parseTrustOption(parser, error);
  if (!trust) return fail(error);

  using grazelab::core::Precision;
  if (command == "info") {
    const QStringList extra = grazelab::cli::simulateOnlyOptionsSet(parser);
    if (!extra.isEmpty()) return fail(extra.join(", ") + " only apply to 'simulate'");
    switch (precision->fixed.value_or(Precision::Double)) {
      case Precision::Double:
        return info<double>(parser);
      case Precision::Long:
        return info<long double>(parser);
      case Precision::Quad:
        return info<grazelab::core::Quad>(parser);
    }
  }
  if (command == "simulate") {
    QString error;
    const int code = grazelab::cli::runSimulate(parser, *precision, *trust, watcher.token(), error);
    return code == kInvalidInput ? fail(error) : code;
  }
  return fail(QStringLiteral("unknown command '%1': use info, simulate, report, stability, map, merge, family, orbit or modes").arg(command));
}
