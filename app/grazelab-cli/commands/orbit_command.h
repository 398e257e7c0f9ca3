// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>
#include <QStringList>

#include <memory>
#include <optional>
#include <stop_token>

#include "commands/periodic_orbit.h"
#include "io/cli_input.h"
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

/// The options of `orbit` (--onepp --period, or --impacts --energy --guess; --precision) as a
/// request; nothing, with `error` the line that says why.
std::optional<OrbitRequest> readOrbitRequest(const OptionValues& options, QString& error);

/// The chain of a two-mass command (orbit, modes): a chain given by --masses of another shape is refused
/// before it is designed; else the chain read and checked once (recentChain), its two-mass form
/// read once in each precision asked for. An interrupted design gives neither a chain nor an
/// error.
Parsed<std::shared_ptr<const PreparedMassChain>> twoMassChainOf(const OptionValues& options, std::stop_token stop = {});
/// The chain of `orbit`: any chain, read and checked once (recentChain).
Parsed<std::shared_ptr<const PreparedMassChain>> orbitChainOf(const OptionValues& options, std::stop_token stop = {});

}  // namespace grazelab::cli
