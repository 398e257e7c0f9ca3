// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// grazelab-cli: `info`, `simulate`, `report` and `stability` (DESIGN.md "Command line"). Exit 0 on success, 2 on
// invalid input with one line on stderr and nothing on stdout; an interrupted run (SIGINT,
// SIGTERM) ends its output cleanly and exits 130.
#if GRAZELAB_CLI_PICTURES
#include <QApplication>
#endif
#include <QCommandLineParser>
#include <QCoreApplication>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <cstring>
#include <memory>
#include <thread>
#include <vector>

#include <signal.h>
#include <unistd.h>

#include "cli_input.h"
#include "cli_output.h"
#include "core/simulate.h"
#include "core/trust.h"
#include "family_command.h"
#include "map_command.h"
#include "report_command.h"

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

// Progress of a long run on stderr, when stderr is a terminal: contacts, simulated time, rate
// and, where the run is bounded, the time left; once a second, on one line rewritten in place.
class ProgressLine {
 public:
  bool enabled() const { return m_enabled; }
  void show(std::int64_t contacts, double simulatedTime, double fraction,
            const std::string& precision) {
    const double elapsed = seconds(m_started);
    if (!m_enabled || elapsed - m_lastShown < 1.0) return;
    m_lastShown = elapsed;
    const double rate = double(contacts) / elapsed;
    char left[64] = "";
    if (fraction > 0 && fraction < 1) {
      std::snprintf(left, sizeof left, ", %.0f%%, about %.0f s left", 100 * fraction,
                    elapsed * (1 - fraction) / fraction);
    }
    std::fprintf(stderr, "\r\033[Kgrazelab-cli: %lld contacts, t = %.6g, %.3g contacts/s (%s)%s",
                 static_cast<long long>(contacts), simulatedTime, rate, precision.c_str(), left);
    std::fflush(stderr);
    m_shown = true;
  }
  void clear() {
    if (m_shown) std::fprintf(stderr, "\r\033[K");
    m_shown = false;
  }

 private:
  static double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
  }
  bool m_enabled = isatty(STDERR_FILENO) != 0;
  bool m_shown = false;
  std::chrono::steady_clock::time_point m_started = std::chrono::steady_clock::now();
  double m_lastShown = 0;
};

// A run of --precision auto in progress: what its output holds so far, so that a run raised to
// a higher precision (again from its input) goes on where the lower one stopped writing.
struct AutoRun {
  bool begun = false;          ///< the output's head is written
  std::int64_t written = 0;    ///< events written
  grazelab::core::EventType lastType = grazelab::core::EventType::Impact;
  long double lastTime = 0;    ///< time of the last event written
  std::vector<std::string> escalations;
  std::string mismatch;        ///< the raised run disagrees with an event already written
  // the error estimate of the events written by a lower precision (its shadow, up to the raise):
  // they stay on the output, so the final estimate is at least theirs
  std::int64_t writtenBeforeRaise = 0;
  double writtenStateError = 0;
  double writtenTimeError = 0;
};
// simulate<S> stopped at a contact S cannot decide: run again one precision up
constexpr int kRaisePrecision = -1;

