// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli simulate`: its options read into the typed command's request
// (commands/simulation.h), and its outcome written as it happens: json, jsonl, csv or a summary;
// the same request and outcome for the Python module (events into a table, the document as values).
#include "commands/simulate_command.h"

#include <QStringList>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "commands/simulation_document.h"
#include "core/solver/chain_run.h"
#include "core/solver/trust.h"
#include "exit_codes.h"
#include "io/cli_input.h"
#include "io/cli_output.h"
#include "io/json_value.h"
#include "io/prepared_chain.h"

namespace grazelab::cli {
namespace {

using V = JsonValue;

// an event as the csv's row: {t, type, u1..uN, v1_pre..vN_pre, v<s>_post}
template <typename S>
V eventValue(const ColumnNames& names, const core::BasicChainEvent<S>& event) {
  std::vector<V::Field> fields;
  fields.reserve(2 * names.u.size() + 3);
  fields.emplace_back("t", V::number(event.t));
  fields.emplace_back("type", V::of(std::string(core::toString(event.type))));
  for (std::size_t i = 0; i < names.u.size(); ++i) fields.emplace_back(names.u[i], V::number(event.u[Eigen::Index(i)]));
  for (std::size_t i = 0; i < names.vPre.size(); ++i) {
    fields.emplace_back(names.vPre[i], V::number(event.vBefore[Eigen::Index(i)]));
  }
  fields.emplace_back(names.vPost, V::number(event.vAfter));
  return V::object(std::move(fields));
}

template <typename S>
std::string listText(const core::ChainVector<S>& values) {
  std::string text = "[";
  for (Eigen::Index i = 0; i < values.size(); ++i) text.append(i > 0 ? ", " : "").append(core::formatScalar(values[i]));
  return text.append("]");
}

// The csv's header: t, type, u1..uN, v1_pre..vN_pre and the stopped mass's v_post
// (strings appended, not "literal" + string: GCC 12 warns falsely on that at -O2)
std::string csvHeader(Eigen::Index n, int stopped) {
  std::string header = "t,type";
  for (Eigen::Index i = 1; i <= n; ++i) header.append(",u").append(std::to_string(i));
  for (Eigen::Index i = 1; i <= n; ++i) header.append(",v").append(std::to_string(i)).append("_pre");
  return header.append(",v").append(std::to_string(stopped)).append("_post\n");
}

template <typename S>
std::string csvLine(const core::BasicChainEvent<S>& event) {
  std::string line = core::formatScalar(event.t);
  line.append(",").append(core::toString(event.type));
  for (Eigen::Index i = 0; i < event.u.size(); ++i) line.append(",").append(core::formatScalar(event.u[i]));
  for (Eigen::Index i = 0; i < event.vBefore.size(); ++i) line.append(",").append(core::formatScalar(event.vBefore[i]));
  return line.append(",").append(core::formatScalar(event.vAfter)).append("\n");
}

// The summary of a run: what the json says but its events, a line for each
template <typename S>
std::string summaryText(const core::BasicReadyChain<S>& ready, const core::BasicChainStart<S>& start,
                        const core::BasicChainRun<S>& run, double seconds, const std::string& precision,
                        const std::vector<std::string>& raised, const core::Trust& trust) {
  const core::BasicMassChain<S>& masses = ready.numbers;
  const core::BasicChainDynamics<S>& dynamics = ready.dynamics;
  using Vector = core::ChainVector<S>;
  std::string text;
  text += "chain          masses " + listText<S>(Eigen::Map<const Vector>(masses.masses.data(), masses.size())) +
          " springs " + listText<S>(Eigen::Map<const Vector>(masses.springs.data(), masses.size())) +
          (masses.rightSpring > 0 ? " right spring " + core::formatScalar(masses.rightSpring) : std::string()) +
          " stop on mass " + std::to_string(masses.stopped()) + " gap " + core::formatScalar(masses.gap) +
          (dynamics.period > 0 ? " (commensurate; T=" + core::formatScalar(dynamics.period) + ")" : std::string(" (not commensurate)")) + "\n";
  text += "start          u=" + listText<S>(start.state.u) + " v=" + listText<S>(start.state.v) + "\n";
  text += "contacts       " + std::to_string(run.contacts) + " (impacts " + std::to_string(run.impacts) + ", grazings " +
          std::to_string(run.grazings) + ", sticks " + std::to_string(run.sticks) + "; releases " +
          std::to_string(run.releases) + ")\n";
  const std::string message = stopMessage(run.stop, std::is_same_v<S, core::Quad>);
  text += "stopped        " + std::string(core::toString(run.stop)) + " at t = " + core::formatScalar(run.tFinal) +
          (message.empty() ? std::string() : " (" + message + ")") + "\n";
  char line[200];
  std::snprintf(line, sizeof line, "wall time      %.4g s (%.4g contacts/s)\n", seconds,
                seconds > 0 ? double(run.contacts) / seconds : 0.0);
  text += line;
  using std::abs;
  std::snprintf(line, sizeof line, "energy drift   %.3g (max relative, at events; final against initial %.3g)\n",
                run.maxEnergyDrift, core::toDouble(abs(run.energyFinal / run.energyInitial - 1)));
  text += line;
  std::snprintf(line, sizeof line, "|u%d - gap|     %.3g (max at contacts, as the flights reached them)\n",
                masses.stopped(), run.maxContactResidual);
  text += line;
  text += "precision      " + precision + "\n";
  for (const std::string& rung : raised) text += "               raised: " + rung + "\n";
  text += "trust          " + std::string(core::toString(trust.verdict)) + ": " + trust.reason + "\n";
  if (trust.verdict != core::Verdict::Unchecked) {
    std::snprintf(line, sizeof line,
                  "               state error %.2g, contact time error %.2g of the slowest period; holds 1e-6 %s t = %.4g (%s)\n",
                  trust.stateError, trust.timeError, trust.horizonObserved ? "until" : "at least until", trust.horizon,
                  trust.horizonObserved ? "observed" : "extrapolated");
    text += line;
  }
  text += "final          t=" + core::formatScalar(run.tFinal) + " u=" + listText<S>(run.final.u) +
          " v=" + listText<S>(run.final.v) + "\n";
  return text;
}

// An event into the Python module's table: packed doubles, and in a wider precision each number's
// decimal text
template <typename S>
void appendRow(ChainEventTable& table, const core::BasicChainEvent<S>& event) {
  if (table.count >= table.maxRows) {
    if (!table.full && table.whenFull) table.whenFull();
    table.full = true;
    return;
  }
  const std::size_t rowBytes = table.rowBytes();
  table.rows.resize((table.count + 1) * rowBytes);
  char* row = table.rows.data() + table.count * rowBytes;
  ++table.count;
  const auto put = [&](std::size_t offset, const S& value) {
    const double rounded = core::toDouble(value);
    std::memcpy(row + offset, &rounded, sizeof rounded);
    if constexpr (!std::is_same_v<S, double>) table.decimals.push_back(core::formatScalar(value));
  };
  put(0, event.t);
  const std::string_view type = core::toString(event.type);
  char32_t letters[8] = {};
  for (std::size_t i = 0; i < type.size() && i < 8; ++i) letters[i] = char32_t(type[i]);
  std::memcpy(row + sizeof(double), letters, sizeof letters);
  std::size_t offset = sizeof(double) + sizeof letters;
  for (Eigen::Index i = 0; i < event.u.size(); ++i, offset += sizeof(double)) put(offset, event.u[i]);
  for (Eigen::Index i = 0; i < event.vBefore.size(); ++i, offset += sizeof(double)) put(offset, event.vBefore[i]);
  put(offset, event.vAfter);
}

// A document's fields on the output: json one per line (the events one per line between head and
// end), jsonl one record per line ("run", each "event", "end"). Every record whole, so that an
// interrupted run leaves complete ones.
void writeFields(std::FILE* out, const std::vector<V::Field>& fields, bool lines) {
  std::string text;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    text.append(lines ? (i > 0 ? ", " : "") : (i > 0 ? ",\n  " : "  "));
    text.append(jsonQuoted(std::string(fields[i].first.view()))).append(": ").append(oneLine(fields[i].second));
  }
  std::fwrite(text.data(), 1, text.size(), out);
}

// A document's end after its `events` events: the json's closing fields, or jsonl's end record
void writeEnd(std::FILE* out, const std::vector<V::Field>& end, bool lines, long events) {
  if (lines) {
    std::fputs("{\"record\": \"end\", ", out);
    writeFields(out, end, true);
    std::fputs("}\n", out);
  } else {
    std::fputs(events == 0 ? "],\n" : "\n  ],\n", out);
    writeFields(out, end, false);
    std::fputs("\n}\n", out);
  }
  std::fflush(out);
}

// A run streamed as json, jsonl, csv or (at its end) a summary. A raised run starts again from
// its start and writes only the events past those a lower precision wrote (they stay on the
// output), comparing the last of them with its own.
class StreamWriter final : public SimulateSink {
 public:
  StreamWriter(const Io& io, Format format, PrecisionChoice precision)
      : m_io(io), m_format(format), m_precision(precision) {}

