// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli simulate`: one exact run streamed as it happens, its error estimate beside it,
// and --precision auto (the run again from its input one precision up at a contact the lower
// one cannot decide).
#include "commands/simulate_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include "io/cli_output.h"
#include "core/solver/simulate.h"
#include "core/solver/trust.h"
#include "exit_codes.h"

namespace grazelab::cli {
namespace {

// Progress of a long run: contacts, simulated time, rate and, where the run is bounded, the
// time left; once a second on one line rewritten in place when the messages go to a terminal,
// and to the caller's progress (the Python module's callback).
class ProgressLine {
 public:
  explicit ProgressLine(const Io& io)
      : m_io(io), m_terminal(fileno(io.messages) >= 0 && isatty(fileno(io.messages)) != 0) {}
  bool enabled() const { return m_terminal || m_io.progress; }
  void show(std::int64_t contacts, double simulatedTime, double fraction,
            const std::string& precision) {
    const double elapsed = seconds(m_started);
    if (!enabled() || elapsed - m_lastShown < (m_terminal ? 1.0 : 0.1)) return;
    m_lastShown = elapsed;
    const double rate = double(contacts) / elapsed;
    char left[64] = "";
    if (fraction > 0 && fraction < 1) {
      std::snprintf(left, sizeof left, ", %.0f%%, about %.0f s left", 100 * fraction,
                    elapsed * (1 - fraction) / fraction);
    }
    char line[256];
    std::snprintf(line, sizeof line, "%lld contacts, t = %.6g, %.3g contacts/s (%s)%s",
                  static_cast<long long>(contacts), simulatedTime, rate, precision.c_str(), left);
    m_io.reportProgress(fraction > 0 ? fraction : -1.0, line);
    if (!m_terminal) return;
    std::fprintf(m_io.messages, "\r\033[Kgrazelab-cli: %s", line);
    std::fflush(m_io.messages);
    m_shown = true;
  }
  void clear() {
    if (m_shown) std::fprintf(m_io.messages, "\r\033[K");
    m_shown = false;
  }