template <typename S>
int simulate(const QCommandLineParser& parser, InterruptWatcher& watcher,
             grazelab::core::TrustMode trustMode, AutoRun* autoRun) {
  using namespace grazelab;
  constexpr bool kTopPrecision = std::is_same_v<S, core::Quad>;
  const std::string precisionName(core::toString(core::precisionOf<S>()));
  auto parsed = cli::parseRun<S>(parser);
  if (!parsed.value) {
    // a chain or start beyond this precision's reach (its refusal names --precision): auto
    // goes higher
    if (autoRun && !kTopPrecision && !autoRun->begun && parsed.error.contains("--precision")) {
      autoRun->escalations.push_back("from " + precisionName + ": " + parsed.error.toStdString());
      return kRaisePrecision;
    }
    return fail(parsed.error);
  }
  cli::RunInput<S>& run = *parsed.value;
  run.request.stopAtUndecided = autoRun != nullptr && !kTopPrecision;
  cli::RunWriter<S> writer(run, stdout, autoRun ? std::string("auto") : precisionName);
  // the error estimate: the same input read one precision up, run beside this one
  std::optional<core::TrustMonitor<S>> monitor;
  std::string noShadow;
  if (trustMode != core::TrustMode::Off) {
    const auto shadow = cli::parseRun<core::ShadowScalar<S>>(parser);
    if (shadow.value) {
      monitor.emplace(shadow.value->model.model, shadow.value->request, trustMode,
                      watcher.token(), cli::exactParameters<core::ShadowScalar<S>>(parser));
    } else {
      noShadow = "no shadow run: " + shadow.error.toStdString();
    }
  }
  // a raised run computes the events already written again: they are checked, not rewritten
  const std::int64_t alreadyWritten = autoRun ? autoRun->written : 0;
  const long double period = static_cast<long double>(S(core::twoPi<S>() / run.model.chain.omegaSlow));
  std::int64_t index = 0;
  run.request.onEvent = [&](const core::BasicEvent<S>& event) {
    ++index;
    if (monitor) monitor->observe(event);
    if (index == alreadyWritten && autoRun->mismatch.empty()) {
      const long double t = static_cast<long double>(event.t);
      if (event.type != autoRun->lastType || std::fabs(t - autoRun->lastTime) > 1e-6L * period) {
        autoRun->mismatch = "event " + std::to_string(index) + " as written before the raise to " +
                            precisionName + " differs from the " + precisionName + " run";
      }
    }
    if (index <= alreadyWritten) return;
    writer.event(event);
    if (autoRun) {
      autoRun->written = index;
      autoRun->lastType = event.type;
      autoRun->lastTime = static_cast<long double>(event.t);
    }
  };
  core::BasicSimulator<S> simulator(run.model.model, run.request);
  if (simulator.result().stop == core::StopReason::InvalidInput) {
    // a chain beyond this precision's reach (its refusal names --precision): auto goes higher
    const std::string& message = simulator.result().message;
    if (autoRun && !kTopPrecision && !autoRun->begun &&
        message.find("--precision") != std::string::npos) {
      autoRun->escalations.push_back("from " + precisionName + ": " + message);
      return kRaisePrecision;
    }
    return fail(QString::fromStdString(message));
  }
  if (!core::isFinite(simulator.result().initialEnergy)) {
    if (autoRun && !kTopPrecision) {
      autoRun->escalations.push_back("from " + precisionName +
                                     ": the energy of this start is beyond its range");
      return kRaisePrecision;
    }
    return fail("the energy of this start is beyond the range of this precision (try "
                "--precision long or quad, whose range is wider)");
  }
  if (!autoRun || !autoRun->begun) {
    for (const std::string& note : run.notes) {
      std::fprintf(stderr, "grazelab-cli: note: %s\n", note.c_str());
    }
    writer.begin(simulator.result());
    if (autoRun) autoRun->begun = true;
  } else {
    writer.resumeAfter(autoRun->written);
  }
  ProgressLine progress;
  while (!simulator.advance(progress.enabled() ? 65536 : std::numeric_limits<std::int64_t>::max(),
                            watcher.token())) {
    progress.show(simulator.result().cost.contacts,
                  core::toDouble(simulator.scale().toPhysicalTime(simulator.state().tau)),
                  simulator.progress(), precisionName);
  }
  progress.clear();
  if (simulator.result().stop == core::StopReason::Undecided) {
    autoRun->escalations.push_back("from " + precisionName + ": " + simulator.result().message);
    if (monitor && autoRun->written > alreadyWritten) {
      const core::Trust written = monitor->finish(simulator.result());
      autoRun->writtenBeforeRaise = autoRun->written;
      autoRun->writtenStateError = std::max(autoRun->writtenStateError, written.stateError);
      autoRun->writtenTimeError = std::max(autoRun->writtenTimeError, written.timeError);
    }
    return kRaisePrecision;
  }
  core::Trust trust;
  if (monitor) {
    trust = monitor->finish(simulator.result());
  } else {
    trust.reason = noShadow.empty() ? "not estimated (--trust off)" : noShadow;
    core::accountForUndecidedTouches(trust, simulator.result());
  }
  if (autoRun && autoRun->writtenBeforeRaise > 0 && trust.verdict != core::Verdict::Unchecked) {
    trust.stateError = std::max(trust.stateError, autoRun->writtenStateError);
    trust.timeError = std::max(trust.timeError, autoRun->writtenTimeError);
    const double worst = std::max(trust.stateError, trust.timeError);
    if (trust.verdict == core::Verdict::Ok && worst > core::kOkTolerance) {
      trust.verdict = worst > core::kHorizonTolerance ? core::Verdict::Unreliable
                                                      : core::Verdict::Degraded;
    }
    char note[160];
    std::snprintf(note, sizeof note,
                  "events 1 to %lld were written before the raise, in a lower precision "
                  "(estimated error %.2g)",
                  static_cast<long long>(autoRun->writtenBeforeRaise),
                  std::max(autoRun->writtenStateError, autoRun->writtenTimeError));
    trust.reason = std::string(note) + "; " + trust.reason;
  }
  if (autoRun && !autoRun->mismatch.empty()) {
    trust.verdict = core::Verdict::Unreliable;
    trust.reason = autoRun->mismatch + "; " + trust.reason;
  }
  cli::PrecisionReport precision{autoRun ? "auto" : precisionName, precisionName,
                                 autoRun ? autoRun->escalations : std::vector<std::string>{}};
  writer.end(simulator.result(), watcher.interrupted(), trust, precision);
  return watcher.interrupted() ? kInterrupted : 0;
}

}  // namespace