  void begin(const AnyRun& run, const std::vector<std::string>& notes) override {
    m_runBegins.push_back(m_events);
    m_seen = 0;
    m_raisedAgrees.reset();
    std::visit(
        [&]<typename S>(const RunIn<S>& began) {
          m_runPrecision = core::toString(core::precisionOf<S>());
          m_names = &namesOf(began);
        },
        run);
    if (m_begun) return;
    // the head once the start is known to be good (bad input writes nothing), in the precision
    // that wrote it first (a raised run's document keeps it, as its text does)
    m_begun = true;
    for (const std::string& note : notes) std::fprintf(m_io.messages, "grazelab-cli: note: %s\n", note.c_str());
    if (m_format == Format::Csv) {
      std::visit([&](const auto& first) { std::fputs(csvHeader(first.ready->numbers.size(),
                                                               first.ready->numbers.stopped()).c_str(), m_io.out); },
                 run);
    } else if (streamsText()) {
      std::fputs(lines() ? "{\"record\": \"run\", " : "{\n", m_io.out);
      writeFields(m_io.out, headFields<V>(run, m_precision), lines());
      std::fputs(lines() ? "}\n" : ",\n  \"events\": [", m_io.out);
    }
  }
  void event(const core::BasicChainEvent<double>& event) override { write(event); }
  void event(const core::BasicChainEvent<long double>& event) override { write(event); }
  void event(const core::BasicChainEvent<core::Quad>& event) override { write(event); }

