// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>
#include <QStringList>

#include <stop_token>

#include "io/cli_io.h"
#include "io/option_values.h"

class QCommandLineParser;

namespace grazelab::cli {

/// The options of `orbit`: --period, --impacts, --energy, --guess.
void addOrbitOptions(QCommandLineParser& parser);

/// `grazelab-cli orbit --onepp --period T [model] [--precision P]` or
/// `grazelab-cli orbit --impacts K --energy E --guess U1,V1 [model] [--precision P]`: one
/// periodic impacting orbit with its exact stability (docs/model.md section 10), as a JSON
/// object on stdout. Exit 2 with `error` (one line) on invalid input, when Newton does not
/// converge or when the orbit is not admissible.
int runOrbit(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

}  // namespace grazelab::cli
