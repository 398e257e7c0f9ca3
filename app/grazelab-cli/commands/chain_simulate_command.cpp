// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/chain_simulate_command.h"

#include <QStringList>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "commands/simulate_command.h"
#include "core/orbits/chain_glo.h"
#include "core/orbits/chain_onepp.h"
#include "core/solver/chain_run.h"
#include "core/solver/chain_trust.h"
#include "exit_codes.h"
#include "io/chain_start.h"
#include "io/cli_input.h"
#include "io/cli_output.h"
#include "io/json_value.h"
#include "io/prepared_chain.h"

namespace grazelab::cli {
namespace {

using V = JsonValue;

// the events of a chain of N masses are kept in memory until the json document is written (csv
// and summary stream them: no bound but the run's own)
constexpr long kMaxChainContacts = 1'000'000;
constexpr long kMaxStreamedContacts = std::numeric_limits<long>::max();

enum class ChainFormat { Json, Csv, Summary };

// The names of a chain's columns, made once per document (an owned name is an allocation)
struct ColumnNames {
  std::vector<JsonKey> u, v, vPre;  ///< u1..uN, v1..vN, v1_pre..vN_pre
  JsonKey vPost;  ///< v<s>_post

  ColumnNames(Eigen::Index n, int stopped) : vPost(JsonKey::owned("v" + std::to_string(stopped) + "_post")) {
    for (Eigen::Index i = 1; i <= n; ++i) {
      u.push_back(JsonKey::owned("u" + std::to_string(i)));
      v.push_back(JsonKey::owned("v" + std::to_string(i)));
      vPre.push_back(JsonKey::owned("v" + std::to_string(i) + "_pre"));
    }
  }
  /// The names of a chain of n masses stopped on mass `stopped`, made once per process (a short
  /// run's document would spend more on them than on its run)
  static const ColumnNames& of(Eigen::Index n, int stopped) {
    static std::mutex mutex;
    static std::map<std::pair<Eigen::Index, int>, ColumnNames> made;
    const std::lock_guard lock(mutex);
    return made.try_emplace({n, stopped}, n, stopped).first->second;
  }
};

// a state at time t as the two-mass documents write it: {t, u1..uN, v1..vN}
template <typename S>
V stateValue(const ColumnNames& names, const S& t, const core::BasicChainState<S>& state) {
  std::vector<V::Field> fields;
  fields.reserve(2 * names.u.size() + 1);
  fields.emplace_back("t", V::number(t));
  for (std::size_t i = 0; i < names.u.size(); ++i) fields.emplace_back(names.u[i], V::number(state.u[Eigen::Index(i)]));
  for (std::size_t i = 0; i < names.v.size(); ++i) fields.emplace_back(names.v[i], V::number(state.v[Eigen::Index(i)]));
  return V::object(std::move(fields));
}

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

// `widest`: the run is in binary128, the last precision there is to raise it to
std::string stopMessage(core::StopReason stop, bool widest) {
  switch (stop) {
    case core::StopReason::NoFurtherContact:
      return "the frequencies are commensurate and the flight stays below the stop for a whole period: "
             "linear forever";
    case core::StopReason::Undecided:
      return "a contact the precision cannot decide: the stopped mass's top comes within rounding of the stop "
             "(a grazing, a slow impact and a miss all fit; the run ends at that flight's start), or it rests "
             "there with no force either way (or, held there, its force comes back to zero without a change of "
             "sign it can see)" +
             std::string(widest ? ": binary128, the widest precision, cannot decide it either"
                                : ": --precision auto raises the run until it is decided");
    case core::StopReason::SearchBudget:
      return "no contact (or release) was decided within 1000 slowest periods: the frequencies are not "
             "commensurate (give --t-end to search longer)";
    default: return "";
  }
}

// The note's chain given by --masses (writesTheNotesChain), its start given as a chain's: run by
// the note's engine, as the two-mass options would run it (the same bits)
int runTheNotesChain(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  if (!noTwoMassStart(options, error) || !oneStartOf(options, 2, error)) return kExitInvalidInput;
  const auto twoMass = notesRunOptions(options, error);
  if (!twoMass) return kExitInvalidInput;
  const auto precision = parsePrecisionOption(*twoMass, error);
  if (!precision) return kExitInvalidInput;
  const auto trust = parseTrustOption(*twoMass, error);
  if (!trust) return kExitInvalidInput;
  return runSimulate(*twoMass, *precision, *trust, io, std::move(stop), error);
}

// The run in S, as the document's fields from "events" on; nothing when the start is refused
// (`error`) or the run was stopped (`stopped`)
template <typename S>
struct ChainRunIn {
  core::BasicChainStart<S> start;  ///< its state, and the modes still in it
  std::string description;  ///< how the start was given, in words
  core::BasicChainRun<S> run;
  S tEnd = 0;
  std::vector<std::pair<double, core::ChainState>> samples;  ///< (t, state) asked for, in double
  bool samplesTruncated = false;
  /// a run whose events were not kept: its error estimate, made as they came (else empty)
  std::optional<core::Trust> trust;
};

// the most samples a json holds (as for two masses)
constexpr std::size_t kMaxChainSamples = 4'000'000;

// --sample-step DT or --sample-times t1,... (json only), or nothing with `error` set
std::optional<core::ChainSampling<double>> samplingOf(const OptionValues& options, QString& error) {
  core::ChainSampling<double> sampling;
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
    sampling.spacing = *step.value;
  }
  if (options.isSet("sample-times")) {
    for (const QString& part : options.value("sample-times").split(',')) {
      const core::ParsedScalar<double> t = core::parseScalar<double>(part.trimmed().toStdString());
      if (!t.value || !(*t.value >= 0) || !std::isfinite(*t.value) ||
          (!sampling.times.empty() && *t.value < sampling.times.back())) {
        error = QStringLiteral("--sample-times: '%1' is not a list of times >= 0, ascending")
                    .arg(options.value("sample-times"));
        return std::nullopt;
      }
      sampling.times.push_back(*t.value);
    }
  }
  return sampling;
}
// --t-end in S (0: none given), or nothing with `error` set
template <typename S>
std::optional<S> timeLimit(const QString& tEndText, QString& error) {
  if (tEndText.isEmpty()) return S(0);
  const core::ParsedScalar<S> parsed = core::parseScalar<S>(tEndText.toStdString());
  if (!parsed.value || !(*parsed.value > 0) || !core::isFinite(*parsed.value)) {
    error = QStringLiteral("--t-end: '%1' is not a positive finite time").arg(tEndText);
    return std::nullopt;
  }
  return *parsed.value;
}

// the shadow chain an error estimate of `mode` runs (none made for Off, which runs none)
template <typename S>
const core::ChainShadow<S>& shadowFor(const PreparedMassChain& chain, core::TrustMode mode) {
  static const core::ChainShadow<S> none;
  return mode == core::TrustMode::Off ? none : chain.shadow<S>();
}

// `keepEvents` false: the run's statistics alone (the Python module's events=False), its error
// estimate made online as the events come, none of them held
template <typename S>
std::optional<ChainRunIn<S>> runIn(const OptionValues& options, const PreparedMassChain& prepared, long contacts,
                                   const QString& tEndText, std::stop_token stop, QString& error,
                                   bool keepEvents = true, core::TrustMode trustMode = core::TrustMode::Off) {
  const core::BasicReadyChain<S>& ready = *prepared.ready<S>().value;
  const core::BasicMassChain<S>& chain = ready.numbers;
  std::string description;
  const auto start = chainStart<S>(options, chain, error, &description);
  if (!start) return std::nullopt;
  const auto tEnd = timeLimit<S>(tEndText, error);
  if (!tEnd) return std::nullopt;
  const auto asked = samplingOf(options, error);
  if (!asked) return std::nullopt;
  ChainRunIn<S> in{*start, std::move(description), {}, *tEnd, {}, false, std::nullopt};
  core::ChainSampling<S> sampling{asked->spacing, asked->times, {}};
  if (asked->spacing > 0 || !asked->times.empty()) {
    sampling.sink = [&](double t, const core::BasicChainState<S>& state) {
      if (in.samples.size() >= kMaxChainSamples) {
        in.samplesTruncated = true;
        return;
      }
      in.samples.emplace_back(t, core::ChainState{state.u.template cast<double>(), state.v.template cast<double>()});
    };
  }
  if (keepEvents) {
    in.run = core::runChain(ready, *start, contacts, *tEnd, stop, {}, sampling);
    return in;
  }
  core::ChainTrustCheck<S> check(shadowFor<S>(prepared, trustMode), *start, contacts, *tEnd, trustMode, stop);
  const core::ChainEventSink<S> sink = [&check](const core::BasicChainEvent<S>& event) { check.observe(event); };
  in.run = core::runChain(ready, *start, contacts, *tEnd, stop, sink, sampling);
  in.trust = check.finish(in.run);
  return in;
}

// the samples as columns t, u1..uN, v1..vN in double, as for two masses
template <typename S>
V samplesValue(const ColumnNames& names, const ChainRunIn<S>& in) {
  const std::size_t n = names.u.size();
  std::vector<std::vector<V>> columns(2 * n + 1);
  for (std::vector<V>& column : columns) column.reserve(in.samples.size());
  for (const auto& [t, state] : in.samples) {
    columns[0].push_back(V::number(t));
    for (std::size_t i = 0; i < n; ++i) {
      columns[1 + i].push_back(V::number(state.u[Eigen::Index(i)]));
      columns[1 + n + i].push_back(V::number(state.v[Eigen::Index(i)]));
    }
  }
  std::vector<V::Field> fields;
  fields.emplace_back("t", V::array(std::move(columns[0])));
  for (std::size_t i = 0; i < n; ++i) fields.emplace_back(names.u[i], V::array(std::move(columns[1 + i])));
  for (std::size_t i = 0; i < n; ++i) fields.emplace_back(names.v[i], V::array(std::move(columns[1 + n + i])));
  return V::object(std::move(fields));
}

// The run's events into `table` (the Python module's arrays): packed rows in double, and in a
// wider precision each number's decimal text
template <typename S>
void fillEventTable(ChainEventTable& table, const core::BasicChainRun<S>& run, const core::BasicMassChain<S>& chain) {
  table.masses = std::size_t(chain.size());
  table.stopped = chain.stopped();
  table.count = run.events.size();
  const std::size_t rowBytes = table.rowBytes();
  table.rows.assign(table.count * rowBytes, 0);
  for (std::size_t k = 0; k < table.count; ++k) {
    const core::BasicChainEvent<S>& event = run.events[k];
    char* row = table.rows.data() + k * rowBytes;
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
}

// (events null when they were not kept)
template <typename S>
V runDocument(const core::BasicReadyChain<S>& ready, const ChainRunIn<S>& in, V precision, const core::Trust& trust,
              bool sampled, bool keptEvents = true) {
  const core::BasicMassChain<S>& masses = ready.numbers;
  const core::BasicChainRun<S>& run = in.run;
  std::vector<V> events;
  events.reserve(run.events.size());
  const ColumnNames& names = ColumnNames::of(masses.size(), masses.stopped());
  for (const core::BasicChainEvent<S>& event : run.events) events.push_back(eventValue(names, event));
  const std::string message = stopMessage(run.stop, std::is_same_v<S, core::Quad>);
  using std::abs;
  V document = V::object(
      {{"chain", massChainValue(masses, ready.dynamics.period)},
       {"initial", V::object({{"description", V::of(in.description)}, {"state", stateValue(names, S(0), in.start.state)}})},
       {"events", keptEvents ? V::array(std::move(events)) : V::null()},
       {"final", stateValue(names, run.tFinal, run.final)},
       {"stop_reason", V::of(std::string(core::toString(run.stop)))},
       {"message", message.empty() ? V::null() : V::of(message)},
       {"contacts", V::object({{"total", V::of(std::int64_t(run.contacts))},
                               {"impacts", V::of(std::int64_t(run.impacts))},
                               {"grazings", V::of(std::int64_t(run.grazings))},
                               {"sticks", V::of(std::int64_t(run.sticks))},
                               {"releases", V::of(std::int64_t(run.releases))}})},
       {"energy", V::object({{"initial", V::number(run.energyInitial)},
                             {"final", V::number(run.energyFinal)},
                             {"relative_drift", V::number(S(abs(run.energyFinal / run.energyInitial - 1)))},
                             {"max_rel_drift", V::number(run.maxEnergyDrift)}})},
       {"accuracy", V::object({{"max_contact_residual", V::number(run.maxContactResidual)}})},
       {"trust", trustValue(trust)},
       {"precision", std::move(precision)}});
  if (sampled) {
    document.fields.emplace_back("samples", samplesValue(names, in));
    document.fields.emplace_back("samples_truncated", V::of(in.samplesTruncated));
  }
  return document;
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

// The summary of a streamed run: what the json says but its events, as the two-mass summary
// lays it out
template <typename S>
std::string summaryText(const core::BasicReadyChain<S>& ready, const ChainRunIn<S>& in, double seconds,
                        const std::string& precision, const std::vector<std::string>& raised,
                        const core::Trust& trust) {
  const core::BasicChainRun<S>& run = in.run;
  const core::BasicMassChain<S>& masses = ready.numbers;
  const core::BasicChainDynamics<S>& dynamics = ready.dynamics;
  using Vector = core::ChainVector<S>;
  std::string text;
  text += "chain          masses " + listText<S>(Eigen::Map<const Vector>(masses.masses.data(), masses.size())) +
          " springs " + listText<S>(Eigen::Map<const Vector>(masses.springs.data(), masses.size())) +
          (masses.rightSpring > 0 ? " right spring " + core::formatScalar(masses.rightSpring) : std::string()) +
          " stop on mass " + std::to_string(masses.stopped()) + " gap " + core::formatScalar(masses.gap) +
          (dynamics.period > 0 ? " (commensurate; T=" + core::formatScalar(dynamics.period) + ")" : std::string(" (not commensurate)")) + "\n";
  text += "start          u=" + listText<S>(in.start.state.u) + " v=" + listText<S>(in.start.state.v) + "\n";
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

}  // namespace

int runChainSimulate(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  if (writesTheNotesChain(options)) return runTheNotesChain(options, io, std::move(stop), error);
  const auto chain = PreparedMassChain::make(options, stop);
  if (!chain.value && chain.error.isEmpty()) return kExitInterrupted;
  if (!chain.value) {
    error = chain.error;
    return kExitInvalidInput;
  }
  return runChainSimulate(**chain.value, options, io, stop, error);
}

int runChainSimulate(const PreparedMassChain& chain, const OptionValues& options, const Io& io, std::stop_token stop,
                     QString& error) {
  if (chain.isTheNotesChain()) {
    const OptionValues whole(options, chain.givenOptions(), {});
    return runTheNotesChain(whole, io, std::move(stop), error);
  }
  if (!noTwoMassStart(options, error)) return kExitInvalidInput;
  const QString formatText = options.isSet("format") ? options.value("format") : QStringLiteral("json");
  if (!QStringList{"json", "csv", "summary"}.contains(formatText)) {
    error = QStringLiteral("--format: '%1' is not json, csv or summary for a chain of N masses").arg(formatText);
    return kExitInvalidInput;
  }
  const ChainFormat format = formatText == "csv" ? ChainFormat::Csv
                             : formatText == "summary" ? ChainFormat::Summary
                                                       : ChainFormat::Json;
  if (format != ChainFormat::Json && (options.isSet("sample-step") || options.isSet("sample-times"))) {
    error = "--sample-step and --sample-times are written in --format json for a chain of N masses";
    return kExitInvalidInput;
  }
  if (format == ChainFormat::Csv && options.isSet("trust") && options.value("trust") != "off") {
    error = "--trust: --format csv writes the events alone; the error estimate is in --format summary or json";
    return kExitInvalidInput;
  }
  const QString precisionText = options.isSet("precision") ? options.value("precision") : QStringLiteral("auto");
  if (!QStringList{"auto", "double", "long", "quad"}.contains(precisionText)) {
    error = QStringLiteral("--precision: '%1' is not auto, double, long or quad").arg(precisionText);
    return kExitInvalidInput;
  }
  const auto trustMode = core::parseTrustMode(
      (options.isSet("trust") ? options.value("trust") : QStringLiteral("auto")).toStdString());
  if (!trustMode) {
    error = QStringLiteral("--trust: '%1' is not off, auto or full").arg(options.value("trust"));
    return kExitInvalidInput;
  }
  // the chain in each rung's precision (its numbers read again from their text there), made
  // ready once
  const auto chainIn = [&]<typename S>() -> const core::BasicReadyChain<S>* {
    const Parsed<core::BasicReadyChain<S>>& ready = chain.ready<S>();
    if (!ready.value) error = ready.error;
    return ready.value ? &*ready.value : nullptr;
  };
  // the Python module's events=False: a json document without events, none of them held
  const bool keepEvents = !(format == ChainFormat::Json && io.events && io.events->discard);
  const long maxContacts = format == ChainFormat::Json && keepEvents ? kMaxChainContacts : kMaxStreamedContacts;
  long contacts = options.isSet("t-end") ? maxContacts : 100;
  if (options.isSet("contacts")) {
    bool ok = false;
    contacts = options.value("contacts").toLong(&ok);
    if (!ok || contacts < 0 || contacts > maxContacts) {
      error = QStringLiteral("--contacts: a whole number from 0 to %1 for a chain of N masses in json (its events are "
                             "kept until written; --format csv or summary stream them, with no bound)")
                  .arg(kMaxChainContacts);
      return kExitInvalidInput;
    }
  }
  const auto fullTrustHeld = [&] { return *trustMode == core::TrustMode::Full && contacts > kMaxChainContacts; };
  if ((format == ChainFormat::Summary || !keepEvents) && fullTrustHeld()) {
    error = QStringLiteral("--trust full holds the shadow run's events: at most %1 contacts (auto shadows the first "
                           "ones and stays bounded)")
                .arg(kMaxChainContacts);
    return kExitInvalidInput;
  }
  const QString tEnd = options.isSet("t-end") ? options.value("t-end") : QString();
  // --precision auto: double, and the whole run again one precision up while it ends undecided
  // (a touch or a release within the precision's rounding)
  std::vector<V> escalations;
  const auto report = [&](const char* used) {
    return V::object({{"requested", V::of(precisionText.toStdString())},
                      {"used", V::of(used)},
                      {"escalations", V::array(escalations)}});
  };
  const auto escalate = [&](const char* from, const char* to, double when) {
    escalations.push_back(V::of(std::string("undecided in ") + from + " at t = " + core::formatScalar(when) +
                                ": the whole run again in " + to));
  };
  // csv: the events written so far (a raised run writes only those past them); the header once
  // the start is known to be good (bad input writes nothing)
  long written = 0;
  bool headed = false;
  // the last event written (in the lower precision, when a run is raised): the raised run's
  // event of the same number is compared with it
  double lastWrittenTime = 0;
  core::EventType lastWrittenType = core::EventType::Impact;
  std::optional<bool> raisedAgrees;
  // a streamed rung (csv, summary): the events go out as they come, none is held
  const auto streamed = [&]<typename S>(const char* name, const char* next, bool last) -> std::optional<int> {
    const core::BasicReadyChain<S>* ready = chainIn.template operator()<S>();
    if (!ready) return kExitInvalidInput;
    const core::BasicMassChain<S>* masses = &ready->numbers;
    const auto start = chainStart<S>(options, *masses, error);
    if (!start) return kExitInvalidInput;
    const long before = written;  // rows a lower precision wrote
    raisedAgrees.reset();
    const auto limit = timeLimit<S>(tEnd, error);
    if (!limit) return kExitInvalidInput;
    if (format == ChainFormat::Csv && !headed) {
      std::fputs(csvHeader(masses->size(), masses->stopped()).c_str(), io.out);
      headed = true;
    }
    std::optional<core::ChainTrustCheck<S>> check;
    if (format == ChainFormat::Summary) check.emplace(shadowFor<S>(chain, *trustMode), *start, contacts, *limit, *trustMode, stop);
    if (stop.stop_requested()) return kExitInterrupted;
    const auto began = std::chrono::steady_clock::now();  // the run's own time, its shadow apart
    long seen = 0;
    const core::ChainEventSink<S> sink = [&](const core::BasicChainEvent<S>& event) {
      if (check) check->observe(event);
      if (format != ChainFormat::Csv) return;
      if (++seen <= written) {
        if (seen == written) {
          // the raised run at the last event the lower precision wrote: the same event?
          using std::abs;
          raisedAgrees = event.type == lastWrittenType &&
                         abs(core::toDouble(event.t) - lastWrittenTime) <= 1e-9 * (1 + abs(lastWrittenTime));
        }
        return;
      }
      std::fputs(csvLine(event).c_str(), io.out);
      ++written;
      lastWrittenTime = core::toDouble(event.t);
      lastWrittenType = event.type;
    };
    const ChainRunIn<S> in{*start, {}, core::runChain(*ready, *start, contacts, *limit, stop, sink), *limit, {}, false,
                           std::nullopt};
    std::fflush(io.out);
    if (in.run.stop == core::StopReason::Cancelled) {
      if (format == ChainFormat::Csv) error = QStringLiteral("the %1 events before it are written").arg(written);
      return kExitInterrupted;
    }
    if (!last && in.run.stop == core::StopReason::Undecided) {
      escalate(name, next, core::toDouble(in.run.tFinal));
      return std::nullopt;
    }
    if (format == ChainFormat::Summary) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
      std::vector<std::string> raised;
      for (const V& line : escalations) raised.push_back(line.text);
      const std::string used = std::string(name) + (precisionText == "auto" ? " (auto)" : "");
      std::fputs(summaryText(*ready, in, seconds, used, raised, check->finish(in.run)).c_str(), io.out);
      std::fflush(io.out);
    } else if (!escalations.empty()) {
      // the rows before the raise are the lower precision's: say whether the raised run meets
      // the last of them again (same type, time to 1e-9)
      std::fprintf(io.messages, "grazelab-cli: note: the run was raised to %s (undecided below it) after %ld rows; %s\n",
                   name, before,
                   before == 0      ? "every row is its own"
                   : !raisedAgrees  ? "it ends before the last of them: the rows past its end are the lower precision's"
                   : *raisedAgrees  ? "it meets the last of them again (same type, time to 1e-9)"
                                    : "it DIFFERS from the last of them: the rows before the raise are not to be trusted");
    }
    return 0;
  };
  // one rung of the ladder in S: the exit code when it ends the command, nothing to go up
  const auto rung = [&]<typename S>(const char* name, const char* next, bool last) -> std::optional<int> {
    if (format != ChainFormat::Json) return streamed.template operator()<S>(name, next, last);
    const core::BasicReadyChain<S>* ready = chainIn.template operator()<S>();
    if (!ready) return kExitInvalidInput;
    const auto in = runIn<S>(options, chain, contacts, tEnd, stop, error, keepEvents, *trustMode);
    if (!in) return kExitInvalidInput;
    if (in->run.stop == core::StopReason::Cancelled) return kExitInterrupted;
    if (!last && in->run.stop == core::StopReason::Undecided) {
      escalate(name, next, core::toDouble(in->run.tFinal));
      return std::nullopt;
    }
    const core::Trust trust = in->trust ? *in->trust
                                        : core::chainTrust(shadowFor<S>(chain, *trustMode), in->start, in->run, contacts,
                                                           in->tEnd, *trustMode, stop);
    if (stop.stop_requested()) return kExitInterrupted;
    // the Python module's arrays: the events straight into its table, not into the document
    const bool intoTable = keepEvents && io.chainEvents;
    if (intoTable) fillEventTable(*io.chainEvents, in->run, ready->numbers);
    emitDocument(io, runDocument(*ready, *in, report(name), trust,
                                 options.isSet("sample-step") || options.isSet("sample-times"), keepEvents && !intoTable));
    return 0;
  };
  const bool automatic = precisionText == "auto";
  if (automatic || precisionText == "double") {
    if (const auto code = rung.operator()<double>("double", "long", !automatic)) return *code;
  }
  if (automatic || precisionText == "long") {
    if (const auto code = rung.operator()<long double>("long", "quad", !automatic)) return *code;
  }
  return rung.operator()<core::Quad>("quad", "", true).value_or(kExitInvalidInput);
}

}  // namespace grazelab::cli