  /// The run's output closed for `outcome`: its exit code, `error` the line that says why when
  /// it is not 0.
  int finish(const SimulateOutcome& outcome, bool sampled, const std::stop_token& stop, QString& error) {
    const long before = m_runBegins.empty() ? 0 : m_runBegins.back();
    if (outcome.status == SimulateStatus::Refused) {
      error = QString::fromStdString(outcome.problem);
      // after a lower precision wrote events (it ended undecided), a json or jsonl document is
      // closed whole, saying so
      if (m_begun && streamsText()) {
        std::vector<V> raised;
        for (const std::string& line : outcome.escalations) raised.push_back(V::of(line));
        const std::vector<V::Field> end{
            {"stop_reason", V::of(std::string(core::toString(core::StopReason::Undecided)))},
            {"message", V::of("the run ended undecided in a lower precision, and in " +
                              std::string(core::toString(outcome.precision)) + " it is refused: " + outcome.problem)},
            {"precision", V::object({{"requested", V::of(std::string(toString(m_precision)))},
                                     {"used", V::of(m_wroteIn)},
                                     {"escalations", V::array(std::move(raised))}})}};
        writeEnd(m_io.out, end, lines(), m_events);
      }
      return kExitInvalidInput;
    }
    std::fflush(m_io.out);
    const core::StopReason stopped = std::visit([](const auto& ran) { return ran.run.stop; }, *outcome.last);
    if (stopped == core::StopReason::Cancelled && !streamsText()) {
      if (m_format == Format::Csv) error = QStringLiteral("the %1 events before it are written").arg(m_events);
      return kExitInterrupted;
    }
    if (m_format == Format::Csv) {
      if (!outcome.escalations.empty()) {
        std::fprintf(m_io.messages,
                     "grazelab-cli: note: the run was raised to %s (undecided below it) after %ld rows; %s\n",
                     m_runPrecision.c_str(), before,
                     before == 0            ? "every row is its own"
                     : !m_raisedAgrees      ? "it ends before the last of them: the rows past its end are the lower precision's"
                     : *m_raisedAgrees      ? "it meets the last of them again (same type, time to 1e-9)"
                                            : "it DIFFERS from the last of them: the rows before the raise are not to be trusted");
      }
      return 0;
    }
    core::Trust trust = outcome.trust;
    if (stop.stop_requested() && !streamsText()) return kExitInterrupted;
    if (before > 0 && streamsText()) keepWrittenEvents(outcome, before, trust);
    withWidenedStart(outcome, trust);
    if (m_format == Format::Summary) {
      const std::string used = std::string(core::toString(outcome.precision)) +
                               (m_precision == PrecisionChoice::Auto ? " (auto)" : "");
      std::visit([&](const auto& ran) {
        std::fputs(summaryText(*ran.ready, ran.start, ran.run, ran.seconds, used, outcome.escalations, trust).c_str(),
                   m_io.out);
      }, *outcome.last);
      std::fflush(m_io.out);
      return 0;
    }
    writeEnd(m_io.out, endFields<V>(outcome, trust, m_precision, sampled), lines(), m_events);
    if (!stop.stop_requested()) return 0;
    error = QStringLiteral("the %1 events before it are written, and the document's end").arg(m_events);
    return kExitInterrupted;
  }

