// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli simulate`: one exact run of any chain (core/solver/chain_run.h), however it is
// written (--masses ..., or the note's --m1 --m2 --k1 --k2 --branch --gap), streamed as it happens
// with its error estimate beside it, and --precision auto (the run again from its input one
// precision up when the lower one ends undecided).
#include "commands/simulate_command.h"

#include <QStringList>

#include <algorithm>
#include <chrono>
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
#include <vector>

#include "core/orbits/chain_glo.h"
#include "core/orbits/chain_onepp.h"
#include "core/orbits/starts.h"
#include "core/solver/chain_run.h"
#include "core/solver/simulate.h"
#include "core/solver/trust.h"
#include "exit_codes.h"
#include "io/chain_start.h"
#include "io/cli_input.h"
#include "io/cli_output.h"
#include "io/json_value.h"
#include "io/prepared_chain.h"

namespace grazelab::cli {
namespace {

using V = JsonValue;

// The names of a chain's columns, made once per document (an owned name is an allocation)
struct ColumnNames {
  std::vector<JsonKey> u, v, vPre;  ///< u1..uN, v1..vN, v1_pre..vN_pre
  JsonKey vPost;  ///< v<s>_post

  // (names appended, not "literal" + string: GCC 12 warns falsely on that at -O2)
  static std::string name(char letter, Eigen::Index i, const char* suffix = "") {
    return std::string(1, letter).append(std::to_string(i)).append(suffix);
  }
  ColumnNames(Eigen::Index n, int stopped) : vPost(JsonKey::owned(name('v', stopped, "_post"))) {
    for (Eigen::Index i = 1; i <= n; ++i) {
      u.push_back(JsonKey::owned(name('u', i)));
      v.push_back(JsonKey::owned(name('v', i)));
      vPre.push_back(JsonKey::owned(name('v', i, "_pre")));
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
      return "no contact (or release) was decided within the search's budget (1000 slowest periods; for a two-mass "
             "chain's detuned flight, --search-steps): the frequencies are not commensurate (give --t-end, or more "
             "--search-steps, to search longer)";
    default: return "";
  }
}

// A start refused: why, and whether the precision is the reason (a higher one may decide it)
struct StartRefusal {
  QString error;
  bool precisionBound = false;
};

// The start of a chain the note's kernel runs, as the note's options give it (--glo lambda,
// --onepp T, --state, --perturb; GLO_0.5 when none is given; --glo-weights 1 - lambda, lambda is
// --glo lambda), from the note's closed forms in S; the words that describe it and the notes on
// its rounding
template <typename S>
std::optional<core::BasicChainStart<S>> notesStart(const OptionValues& options, const core::BasicReadyChain<S>& ready,
                                                   StartRefusal& refusal, std::string& description,
                                                   std::vector<std::string>& notes) {
  if (options.isSet("glo") && options.isSet("glo-weights")) {
    refusal.error = "--glo and --glo-weights give the same start twice: give one";
    return std::nullopt;
  }
  const auto twoMass = notesRunOptions(options, refusal.error);
  if (!twoMass) return std::nullopt;
  const Parsed<core::StartSpec<S>> spec = parseStartSpec<S>(*twoMass, *ready.notesModel);
  if (!spec.value) {
    refusal.error = spec.error;
    return std::nullopt;
  }
  core::StartOrProblem<S> made = core::makeStart(*ready.notes, *spec.value);
  if (!made.start) {
    const bool onepp = spec.value->kind == core::StartSpec<S>::Kind::OnePeriodic;
    refusal.error = QString::fromStdString((onepp ? "--onepp: " : "") + made.problem +
                                           (made.undecided ? " (--precision auto goes higher)" : ""));
    refusal.precisionBound = made.undecided;
    return std::nullopt;
  }
  const auto problems = core::validateState(*ready.notesModel, made.start->state, "initial");
  if (!problems.empty()) {
    refusal.error = QString::fromStdString(core::describe(problems));
    return std::nullopt;
  }
  description = std::move(made.start->description);
  // core's notes on the start are about rounding: the command line can raise the precision
  for (const std::string& note : made.start->notes) notes.push_back(note + " (try --precision quad)");
  return core::BasicChainStart<S>{core::chainStateOf(made.start->state), made.start->stillModes};
}

// the most samples a json holds
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

// The samples asked for, in double (the json's columns), as the run passes them
struct HeldSamples {
  std::vector<std::pair<double, core::ChainState>> samples;
  bool truncated = false;
};

// the samples as columns t, u1..uN, v1..vN, in double
V samplesValue(const ColumnNames& names, const HeldSamples& held) {
  const std::size_t n = names.u.size();
  std::vector<std::vector<V>> columns(2 * n + 1);
  for (std::vector<V>& column : columns) column.reserve(held.samples.size());
  for (const auto& [t, state] : held.samples) {
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

// The fields before the events: the chain, the note's model of it when the note's kernel runs it
// (two masses stopped on the second, no wall, a 1:2 design or not commensurate: its frequencies,
// periods, mode shapes, lambda*), and the start
template <typename S>
std::vector<V::Field> headFields(const core::BasicReadyChain<S>& ready, const std::string& description,
                                 const ColumnNames& names, const core::BasicChainState<S>& start,
                                 const QString& precision) {
  std::vector<V::Field> head;
  head.emplace_back("chain", massChainValue(ready.numbers, ready.dynamics.period));
  if (ready.notesModel) {
    head.emplace_back("model", modelValue(ModelInput<S>{*ready.notesModel, *ready.notes}, precision.toStdString()));
  }
  head.emplace_back("initial", V::object({{"description", V::of(description)}, {"state", stateValue(names, S(0), start)}}));
  return head;
}

// What the output holds so far, across the rungs of --precision auto: a raised run starts again
// from its start and writes only the events past those a lower precision wrote (they stay on the
// output), comparing the last of them with its own
struct Written {
  bool begun = false;  ///< the head (json, jsonl) or header (csv) is out
  long events = 0;
  double lastTime = 0;
  core::EventType lastType = core::EventType::Impact;
  const char* precision = "";  ///< the precision that wrote them
  std::optional<bool> raisedAgrees;  ///< the raised run met the last of them again
  bool differed = false;  ///< a raised run differed from the events a lower one wrote (any rung)
  double stateError = 0, timeError = 0;  ///< their error, as the precision that wrote them estimated it
};

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

// The run of a chain read once, its run options `options`; `notesOptions`: the chain was written
// with the note's options (its starts then default to GLO_0.5 and take --glo)
int runPrepared(const PreparedMassChain& chain, const OptionValues& options, const Io& io, std::stop_token stop,
                QString& error, bool notesOptions) {
  const QString formatText = options.isSet("format") ? options.value("format") : QStringLiteral("json");
  if (!QStringList{"json", "jsonl", "csv", "summary"}.contains(formatText)) {
    error = QStringLiteral("--format: '%1' is not json, jsonl, csv or summary").arg(formatText);
    return kExitInvalidInput;
  }
  const Format format = formatText == "csv"       ? Format::Csv
                             : formatText == "summary" ? Format::Summary
                             : formatText == "jsonl"   ? Format::JsonLines
                                                       : Format::Json;
  const bool sampled = options.isSet("sample-step") || options.isSet("sample-times");
  if ((format == Format::Csv || format == Format::Summary) && sampled) {
    error = "--sample-step and --sample-times are written in --format json and jsonl only";
    return kExitInvalidInput;
  }
  if (format == Format::Csv && options.isSet("trust") && options.value("trust") != "off") {
    error = "--trust: --format csv writes the events alone; the error estimate is in --format summary or json";
    return kExitInvalidInput;
  }
  const QString precisionText = options.isSet("precision") ? options.value("precision") : QStringLiteral("auto");
  if (!QStringList{"auto", "double", "long", "quad"}.contains(precisionText)) {
    error = QStringLiteral("--precision: '%1' is not auto, double, long or quad").arg(precisionText);
    return kExitInvalidInput;
  }
  const auto trustMode = core::parseTrustMode(
      (options.isSet("trust") ? options.value("trust") : QStringLiteral("auto"))
          .toStdString());
  if (!trustMode) {
    error = QStringLiteral("--trust: '%1' is not off, auto or full").arg(options.value("trust"));
    return kExitInvalidInput;
  }
  // the Python module: the document as values, the events into its table (held there, up to its
  // bound) or, with events=False, nowhere
  const bool asValues = io.document != nullptr;
  const bool intoTable = asValues && io.chainEvents && !io.chainEvents->discard;
  long contacts = options.isSet("t-end") ? std::numeric_limits<long>::max() : 100;
  if (options.isSet("contacts")) {
    const auto count = countOption(options, "contacts", 0, error);
    if (!count) return kExitInvalidInput;
    contacts = long(*count);
  }
  std::int64_t searchSteps = 0;
  if (options.isSet("search-steps")) {
    const auto steps = countOption(options, "search-steps", 1, error);
    if (!steps) return kExitInvalidInput;
    searchSteps = *steps;
  }
  const auto asked = samplingOf(options, error);
  if (!asked) return kExitInvalidInput;
  const QString tEnd = options.isSet("t-end") ? options.value("t-end") : QString();
  // --precision auto: double, and the whole run again one precision up while it ends undecided
  // (a touch or a release within the precision's rounding)
  std::vector<std::string> escalations;
  Written written;
  std::vector<V::Field> head;
  // one rung of the ladder in S: the exit code when it ends the command, nothing to go up
  const auto rung = [&]<typename S>(const char* name, const char* next, bool last) -> std::optional<int> {
    // a refusal here: one the precision causes (a chain or start beyond its reach: a ratio beyond
    // its range, a fast phase that is rounding in it, an undecided return) goes up with auto; any
    // other is the answer (exit 2, one line). After a lower precision wrote events (it ended
    // undecided), a json or jsonl document is closed whole first, saying so.
    const auto refuse = [&](const QString& why, bool precisionBound) -> std::optional<int> {
      if (precisionBound && !last) {
        escalations.push_back(std::string("from ") + name + ": " + why.toStdString());
        return std::nullopt;
      }
      error = why;
      const bool lines = format == Format::JsonLines;
      if (written.begun && !asValues && (format == Format::Json || lines)) {
        std::vector<V> raised;
        for (const std::string& line : escalations) raised.push_back(V::of(line));
        const std::vector<V::Field> end{
            {"stop_reason", V::of(std::string(core::toString(core::StopReason::Undecided)))},
            {"message", V::of(std::string("the run ended undecided in a lower precision, and in ") + name +
                              " it is refused: " + why.toStdString())},
            {"precision", V::object({{"requested", V::of(precisionText.toStdString())},
                                     {"used", V::of(written.precision)},
                                     {"escalations", V::array(std::move(raised))}})}};
        writeEnd(io.out, end, lines, written.events);
      }
      return kExitInvalidInput;
    };
    const Parsed<core::BasicReadyChain<S>>& prepared = chain.ready<S>();
    if (!prepared.value) return refuse(prepared.error, prepared.precisionBound);
    const core::BasicReadyChain<S>& ready = *prepared.value;
    const core::BasicMassChain<S>& masses = ready.numbers;
    std::string description;
    std::vector<std::string> notes;
    std::optional<core::BasicChainStart<S>> start;
    if (ready.notesModel) {
      // the note's chain: the note's starts, from its closed forms (written with --masses, its
      // start is a chain's: one of --state, --glo-weights, --onepp)
      if (!notesOptions && (!noTwoMassStart(options, error) || !oneStartOf(options, 2, error))) return kExitInvalidInput;
      StartRefusal refusal;
      start = notesStart<S>(options, ready, refusal, description, notes);
      if (!start) return refuse(refusal.error, refusal.precisionBound);
    } else {
      if (!noTwoMassStart(options, error) || !oneStartOf(options, masses.size(), error)) return kExitInvalidInput;
      if (searchSteps > 0) {
        error = "--search-steps bounds the search of a two-mass chain's detuned flight (the note's kernel); this "
                "chain's searches go 1000 slowest periods (give --t-end to search longer)";
        return kExitInvalidInput;
      }
      QString why;
      start = chainStart<S>(options, masses, why, &description);
      if (!start) return refuse(why, false);
    }
    const auto limit = timeLimit<S>(tEnd, error);
    if (!limit) return kExitInvalidInput;
    const ColumnNames& names = ColumnNames::of(masses.size(), masses.stopped());
    // the Python module's table is refilled by a raised run (nothing of it was handed over)
    if (io.chainEvents) {
      ChainEventTable& table = *io.chainEvents;
      table.count = 0;
      table.rows.clear();
      table.decimals.clear();
      table.masses = std::size_t(masses.size());
      table.stopped = masses.stopped();
    }
    const bool lines = format == Format::JsonLines;
    const bool text = !asValues && (format == Format::Json || lines);
    if (!written.begun) {
      // the head once the start is known to be good (bad input writes nothing), in the
      // precision that wrote it first (a raised run's document keeps it, as its text does)
      for (const std::string& note : notes) std::fprintf(io.messages, "grazelab-cli: note: %s\n", note.c_str());
      head = headFields(ready, description, names, start->state, precisionText);
      if (!asValues && format == Format::Csv) {
        std::fputs(csvHeader(masses.size(), masses.stopped()).c_str(), io.out);
      } else if (text) {
        std::fputs(lines ? "{\"record\": \"run\", " : "{\n", io.out);
        writeFields(io.out, head, lines);
        std::fputs(lines ? "}\n" : ",\n  \"events\": [", io.out);
      }
      written.begun = true;
    }
    const long before = written.events;
    written.raisedAgrees.reset();
    // the error estimate, event by event as the run goes (TrustMonitor: the same run of the
    // chain read one precision up, binary128's scaled; a doubtful double run arbitrated in
    // binary128; Reference.TrustIsHonest holds it to an independent 50-digit reference)
    std::optional<core::TrustMonitor<S>> check;
    std::string widenedStart;  ///< why the shadow's start is the run's own, when it is
    if (format != Format::Csv) {
      using H = core::ShadowScalar<S>;
      const core::ChainShadow<S>& shadow = shadowFor<S>(chain, *trustMode);
      // the start read one precision up from the same input, so that its rounding counts as
      // error (the note's starts by the note's reader); a start not read there, widened
      std::optional<core::BasicChainStart<H>> upStart;
      if (shadow.usable()) {
        const core::BasicReadyChain<H>& up = *shadow.input;
        StartRefusal refusal;
        std::string words;
        std::vector<std::string> quiet;
        QString why;
        upStart = up.notesModel ? notesStart<H>(options, up, refusal, words, quiet)
                                : chainStart<H>(options, up.numbers, why, nullptr);
      }
      if (!upStart) {
        upStart = core::BasicChainStart<H>{{start->state.u.template cast<H>(), start->state.v.template cast<H>()},
                                           start->stillModes};
        if (shadow.usable()) {
          widenedStart = std::string("the shadow starts from the run's start widened (not read one precision up: its "
                                     "rounding is not in the estimate)");
        }
      }
      QString ignored;
      const auto upLimit = timeLimit<H>(tEnd, ignored);
      check.emplace(shadow, *upStart, contacts, upLimit ? *upLimit : H(*limit), *trustMode, stop, searchSteps);
    }
    if (stop.stop_requested() && !text) return kExitInterrupted;
    HeldSamples held;
    core::ChainSampling<S> sampling{asked->spacing, asked->times, {}};
    if (sampled) {
      sampling.sink = [&held](double t, const core::BasicChainState<S>& state) {
        if (held.samples.size() >= kMaxChainSamples) {
          held.truncated = true;
          return;
        }
        held.samples.emplace_back(t, core::ChainState{state.u.template cast<double>(), state.v.template cast<double>()});
      };
    }
    const auto began = std::chrono::steady_clock::now();  // the run's own time, its shadow apart
    long seen = 0;
    const core::ChainEventSink<S> sink = [&](const core::BasicChainEvent<S>& event) {
      if (check) check->observe(event);
      if (intoTable) appendRow(*io.chainEvents, event);
      if (intoTable && io.chainEvents->full) return;
      if (asValues || format == Format::Summary) return;
      if (++seen <= written.events) {
        if (seen == written.events) {
          // the raised run at the last event the lower precision wrote: the same event?
          using std::abs;
          written.raisedAgrees = event.type == written.lastType &&
                                 abs(core::toDouble(event.t) - written.lastTime) <= 1e-9 * (1 + abs(written.lastTime));
          if (!*written.raisedAgrees) written.differed = true;
        }
        return;
      }
      if (format == Format::Csv) {
        std::fputs(csvLine(event).c_str(), io.out);
      } else if (lines) {
        std::string record = oneLine(eventValue(names, event));
        record.insert(1, "\"record\": \"event\", ");
        std::fputs(record.append("\n").c_str(), io.out);
      } else {
        std::fputs((written.events == 0 ? "\n    " : ",\n    "), io.out);
        std::fputs(oneLine(eventValue(names, event)).c_str(), io.out);
      }
      ++written.events;
      written.lastTime = core::toDouble(event.t);
      written.lastType = event.type;
      written.precision = name;
    };
    const core::BasicChainRun<S> run = core::runChain(ready, *start, contacts, *limit, stop, sink, sampling, searchSteps);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    std::fflush(io.out);
    const bool cancelled = run.stop == core::StopReason::Cancelled;
    if (cancelled && !text) {
      if (format == Format::Csv) error = QStringLiteral("the %1 events before it are written").arg(written.events);
      return kExitInterrupted;
    }
    if (!last && run.stop == core::StopReason::Undecided) {
      escalations.push_back(std::string("undecided in ") + name + " at t = " + core::formatScalar(core::toDouble(run.tFinal)) +
                            ": the whole run again in " + next);
      if (check && written.events > before) {
        // the events this precision wrote stay on the output with its error: the final estimate
        // is at least theirs
        const core::Trust lower = check->finish(run);
        written.stateError = std::max(written.stateError, lower.stateError);
        written.timeError = std::max(written.timeError, lower.timeError);
      }
      return std::nullopt;
    }
    // events written before a raise stay on the output: say whether the raised run meets the
    // last of them again (same type, time to 1e-9)
    // (a stream, not string concatenation: GCC 12 warns falsely on that at -O2)
    std::ostringstream kept;
    if (before > 0 && !asValues && format != Format::Summary) {
      if (!written.raisedAgrees) {
        kept << "the run ends before the last of the " << before
             << " events written before the raise: the events past its end are the lower precision's";
      } else {
        kept << "events 1 to " << before << " were written before the raise, in a lower precision, and the raised run "
             << (*written.raisedAgrees ? "meets the last of them again (same type, time to 1e-9)"
                                       : "DIFFERS from the last of them: they are not to be trusted");
      }
      if (written.differed && written.raisedAgrees != false) {
        kept << "; an earlier raise DIFFERED from the events written before it: they are not to be trusted";
      }
    }
    if (format == Format::Csv) {
      if (!escalations.empty()) {
        std::fprintf(io.messages, "grazelab-cli: note: the run was raised to %s (undecided below it) after %ld rows; %s\n",
                     name, before,
                     before == 0              ? "every row is its own"
                     : !written.raisedAgrees  ? "it ends before the last of them: the rows past its end are the lower precision's"
                     : *written.raisedAgrees  ? "it meets the last of them again (same type, time to 1e-9)"
                                              : "it DIFFERS from the last of them: the rows before the raise are not to be trusted");
      }
      return 0;
    }
    // an interrupted json or jsonl still ends its document: the events so far, stop reason
    // cancelled, no estimate
    core::Trust trust;
    trust.reason = "not estimated: the run was interrupted";
    if (!cancelled) trust = check->finish(run);
    if (stop.stop_requested() && !text) return kExitInterrupted;
    if (!kept.str().empty()) {
      if (trust.verdict != core::Verdict::Unchecked) {
        trust.stateError = std::max(trust.stateError, written.stateError);
        trust.timeError = std::max(trust.timeError, written.timeError);
        const double worst = std::max(trust.stateError, trust.timeError);
        if (trust.verdict == core::Verdict::Ok && worst > core::kOkTolerance) {
          trust.verdict = worst > core::kHorizonTolerance ? core::Verdict::Unreliable : core::Verdict::Degraded;
        }
        kept << " (their estimated error " << std::max(written.stateError, written.timeError) << ")";
      }
      if (written.differed) trust.verdict = core::Verdict::Unreliable;
      trust.reason = kept.str() + "; " + trust.reason;
    }
    // (a fixed precision that could not decide a contact: the estimate says the run ended there,
    // at best degraded; the document's message says what a higher precision does)
    if (!widenedStart.empty() && trust.verdict != core::Verdict::Unchecked) trust.reason += "; " + widenedStart;
    if (format == Format::Summary) {
      const std::string used = std::string(name) + (precisionText == "auto" ? " (auto)" : "");
      std::fputs(summaryText(ready, *start, run, seconds, used, escalations, trust).c_str(), io.out);
      std::fflush(io.out);
      return 0;
    }
    using std::abs;
    std::vector<V> raised;
    for (const std::string& line : escalations) raised.push_back(V::of(line));
    const std::string message = stopMessage(run.stop, std::is_same_v<S, core::Quad>);
    std::vector<V::Field> end{
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
        {"precision", V::object({{"requested", V::of(precisionText.toStdString())},
                                 {"used", V::of(name)},
                                 {"escalations", V::array(std::move(raised))}})}};
    if (!escalations.empty()) {
      // the start the raised run used, in its digits (the head holds the one read first)
      end.back().second.fields.emplace_back("initial_state_used", stateValue(names, S(0), start->state));
    }
    // the run's own time, its shadow apart
    end.emplace_back("timing", V::object({{"seconds", V::number(seconds)},
                                          {"contacts_per_second",
                                           V::number(seconds > 0 ? double(run.contacts) / seconds : 0.0)}}));
    if (sampled) {
      end.emplace_back("samples", samplesValue(names, held));
      end.emplace_back("samples_truncated", V::of(held.truncated));
    }
    if (asValues) {
      std::vector<V::Field> fields = std::move(head);
      fields.emplace_back("events", V::null());
      for (V::Field& field : end) fields.push_back(std::move(field));
      *io.document = V::object(std::move(fields));
      return 0;
    }
    writeEnd(io.out, end, lines, written.events);
    if (!stop.stop_requested()) return 0;
    error = QStringLiteral("the %1 events before it are written, and the document's end").arg(written.events);
    return kExitInterrupted;
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


}  // namespace

int runSimulate(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  // the chains read last, by their options' text: a script that runs one chain many times (the
  // Python module's simulate) reads and readies it once (its modes: a binary128 eigensolve)
  static std::mutex recentMutex;
  static std::deque<std::pair<QString, std::shared_ptr<const PreparedMassChain>>> recent;
  QString key;
  for (const char* name : {"masses", "springs", "right-spring", "stop-mass", "gap", "frequencies", "design-branch", "m1",
                           "m2", "k1", "k2", "branch"}) {
    key.append(options.isSet(name) ? options.value(name) : QString()).append(QChar(';'));
  }
  std::shared_ptr<const PreparedMassChain> chain;
  {
    const std::lock_guard lock(recentMutex);
    for (const auto& [text, made] : recent) {
      if (text == key) chain = made;
    }
  }
  if (!chain) {
    auto made = PreparedMassChain::make(options, stop);
    if (!made.value && made.error.isEmpty()) return kExitInterrupted;
    if (!made.value) {
      error = made.error;
      return kExitInvalidInput;
    }
    chain = *made.value;
    const std::lock_guard lock(recentMutex);
    recent.emplace_back(key, chain);
    if (recent.size() > 16) recent.pop_front();
  }
  return runPrepared(*chain, options, io, stop, error, !options.isSet("masses"));
}

int runSimulate(const PreparedMassChain& chain, const OptionValues& options, const Io& io, std::stop_token stop,
                QString& error) {
  return runPrepared(chain, options, io, std::move(stop), error, false);
}

}  // namespace grazelab::cli
