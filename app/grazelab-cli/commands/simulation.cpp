// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// One run of a prepared chain with its error estimate beside it, and PrecisionChoice::Auto: the
// run again from its input one precision up when the lower one ends undecided.
#include "commands/simulation.h"

#include <chrono>
#include <limits>
#include <type_traits>

#include "core/orbits/starts.h"
#include "core/solver/simulate.h"
#include "io/chain_start.h"
#include "io/cli_input.h"
#include "io/prepared_chain.h"

namespace grazelab::cli {
namespace {

// the most samples a run holds
constexpr std::size_t kMaxSamples = 4'000'000;

// A start refused: why, and whether the precision is the reason (a higher one may decide it)
struct StartRefusal {
  QString error;
  bool precisionBound = false;
};

// The start's options as the start readers take them (--state, --glo-weights, ...)
OptionValues startOptions(const StartRequest& start) {
  std::vector<GivenOption> given;
  const auto add = [&given](const char* name, const std::optional<GivenNumbers>& numbers) {
    if (!numbers) return;
    GivenOption option{name, QString::fromStdString(numbers->text), {}, numbers->numeric};
    option.numbers.assign(numbers->numbers.begin(), numbers->numbers.end());
    given.push_back(std::move(option));
  };
  add("state", start.state);
  add("glo-weights", start.gloWeights);
  add("onepp", start.onepp);
  add("glo", start.glo);
  add("perturb", start.perturb);
  return OptionValues(std::move(given));
}

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

// the run's end time in S (0: none given), or nothing with `error` set
template <typename S>
std::optional<S> timeLimit(const std::string& tEnd, std::string& error) {
  if (tEnd.empty()) return S(0);
  const core::ParsedScalar<S> parsed = core::parseScalar<S>(tEnd);
  if (!parsed.value || !(*parsed.value > 0) || !core::isFinite(*parsed.value)) {
    error = "--t-end: '" + tEnd + "' is not a positive finite time";
    return std::nullopt;
  }
  return *parsed.value;
}

// The rungs of one request: each precision's run in turn, into one outcome
class Ladder {
 public:
  Ladder(const PreparedMassChain& chain, const SimulateRequest& request, SimulateSink& sink, std::stop_token stop)
      : m_chain(chain), m_request(request), m_options(startOptions(request.start)), m_sink(sink), m_stop(stop) {}

  SimulateOutcome climb() && {
    const bool automatic = m_request.precision == PrecisionChoice::Auto;
    if (automatic || m_request.precision == PrecisionChoice::Double) {
      if (rung<double>(!automatic)) return std::move(m_outcome);
    }
    if (automatic || m_request.precision == PrecisionChoice::Long) {
      if (rung<long double>(!automatic)) return std::move(m_outcome);
    }
    rung<core::Quad>(true);
    return std::move(m_outcome);
  }

 private:
  // A refusal: one the precision causes (a chain or start beyond its reach: a ratio beyond its
  // range, a fast phase that is rounding in it, an undecided return) goes up with Auto (false);
  // any other is the answer (true)
  template <typename S>
  bool refuse(const QString& why, bool precisionBound, bool last) {
    if (precisionBound && !last) {
      m_outcome.escalations.push_back("from " + std::string(core::toString(core::precisionOf<S>())) + ": " +
                                      why.toStdString());
      return false;
    }
    return refuse(why.toStdString());
  }
  bool refuse(std::string why) {
    m_outcome.status = SimulateStatus::Refused;
    m_outcome.problem = std::move(why);
    return true;
  }

  // The run in S: true when it is the answer, false to go one precision up
  template <typename S>
  bool rung(bool last) {
    m_outcome.precision = core::precisionOf<S>();
    const Parsed<core::BasicReadyChain<S>>& prepared = m_chain.ready<S>();
    if (!prepared.value) return refuse<S>(prepared.error, prepared.precisionBound, last);
    const core::BasicReadyChain<S>& ready = *prepared.value;
    RunIn<S> ran;
    ran.ready = &ready;
    std::vector<std::string> notes;
    QString error;
    if (ready.notesModel) {
      // the note's chain: the note's starts, from its closed forms (written with --masses, its
      // start is a chain's: one of --state, --glo-weights, --onepp)
      if (!m_request.notesStarts && (!noTwoMassStart(m_options, error) || !oneStartOf(m_options, 2, error))) {
        return refuse(error.toStdString());
      }
      StartRefusal refusal;
      auto start = notesStart<S>(m_options, ready, refusal, ran.description, notes);
      if (!start) return refuse<S>(refusal.error, refusal.precisionBound, last);
      ran.start = std::move(*start);
    } else {
      if (!noTwoMassStart(m_options, error) || !oneStartOf(m_options, ready.numbers.size(), error)) {
        return refuse(error.toStdString());
      }
      if (m_request.searchSteps > 0) {
        return refuse("--search-steps bounds the search of a two-mass chain's detuned flight (the note's kernel); "
                      "this chain's searches go 1000 slowest periods (give --t-end to search longer)");
      }
      auto start = chainStart<S>(m_options, ready.numbers, error, &ran.description, &ready.dynamics);
      if (!start) return refuse<S>(error, false, last);
      ran.start = std::move(*start);
    }
    std::string why;
    const auto limit = timeLimit<S>(m_request.tEnd, why);
    if (!limit) return refuse(std::move(why));
    if (!m_outcome.last) {
      m_outcome.notes = notes;  // (the first start's: a raised run's are the same words)
    } else if (!m_outcome.first) {
      m_outcome.first = std::move(m_outcome.last);  // the head of a raised run's documents
    }
    return run<S>(std::get<RunIn<S>>(m_outcome.last.emplace(std::move(ran))), *limit, notes, last);
  }

