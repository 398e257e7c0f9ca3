// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <optional>
#include <stop_token>
#include <string>

#include "core/numbers/scalar.h"
#include "io/json_value.h"
#include "io/option_values.h"

// `info` as a typed command, the one both faces call (as `glo-set` is, commands/grazing_set.h):
// the chain's options read into its derived quantities, a refusal a status and its line.
namespace grazelab::cli {

/// The precision the note's chain is read in (none: auto, double); a chain of N masses is read
/// in double.
struct InfoRequest {
  std::optional<core::Precision> precision;
};

enum class InfoStatus {
  Described,
  Refused,      ///< bad input, or a precision a chain of N masses is not read in: `problem`
  Interrupted,  ///< the stop token ended the design of the springs
};

struct InfoOutcome {
  InfoStatus status = InfoStatus::Refused;
  std::string problem;  ///< why refused, one line
  /// The note's chain: {model: k2, omega1, omega2, T1, T2, P, lambda_star, ...} to the digits of
  /// its precision; a chain of N masses (--masses): {chain, modes, ratios, design}.
  JsonValue document;
  bool notesModel = false;  ///< the document is the note's {model: ...}
};

/// --precision (auto, double, long or quad), or nothing with `error`.
std::optional<InfoRequest> readInfoRequest(const OptionValues& options, QString& error);

/// The chain of `options` (the note's flags, or --masses ...) and its derived quantities.
InfoOutcome describeChain(const OptionValues& options, const InfoRequest& request, std::stop_token stop = {});

/// The command line's text of a described chain: the note's model one field per line, a chain
/// of N masses as every document is written.
std::string infoText(const InfoOutcome& outcome);

}  // namespace grazelab::cli
