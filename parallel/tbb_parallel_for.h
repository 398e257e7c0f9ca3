// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "core/experiments/maps.h"

namespace grazelab::parallel {

/// A core::ParallelFor on oneTBB: the pieces run on `threads` threads of a task arena (0: all
/// cores). Core starts no thread itself; the command line and the explorer hand it this one.
core::ParallelFor tbbParallelFor(int threads);

/// The number of threads tbbParallelFor(0) uses.
int defaultThreadCount();

}  // namespace grazelab::parallel
