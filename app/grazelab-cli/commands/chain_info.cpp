// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/chain_info.h"

#include "io/cli_input.h"
#include "io/cli_output.h"

namespace grazelab::cli {
namespace {

template <typename S>
InfoOutcome notesModelInfo(const OptionValues& options) {
  InfoOutcome outcome;
  const auto model = parseModel<S>(options);
  if (!model.value) {
    outcome.problem = model.error.simplified().toStdString();
    return outcome;
  }
  outcome.document = infoValue(*model.value);
  outcome.notesModel = true;
  outcome.status = InfoStatus::Described;
  return outcome;
}

// a chain of N masses, in double for now
InfoOutcome massChainInfo(const OptionValues& options, const InfoRequest& request, std::stop_token stop) {
  InfoOutcome outcome;
  if (request.precision && *request.precision != core::Precision::Double) {
    outcome.problem = "--precision: a chain of N masses is computed in double for now (give double or auto)";
    return outcome;
  }
  if (!options.isSet("masses")) {
    outcome.problem = "--springs, --right-spring, --stop-mass and --frequencies describe a chain given by --masses";
    return outcome;
  }
  const auto chain = parseMassChain(options, stop);
  if (!chain.value && chain.error.isEmpty()) {  // the design was stopped
    outcome.status = InfoStatus::Interrupted;
    return outcome;
  }
  if (!chain.value) {
    outcome.problem = chain.error.simplified().toStdString();
    return outcome;
  }
  outcome.document = massChainInfoValue(chain.value->chain, chain.value->design);
  outcome.status = InfoStatus::Described;
  return outcome;
}

}  // namespace

std::optional<InfoRequest> readInfoRequest(const OptionValues& options, QString& error) {
  const auto precision = parsePrecisionOption(options, error);
  if (!precision) return std::nullopt;
  return InfoRequest{precision->fixed};
}

InfoOutcome describeChain(const OptionValues& options, const InfoRequest& request, std::stop_token stop) {
  for (const char* name : {"masses", "springs", "right-spring", "stop-mass", "frequencies", "design-branch"}) {
    if (options.isSet(name)) return massChainInfo(options, request, stop);
  }
  switch (request.precision.value_or(core::Precision::Double)) {
    case core::Precision::Double: return notesModelInfo<double>(options);
    case core::Precision::Long: return notesModelInfo<long double>(options);
    case core::Precision::Quad: return notesModelInfo<core::Quad>(options);
  }
  return {};
}

std::string infoText(const InfoOutcome& outcome) {
  if (outcome.notesModel) {
    return "{\n  \"model\": " + fieldPerLine(outcome.document.fields[0].second, "    ", "  ") + "\n}\n";
  }
  return fieldPerLine(outcome.document, "  ", "") + "\n";
}

}  // namespace grazelab::cli
