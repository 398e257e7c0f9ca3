// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include "core/experiments/chain_series.h"
#include "core/experiments/run.h"

namespace grazelab::ui {

/// The command line that runs a shown run again with the command-line tool:
///   grazelab-cli simulate --m1 … --m2 … --k1 … --gap … (--branch B | --k2 …)
///                         --state u1,u2,v1,v2 (--contacts N | --t-end T)
/// the chain, the start the run used (a clicked one included) and its length, numbers in their
/// shortest round-trip form; the precision is `auto`, the explorer's rule, so the events are
/// the same to the last bit.
QString simulateCommand(const core::experiments::Spec& spec);

/// The same for a run of a chain of N masses:
///   grazelab-cli simulate --masses … --springs … [--right-spring K] --stop-mass S --gap D
///                         --state u1,…,uN,v1,…,vN --contacts N
/// with the springs the run used (designed ones as numbers), in double as the explorer runs it.
QString chainSimulateCommand(const core::experiments::ChainSeries& series);

}  // namespace grazelab::ui
