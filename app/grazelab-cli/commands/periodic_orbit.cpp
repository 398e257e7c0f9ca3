// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `orbit`'s request -> outcome: one periodic impacting orbit, its multipliers, stability and
// checks, in the precision that decides it.
#include "commands/periodic_orbit.h"

#include <cstdio>
#include <optional>
#include <string>
#include <type_traits>

#include "commands/orbit_json.h"
#include "core/orbits/chain_kipp.h"
#include "core/orbits/onepp_family_points.h"
#include "core/version.h"
#include "io/chain_start.h"
#include "io/document_values.h"
#include "io/prepared_chain.h"

namespace grazelab::cli {
namespace {

// the closed form's data must be right to this (relative), or a higher precision is needed
constexpr double kDataAccuracy = 1e-9;

template <typename S>
JsonValue orbitValue(const FoundOrbit<S>& found, core::Precision precision) {
  using V = JsonValue;
  const core::PeriodicOrbit<S>& orbit = found.orbit;
  const core::TwoMassForm<S>& chain = found.chain;
  const S T2 = core::twoPi<S>() / chain.omegaSlow;
  std::vector<V> events;
  for (const core::BasicEvent<S>& e : orbit.events) {
    events.push_back(V::object({{"t", V::number(e.t)},
                                {"type", V::of(std::string(core::toString(e.type)))},
                                {"before", orbitStateValue(e.before)},
                                {"after", orbitStateValue(e.after)}}));
  }
  const auto& mu = orbit.multipliers;
  const std::string symmetry = core::orbitSymmetry(orbit, core::symmetryTolerance<S>());
  const core::BasicModel<S>& m = chain.model;
  return V::object(
      {{"format", V::of("grazelab-orbit")},
       {"precision", V::of(std::string(core::toString(precision)))},
       {"model", V::object({{"m1", V::number(m.m1)},
                            {"m2", V::number(m.m2)},
                            {"k1", V::number(m.k1)},
                            {"k2", V::number(S(chain.kappa * m.k1))},
                            {"gap", V::number(m.gap)},
                            {"T2", V::number(T2)}})},
       {"period", V::number(orbit.period)},
       {"T_over_T2", V::number(S(orbit.period / T2))},
       {"energy", V::number(orbit.energy)},
       {"impacts", V::of(std::int64_t(orbit.impacts))},
       {"state", orbitStateValue(orbit.state)},
       {"events", V::array(std::move(events))},
       {"trace", V::number(orbit.trace)},
       {"trace_error", V::number(orbit.traceError)},
       {"multipliers", V::array({V::array({V::number(mu[0][0]), V::number(mu[0][1])}),
                                 V::array({V::number(mu[1][0]), V::number(mu[1][1])})})},
       {"stability", V::of(std::string(core::toString(core::decidedStability(orbit))))},
       {"symmetry", symmetry.empty() ? V::null() : V::of(symmetry)},
       {"checks", V::object({{"det_minus_1", V::number(orbit.checks.detMinus1)},
                             {"trivial_pair", V::number(orbit.checks.trivialPair)},
                             {"periodicity_residual", V::number(orbit.checks.periodicityResidual)}})},
       {"min_impact_speed", V::number(orbit.minImpactSpeed)},
       {"min_clearance", V::number(orbit.minClearance)},
       {"admissible", V::of(true)},
       {"reason", V::null()},
       {"generator", V::of(std::string("grazelab-cli ") + kVersion)}});
}

// `text` as a number of S, or why not (named as the command line names its option).
template <typename S>
std::optional<S> numberIn(const std::string& text, const char* option, std::string& problem) {
  const core::ParsedScalar<S> parsed = core::parseScalar<S>(text);
  if (!parsed.value) problem = std::string("--") + option + ": '" + text + "' " + parsed.error;
  return parsed.value;
}

template <typename S>
JsonValue chainOrbitValue(const FoundChainOrbit<S>& found, core::Precision precision) {
  using V = JsonValue;
  const core::BasicChainPeriodicOrbit<S>& orbit = found.orbit;
  const core::ChainMonodromy<S>& monodromy = orbit.monodromy;
  std::vector<V> events;
  for (const core::BasicChainEvent<S>& e : orbit.events) {
    events.push_back(V::object({{"t", V::number(e.t)},
                                {"type", V::of(std::string(core::toString(e.type)))},
                                {"u", numbersValue(e.u)},
                                {"v_before", numbersValue(e.vBefore)},
                                {"v_after", V::number(e.vAfter)}}));
  }
  std::vector<V> multipliers, errors, onCircle, krein;
  for (const core::ChainMultiplier<S>& m : monodromy.multipliers) {
    multipliers.push_back(V::array({V::number(m.re), V::number(m.im)}));
    errors.push_back(V::number(m.error));
    onCircle.push_back(V::of(m.onCircle));
    krein.push_back(V::of(std::int64_t(m.krein)));
  }
  return V::object({{"format", V::of("grazelab-orbit")},
                    {"precision", V::of(std::string(core::toString(precision)))},
                    {"chain", values::massChain<V>(found.chain, found.commonPeriod)},
                    {"period", V::number(orbit.period)},
                    {"energy", V::number(orbit.energy)},
                    {"impacts", V::of(std::int64_t(orbit.impacts))},
                    {"state", V::object({{"u", numbersValue(orbit.state.u)}, {"v", numbersValue(orbit.state.v)}})},
                    {"events", V::array(std::move(events))},
                    {"multipliers", V::array(std::move(multipliers))},
                    {"multiplier_errors", V::array(std::move(errors))},
                    {"on_circle", V::array(std::move(onCircle))},
                    {"krein", V::array(std::move(krein))},
                    {"stability", V::of(std::string(core::toString(monodromy.stability)))},
                    {"checks", V::object({{"symplectic", V::number(monodromy.symplecticDefect)},
                                          {"trivial_pair", V::number(monodromy.trivialPairDefect)},
                                          {"det_minus_1", V::number(monodromy.detDefect)},
                                          {"periodicity_residual", V::number(orbit.periodicityResidual)},
                                          {"rounding", V::number(monodromy.rounding)}})},
                    {"admissible", V::of(true)},
                    {"reason", V::null()},
                    {"generator", V::of(std::string("grazelab-cli ") + kVersion)}});
}

// why an orbit's path is not a periodic orbit, in words
const char* orbitRefusalWords(core::OrbitRefusal refusal) {
  switch (refusal) {
    case core::OrbitRefusal::None: return "admissible";
    case core::OrbitRefusal::BadStart: return "its start is not just after an impact";
    case core::OrbitRefusal::Undecided: return "a contact of its path cannot be decided in this precision";
    case core::OrbitRefusal::ContactCount: return "its path makes another number of contacts";
    case core::OrbitRefusal::NotImpact: return "a contact of its path is a grazing or a stick";
    case core::OrbitRefusal::NotClosed: return "its path does not close to its rounding";
    case core::OrbitRefusal::Repeated: return "it is a shorter orbit repeated";
    case core::OrbitRefusal::TouchesStop: return "a flight touches the stop";
  }
  return "unknown";
}

}  // namespace

template <typename S>
OrbitOutcome chainOrbitByNewton(const core::BasicReadyChain<S>& ready, const OrbitRequest& request,
                                std::stop_token stop) {
  OrbitOutcome outcome;
  outcome.precision = core::precisionOf<S>();
  if (ready.numbers.floats()) {
    outcome.problem = std::string("orbit: ") + core::kFloatingChainHasNoOrbit;
    return outcome;
  }
  const core::ChainOrbitConstraint fixed = request.fixed;
  const bool atPeriod = fixed == core::ChainOrbitConstraint::Period;
  const std::optional<S> value = numberIn<S>(atPeriod ? request.period : request.energy, atPeriod ? "period" : "energy",
                                             outcome.problem);
  if (!value) return outcome;
  if (!(*value > 0)) {
    outcome.problem = std::string(atPeriod ? "--period: '" + request.period + "' is not a positive period"
                                           : "--energy: '" + request.energy + "' is not a positive energy");
    return outcome;
  }
  // the guess: u then v of every mass but the stopped one, and at a fixed period v_s last
  const Eigen::Index n = ready.dynamics.mass.size();
  const Eigen::Index s = ready.dynamics.stop;
  const std::size_t expected = std::size_t(2 * n - 2 + (atPeriod ? 1 : 0));
  // (one mass at a fixed energy: nothing to guess, --guess "")
  const std::vector<std::string> given =
      request.guess.size() == 1 && request.guess[0].empty() ? std::vector<std::string>{} : request.guess;
  if (given.size() != expected) {
    outcome.problem = "--guess: give " + std::to_string(expected) + " numbers: u then v of every mass but the stopped one (mass " +
                      std::to_string(s + 1) + ")" + (atPeriod ? ", then its speed v_s < 0 just after the impact" : "");
    return outcome;
  }
  core::BasicChainState<S> guess{core::ChainVector<S>::Zero(n), core::ChainVector<S>::Zero(n)};
  guess.u[s] = ready.dynamics.gap;
  std::size_t next = 0;
  for (core::ChainVector<S>* part : {&guess.u, &guess.v}) {
    for (Eigen::Index j = 0; j < n; ++j) {
      if (j == s) continue;
      const std::optional<S> x = numberIn<S>(given[next++], "guess", outcome.problem);
      if (!x) return outcome;
      (*part)[j] = *x;
    }
  }
  if (atPeriod) {
    const std::optional<S> vs = numberIn<S>(given[next], "guess", outcome.problem);
    if (!vs) return outcome;
    if (!(*vs < 0)) {
      outcome.problem = "--guess: the stopped mass's speed just after the impact must be below 0, not " + given[next];
      return outcome;
    }
    guess.v[s] = *vs;
  }
  core::ChainOrbitSearch<S> search = core::findChainOrbit(ready, guess, request.impacts, fixed, *value, std::move(stop));
  if (!search.orbit) {
    outcome.problem = "orbit: " + std::string(core::toString(search.problem));
    if (search.refusal != core::OrbitRefusal::None) outcome.problem += std::string(": ") + orbitRefusalWords(search.refusal);
    if (search.refusal == core::OrbitRefusal::Undecided) outcome.status = OrbitStatus::Undecided;
    return outcome;
  }
  outcome.status = OrbitStatus::Found;
  outcome.found = FoundChainOrbit<S>{ready.numbers, ready.dynamics.period, std::move(*search.orbit)};
  return outcome;
}

template OrbitOutcome chainOrbitByNewton(const core::BasicReadyChain<double>&, const OrbitRequest&, std::stop_token);
template OrbitOutcome chainOrbitByNewton(const core::BasicReadyChain<long double>&, const OrbitRequest&,
                                         std::stop_token);
template OrbitOutcome chainOrbitByNewton(const core::BasicReadyChain<core::Quad>&, const OrbitRequest&,
                                         std::stop_token);

namespace {

// The orbit of any chain in precision S: the 1IPP orbit of period request.period by its 2N x 2N
// monodromy, or a kIPP orbit by Newton.
template <typename S>
OrbitOutcome chainOrbitIn(const PreparedMassChain& prepared, const OrbitRequest& request, std::stop_token stop) {
  OrbitOutcome outcome;
  outcome.precision = core::precisionOf<S>();
  const Parsed<core::BasicReadyChain<S>>& ready = prepared.ready<S>();
  if (!ready.value) {
    outcome.problem = ready.error.toStdString();
    return outcome;
  }
  if (request.impacts != 0 || ready.value->numbers.floats()) {
    return chainOrbitByNewton<S>(*ready.value, request, std::move(stop));
  }
  const std::optional<S> T = numberIn<S>(request.period, "period", outcome.problem);
  if (!T) return outcome;
  core::ChainOnePeriodicStability<S> found = core::chainOnePeriodicStability(*ready.value, *T);
  if (found.onePeriodic != core::OnePeriodicRefusal::None) {
    outcome.problem = "orbit: no 1IPP orbit of period " + request.period + ": " + onePeriodicRefusalWords(found.onePeriodic);
    if (found.onePeriodic == core::OnePeriodicRefusal::NotDecided) outcome.status = OrbitStatus::Undecided;
    return outcome;
  }
  if (!found.orbit.admissible()) {
    outcome.problem = "orbit: the 1IPP data of period " + request.period + " are no orbit in " +
                      std::string(core::toString(outcome.precision)) + ": " + orbitRefusalWords(found.orbit.refusal);
    if (found.orbit.refusal == core::OrbitRefusal::Undecided) outcome.status = OrbitStatus::Undecided;
    return outcome;
  }
  outcome.status = OrbitStatus::Found;
  outcome.found = FoundChainOrbit<S>{ready.value->numbers, ready.value->dynamics.period, std::move(found.orbit)};
  return outcome;
}

// The orbit in precision S.
template <typename S>
OrbitOutcome orbitIn(const PreparedMassChain& prepared, const OrbitRequest& request, std::stop_token stop) {
  OrbitOutcome outcome;
  outcome.precision = core::precisionOf<S>();
  const Parsed<ModelInput<S>>& model = prepared.twoMassForm<S>();
  if (!model.value) {
    // not the note's shape: the 1IPP orbit of any chain (the note's chain whose ratio S cannot
    // hold is refused as before)
    if (prepared.isTheNotesChain()) {
      outcome.problem = model.error.toStdString();
      return outcome;
    }
    return chainOrbitIn<S>(prepared, request, std::move(stop));
  }
  // a kIPP orbit at a fixed period: Newton on the return map of any chain, this one as two masses
  if (request.impacts != 0 && request.fixed == core::ChainOrbitConstraint::Period) {
    return chainOrbitIn<S>(prepared, request, std::move(stop));
  }
  const core::TwoMassForm<S>& chain = model.value->chain;
  core::OrbitSearch<S> search;
  if (request.impacts == 0) {
    const std::optional<S> T = numberIn<S>(request.period, "period", outcome.problem);
    if (!T) return outcome;
    search = core::onePeriodicOrbitStability(chain, *T);
    if (!search.orbit && search.refusal != core::OrbitRefusal::Undecided) {
      // say where the family is, to the resolution of a scan of 400 periods
      const S T2 = core::twoPi<S>() / chain.omegaSlow;
      std::string parts;
      for (const auto& part : core::onePeriodicParts(chain, 400)) {
        char text[64];
        std::snprintf(text, sizeof text, "%s[%.4f, %.4f]", parts.empty() ? "" : " and ",
                      core::toDouble(S(part[0] / T2)), core::toDouble(S(part[1] / T2)));
        parts += text;
      }
      if (!parts.empty()) search.problem += "; this chain's 1IPP orbits have T/T2 in about " + parts;
    }
  } else {
    if (request.impacts < 1 || request.impacts > 64) {
      outcome.problem = "--impacts: '" + std::to_string(request.impacts) + "' is not a number of impacts from 1 to 64";
      return outcome;
    }
    const std::optional<S> energy = numberIn<S>(request.energy, "energy", outcome.problem);
    if (!energy) return outcome;
    if (!(*energy > 0)) {
      outcome.problem = "--energy: '" + request.energy + "' is not a positive energy";
      return outcome;
    }
    const bool two = request.guess.size() == 2;
    const core::ParsedScalar<S> u1 = core::parseScalar<S>(two ? request.guess[0] : std::string());
    const core::ParsedScalar<S> v1 = core::parseScalar<S>(two ? request.guess[1] : std::string());
    if (!u1.value || !v1.value) {
      std::string given;
      for (const std::string& x : request.guess) given += (given.empty() ? "" : ",") + x;
      outcome.problem = "--guess: '" + given + "' is not two numbers u1,v1";
      return outcome;
    }
    search = core::findOrbit(chain, *energy, *u1.value, *v1.value, request.impacts, stop);
  }
  if (!search.orbit) {
    outcome.problem = "orbit: " + search.problem;
    if (search.refusal == core::OrbitRefusal::Undecided) outcome.status = OrbitStatus::Undecided;
    return outcome;
  }
  if (core::toDouble(search.dataError) > kDataAccuracy) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "orbit --onepp: this near a multiple of T1 or T2 the closed form's data are right only to "
                  "about %.1g (relative) in %s: use --precision quad (or auto)",
                  core::toDouble(search.dataError), std::string(core::toString(outcome.precision)).c_str());
    outcome.problem = text;
    outcome.status = OrbitStatus::Undecided;
    return outcome;
  }
  outcome.status = OrbitStatus::Found;
  outcome.found = FoundOrbit<S>{chain, std::move(*search.orbit)};
  return outcome;
}

}  // namespace

