// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "commands/simulation.h"
#include "io/cli_input.h"
#include "io/cli_io.h"
#include "io/option_values.h"

namespace grazelab::cli {


/// `grazelab-cli simulate`: an exact run of a chain (commands/simulation.h), given by --masses
/// ... or by the note's options (--m1 --m2 --k1 --k2 --branch --gap: the two-mass chain they
/// write), from its start, up to --contacts (default 100) or --t-end, streamed as json, jsonl, csv
/// or a summary with its error estimate (docs/cli.md). Exit 0; 2 on invalid input (`error`;
/// nothing on stdout, but for a json or jsonl document closed whole when the refusal came after
/// a lower precision wrote events); 130 when `stop` ended it (`error`: what was written).
int runSimulate(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

/// --precision as a choice (auto when absent); nothing, with `error` the line that says why.
std::optional<PrecisionChoice> readPrecisionChoice(const OptionValues& options, QString& error);

/// The run options of `simulate` (--state, --glo-weights, --onepp, --glo, --perturb, --contacts,
/// --t-end, --search-steps, --precision, --trust, --sample-step, --sample-times) as a request,
/// for output in `format` (csv runs no estimate, writes no samples); nothing, with `error` the
/// line that says why. Its notesStarts is the caller's to set.
std::optional<SimulateRequest> readSimulateRequest(const OptionValues& options, Format format, QString& error);

/// The chain of the options (the seven of a chain given by --masses, or the note's), read,
/// checked and designed once for the last 16 chains asked for (a script that runs one chain many
/// times pays for it once). An interrupted design gives neither a chain nor an error.
Parsed<std::shared_ptr<const PreparedMassChain>> recentChain(const OptionValues& options, std::stop_token stop = {});

/// A run's events into a table (the Python module's arrays), refilled when a run is raised.
class EventTableSink final : public SimulateSink {
 public:
  explicit EventTableSink(ChainEventTable& table) : m_table(table) {}
  void begin(const AnyRun& run, const std::vector<std::string>& notes) override;
  void event(const core::BasicChainEvent<double>& event) override;
  void event(const core::BasicChainEvent<long double>& event) override;
  void event(const core::BasicChainEvent<core::Quad>& event) override;

 private:
  ChainEventTable& m_table;
};

}  // namespace grazelab::cli
