// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `family --onepp`'s request -> outcome: the 1IPP family of the note's chain (Theorem 2.1's
// closed form, each orbit's exact stability, the bifurcations) or of a chain of N masses.
#include "commands/onepp_family.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>

#include "commands/orbit_json.h"
#include "core/orbits/chain_glo.h"
#include "core/orbits/chain_monodromy.h"
#include "core/orbits/chain_onepp.h"
#include "core/orbits/onepp_family.h"
#include "core/orbits/onepp_family_points.h"
#include "core/orbits/special_orbits.h"
#include "core/solver/chain_run.h"
#include "core/version.h"
#include "io/cli_output.h"
#include "io/prepared_chain.h"

namespace grazelab::cli {
namespace {

using V = JsonValue;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The stability along the note's family in precision S: the trace and class of each admissible
// row, and the bifurcations over (0, T2) with the 2-impact orbit born at each flip.
struct FamilyStability {
  std::vector<double> traces;
  std::vector<double> codes;  ///< core::Stability as a number
  std::vector<JsonValue> bifurcations;
};

template <typename S>
std::optional<FamilyStability> familyStability(const core::TwoMassForm<S>& chain,
                                               const std::vector<core::OnePeriodicOrbit<double>>& family,
                                               const std::function<void(double, const std::string&)>& progress,
                                               std::stop_token stop) {
  const auto report = [&progress](double fraction, const std::string& text) {
    if (progress) progress(fraction, text);
  };
  FamilyStability result;
  for (const core::OnePeriodicOrbit<double>& p : family) {
    if (stop.stop_requested()) return std::nullopt;
    const std::size_t index = result.traces.size();
    if (index % 64 == 0) {
      report(0.9 * double(index) / double(family.size()),
             "stability of orbit " + std::to_string(index + 1) + " of " + std::to_string(family.size()));
    }
    const core::OrbitSearch<S> found = p.admissible ? core::onePeriodicOrbitStability(chain, S(p.T))
                                                    : core::OrbitSearch<S>{};
    result.traces.push_back(found.orbit ? double(found.orbit->trace) : kNaN);
    result.codes.push_back(found.orbit ? double(int(core::decidedStability(*found.orbit))) : kNaN);
  }
  const S T2 = core::twoPi<S>() / chain.omegaSlow;
  report(0.9, "bifurcations of the family");
  const std::vector<core::FamilyBifurcation<S>> points = core::onePeriodicBifurcations(chain, 2000, stop);
  std::vector<S> energies;
  for (const core::FamilyBifurcation<S>& b : points) energies.push_back(b.energy);
  for (const core::FamilyBifurcation<S>& b : points) {
    if (stop.stop_requested()) return std::nullopt;
    // this command writes "checked" only when false
    std::vector<JsonValue::Field> point = bifurcationFields(b, T2, false);
    if (b.kind == core::PointKind::Undecided && b.checked) {
      point.emplace_back("note", V::of("not a bifurcation: beyond this period the orbit's data lose their digits "
                                       "(near a multiple of T1) or a contact cannot be decided in this precision; "
                                       "a higher --precision moves the point"));
    }
    if (b.kind == core::PointKind::PeriodDoubling) {
      const core::FlipSwitch<S> born = core::switchAtFlip(chain, b, 1, core::birthOffsetBound(b, energies), stop);
      if (born.search.orbit) {
        const core::PeriodicOrbit<S>& o = *born.search.orbit;
        const std::string symmetry = core::orbitSymmetry(o, core::symmetryTolerance<S>());
        point.emplace_back("born", V::object({{"impacts", V::of(std::int64_t(o.impacts))},
                                              {"side", V::of(std::string(core::toString(born.side)))},
                                              {"energy", V::number(o.energy)},
                                              {"period", V::number(o.period)},
                                              {"trace", V::number(o.trace)},
                                              {"stability", V::of(std::string(core::toString(core::decidedStability(o))))},
                                              {"symmetry", symmetry.empty() ? V::null() : V::of(symmetry)},
                                              {"state", orbitStateValue(o.state)}}));
      } else {
        point.emplace_back("born", V::object({{"impacts", V::of(std::int64_t(2))}, {"problem", V::of(born.search.problem)}}));
      }
    }
    result.bifurcations.push_back(V::object(std::move(point)));
  }
  if (stop.stop_requested()) return std::nullopt;
  return result;
}

// The stability in the precision asked for (auto: double); none when stopped, or with `problem`
// when the chain cannot be read there.
std::optional<FamilyStability> stabilityIn(const PreparedMassChain& prepared, PrecisionChoice precision,
                                           const std::vector<core::OnePeriodicOrbit<double>>& family,
                                           const std::function<void(double, const std::string&)>& progress,
                                           std::stop_token stop, std::string& problem) {
  const auto in = [&]<typename S>(const Parsed<ModelInput<S>>& model) -> std::optional<FamilyStability> {
    if (!model.value) {
      problem = model.error.toStdString();
      return std::nullopt;
    }
    return familyStability(model.value->chain, family, progress, stop);
  };
  switch (precision) {
    case PrecisionChoice::Long: return in(prepared.twoMassForm<long double>());
    case PrecisionChoice::Quad: return in(prepared.twoMassForm<core::Quad>());
    case PrecisionChoice::Auto:
    case PrecisionChoice::Double: break;
  }
  return in(prepared.twoMassForm<double>());
}

FamilyOutcome notesFamily(const PreparedMassChain& prepared, const FamilyRequest& request,
                          const std::function<void(double, const std::string&)>& progress, std::stop_token stop) {
  FamilyOutcome outcome;
  outcome.count = request.count;
  const core::TwoMassForm<double>& chain = prepared.twoMassForm<double>().value->chain;
  const std::vector<core::OnePeriodicOrbit<double>> family = core::onePeriodicFamily(chain, request.count, stop);
  if (stop.stop_requested()) {
    outcome.status = FamilyStatus::Interrupted;
    return outcome;
  }
  const std::optional<FamilyStability> stability =
      stabilityIn(prepared, request.precision, family, progress, stop, outcome.problem);
  if (stop.stop_requested()) {
    outcome.status = FamilyStatus::Interrupted;
    return outcome;
  }
  if (!stability) return outcome;  // (refused: `problem` says why)
  outcome.columns = {"T", "omega", "V", "u1", "energy", "admissible", "trace", "stability"};
  outcome.table.reserve(family.size() * outcome.columns.size());
  for (std::size_t i = 0; i < family.size(); ++i) {
    const core::OnePeriodicOrbit<double>& p = family[i];
    const double omega = core::twoPi<double>() / p.T;
    for (double v : {p.T, omega, p.V, p.postImpact.u1, p.energy, p.admissible ? 1.0 : 0.0, stability->traces[i],
                     stability->codes[i]}) {
      outcome.table.push_back(v);
    }
    outcome.admissible += p.admissible ? 1 : 0;
    outcome.points.push_back({p.energy, omega, p.admissible});
  }
  const core::OnePeriodicOrbit<double> end = core::grazingEnd(chain);
  const core::Model& m = chain.model;
  NotesFamily notes;
  notes.m1 = m.m1;
  notes.m2 = m.m2;
  notes.k1 = m.k1;
  notes.k2 = m.k2;
  notes.gap = m.gap;
  notes.T2 = core::twoPi<double>() / chain.omegaSlow;
  notes.lambdaStar = core::lambdaStar(chain);
  notes.endT = end.T;
  notes.endV = end.V;
  notes.endU1 = end.postImpact.u1;
  notes.endEnergy = end.energy;
  notes.stabilityPrecision =
      request.precision == PrecisionChoice::Auto ? std::string("double") : std::string(toString(request.precision));
  notes.bifurcations = V::array(std::move(stability->bifurcations));
  outcome.of = std::move(notes);
  outcome.end = {end.energy, core::twoPi<double>() / end.T, true};
  char title[160];
  std::snprintf(title, sizeof title, "1IPP family: frequency against energy (m2/m1 = %.4g, λ* = %.4g)", m.m2 / m.m1,
                core::lambdaStar(chain));
  outcome.title = title;
  outcome.status = FamilyStatus::Computed;
  return outcome;
}

FamilyOutcome chainFamily(const PreparedMassChain& prepared, const FamilyRequest& request, std::stop_token stop) {
  FamilyOutcome outcome;
  outcome.count = request.count;
  const core::MassChain& chain = prepared.input().chain;
  const std::vector<core::ChainFamilyRow> rows = core::chainOnePeriodicFamily(chain, request.count, stop);
  if (stop.stop_requested()) {
    outcome.status = FamilyStatus::Interrupted;
    return outcome;
  }
  const core::ChainDynamics dynamics = core::chainDynamics(chain);
  if (!rows.empty() && rows.back().orbit.refusal == core::OnePeriodicRefusal::SearchBudget) {
    // (the family stopped after its first rows: none of them could be searched)
    char text[320];
    std::snprintf(text, sizeof text,
                  "family --onepp: the returns of this chain's flights cannot be searched within the budget "
                  "(its fastest mode turns %.2g times per slowest period; %d rows ran out of it before any was "
                  "admissible): no family",
                  dynamics.omega.maxCoeff() / core::slowestFrequency(dynamics.omega), core::kFamilySearchBudgetRows);
    outcome.problem = text;
    return outcome;
  }
  const double end = core::chainOnePeriodicEnd(chain);
  // the grazing limit of Theorem 2.1: the GLO the data tend to as T -> T_max
  ChainFamily described;
  described.chain = massChainValue(chain, dynamics.period);
  described.tMax = end;
  described.commensurate = dynamics.period > 0;
  described.weights = core::onePeriodicGrazingWeights(chain, end);
  const core::ChainGloStart glo = core::chainGloStart(chain, described.weights);
  if (glo.problem == core::GloStartProblem::None) {
    described.gloU = std::vector<double>(glo.state.u.data(), glo.state.u.data() + glo.state.u.size());
    described.gloEnergy = core::chainEnergy(chain, glo.state);
  }
  const Eigen::Index n = chain.size();
  const Eigen::Index pairs = 2 * n - 2;  // the nontrivial multipliers
  outcome.columns = {"T", "omega", "V", "energy", "admissible"};
  for (Eigen::Index i = 0; i < n; ++i) outcome.columns.push_back("u" + std::to_string(i + 1));
  outcome.columns.push_back("class");
  for (Eigen::Index k = 1; k <= pairs; ++k) {
    for (const char* part : {"_re", "_im", "_krein"}) outcome.columns.push_back("mu" + std::to_string(k) + part);
  }
  outcome.table.reserve(rows.size() * outcome.columns.size());
  const Parsed<core::ReadyChain>& ready = prepared.ready<double>();
  std::vector<core::CensusRow<double>> censuses;
  for (const core::ChainFamilyRow& row : rows) {
    if (stop.stop_requested()) {
      outcome.status = FamilyStatus::Interrupted;
      return outcome;
    }
    const core::ChainOnePeriodicOrbit& orbit = row.orbit;
    const bool hasData = orbit.refusal != core::OnePeriodicRefusal::MultipleOfPeriod &&
                         orbit.refusal != core::OnePeriodicRefusal::BadPeriod;
    const double omega = 2 * std::numbers::pi / row.T;
    for (double value : {row.T, omega, hasData ? orbit.V : kNaN, hasData ? orbit.energy : kNaN,
                         orbit.admissible() ? 1.0 : 0.0}) {
      outcome.table.push_back(value);
    }
    for (Eigen::Index i = 0; i < n; ++i) outcome.table.push_back(hasData ? orbit.postImpact.u[i] : kNaN);
    // the exact stability of an admissible row (its monodromy, core/orbits/chain_monodromy.h)
    std::optional<core::ChainOnePeriodicStability<double>> stability;
    if (orbit.admissible() && ready.value) stability = core::chainOnePeriodicStability(*ready.value, row.T);
    const bool stable = stability && stability->orbit.admissible();
    outcome.table.push_back(stable ? double(int(stability->orbit.monodromy.stability)) : kNaN);
    censuses.push_back({row.T, stable ? std::optional(core::censusOf(stability->orbit.monodromy)) : std::nullopt,
                        stable ? stability->orbit.monodromy.multipliers : std::vector<core::ChainMultiplier<double>>{}});
    for (Eigen::Index k = 0; k < pairs; ++k) {
      const core::ChainMultiplier<double>* mu =
          stable && std::size_t(k) < stability->orbit.monodromy.multipliers.size()
              ? &stability->orbit.monodromy.multipliers[std::size_t(k)]
              : nullptr;
      outcome.table.push_back(mu ? mu->re : kNaN);
      outcome.table.push_back(mu ? mu->im : kNaN);
      outcome.table.push_back(mu ? double(mu->krein) : kNaN);
    }
    outcome.admissible += orbit.admissible() ? 1 : 0;
    if (hasData) outcome.points.push_back({orbit.energy, omega, orbit.admissible()});
  }
  if (ready.value) described.bifurcations = core::chainOnePeriodicBifurcations(*ready.value, censuses, stop);
  if (stop.stop_requested()) {
    outcome.status = FamilyStatus::Interrupted;
    return outcome;
  }
  outcome.end = {described.gloEnergy, 2 * std::numbers::pi / end, true};
  outcome.title = "1IPP family of " + std::to_string(n) + " masses: frequency against energy";
  outcome.of = std::move(described);
  outcome.status = FamilyStatus::Computed;
  return outcome;
}

V numbers(const std::vector<double>& values) {
  std::vector<V> items;
  for (double value : values) items.push_back(V::number(value));
  return V::array(std::move(items));
}

V notesDocument(const FamilyOutcome& outcome, const NotesFamily& notes, const std::optional<std::string>& files) {
  std::vector<V::Field> fields{
      {"format", V::of("grazelab-family")},
      {"family", V::of("onepp")},
      {"model", V::object({{"m1", V::number(notes.m1)}, {"m2", V::number(notes.m2)}, {"k1", V::number(notes.k1)},
                           {"k2", V::number(notes.k2)}, {"gap", V::number(notes.gap)}, {"T2", V::number(notes.T2)}})},
      {"lambda_star", V::number(notes.lambdaStar)},
      {"grazing_end", V::object({{"T", V::number(notes.endT)},
                                 {"omega", V::number(core::twoPi<double>() / notes.endT)},
                                 {"V", V::number(notes.endV)},
                                 {"u1", V::number(notes.endU1)},
                                 {"energy", V::number(notes.endEnergy)}})},
      {"columns", V::array({V::of("T"), V::of("omega"), V::of("V"), V::of("u1"), V::of("energy"), V::of("admissible"),
                            V::of("trace"), V::of("stability")})},
      {"stability_precision", V::of(notes.stabilityPrecision)},
      {"trace", V::of("tr DP of the return map at fixed energy (exact: flow and saltation matrices), in "
                      "the stability precision; empty (NaN in the .npy) where the orbit is not admissible")},
      {"stability", V::of("elliptic (|tr| < 2), hyperbolic (tr > 2), flip-hyperbolic (tr < -2), parabolic "
                          "(|tr| = 2 within rounding), undecided (|tr| within its error bound of 2 in this precision, "
                          "and not parabolic); in the .npy 0, 1, 2, 3, 4 (NaN: not admissible)")},
      {"bifurcations", notes.bifurcations},
      {"rows", V::of(std::int64_t(outcome.rows()))},
      {"periods", V::of(std::string("T2 k / (count + 1) for k = 1 ... ").append(std::to_string(outcome.count)) +
                        ", and T2 (1 - 2^-k) for k = 8 ... 40, sorted; multiples of T1 left out")},
      {"energy", V::of("E = 1/2 v^T M v + 1/2 u^T K u of the post-impact state (constant on the orbit)")},
      {"post_impact_state", V::of("u1 = u1, u2 = gap, v1 = 0, v2 = V")},
      {"conditioning", V::of("each row is computed in binary128 from its double period and rounded "
                             "once; near T2, V is conditioned like T2 / (T2 - T) in T and in the "
                             "masses: a mass that is not a binary number (m2 = 0.3) read exactly moves "
                             "V there by up to that factor times 1e-17")}};
  if (files) {
    fields.emplace_back("files", V::object({{"csv", V::of(*files + ".csv")},
                                            {"npy", V::of(*files + ".npy (float64, rows x 8 columns in the CSV's "
                                                                   "order, admissible as 1.0 / 0.0, stability as 0..4)")}}));
  }
  fields.emplace_back("admissible", V::of("1 when V < 0 and the free flight from the data first returns to the stop "
                                          "at T (exact contact search), else 0"));
  fields.emplace_back("generator", V::of(std::string("grazelab-cli ") + kVersion));
  return V::object(std::move(fields));
}

// where the family's stability changes: kind, period with its error, energy, and whether
// multipliers leave the unit circle there as T grows
V bifurcationsValue(const core::ChainBifurcations<double>& bifurcations) {
  std::vector<V> items;
  for (const core::ChainBifurcation<double>& b : bifurcations.changes) {
    items.push_back(V::object({{"kind", V::of(std::string(core::toString(b.kind)))},
                               {"T", V::number(b.T)},
                               {"T_error", V::number(b.periodError)},
                               {"energy", V::number(b.energy)},
                               {"energy_error", V::number(b.energyError)},
                               {"leaves_the_circle", V::of(b.leaves)}}));
  }
  return V::array(std::move(items));
}

V chainDocument(const FamilyOutcome& outcome, const ChainFamily& family, const std::optional<std::string>& files) {
  std::vector<V> columns;
  for (const std::string& column : outcome.columns) columns.push_back(V::of(column));
  std::vector<V::Field> fields{
      {"format", V::of("grazelab-family")},
      {"family", V::of("onepp")},
      {"chain", family.chain},
      {"T_max", V::number(family.tMax)},
      {"T_max_is", V::of(family.commensurate ? "the common period of the commensurate chain"
                                             : "the slowest mode's period (the frequencies are not commensurate)")},
      {"grazing_limit",
       V::object({{"weights", numbers(family.weights)},
                  {"u", family.gloU ? numbers(*family.gloU) : V::null()},
                  {"energy", V::number(family.gloEnergy)},
                  {"meaning", V::of("as T -> T_max the post-impact data tend to GLO_lambda with these weights "
                                    "(fastest mode first; Theorem 2.1 for any N: lambda_j = a_sj w_j^-2 / sum "
                                    "a_si w_i^-2 over the modes whose period divides T_max), V -> 0")}})},
      {"bifurcations", bifurcationsValue(family.bifurcations)},
      // where the search for a pair of changes hidden between two rows ran out of its budget
      {"unsearched", [&family] {
         std::vector<V> stretches;
         for (const auto& [from, to] : family.bifurcations.unsearched) {
           stretches.push_back(V::array({V::number(from), V::number(to)}));
         }
         return V::array(std::move(stretches));
       }()},
      {"columns", V::array(std::move(columns))},
      {"rows", V::of(std::int64_t(outcome.rows()))},
      {"admissible_rows", V::of(outcome.admissible)},
      {"periods", V::of(std::string("T_max k / (count + 1) for k = 1 ... ").append(std::to_string(outcome.count)) +
                        ", and T_max (1 - 2^-k) for k = 8 ... 30, sorted")},
      {"post_impact_state", V::of("u = V g(T) (u_s = gap), v = V e_s")},
      {"admissible", V::of("1 when V < 0 and the free flight from the data first returns to the stop at T "
                           "(certified contact search), else 0; V, energy and u empty (NaN in the .npy) at a "
                           "multiple of a mode's period")},
      {"class", V::of("an admissible row's class from its exact 2N x 2N monodromy (in the .npy 0 elliptic, 1 "
                          "hyperbolic, 2 flip-hyperbolic, 3 complex-quadruplet, 4 undecided; in the CSV those "
                          "words); muK_re, muK_im its 2N - 2 "
                          "nontrivial multipliers by angle, muK_krein their Krein signatures (+1, -1, 0); "
                          "empty on the other rows, and on an admissible row whose path does not close to its "
                          "rounding (docs/model.md section 12)")}};
  if (files) {
    fields.emplace_back("files", V::object({{"csv", V::of(*files + ".csv")},
                                            {"npy", V::of(*files + ".npy (float64, rows x " +
                                                          std::to_string(outcome.columns.size()) +
                                                          " columns in the CSV's order)")}}));
  }
  fields.emplace_back("generator", V::of(std::string("grazelab-cli ") + kVersion));
  return V::object(std::move(fields));
}

}  // namespace

std::int64_t familyMaxCount(bool notesChain) { return notesChain ? 10'000'000 : 1'000'000; }

std::optional<std::string> familyRequestRefusal(const FamilyRequest& request, bool notesChain) {
  if (!notesChain && request.precision != PrecisionChoice::Auto && request.precision != PrecisionChoice::Double) {
    return kFamilyOfNMassesInDouble;
  }
  if (request.count < 1 || request.count > familyMaxCount(notesChain)) {
    return "--count: '" + std::to_string(request.count) + "' is not a count from 1 to " +
           std::to_string(familyMaxCount(notesChain));
  }
  return std::nullopt;
}

std::optional<std::string> familyRefusal(const PreparedMassChain& chain, const FamilyRequest& request) {
  if (std::optional<std::string> refusal = familyRequestRefusal(request, chain.isTheNotesChain())) return refusal;
  if (!chain.isTheNotesChain()) {
    if (chain.input().chain.floats()) return std::string("family: ") + core::kFloatingChainHasNoOrbit;
    return std::nullopt;
  }
  const Parsed<ModelInput<double>>& model = chain.twoMassForm<double>();
  if (!model.value) return model.error.toStdString();
  if (!model.value->chain.resonant) {
    return "family: the 1IPP family of Theorem 2.1 needs the 1:2 resonant chain (give no --k2)";
  }
  return std::nullopt;
}

FamilyOutcome onePeriodicFamily(const PreparedMassChain& chain, const FamilyRequest& request,
                                const std::function<void(double, const std::string&)>& progress, std::stop_token stop) {
  if (std::optional<std::string> refusal = familyRefusal(chain, request)) {
    FamilyOutcome outcome;
    outcome.problem = std::move(*refusal);
    return outcome;
  }
  return chain.isTheNotesChain() ? notesFamily(chain, request, progress, std::move(stop))
                                 : chainFamily(chain, request, std::move(stop));
}

JsonValue familyDocument(const FamilyOutcome& outcome, const std::optional<std::string>& files) {
  if (const auto* notes = std::get_if<NotesFamily>(&outcome.of)) return notesDocument(outcome, *notes, files);
  return chainDocument(outcome, std::get<ChainFamily>(outcome.of), files);
}

}  // namespace grazelab::cli
