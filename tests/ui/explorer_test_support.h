// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Helpers shared by the ui tests.
#pragma once

#include <QDeadlineTimer>
#include <QSignalSpy>
#include <QTest>

#include <memory>

#include "ui/window/main_window.h"
#include "ui/compute/sim_controller.h"

namespace grazelab::ui::testing {

/// Waits until the plots show the final result of the latest request.
inline bool waitForLatestFinal(MainWindow& window, int timeoutMs = 20000) {
  QDeadlineTimer deadline(timeoutMs);
  while (!deadline.hasExpired()) {
    const SimUpdate* shown = window.displayed();
    if (shown && shown->final && shown->id == window.controller()->latestId() &&
        !window.controller()->busy()) {
      return true;
    }
    QTest::qWait(5);
  }
  return false;
}

/// The N-mass run the window shows (the experiment's first chain run), or none.
inline std::shared_ptr<const core::experiments::ChainSeries> shownChainRun(const MainWindow& window) {
  const SimUpdate* shown = window.displayed();
  return shown && !shown->chains.empty() ? shown->chains.front() : nullptr;
}

/// A shown explorer window that keeps no settings, sized for the tests' plots.
inline std::unique_ptr<MainWindow> openTestWindow() {
  auto window = std::make_unique<MainWindow>(
      MainWindow::Options{.synchronous = false, .useSettings = false});
  window->resize(1400, 900);
  window->show();
  return window;
}

}  // namespace grazelab::ui::testing