 private:
  bool lines() const { return m_format == Format::JsonLines; }
  bool streamsText() const { return m_format == Format::Json || m_format == Format::JsonLines; }

  template <typename S>
  void write(const core::BasicChainEvent<S>& event) {
    if (m_format == Format::Summary) return;
    if (++m_seen <= m_events) {
      if (m_seen == m_events) {
        // the raised run at the last event the lower precision wrote: the same event?
        using std::abs;
        m_raisedAgrees = event.type == m_lastType &&
                         abs(core::toDouble(event.t) - m_lastTime) <= 1e-9 * (1 + abs(m_lastTime));
        if (!*m_raisedAgrees) m_differed = true;
      }
      return;
    }
    if (m_format == Format::Csv) {
      std::fputs(csvLine(event).c_str(), m_io.out);
    } else if (lines()) {
      std::string record = oneLine(eventValue(*m_names, event));
      record.insert(1, "\"record\": \"event\", ");
      std::fputs(record.append("\n").c_str(), m_io.out);
    } else {
      std::fputs((m_events == 0 ? "\n    " : ",\n    "), m_io.out);
      std::fputs(oneLine(eventValue(*m_names, event)).c_str(), m_io.out);
    }
    ++m_events;
    m_lastTime = core::toDouble(event.t);
    m_lastType = event.type;
    m_wroteIn = m_runPrecision;
  }

  // Events written before a raise stay on the output: the estimate says so, with their error
  // (the final estimate is at least theirs), and whether the raised run met the last of them
  // again (same type, time to 1e-9)
  void keepWrittenEvents(const SimulateOutcome& outcome, long before, core::Trust& trust) const {
    double stateError = 0, timeError = 0;  // of the events written, as the precision that wrote them estimated it
    for (std::size_t i = 0; i < outcome.raised.size() && i + 1 < m_runBegins.size(); ++i) {
      if (m_runBegins[i + 1] == m_runBegins[i]) continue;  // (wrote none)
      stateError = std::max(stateError, outcome.raised[i].trust.stateError);
      timeError = std::max(timeError, outcome.raised[i].trust.timeError);
    }
    // (a stream, not string concatenation: GCC 12 warns falsely on that at -O2)
    std::ostringstream kept;
    if (!m_raisedAgrees) {
      kept << "the run ends before the last of the " << before
           << " events written before the raise: the events past its end are the lower precision's";
    } else {
      kept << "events 1 to " << before << " were written before the raise, in a lower precision, and the raised run "
           << (*m_raisedAgrees ? "meets the last of them again (same type, time to 1e-9)"
                               : "DIFFERS from the last of them: they are not to be trusted");
    }
    if (m_differed && m_raisedAgrees != false) {
      kept << "; an earlier raise DIFFERED from the events written before it: they are not to be trusted";
    }
    if (trust.verdict != core::Verdict::Unchecked) {
      trust.stateError = std::max(trust.stateError, stateError);
      trust.timeError = std::max(trust.timeError, timeError);
      const double worst = std::max(trust.stateError, trust.timeError);
      if (trust.verdict == core::Verdict::Ok && worst > core::kOkTolerance) {
        trust.verdict = worst > core::kHorizonTolerance ? core::Verdict::Unreliable : core::Verdict::Degraded;
      }
      kept << " (their estimated error " << std::max(stateError, timeError) << ")";
    }
    if (m_differed) trust.verdict = core::Verdict::Unreliable;
    trust.reason = kept.str() + "; " + trust.reason;
  }

