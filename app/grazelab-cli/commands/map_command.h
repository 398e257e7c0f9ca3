// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>
#include <QStringList>

#include <optional>
#include <stop_token>

#include "commands/parameter_map.h"
#include "io/cli_io.h"
#include "io/json_value.h"
#include "io/option_values.h"

class QCommandLineParser;

namespace grazelab::cli {

/// Registers the options of `map`, `merge` and `family` (--x, --y, --threads, --shard,
/// --picture, --count; --out is shared with `report`).
void addMapOptions(QCommandLineParser& parser);


/// The options of `map` as a request (commands/parameter_map.h): --x, --y, the chain (--m1 ... or
/// --masses ...) and its start, --contacts, --trust, --precision (auto or double), --shard,
/// --threads, --picture; nothing, with `error` the line that says why, or with `stopped` when
/// `stop` ended a chain's design.
std::optional<MapRequest> readMapRequest(const OptionValues& options, std::stop_token stop, QString& error,
                                         bool& stopped);

/// A map or merge with its files where --out names them (`filesRequired`: the command line, which
/// writes nothing else, refuses one without --out; the Python module writes files only when
/// asked, and draws no picture). `code` is the command's exit code (0; 2 on invalid input with
/// `error`, nothing written; 130 when interrupted, nothing written; 1 when a file could not be
/// written); `outcome` the map when computed; `files` the names written (the document's `files`).
struct MapRun {
  int code = 0;
  MapOutcome outcome;
  std::optional<JsonValue> files;
};
MapRun mapWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                    bool filesRequired);
/// The stripes of one map (the prefixes `parts`) joined, as mapWithFiles writes a map.
MapRun mergeWithFiles(const OptionValues& options, const QStringList& parts, const Io& io, std::stop_token stop,
                      QString& error, bool filesRequired);

/// `grazelab-cli map`: a 2-D grid of exact runs reduced to summaries (issue 10), mapWithFiles
/// with --out required. Exit 0, 2 on invalid input (`error`, nothing written), 130 when
/// interrupted (nothing written).
int runMap(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

/// `grazelab-cli merge --out PREFIX PART1 ... PARTN`: the stripes of one map joined.
int runMerge(const OptionValues& options, const QStringList& parts, const Io& io,
             std::stop_token stop, QString& error);

}  // namespace grazelab::cli
