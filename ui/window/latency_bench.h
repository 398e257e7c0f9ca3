// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

class QTextStream;

namespace grazelab::ui {

/// Measures, for each scene, the time from a parameter change to the plots redrawn (worker
/// thread, decimation, series replace and the paint the event loop then does), and the frames per
/// second during a simulated slider drag (one slider step every 8 ms for 2 s). Prints a table.
/// Not a test: figures depend on the machine. `onlyScene` (a name or alias) limits it to one
/// scene (the 10^6-point pan runs with near grazing). Returns 0, or 2 for an unknown scene.
int runLatencyBenchmark(QTextStream& out, const QString& onlyScene = {});

}  // namespace grazelab::ui
