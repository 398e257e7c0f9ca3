// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QCommandLineParser>
#include <QString>

#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "core/experiments/bar.h"
#include "io/cli_io.h"
#include "io/json_value.h"
#include "io/option_values.h"

// `bar` as a typed command: an elastic bar thrown at a rigid wall, lumped into N masses for each N
// asked, each computed exactly, against the continuum's answer. The command line reads the
// options into a BarRequest and writes the document; the Python module hands the same document
// over as values. No Qt in the computation.
namespace grazelab::cli {

struct BarRequest {
  static constexpr int kMaxMasses = 2000;
  core::Bar bar;
  std::vector<int> masses = {10, 100, 1000};  ///< ascending
  core::BarEnd end = core::BarEnd::Last;
  bool eachImpact = false;  ///< list every impact's time and impulse
};

enum class BarOutcomeStatus { Computed, Interrupted };

struct BarOutcome {
  BarOutcomeStatus status = BarOutcomeStatus::Computed;
  BarRequest request;
  core::BarContinuum continuum;
  std::vector<core::BarImpact> rows;
  std::vector<double> seconds;  ///< each row's wall time
};

/// --bar E,rho,S,L, --speed, --masses-count N1,N2,... (ascending, 1 to 2000), --stop-end
/// last|first, --each-impact; or nothing with `error`.
std::optional<BarRequest> readBarRequest(const OptionValues& options, QString& error);
/// Every N of the request thrown, in order; Interrupted when `stop` ended one.
BarOutcome throwBars(const BarRequest& request, std::stop_token stop = {});
/// bar, continuum, rows (with each quantity relative to the continuum's), convergence.
JsonValue barDocument(const BarOutcome& outcome);

/// --bar, --speed, --masses-count, --stop-end, --each-impact.
void addBarOptions(QCommandLineParser& parser);

/// `grazelab-cli bar`: the document on stdout; exit 0, 2 on invalid input, 130 when interrupted
/// (nothing written).
int runBar(const OptionValues& options, const Io& io, std::stop_token stop, QString& error);

}  // namespace grazelab::cli