OrbitOutcome solveOrbit(const PreparedMassChain& chain, const OrbitRequest& request, std::stop_token stop) {
  switch (request.precision) {
    case PrecisionChoice::Double: return orbitIn<double>(chain, request, stop);
    case PrecisionChoice::Long: return orbitIn<long double>(chain, request, stop);
    case PrecisionChoice::Quad: return orbitIn<core::Quad>(chain, request, stop);
    case PrecisionChoice::Auto: break;
  }
  // double, and again in long double then binary128 when a contact is too near tangent or the
  // orbit's class is not decided (binary128's answer is kept either way: its class then says so)
  const auto classUndecided = [](const OrbitOutcome& outcome) {
    return std::visit(
        [](const auto& found) {
          using Found = std::decay_t<decltype(found)>;
          if constexpr (std::is_same_v<Found, std::monostate>) return false;
          else if constexpr (requires { found.commonPeriod; })
            return found.orbit.monodromy.stability == core::ChainStability::Undecided;
          else return core::decidedStability(found.orbit) == core::Stability::Undecided;
        },
        outcome.found);
  };
  // raised for its class alone, an orbit found is kept when the higher precision finds none
  // (Newton may stall there, next to the nearly singular DP - I of a class on the boundary)
  const auto raised = [](OrbitOutcome outcome, OrbitOutcome higher) {
    if (outcome.status == OrbitStatus::Found && higher.status != OrbitStatus::Found) return outcome;
    return higher;
  };
  OrbitOutcome outcome = orbitIn<double>(chain, request, stop);
  if (outcome.status == OrbitStatus::Undecided || classUndecided(outcome)) {
    outcome = raised(std::move(outcome), orbitIn<long double>(chain, request, stop));
  }
  if (outcome.status == OrbitStatus::Undecided || classUndecided(outcome)) {
    outcome = raised(std::move(outcome), orbitIn<core::Quad>(chain, request, stop));
  }
  return outcome;
}

JsonValue orbitDocument(const OrbitOutcome& outcome) {
  return std::visit(
      [&outcome](const auto& found) -> JsonValue {
        using Found = std::decay_t<decltype(found)>;
        if constexpr (std::is_same_v<Found, std::monostate>) {
          return JsonValue::null();
        } else if constexpr (requires { found.commonPeriod; }) {
          return chainOrbitValue(found, outcome.precision);
        } else {
          return orbitValue(found, outcome.precision);
        }
      },
      outcome.found);
}

}  // namespace grazelab::cli
