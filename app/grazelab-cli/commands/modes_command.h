// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <stop_token>

#include "io/cli_io.h"
#include "io/option_values.h"

class QCommandLineParser;

namespace grazelab::cli {

/// The options of `modes`: --max-impacts, --energy-range.
void addModesOptions(QCommandLineParser& parser);

/// `grazelab-cli modes [model] [--max-impacts K] [--energy-range A:B] [--precision P] --out
/// PREFIX`: the atlas of the chain's periodic impacting families up to K impacts per period
/// (PREFIX.json, one CSV and .npy per family, the frequency-energy picture PREFIX.png/.svg).
/// Exit 2 with `error` on invalid input, 130 (nothing written) when `stop` is requested.
int runModes(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

}  // namespace grazelab::cli
