// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

class QTextStream;

namespace grazelab::ui {

/// Measures, for each scene, the time from a parameter change to the plots redrawn (worker
/// thread, decimation, series replace and a forced synchronous repaint), and the frames per
/// second during a simulated slider drag (one slider step every 8 ms for 2 s). Prints a table.
/// Not a test: figures depend on the machine. Returns 0.
int runLatencyBenchmark(QTextStream& out);

}  // namespace grazelab::ui
