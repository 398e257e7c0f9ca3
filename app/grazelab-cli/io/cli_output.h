// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "io/cli_input.h"
#include "io/cli_io.h"
#include "io/json_value.h"
#include "core/solver/simulate.h"
#include "core/solver/trust.h"

namespace grazelab::cli {

/// A number as JSON with the digits of its precision; null when it is not finite.
template <typename S>
std::string jsonNumber(const S& value) {
  return core::isFinite(value) ? core::formatScalar(value) : std::string("null");
}

/// A string as JSON (quotes and backslashes escaped).
std::string jsonQuoted(const std::string& text);

/// `info`: the model with its derived quantities (k2, w1, w2, T1, T2, P, lambda*), as JSON.
template <typename S>
std::string infoJson(const ModelInput<S>& model);
/// The same document as values.
template <typename S>
JsonValue infoValue(const ModelInput<S>& model);

/// `info` of a chain of N masses: the chain, each mode (frequency, period, shape, whether it has
/// a node at the stop, its harmonic number) and the frequencies' ratios, in double; for a
/// designed chain also its `design`: the ratios asked, the design used and every design found.
JsonValue massChainInfoValue(const core::MassChain& chain, const std::optional<core::DesignChoice>& design = std::nullopt);
/// A command's one JSON document: handed over as values (Io::document, the Python module) or
/// written to stdout, one field per line.
void emitDocument(const Io& io, JsonValue document);
/// A run's error estimate: estimated_state_error, estimated_time_error, horizon, horizon_method
/// (null when not estimated), verdict, reason.
JsonValue trustValue(const core::Trust& trust);
/// A chain of N masses as the other commands' documents name it: masses, springs, right_spring
/// (null: none), stop_mass, gap and the common `period` of a commensurate chain (null: none), to
/// the digits of the chain's precision.
template <typename S>
JsonValue massChainValue(const core::BasicMassChain<S>& chain, const S& period);

/// The arithmetic of a run as its output reports it: asked for ("auto", "double", ...), used
/// in the end, and each raise of --precision auto (one line: from where and why).
struct PrecisionReport {
  std::string requested;
  std::string used;
  std::vector<std::string> escalations;
};

/// Writes a run as it happens (docs/design.md "Command line"): json (one document, the events array
/// streamed), jsonl (one record per line: the run, each event, the end), csv (one row per
/// event) or summary (a few lines at the end). Numbers carry the digits of the run's precision.
/// Every record is written whole, so an interrupted run leaves complete records.
template <typename S>
class RunWriter {
 public:
  /// `precision` is what the run was asked for (the model's "precision" field). With a `table`
  /// the events go there and the text's events array stays empty; with a `document` the whole
  /// output goes there as values instead of text (both: the Python module).
  RunWriter(const RunInput<S>& run, std::FILE* out, std::string precision,
            EventTable* table = nullptr, JsonValue* document = nullptr,
            std::vector<core::Sample>* samples = nullptr)
      : m_run(run), m_out(out), m_precision(std::move(precision)), m_table(table),
        m_document(document), m_samples(samples) {}

  /// Everything known before the first event.
  void begin(const core::BasicResult<S>& result);
  /// Goes on after `written` events an earlier writer of the same output wrote (a run of
  /// --precision auto raised to a higher precision): begin() is not called again.
  void resumeAfter(std::int64_t written) { m_events = written; }
  void event(const core::BasicEvent<S>& event);
  /// Everything known at the end; `interrupted` when a signal ended the run.
  void end(const core::BasicResult<S>& result, bool interrupted, const core::Trust& trust,
           const PrecisionReport& precision);

 private:
  void write(const std::string& text);

  const RunInput<S>& m_run;
  std::FILE* m_out;
  std::string m_precision;
  EventTable* m_table;
  JsonValue* m_document;
  std::vector<core::Sample>* m_samples;
  std::int64_t m_events = 0;
};

}  // namespace grazelab::cli