  const Io& m_io;
  Format m_format;
  PrecisionChoice m_precision;
  bool m_begun = false;  ///< the head (json, jsonl) or header (csv) is out
  std::vector<long> m_runBegins;  ///< the events written when each run began
  std::string m_runPrecision;  ///< the present run's precision
  const ColumnNames* m_names = nullptr;  ///< the present run's chain's
  long m_seen = 0;  ///< the present run's events so far
  long m_events = 0;  ///< written
  double m_lastTime = 0;
  core::EventType m_lastType = core::EventType::Impact;
  std::string m_wroteIn;  ///< the precision that wrote them
  std::optional<bool> m_raisedAgrees;  ///< the raised run met the last of them again
  bool m_differed = false;  ///< a raised run differed from the events a lower one wrote (any rung)
};

}  // namespace

std::optional<PrecisionChoice> readPrecisionChoice(const OptionValues& options, QString& error) {
  const std::optional<PrecisionOption> option = parsePrecisionOption(options, error);
  if (!option) return std::nullopt;
  if (!option->fixed) return PrecisionChoice::Auto;
  switch (*option->fixed) {
    case core::Precision::Double: return PrecisionChoice::Double;
    case core::Precision::Long: return PrecisionChoice::Long;
    case core::Precision::Quad: break;
  }
  return PrecisionChoice::Quad;
}

std::optional<SimulateRequest> readSimulateRequest(const OptionValues& options, Format format, QString& error) {
  SimulateRequest request;
  request.sampled = options.isSet("sample-step") || options.isSet("sample-times");
  if ((format == Format::Csv || format == Format::Summary) && request.sampled) {
    error = "--sample-step and --sample-times are written in --format json and jsonl only";
    return std::nullopt;
  }
  if (format == Format::Csv && options.isSet("trust") && options.value("trust") != "off") {
    error = "--trust: --format csv writes the events alone; the error estimate is in --format summary or json";
    return std::nullopt;
  }
  const std::optional<PrecisionChoice> precision = readPrecisionChoice(options, error);
  if (!precision) return std::nullopt;
  request.precision = *precision;
  const auto trust = core::parseTrustMode((options.isSet("trust") ? options.value("trust") : QStringLiteral("auto"))
                                              .toStdString());
  if (!trust) {
    error = QStringLiteral("--trust: '%1' is not off, auto or full").arg(options.value("trust"));
    return std::nullopt;
  }
  // (csv writes no estimate: it runs none)
  request.trust = format == Format::Csv ? core::TrustMode::Off : *trust;
  request.contacts = options.isSet("t-end") ? std::numeric_limits<long>::max() : 100;
  if (options.isSet("contacts")) {
    const auto count = countOption(options, "contacts", 0, error);
    if (!count) return std::nullopt;
    request.contacts = long(*count);
  }
  if (options.isSet("search-steps")) {
    const auto steps = countOption(options, "search-steps", 1, error);
    if (!steps) return std::nullopt;
    request.searchSteps = *steps;
  }
  if (options.isSet("sample-step") && options.isSet("sample-times")) {
    error = "--sample-step and --sample-times exclude each other";
    return std::nullopt;
  }
  if (options.isSet("sample-step")) {
    const core::ParsedScalar<double> step = core::parseScalar<double>(options.value("sample-step").toStdString());
    if (!step.value || !(*step.value > 0) || !std::isfinite(*step.value)) {
      error = QStringLiteral("--sample-step: '%1' is not a time > 0").arg(options.value("sample-step"));
      return std::nullopt;
    }
    request.sampleStep = *step.value;
  }
  if (options.isSet("sample-times")) {
    for (const QString& part : options.value("sample-times").split(',')) {
      const core::ParsedScalar<double> t = core::parseScalar<double>(part.trimmed().toStdString());
      if (!t.value || !(*t.value >= 0) || !std::isfinite(*t.value) ||
          (!request.sampleTimes.empty() && *t.value < request.sampleTimes.back())) {
        error = QStringLiteral("--sample-times: '%1' is not a list of times >= 0, ascending")
                    .arg(options.value("sample-times"));
        return std::nullopt;
      }
      request.sampleTimes.push_back(*t.value);
    }
  }
  if (options.isSet("t-end")) request.tEnd = options.value("t-end").toStdString();
  const auto given = [&options](const char* name) -> std::optional<GivenNumbers> {
    if (!options.isSet(name)) return std::nullopt;
    GivenNumbers numbers;
    if (const auto values = options.numbers(name)) {
      numbers.numeric = true;
      numbers.numbers.assign(values->begin(), values->end());
    } else {
      numbers.text = options.value(name).toStdString();
    }
    return numbers;
  };
  request.start = {given("state"), given("glo-weights"), given("onepp"), given("glo"), given("perturb")};
  return request;
}