  // The run begun in S, its start good: true when it is the answer, false to go one precision up
  template <typename S>
  bool run(RunIn<S>& ran, const S& limit, const std::vector<std::string>& notes, bool last) {
    const std::string_view name = core::toString(core::precisionOf<S>());
    const core::BasicReadyChain<S>& ready = *ran.ready;
    m_sink.begin(*m_outcome.last, notes);

    // the error estimate, event by event as the run goes (TrustMonitor: the same run of the
    // chain read one precision up, binary128's scaled; a doubtful double run arbitrated in
    // binary128; Reference.TrustIsHonest holds it to an independent 50-digit reference)
    m_outcome.widenedStart.clear();
    core::TrustMonitor<S> check(shadow<S>(), startUp<S>(ran), m_request.contacts, upLimit<S>(limit), m_request.trust,
                                m_stop, m_request.searchSteps);
    core::ChainSampling<S> sampling{m_request.sampleStep, m_request.sampleTimes, {}};
    m_outcome.samples.clear();
    m_outcome.samplesTruncated = false;
    if (m_request.sampled) {
      sampling.sink = [this](double t, const core::BasicChainState<S>& state) {
        if (m_outcome.samples.size() >= kMaxSamples) {
          m_outcome.samplesTruncated = true;
          return;
        }
        m_outcome.samples.emplace_back(
            t, core::ChainState{state.u.template cast<double>(), state.v.template cast<double>()});
      };
    }
    const auto began = std::chrono::steady_clock::now();  // the run's own time, its shadow apart
    const core::ChainEventSink<S> events = [&](const core::BasicChainEvent<S>& event) {
      check.observe(event);
      m_sink.event(event);
    };
    ran.run = core::runChain(ready, ran.start, m_request.contacts, limit, m_stop, events, sampling,
                             m_request.searchSteps);
    ran.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    if (!last && ran.run.stop == core::StopReason::Undecided) {
      m_outcome.escalations.push_back("undecided in " + std::string(name) + " at t = " +
                                      core::formatScalar(core::toDouble(ran.run.tFinal)) + ": the whole run again in " +
                                      std::string(core::toString(core::Precision(int(core::precisionOf<S>()) + 1))));
      m_outcome.raised.push_back({core::precisionOf<S>(), core::toDouble(ran.run.tFinal), check.finish(ran.run)});
      return false;
    }
    m_outcome.status = SimulateStatus::Ran;
    m_outcome.trust = core::Trust{};
    m_outcome.trust.reason = "not estimated: the run was interrupted";
    if (ran.run.stop != core::StopReason::Cancelled) m_outcome.trust = check.finish(ran.run);
    return true;
  }

  // the shadow chain the error estimate runs (none made for TrustMode::Off, which runs none)
  template <typename S>
  const core::ChainShadow<S>& shadow() const {
    static const core::ChainShadow<S> none;
    return m_request.trust == core::TrustMode::Off ? none : m_chain.shadow<S>();
  }

  // The run's start read one precision up from the same input, so that its rounding counts as
  // error (the note's starts by the note's reader); a start not read there, widened
  template <typename S>
  core::BasicChainStart<core::ShadowScalar<S>> startUp(const RunIn<S>& ran) {
    using H = core::ShadowScalar<S>;
    const core::ChainShadow<S>& up = shadow<S>();
    std::optional<core::BasicChainStart<H>> read;
    if (up.usable()) {
      const core::BasicReadyChain<H>& chain = *up.input;
      StartRefusal refusal;
      std::string words;
      std::vector<std::string> quiet;
      QString why;
      read = chain.notesModel ? notesStart<H>(m_options, chain, refusal, words, quiet)
                              : chainStart<H>(m_options, chain.numbers, why, nullptr, &chain.dynamics);
    }
    if (read) return std::move(*read);
    if (up.usable()) {
      m_outcome.widenedStart = "the shadow starts from the run's start widened (not read one precision up: its "
                               "rounding is not in the estimate)";
    }
    return {{ran.start.state.u.template cast<H>(), ran.start.state.v.template cast<H>()}, ran.start.stillModes};
  }

  // the run's end time read one precision up
  template <typename S>
  core::ShadowScalar<S> upLimit(const S& limit) const {
    using H = core::ShadowScalar<S>;
    std::string ignored;
    const auto up = timeLimit<H>(m_request.tEnd, ignored);
    return up ? *up : H(limit);
  }

  const PreparedMassChain& m_chain;
  const SimulateRequest& m_request;
  const OptionValues m_options;  ///< the start's, as the start readers take them
  SimulateSink& m_sink;
  std::stop_token m_stop;
  SimulateOutcome m_outcome;
};

}  // namespace

std::string_view toString(PrecisionChoice choice) {
  switch (choice) {
    case PrecisionChoice::Auto: return "auto";
    case PrecisionChoice::Double: return "double";
    case PrecisionChoice::Long: return "long";
    case PrecisionChoice::Quad: return "quad";
  }
  return "auto";
}

std::string stopMessage(core::StopReason stop, bool widest) {
  switch (stop) {
    case core::StopReason::NoFurtherContact:
      return "the flight stays below the stop for a whole period of commensurate frequencies, or its modes' "
             "amplitudes together fall short of the stop, or a floating chain drifts away from it for good: linear "
             "forever";
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

SimulateOutcome simulate(const PreparedMassChain& chain, const SimulateRequest& request, SimulateSink& sink,
                         std::stop_token stop) {
  return Ladder(chain, request, sink, std::move(stop)).climb();
}

}  // namespace grazelab::cli
