// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <optional>
#include <stop_token>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/numbers/scalar.h"
#include "core/solver/chain_run.h"
#include "core/solver/trust.h"

// `simulate` as a typed command, the one both faces call: the command line reads its options
// into a SimulateRequest and writes the outcome as json, jsonl, csv or a summary
// (simulate_command.cpp); the Python module hands the events to NumPy and the outcome to a
// Result. The request and the outcome are plain structs without Qt, and neither face reads text
// back: a refusal is a status and its line, the notes are a list. (Behind them the start is
// still read by the command line's readers, io/chain_start.h and io/cli_input.h.)
namespace grazelab::cli {

class PreparedMassChain;

/// Numbers given to a start's option: their decimal text, read in the run's precision (0.1 is
/// 0.1 to binary128's digits); or the doubles themselves (the Python module), read as they are
/// in double and as their shortest decimal text in a wider precision.
struct GivenNumbers {
  std::string text;
  std::vector<double> numbers;
  bool numeric = false;  ///< given as `numbers`, not as `text`
};

/// Where a run starts: one of `state` (u1..uN, v1..vN), `gloWeights` (GLO_lambda at its touch),
/// `onepp` (the 1IPP orbit of that period, right after its impact) or, for the note's chain
/// written with the note's options, `glo` (lambda; GLO_0.5 when none is given), plus `perturb`.
struct StartRequest {
  std::optional<GivenNumbers> state, gloWeights, onepp, glo, perturb;
};

/// How precise a run is: one precision, or Auto (double, then the whole run again one
/// precision up while it ends undecided).
enum class PrecisionChoice { Auto, Double, Long, Quad };
std::string_view toString(PrecisionChoice choice);

/// One run of a prepared chain.
struct SimulateRequest {
  StartRequest start;
  /// the chain was written with the note's options: its start may be `glo`, GLO_0.5 by default
  bool notesStarts = false;
  long contacts = 100;             ///< at most this many contacts
  std::string tEnd;                ///< the run's end time as decimal text, read in its precision; empty: none
  std::int64_t searchSteps = 0;    ///< a two-mass detuned flight's search budget; 0: the default
  PrecisionChoice precision = PrecisionChoice::Auto;
  core::TrustMode trust = core::TrustMode::Auto;
  /// the state sampled every `sampleStep` from t = 0 or at `sampleTimes` (ascending), in double
  bool sampled = false;
  double sampleStep = 0;
  std::vector<double> sampleTimes = {};
};

/// A run in its precision S: the chain (owned by the prepared chain), its start, in words,
/// and, once it ended, the run's totals (its events went to the sink).
template <typename S>
struct RunIn {
  const core::BasicReadyChain<S>* ready = nullptr;
  core::BasicChainStart<S> start;
  std::string description;
  core::BasicChainRun<S> run;
  double seconds = 0;  ///< the run's own time, its shadow apart
};
using AnyRun = std::variant<RunIn<double>, RunIn<long double>, RunIn<core::Quad>>;

/// What a request's run reports as it goes. A run raised one precision up starts again from its
/// start: `begin` again, then every event again from the first.
class SimulateSink {
 public:
  virtual ~SimulateSink() = default;
  /// A run begins (its chain and start are read and good): `run` without its totals yet, and
  /// the notes on its start's rounding.
  virtual void begin(const AnyRun& run, const std::vector<std::string>& notes) = 0;
  virtual void event(const core::BasicChainEvent<double>& event) = 0;
  virtual void event(const core::BasicChainEvent<long double>& event) = 0;
  virtual void event(const core::BasicChainEvent<core::Quad>& event) = 0;
};

enum class SimulateStatus {
  Ran,      ///< the run ended (its stop reason says how: Cancelled when interrupted)
  Refused,  ///< bad input, or a chain or start no precision could read: `problem` says why
};

/// A run that ended undecided and was raised.
struct RaisedRun {
  core::Precision precision = core::Precision::Double;
  double tFinal = 0;  ///< where it ended undecided
  core::Trust trust;  ///< its error estimate over its events (none: no estimate was asked for)
};

struct SimulateOutcome {
  SimulateStatus status = SimulateStatus::Refused;
  std::string problem;  ///< why refused, one line
  core::Precision precision = core::Precision::Double;  ///< the precision that ran (or refused) last
  std::vector<std::string> escalations;                 ///< why each lower precision was left
  std::vector<RaisedRun> raised;                        ///< the runs that ended undecided, in order
  std::vector<std::string> notes;                       ///< on the start's rounding
  /// the run begun last (its totals once it ended), and the first run begun when another was
  /// begun after it (a run raised one precision up)
  std::optional<AnyRun> last, first;
  core::Trust trust;  ///< the last run's error estimate
  /// why the estimate does not count the start's rounding (its shadow started from the run's
  /// start widened); empty when it does
  std::string widenedStart;
  std::vector<std::pair<double, core::ChainState>> samples;  ///< (sampled) in double
  bool samplesTruncated = false;  ///< more samples were asked for than are held (4 000 000)

  /// The first run begun: the documents' head (the chain, the note's model, the start as read
  /// first). Only when one began.
  const AnyRun& head() const { return first ? *first : *last; }
};

/// Runs `request` on `chain`, its events to `sink` as they happen. `stop` ends the run (stop
/// reason Cancelled, no estimate).
SimulateOutcome simulate(const PreparedMassChain& chain, const SimulateRequest& request, SimulateSink& sink,
                         std::stop_token stop = {});

/// Why a run stopped, in words (empty for the plain stops: contacts, time).
std::string stopMessage(core::StopReason stop, bool widest);

}  // namespace grazelab::cli