void EventTableSink::begin(const AnyRun& run, const std::vector<std::string>&) {
  // refilled by a raised run (nothing of it was handed over)
  m_table.count = 0;
  m_table.rows.clear();
  m_table.decimals.clear();
  std::visit([&](const auto& began) {
    m_table.masses = std::size_t(began.ready->numbers.size());
    m_table.stopped = began.ready->numbers.stopped();
  }, run);
}
void EventTableSink::event(const core::BasicChainEvent<double>& event) {
  if (!m_table.discard) appendRow(m_table, event);
}
void EventTableSink::event(const core::BasicChainEvent<long double>& event) {
  if (!m_table.discard) appendRow(m_table, event);
}
void EventTableSink::event(const core::BasicChainEvent<core::Quad>& event) {
  if (!m_table.discard) appendRow(m_table, event);
}


Parsed<std::shared_ptr<const PreparedMassChain>> recentChain(const OptionValues& options, std::stop_token stop) {
  // the chains read last, by their options' text: a script that runs one chain many times (the
  // Python module's simulate) reads and readies it once (its modes: a binary128 eigensolve)
  static std::mutex recentMutex;
  static std::deque<std::pair<std::string, std::shared_ptr<const PreparedMassChain>>> recent;
  // Each option as its length and its bytes (no two option sets read alike), numbers given as
  // numbers by their bits: their text costs more than the run of a short request
  std::string key;
  for (const char* name : {"masses", "springs", "right-spring", "stop-mass", "gap", "frequencies", "design-branch", "m1",
                           "m2", "k1", "k2", "branch"}) {
    if (const auto numbers = options.numbers(name)) {
      key.append("n").append(std::to_string(numbers->size())).append(":");
      key.append(reinterpret_cast<const char*>(numbers->data()), numbers->size_bytes());
    } else if (options.isSet(name)) {
      const std::string text = options.value(name).toStdString();
      key.append("t").append(std::to_string(text.size())).append(":").append(text);
    } else {
      key.append("-");
    }
  }
  {
    const std::lock_guard lock(recentMutex);
    for (const auto& [text, made] : recent) {
      if (text == key) return {made, {}};
    }
  }
  auto made = PreparedMassChain::make(options, std::move(stop));
  if (made.value) {
    const std::lock_guard lock(recentMutex);
    recent.emplace_back(key, *made.value);
    if (recent.size() > 16) recent.pop_front();
  }
  return made;
}

int runSimulate(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  // the chain first: what is wrong with it is said before what is wrong with the run
  const auto chain = recentChain(options, stop);
  if (!chain.value) {
    error = chain.error;
    return chain.error.isEmpty() ? kExitInterrupted : kExitInvalidInput;  // (empty: the design was interrupted)
  }
  const QString formatText = options.isSet("format") ? options.value("format") : QStringLiteral("json");
  if (!QStringList{"json", "jsonl", "csv", "summary"}.contains(formatText)) {
    error = QStringLiteral("--format: '%1' is not json, jsonl, csv or summary").arg(formatText);
    return kExitInvalidInput;
  }
  const Format format = formatText == "csv"       ? Format::Csv
                        : formatText == "summary" ? Format::Summary
                        : formatText == "jsonl"   ? Format::JsonLines
                                                  : Format::Json;
  std::optional<SimulateRequest> request = readSimulateRequest(options, format, error);
  if (!request) return kExitInvalidInput;
  request->notesStarts = !options.isSet("masses");
  StreamWriter writer(io, format, request->precision);
  const SimulateOutcome outcome = simulate(**chain.value, *request, writer, stop);
  return writer.finish(outcome, request->sampled, stop, error);
}

}  // namespace grazelab::cli
