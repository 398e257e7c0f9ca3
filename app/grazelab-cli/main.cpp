// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// grazelab-cli: the command line (docs/design.md "Command line"); cli_run.cpp parses and runs it.
// Exit 0 on success, 2 on invalid input with one line on stderr and nothing on stdout; an
// interrupted run (SIGINT, SIGTERM) ends its output cleanly and exits 130.
#include <QCoreApplication>
#include <QGuiApplication>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <cstring>
#include <memory>
#include <thread>

#include <signal.h>

#include "cli_run.h"

namespace {

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

}  // namespace

// The commands that draw pictures need a QGuiApplication (fonts); without a display it renders
// off screen. The other commands need Qt Core only. No widgets either way.
bool drawsPictures(int argc, char* argv[]) {
  for (int i = 1; i < argc; ++i) {
    for (const char* command : {"report", "map", "merge", "family", "modes", "glo-set"}) {
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
  if (drawsPictures(argc, argv)) {
    qInstallMessageHandler(quietQtMessages);
    if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr &&
        std::getenv("QT_QPA_PLATFORM") == nullptr) {
      setenv("QT_QPA_PLATFORM", "offscreen", 1);
    }
    application = std::make_unique<QGuiApplication>(argc, argv);
  }
  if (!application) application = std::make_unique<QCoreApplication>(argc, argv);
  QCoreApplication::setApplicationName("grazelab-cli");
  QCoreApplication::setApplicationVersion(grazelab::cli::kVersion);

  grazelab::cli::Io io;  // stdout and stderr
  return grazelab::cli::runCommandLine(QCoreApplication::arguments(), io, watcher.token());
}