 private:
  static double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
  }
  const Io& m_io;
  bool m_terminal;
  bool m_shown = false;
  std::chrono::steady_clock::time_point m_started = std::chrono::steady_clock::now();
  double m_lastShown = 0;
};

// A run of --precision auto in progress: what its output holds so far, so that a run raised to
// a higher precision (again from its input) goes on where the lower one stopped writing.
struct AutoRun {
  bool begun = false;          ///< the output's head is written
  std::int64_t written = 0;    ///< events written
  core::EventType lastType = core::EventType::Impact;
  long double lastTime = 0;    ///< time of the last event written
  std::vector<std::string> escalations;
  std::string mismatch;        ///< the raised run disagrees with an event already written
  // the error estimate of the events written by a lower precision (its shadow, up to the raise):
  // they stay on the output, so the final estimate is at least theirs
  std::int64_t writtenBeforeRaise = 0;
  double writtenStateError = 0;
  double writtenTimeError = 0;
};
// simulate<S> stopped at a contact S cannot decide: run again one precision up
constexpr int kRaisePrecision = -1;

template <typename S>
int simulateIn(const OptionValues& options, core::TrustMode trustMode, AutoRun* autoRun,
               const Io& io, std::stop_token stop, QString& error) {
  constexpr bool kTopPrecision = std::is_same_v<S, core::Quad>;
  const std::string precisionName(core::toString(core::precisionOf<S>()));
  // a refusal the precision causes (a chain or start beyond its reach): auto goes higher before
  // anything is written; any other is the answer
  auto refused = [&](const std::string& message, bool precisionBound) {
    if (autoRun && !kTopPrecision && !autoRun->begun && precisionBound) {
      autoRun->escalations.push_back("from " + precisionName + ": " + message);
      return kRaisePrecision;
    }
    error = QString::fromStdString(message);
    return kExitInvalidInput;
  };
  auto parsed = parseRun<S>(options);
  if (!parsed.value) return refused(parsed.error.toStdString(), parsed.precisionBound);
  RunInput<S>& run = *parsed.value;
  run.request.stopAtUndecided = autoRun != nullptr && !kTopPrecision;
  RunWriter<S> writer(run, io.out, autoRun ? std::string("auto") : precisionName, io.events,
                      io.document, io.samples);
  // the error estimate: the same input read one precision up, run beside this one
  std::optional<core::TrustMonitor<S>> monitor;
  std::string noShadow;
  if (trustMode != core::TrustMode::Off) {
    const auto shadow = parseRun<core::ShadowScalar<S>>(options);
    if (shadow.value) {
      monitor.emplace(shadow.value->model.model, shadow.value->request, trustMode,
                      stop, exactParameters<core::ShadowScalar<S>>(options));
    } else {
      noShadow = "no shadow run: " + shadow.error.toStdString();
    }
  }
  // a raised run computes the events already written again: they are checked, not rewritten
  const std::int64_t alreadyWritten = autoRun ? autoRun->written : 0;
  const long double period = static_cast<long double>(S(core::twoPi<S>() / run.model.chain.omegaSlow));
  std::int64_t index = 0;
  const auto onEvent = [&](const core::BasicEvent<S>& event) {
    ++index;
    if (monitor) monitor->observe(event);
    if (index == alreadyWritten && autoRun->mismatch.empty()) {
      const long double t = static_cast<long double>(event.t);
      if (event.type != autoRun->lastType || std::fabs(t - autoRun->lastTime) > 1e-6L * period) {
        autoRun->mismatch = "event " + std::to_string(index) + " as written before the raise to " +
                            precisionName + " differs from the " + precisionName + " run";
      }
    }
    if (index <= alreadyWritten) return;
    writer.event(event);
    if (autoRun) {
      autoRun->written = index;
      autoRun->lastType = event.type;
      autoRun->lastTime = static_cast<long double>(event.t);
    }
  };
  // a summary without an error estimate looks at no event: none is handed over (the core then
  // spends no time putting them in physical units), and the run costs what the core's does
  const bool eventsLookedAt = run.format != Format::Summary || monitor || io.events || io.document;
  if (eventsLookedAt) run.request.onEvent = onEvent;
  core::BasicSimulator<S> simulator(run.model.model, run.request);
  if (simulator.result().stop == core::StopReason::InvalidInput) {
    return refused(simulator.result().message, false);
  }
  if (!core::isFinite(simulator.result().initialEnergy)) {
    if (autoRun && !kTopPrecision) {
      autoRun->escalations.push_back("from " + precisionName +
                                     ": the energy of this start is beyond its range");
      return kRaisePrecision;
    }
    error = "the energy of this start is beyond the range of this precision (try "
            "--precision long or quad, whose range is wider)";
    return kExitInvalidInput;
  }
  if (!autoRun || !autoRun->begun) {
    for (const std::string& note : run.notes) {
      std::fprintf(io.messages, "grazelab-cli: note: %s\n", note.c_str());
    }
    writer.begin(simulator.result());
    if (autoRun) autoRun->begun = true;
  } else {
    writer.resumeAfter(autoRun->written);
  }
  ProgressLine progress(io);
  while (!simulator.advance(progress.enabled() ? 65536 : std::numeric_limits<std::int64_t>::max(),
                            stop)) {
    progress.show(simulator.result().cost.contacts,
                  core::toDouble(simulator.scale().toPhysicalTime(simulator.state().tau)),
                  simulator.progress(), precisionName);
  }
  progress.clear();
  if (simulator.result().stop == core::StopReason::Undecided) {
    autoRun->escalations.push_back("from " + precisionName + ": " + simulator.result().message);
    if (monitor && autoRun->written > alreadyWritten) {
      const core::Trust written = monitor->finish(simulator.result());
      autoRun->writtenBeforeRaise = autoRun->written;
      autoRun->writtenStateError = std::max(autoRun->writtenStateError, written.stateError);
      autoRun->writtenTimeError = std::max(autoRun->writtenTimeError, written.timeError);
    }
    return kRaisePrecision;
  }
  core::Trust trust;
  if (monitor) {
    trust = monitor->finish(simulator.result());
  } else {
    trust.reason = noShadow.empty() ? "not estimated (--trust off)" : noShadow;
    core::accountForUndecidedTouches(trust, simulator.result());
  }
  if (autoRun && autoRun->writtenBeforeRaise > 0 && trust.verdict != core::Verdict::Unchecked) {
    trust.stateError = std::max(trust.stateError, autoRun->writtenStateError);
    trust.timeError = std::max(trust.timeError, autoRun->writtenTimeError);
    const double worst = std::max(trust.stateError, trust.timeError);
    if (trust.verdict == core::Verdict::Ok && worst > core::kOkTolerance) {
      trust.verdict = worst > core::kHorizonTolerance ? core::Verdict::Unreliable
                                                      : core::Verdict::Degraded;
    }
    char note[160];
    std::snprintf(note, sizeof note,
                  "events 1 to %lld were written before the raise, in a lower precision "
                  "(estimated error %.2g)",
                  static_cast<long long>(autoRun->writtenBeforeRaise),
                  std::max(autoRun->writtenStateError, autoRun->writtenTimeError));
    trust.reason = std::string(note) + "; " + trust.reason;
  }
  if (autoRun && !autoRun->mismatch.empty()) {
    trust.verdict = core::Verdict::Unreliable;
    trust.reason = autoRun->mismatch + "; " + trust.reason;
  }
  PrecisionReport precision{autoRun ? "auto" : precisionName, precisionName,
                                 autoRun ? autoRun->escalations : std::vector<std::string>{}};
  writer.end(simulator.result(), stop.stop_requested(), trust, precision);
  return stop.stop_requested() ? kExitInterrupted : kExitOk;
}


}  // namespace

int runSimulate(const OptionValues& options, const PrecisionOption& precision,
                core::TrustMode trust, const Io& io, std::stop_token stop, QString& error) {
  using core::Precision;
  if (!precision.fixed) {
    // auto: double, and from the input again one precision up while a contact needs it
    AutoRun autoRun;
    int code = simulateIn<double>(options, trust, &autoRun, io, stop, error);
    if (code == kRaisePrecision) code = simulateIn<long double>(options, trust, &autoRun, io, stop, error);
    if (code == kRaisePrecision) code = simulateIn<core::Quad>(options, trust, &autoRun, io, stop, error);
    return code;
  }
  switch (*precision.fixed) {
    case Precision::Double:
      return simulateIn<double>(options, trust, nullptr, io, stop, error);
    case Precision::Long:
      return simulateIn<long double>(options, trust, nullptr, io, stop, error);
    case Precision::Quad:
      return simulateIn<core::Quad>(options, trust, nullptr, io, stop, error);
  }
  return kExitInvalidInput;
}

}  // namespace grazelab::cli
