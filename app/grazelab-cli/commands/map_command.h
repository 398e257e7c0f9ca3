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

/// Registers the options of `map`, `merge` and `family` (--x, --y, --threads, --shard,
/// --picture, --count; --out is shared with `report`).
void addMapOptions(QCommandLineParser& parser);


/// `grazelab-cli map`: a 2-D grid of exact runs reduced to summaries (issue 10). Exit 0, 2 on
/// invalid input (`error`, nothing written), 130 when interrupted (nothing written).
int runMap(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

/// `grazelab-cli merge --out PREFIX PART1 ... PARTN`: the stripes of one map joined.
int runMerge(const OptionValues& options, const QStringList& parts, const Io& io,
             std::stop_token stop, QString& error);

}  // namespace grazelab::cli
