// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `modes`'s request -> outcome: the atlas of the chain's nonlinear normal modes (issue 22).
#include "commands/modes_atlas_command.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <type_traits>

#include "commands/chain_modes_document.h"
#include "commands/orbit_json.h"
#include "core/orbits/chain_onepp.h"
#include "core/orbits/special_orbits.h"
#include "core/version.h"
#include "io/prepared_chain.h"

namespace grazelab::cli {
namespace {

using V = JsonValue;

template <typename S>
V endValue(const core::FamilyEnd<S>& end) {
  std::vector<V::Field> fields;
  fields.emplace_back("kind", V::of(std::string(core::toString(end.kind))));
  fields.emplace_back("energy", V::number(end.energy));
  fields.emplace_back("period", V::number(end.period));
  fields.emplace_back("state", orbitStateValue(end.state));
  if (core::isFinite(end.gloLambda)) fields.emplace_back("glo_lambda", V::number(end.gloLambda));
  if (end.kind == core::PointKind::GrazingOrbit || end.kind == core::PointKind::PeriodDoubling) {
    fields.emplace_back("exact", V::of(end.exact));
    fields.emplace_back("last_energy", V::number(end.lastEnergy));
  }
  if (end.family >= 0) fields.emplace_back("family", V::of(std::int64_t(end.family)));
  return V::object(std::move(fields));
}

// --energy-range's "A:B" read in S, or why not; none: not given
template <typename S>
std::optional<std::pair<S, S>> energyRangeOf(const ModesRequest& request, std::string& problem) {
  if (!request.energyRange) return std::nullopt;
  const std::string& text = *request.energyRange;
  const std::size_t colon = text.find(':');
  const bool two = colon != std::string::npos && text.find(':', colon + 1) == std::string::npos;
  const auto a = two ? core::parseScalar<S>(text.substr(0, colon)) : core::ParsedScalar<S>{};
  const auto b = two ? core::parseScalar<S>(text.substr(colon + 1)) : core::ParsedScalar<S>{};
  if (!a.value || !b.value || !(*a.value > 0) || !(*b.value > *a.value)) {
    problem = "--energy-range: '" + text + "' is not A:B with 0 < A < B";
    return std::nullopt;
  }
  return std::pair(*a.value, *b.value);
}

// the note's 1:2 chain: the two-mass atlas, its results unchanged
template <typename S>
ModesOutcome twoMassModes(const core::TwoMassForm<S>& chain, const ModesRequest& request,
                          const std::function<void(double, const std::string&)>& progress, std::stop_token stop) {
  ModesOutcome outcome;
  outcome.precision = core::precisionOf<S>();
  outcome.maxImpacts = request.maxImpacts;
  const core::AtlasEnergyRange<S> range = core::defaultAtlasEnergyRange(chain);
  S low = range.low;
  S high = range.high;
  if (request.energyRange) {
    const std::optional<std::pair<S, S>> given = energyRangeOf<S>(request, outcome.problem);
    if (!given) return outcome;
    std::tie(low, high) = *given;
  }
  int familiesDone = 0;
  core::ModesAtlas<S> atlas = core::computeModesAtlas<S>(
      chain, request.maxImpacts, low, high, stop, [&](const core::ModeFamily<S>& family) {
        if (progress) {
          progress(-1, "family " + std::to_string(++familiesDone) + " followed (" + std::to_string(family.impacts) +
                           " impacts per period)");
        }
      });
  if (stop.stop_requested() || !atlas.complete) {
    outcome.status = ModesStatus::Interrupted;
    return outcome;
  }
  outcome.atlas = AtlasIn<S>{chain, std::move(atlas), low, high};
  outcome.status = ModesStatus::Computed;
  return outcome;
}

// any other chain, of any N: the atlas of any chain
template <typename S>
ModesOutcome chainModes(const core::BasicReadyChain<S>& ready, const ModesRequest& request,
                        const std::function<void(double, const std::string&)>& progress, std::stop_token stop) {
  ModesOutcome outcome;
  outcome.precision = core::precisionOf<S>();
  outcome.maxImpacts = request.maxImpacts;
  if (ready.numbers.floats()) {
    outcome.problem = std::string("modes: ") + core::kFloatingChainHasNoOrbit;
    return outcome;
  }
  core::ChainAtlasOptions<S> options;
  options.maxImpacts = request.maxImpacts;
  const core::AtlasEnergyRange<S> range = core::defaultChainAtlasEnergyRange(ready);
  options.energyLow = range.low;
  options.energyHigh = range.high;
  if (request.energyRange) {
    const std::optional<std::pair<S, S>> given = energyRangeOf<S>(request, outcome.problem);
    if (!given) return outcome;
    std::tie(options.energyLow, options.energyHigh) = *given;
  }
  int familiesDone = 0;
  core::ChainAtlas<S> atlas =
      core::computeChainAtlas<S>(ready, options, stop, [&](const core::ChainAtlasFamily<S>& family) {
        if (progress) {
          progress(-1, "family " + std::to_string(++familiesDone) + " followed (" +
                           std::to_string(family.path.impacts) + " impacts per period)");
        }
      });
  if (stop.stop_requested() || !atlas.complete) {
    outcome.status = ModesStatus::Interrupted;
    return outcome;
  }
  if (atlas.searchBudgetExhausted) {
    const auto& omega = ready.dynamics.omega;
    char text[320];
    std::snprintf(text, sizeof text,
                  "modes: the returns of this chain's flights cannot be searched within the budget (its fastest "
                  "mode turns %.2g times per slowest period; %d periods of the 1IPP family ran out of it before "
                  "any was decided): no atlas",
                  double(omega.maxCoeff() / core::slowestFrequency(omega)), core::kFamilySearchBudgetRows);
    outcome.problem = text;
    return outcome;
  }
  outcome.atlas = ChainAtlasIn<S>{ready.numbers, ready.dynamics.period, std::move(atlas), options.energyLow,
                                  options.energyHigh};
  outcome.status = ModesStatus::Computed;
  return outcome;
}

template <typename S>
ModesOutcome modesIn(const PreparedMassChain& prepared, const ModesRequest& request,
                     const std::function<void(double, const std::string&)>& progress, std::stop_token stop) {
  const Parsed<core::BasicReadyChain<S>>& ready = prepared.ready<S>();
  if (!ready.value) {
    ModesOutcome outcome;
    outcome.problem = ready.error.toStdString();
    return outcome;
  }
  // the note's form (two masses, the second stopped, no wall) in 1:2 resonance
  if (ready.value->notes && ready.value->notes->resonant) {
    const Parsed<ModelInput<S>>& model = prepared.twoMassForm<S>();
    if (model.value && model.value->chain.resonant) return twoMassModes(model.value->chain, request, progress, stop);
  }
  return chainModes(*ready.value, request, progress, stop);
}

template <typename S>
ModesOutcome impactsFamilyIn(const PreparedMassChain& prepared, const ImpactsFamilyRequest& request,
                             std::stop_token stop) {
  ModesOutcome outcome;
  outcome.precision = core::precisionOf<S>();
  outcome.maxImpacts = request.start.impacts;
  const Parsed<core::BasicReadyChain<S>>& ready = prepared.ready<S>();
  if (!ready.value) {
    outcome.problem = ready.error.toStdString();
    return outcome;
  }
  OrbitOutcome found = chainOrbitByNewton<S>(*ready.value, request.start, stop);
  if (stop.stop_requested()) {
    outcome.status = ModesStatus::Interrupted;
    return outcome;
  }
  if (found.status != OrbitStatus::Found) {
    outcome.problem = "family: no orbit to follow: " + found.problem;
    return outcome;
  }
  const core::BasicChainPeriodicOrbit<S>& start = std::get<FoundChainOrbit<S>>(found.found).orbit;
  core::ChainContinuationOptions<S> options;
  options.maxOrbits = request.maxOrbits;
  options.energyLow = start.energy / 10000;
  options.energyHigh = start.energy * 10000;
  if (request.energyRange) {
    ModesRequest range;
    range.energyRange = request.energyRange;
    const std::optional<std::pair<S, S>> given = energyRangeOf<S>(range, outcome.problem);
    if (!given) return outcome;
    std::tie(options.energyLow, options.energyHigh) = *given;
    if (!(start.energy >= options.energyLow && start.energy <= options.energyHigh)) {
      outcome.problem = "--energy-range: the orbit found lies outside it (energy " +
                        core::formatScalar(start.energy) + ")";
      return outcome;
    }
  }
  core::ChainAtlasFamily<S> family = core::followChainFamily(*ready.value, start, options, stop);
  if (stop.stop_requested()) {
    outcome.status = ModesStatus::Interrupted;
    return outcome;
  }
  if (family.path.orbits.empty()) {  // (Newton's orbit, evaluated again, not admissible)
    outcome.problem = "family: the orbit found cannot be followed: " +
                      std::string(core::toString(family.lastEnd.kind));
    return outcome;
  }
  core::ChainAtlas<S> atlas;
  atlas.families.push_back(std::move(family));
  atlas.complete = true;
  outcome.atlas = ChainAtlasIn<S>{ready.value->numbers, ready.value->dynamics.period, std::move(atlas),
                                  options.energyLow, options.energyHigh, true};
  outcome.status = ModesStatus::Computed;
  return outcome;
}

template <typename S>
std::vector<double> tableOf(const core::ModeFamily<S>& family) {
  std::vector<double> rows;
  rows.reserve(family.orbits.size() * kModesColumns.size());
  for (const core::FamilyOrbit<S>& o : family.orbits) {
    const double period = double(o.period);
    for (double value : {double(o.energy), period, 2 * std::numbers::pi / period, double(o.trace),
                         double(int(o.stability)), double(o.state.u1), double(o.state.v1), double(o.minImpactSpeed),
                         // no interior maximum (the core's infinity): NaN, as the CSV's empty cell
                         core::isFinite(o.minClearance) ? double(o.minClearance) : std::nan("")}) {
      rows.push_back(value);
    }
  }
  return rows;
}

template <typename S>
V documentOf(const AtlasIn<S>& in, const ModesOutcome& outcome, const std::optional<std::string>& base) {
  const core::TwoMassForm<S>& chain = in.chain;
  const S T2 = core::twoPi<S>() / chain.omegaSlow;
  std::vector<V> families;
  for (const core::ModeFamily<S>& family : in.atlas.families) {
    std::vector<V> bifurcations;
    for (const core::FamilyBifurcation<S>& b : family.bifurcations) {
      std::vector<V::Field> point = bifurcationFields(b, T2, true);
      if (b.kind == core::PointKind::PeriodDoubling) {
        if (b.born >= 0) point.emplace_back("born_family", V::of(std::int64_t(b.born)));
        else if (!b.birthProblem.empty()) point.emplace_back("born_family", V::null());
        if (!b.birthProblem.empty()) point.emplace_back("birth_problem", V::of(b.birthProblem));
      }
      bifurcations.push_back(V::object(std::move(point)));
    }
    V born = V::object({{"kind", V::of(std::string(core::toString(family.birth)))},
                        {"family", family.parent < 0 ? V::null() : V::of(std::int64_t(family.parent))},
                        {"energy", V::number(family.bornEnergy)},
                        {"T", V::number(family.bornPeriod)}});
    std::vector<V::Field> fields{
        {"id", V::of(std::int64_t(family.id))},
        {"impacts", V::of(std::int64_t(family.impacts))},
        {"symmetry", family.symmetry.empty() ? V::null() : V::of(family.symmetry)},
        {"born_at", std::move(born)},
        {"side", family.birth == core::Birth::OnePeriodic ? V::null() : V::of(std::string(core::toString(family.side)))},
        {"start", endValue(family.startEnd)},
        {"end", endValue(family.end)},
        {"bifurcations", V::array(std::move(bifurcations))},
        {"rows", V::of(std::int64_t(family.orbits.size()))}};
    if (base) fields.emplace_back("file", V::of(*base + "-family-" + std::to_string(family.id) + ".csv"));
    families.push_back(V::object(std::move(fields)));
  }
  std::string columns;
  for (const std::string& column : kModesColumns) columns += (columns.empty() ? "" : ",") + column;
  const core::BasicModel<S>& m = chain.model;
  return V::object({
      {"format", V::of("grazelab-modes")},
      {"precision", V::of(std::string(core::toString(outcome.precision)))},
      {"model", V::object({{"m1", V::number(m.m1)}, {"m2", V::number(m.m2)}, {"k1", V::number(m.k1)},
                           {"k2", V::number(S(chain.kappa * m.k1))}, {"gap", V::number(m.gap)},
                           {"T2", V::number(T2)}})},
      {"max_impacts", V::of(std::int64_t(outcome.maxImpacts))},
      {"energy_range", V::array({V::number(in.low), V::number(in.high)})},
      {"families", V::array(std::move(families))},
      // what the fields of each family mean, apart from the families themselves
      {"about", V::object({
        {"columns", V::of(columns)},
        {"stability", V::of("elliptic (|tr| < 2, stable), hyperbolic (tr > 2), flip-hyperbolic (tr < -2), "
                      "parabolic (|tr| = 2 within rounding); in the .npy 0, 1, 2, 3")},
        {"start", V::of("a 1IPP part: its low-energy end; a family born at a flip: the flip (at twice its period)")},
        {"end", V::of("grazing-orbit (every impact speed, or one with a clearance, tends to 0: a grazing linear "
                "orbit), interior-grazing (a flight touches the stop), impact-speed-zero (one impact fades), "
                "period-doubling (the family comes back to a flip of `family`: its orbit becomes that "
                "flip's run twice), energy-limit (the --energy-range, or the 1IPP part's energy growing "
                "without bound), step-limit, undecided (the continuation, or the precision, cannot go "
                "on with no event in sight), classified from the last orbit within 5 % of w2 d or of the "
                "gap. A 1IPP part's ends are its closed form's, located by bisection in T. Where impact "
                "speeds tend to 0 the end is located by bisection in the energy when Newton at fixed "
                "energy can follow. energy, period and state are the last orbit's, except where exact "
                "is true: then they are the limit orbit's, known exactly (a period tending to an odd "
                "number of T1 belongs to GLOM1 alone; the 1IPP family ends on GLO_lambda*; a "
                "period-doubling end is the flip's orbit), last_energy being the last orbit computed. "
                "glo_lambda: the GLO_lambda a grazing-orbit end tends to")},
        {"born_at", V::of("one-periodic: a part of the 1IPP family from its closed form (energy and period T "
                    "of its orbit nearest the middle of the range); period-doubling: born at a flip of "
                    "`family`")},
        {"bifurcations", V::of("kind period-doubling (tr = -2), fold (tr = +2, the energy turns back) or "
                         "branch-point (tr = +2, it goes on); checked: the trace is within sqrt(eps) of "
                         "the level (false: not solved in this precision, where the search stopped); "
                         "energy_error: an estimate of how far the energy may be from the exact point "
                         "(the trace's error over its slope in the energy; null when it cannot be "
                         "estimated); born_family: the family born at a flip, or null with birth_problem saying why "
                         "none was found (absent beyond --max-impacts)")},
        {"min_clearance", V::of("the smallest distance below the stop of an interior maximum of u2 over "
                          "the gap (empty / NaN: no flight turns back below the stop)")}})},
      {"generator", V::of(std::string("grazelab-cli ") + kVersion)}});
}

}  // namespace

const std::vector<std::string> kModesColumns = {"energy", "period", "omega", "trace", "stability",
                                                "u1", "v1", "min_impact_speed", "min_clearance"};

ModesOutcome modesAtlas(const PreparedMassChain& chain, const ModesRequest& request,
                        const std::function<void(double, const std::string&)>& progress, std::stop_token stop) {
  if (request.maxImpacts < 1 || request.maxImpacts > 64) {
    ModesOutcome outcome;
    outcome.problem = "--max-impacts: '" + std::to_string(request.maxImpacts) + "' is not a number from 1 to 64";
    return outcome;
  }
  switch (request.precision) {
    case PrecisionChoice::Long: return modesIn<long double>(chain, request, progress, stop);
    case PrecisionChoice::Quad: return modesIn<core::Quad>(chain, request, progress, stop);
    case PrecisionChoice::Auto:
    case PrecisionChoice::Double: break;
  }
  return modesIn<double>(chain, request, progress, stop);
}

namespace {
// whether an outcome's atlas is that of a chain of N masses (not the two-mass atlas)
template <typename>
constexpr bool kOfAChain = false;
template <typename S>
constexpr bool kOfAChain<ChainAtlasIn<S>> = true;
}  // namespace

ModesOutcome impactsFamily(const PreparedMassChain& chain, const ImpactsFamilyRequest& request,
                           std::stop_token stop) {
  if (request.maxOrbits < 2 || request.maxOrbits > 1000000) {
    ModesOutcome outcome;
    outcome.problem = "--count: '" + std::to_string(request.maxOrbits) + "' is not a count of orbits from 2 to 1000000";
    return outcome;
  }
  switch (request.start.precision) {
    case PrecisionChoice::Long: return impactsFamilyIn<long double>(chain, request, stop);
    case PrecisionChoice::Quad: return impactsFamilyIn<core::Quad>(chain, request, stop);
    case PrecisionChoice::Auto:
    case PrecisionChoice::Double: break;
  }
  return impactsFamilyIn<double>(chain, request, stop);
}

std::size_t modesFamilyCount(const ModesOutcome& outcome) {
  return std::visit(
      [](const auto& in) -> std::size_t {
        if constexpr (std::is_same_v<std::decay_t<decltype(in)>, std::monostate>) return 0;
        else return in.atlas.families.size();
      },
      outcome.atlas);
}

std::vector<std::string> modesColumns(const ModesOutcome& outcome) {
  return std::visit(
      [](const auto& in) -> std::vector<std::string> {
        if constexpr (std::is_same_v<std::decay_t<decltype(in)>, std::monostate>) return {};
        else if constexpr (kOfAChain<std::decay_t<decltype(in)>>) return chainModesColumns(in.chain.size());
        else return kModesColumns;
      },
      outcome.atlas);
}

std::vector<double> modesTable(const ModesOutcome& outcome, std::size_t index) {
  return std::visit(
      [index](const auto& in) -> std::vector<double> {
        if constexpr (std::is_same_v<std::decay_t<decltype(in)>, std::monostate>) return {};
        else if constexpr (kOfAChain<std::decay_t<decltype(in)>>) return chainModesTable(in, index);
        else return tableOf(in.atlas.families[index]);
      },
      outcome.atlas);
}

JsonValue modesDocument(const ModesOutcome& outcome, const std::optional<std::string>& base) {
  return std::visit(
      [&](const auto& in) -> JsonValue {
        if constexpr (std::is_same_v<std::decay_t<decltype(in)>, std::monostate>) return JsonValue::null();
        else if constexpr (kOfAChain<std::decay_t<decltype(in)>>) return chainModesDocument(in, outcome, base);
        else return documentOf(in, outcome, base);
      },
      outcome.atlas);
}

}  // namespace grazelab::cli
