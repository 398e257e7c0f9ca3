// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>
#include <QJsonObject>

#include "cli_input.h"
#include "core/modes.h"
#include "core/simulate.h"

namespace grazelab::cli {

/// The `model` object: parameters and derived quantities (k2, w1, w2, T1, T2, P, lambda*).
QJsonObject modelJson(const ModelInput& input, const core::Modes& modes);

/// `simulate --format json`: model, events, final, energy, timing (DESIGN.md).
QByteArray simulationJson(const RunInput& run, const core::Result& result);

/// `simulate --format csv`: one row per event.
QByteArray simulationCsv(const core::Result& result);

/// `simulate --format summary`: counts, cost and accuracy in a few lines.
QByteArray simulationSummary(const RunInput& run, const core::Result& result);

}  // namespace grazelab::cli