// `report` draws its pictures with Qt Charts, which needs a QApplication; without a display it
// renders off screen. The other commands need Qt Core only.
bool drawsPictures(int argc, char* argv[]) {
  for (int i = 1; i < argc; ++i) {
    for (const char* command : {"report", "map", "merge", "family"}) {
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
      "PART1 ... PARTN), family --onepp (the 1IPP family: --out PREFIX).");
  parser.addPositionalArgument("command", "info | simulate | report | stability | map | merge | family");
  const QCommandLineOption help = parser.addHelpOption();
  const QCommandLineOption version = parser.addVersionOption();
  grazelab::cli::addOptions(parser);
  grazelab::cli::addReportOptions(parser);
  grazelab::cli::addMapOptions(parser);

  // `family --onepp` names the family: the option takes no period there
  QStringList arguments = QCoreApplication::arguments();
  if (arguments.contains("family")) {
    for (qsizetype i = 0; i < arguments.size(); ++i) {
      const bool bare = arguments[i] == "--onepp" &&
                        (i + 1 == arguments.size() || arguments[i + 1].startsWith("--") ||
                         arguments[i + 1] == "family");
      if (bare) arguments[i] = "--onepp=family";
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
    return fail("expected one command: info, simulate, report, stability, map, merge or family (see --help)");
  }
  const QString command = positional.first();
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
    if (!precision->fixed) {
      // auto: double, and from the input again one precision up while a contact needs it
      AutoRun autoRun;
      int code = simulate<double>(parser, watcher, *trust, &autoRun);
      if (code == kRaisePrecision) code = simulate<long double>(parser, watcher, *trust, &autoRun);
      if (code == kRaisePrecision) {
        code = simulate<grazelab::core::Quad>(parser, watcher, *trust, &autoRun);
      }
      return code;
    }
    switch (*precision->fixed) {
      case Precision::Double:
        return simulate<double>(parser, watcher, *trust, nullptr);
      case Precision::Long:
        return simulate<long double>(parser, watcher, *trust, nullptr);
      case Precision::Quad:
        return simulate<grazelab::core::Quad>(parser, watcher, *trust, nullptr);
    }
  }
  return fail(QStringLiteral("unknown command '%1': use info, simulate, report, stability, map, merge or family").arg(command));
}
