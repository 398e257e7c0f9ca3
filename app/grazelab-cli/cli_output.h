// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdio>
#include <string>

#include "cli_input.h"
#include "core/simulate.h"
#include "core/trust.h"

namespace grazelab::cli {

/// `info`: the model with its derived quantities (k2, w1, w2, T1, T2, P, lambda*), as JSON.
template <typename S>
std::string infoJson(const ModelInput<S>& model);

/// Writes a run as it happens (DESIGN.md "Command line"): json (one document, the events array
/// streamed), jsonl (one record per line: the run, each event, the end), csv (one row per
/// event) or summary (a few lines at the end). Numbers carry the digits of the run's precision.
/// Every record is written whole, so an interrupted run leaves complete records.
template <typename S>
class RunWriter {
 public:
  RunWriter(const RunInput<S>& run, std::FILE* out) : m_run(run), m_out(out) {}

  /// Everything known before the first event.
  void begin(const core::BasicResult<S>& result);
  void event(const core::BasicEvent<S>& event);
  /// Everything known at the end; `interrupted` when a signal ended the run.
  void end(const core::BasicResult<S>& result, bool interrupted, const core::Trust& trust);

 private:
  void write(const std::string& text);

  const RunInput<S>& m_run;
  std::FILE* m_out;
  std::int64_t m_events = 0;
};

}  // namespace grazelab::cli
