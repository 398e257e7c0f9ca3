// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `modes` on a chain of N masses: the atlas of any chain (core/orbits/chain_atlas.h) as a JSON
// document and one table per family.
#include "commands/chain_modes_document.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "commands/orbit_json.h"
#include "core/version.h"
#include "io/document_values.h"

namespace grazelab::cli {
namespace {

using V = JsonValue;

template <typename S>
V orbitPoint(const core::BasicChainPeriodicOrbit<S>& orbit) {
  return V::object({{"energy", V::number(orbit.energy)},
                    {"T", V::number(orbit.period)},
                    {"state", V::object({{"u", numbersValue(orbit.state.u)}, {"v", numbersValue(orbit.state.v)}})},
                    {"class", V::of(std::string(core::toString(orbit.monodromy.stability)))}});
}

// "orbit": the family's orbit at that end
template <typename S>
V endValue(const core::ChainAtlasEnd& end, const core::BasicChainPeriodicOrbit<S>& orbit) {
  std::vector<V::Field> fields{{"kind", V::of(std::string(core::toString(end.kind)))}, {"orbit", orbitPoint(orbit)}};
  if (end.family >= 0) {
    fields.emplace_back("family", V::of(std::int64_t(end.family)));
    fields.emplace_back("bifurcation", V::of(std::int64_t(end.change)));
  }
  return V::object(std::move(fields));
}

template <typename S>
V bifurcationValue(const core::ChainFamilyChange<S>& change, const core::ChainAtlasBranch* branch) {
  std::vector<V::Field> fields{{"kind", V::of(std::string(core::toString(change.kind)))},
                               {"leaves_the_circle", V::of(change.leaves)},
                               {"energy", V::number(change.energy)},
                               {"energy_error", V::number(change.energyError)},
                               {"T", V::number(change.period)},
                               {"T_error", V::number(change.periodError)}};
  if (branch) {
    fields.emplace_back("branch", V::of(std::string(core::toString(branch->outcome))));
    fields.emplace_back("family", branch->family >= 0 ? V::of(std::int64_t(branch->family)) : V::null());
    if (branch->outcome == core::ChainBranchOutcome::NotFound) {
      fields.emplace_back("problem", V::of(std::string(core::toString(branch->problem))));
    }
  }
  return V::object(std::move(fields));
}

template <typename S>
V familyValue(const core::ChainAtlasFamily<S>& family, const std::optional<std::string>& base) {
  const std::vector<core::BasicChainPeriodicOrbit<S>>& orbits = family.path.orbits;
  std::vector<V> bifurcations;
  for (std::size_t i = 0; i < family.path.changes.size(); ++i) {
    const core::ChainAtlasBranch* branch = nullptr;
    for (const core::ChainAtlasBranch& b : family.branches) {
      if (b.change == i) branch = &b;
    }
    bifurcations.push_back(bifurcationValue(family.path.changes[i], branch));
  }
  const bool born = family.birth == core::ChainBirth::PeriodDoubling;
  std::vector<V::Field> fields{
      {"id", V::of(std::int64_t(family.id))},
      {"impacts", V::of(std::int64_t(family.path.impacts))},
      {"born_at", V::object({{"kind", V::of(std::string(core::toString(family.birth)))},
                             {"family", born ? V::of(std::int64_t(family.parent)) : V::null()},
                             {"bifurcation", born ? V::of(std::int64_t(family.parentChange)) : V::null()}})},
      {"start", family.firstEnd && !orbits.empty() ? endValue(*family.firstEnd, orbits.front()) : V::null()},
      {"end", orbits.empty() ? V::null() : endValue(family.lastEnd, orbits.back())},
      {"bifurcations", V::array(std::move(bifurcations))},
      {"unsearched", V::of(std::int64_t(family.path.unsearched))},
      {"one_period", V::of(family.onePeriod)},
      {"rows", V::of(std::int64_t(orbits.size()))}};
  if (base) fields.emplace_back("file", V::of(*base + "-family-" + std::to_string(family.id) + ".csv"));
  return V::object(std::move(fields));
}

}  // namespace

std::vector<std::string> chainModesColumns(int masses) {
  std::vector<std::string> columns = {"energy", "period", "omega", "class", "min_impact_speed"};
  for (const char* part : {"u", "v"}) {
    for (int i = 1; i <= masses; ++i) columns.push_back(part + std::to_string(i));
  }
  for (int k = 1; k <= 2 * masses - 2; ++k) {
    for (const char* part : {"_re", "_im", "_krein"}) columns.push_back("mu" + std::to_string(k) + part);
  }
  return columns;
}

template <typename S>
std::vector<double> chainModesTable(const ChainAtlasIn<S>& in, std::size_t index) {
  const int n = in.chain.size();
  const int stopped = in.chain.stopped() - 1;
  const std::size_t pairs = std::size_t(2 * n - 2);
  const std::vector<core::BasicChainPeriodicOrbit<S>>& orbits = in.atlas.families[index].path.orbits;
  std::vector<double> rows;
  rows.reserve(orbits.size() * chainModesColumns(n).size());
  for (const core::BasicChainPeriodicOrbit<S>& o : orbits) {
    double slowest = std::numeric_limits<double>::infinity();
    for (const core::BasicChainEvent<S>& e : o.events) slowest = std::min(slowest, std::abs(double(e.vBefore[stopped])));
    const double period = double(o.period);
    for (double value : {double(o.energy), period, 2 * std::numbers::pi / period,
                         double(int(o.monodromy.stability)), slowest}) {
      rows.push_back(value);
    }
    for (int i = 0; i < n; ++i) rows.push_back(double(o.state.u[i]));
    for (int i = 0; i < n; ++i) rows.push_back(double(o.state.v[i]));
    for (std::size_t k = 0; k < pairs; ++k) {
      const bool has = k < o.monodromy.multipliers.size();
      const core::ChainMultiplier<S>* mu = has ? &o.monodromy.multipliers[k] : nullptr;
      rows.push_back(mu ? double(mu->re) : std::nan(""));
      rows.push_back(mu ? double(mu->im) : std::nan(""));
      rows.push_back(mu ? double(mu->krein) : std::nan(""));
    }
  }
  return rows;
}

template <typename S>
JsonValue chainModesDocument(const ChainAtlasIn<S>& in, const ModesOutcome& outcome,
                             const std::optional<std::string>& base) {
  std::vector<V> families;
  for (const core::ChainAtlasFamily<S>& family : in.atlas.families) families.push_back(familyValue(family, base));
  std::string columns;
  for (const std::string& column : chainModesColumns(in.chain.size())) columns += (columns.empty() ? "" : ",") + column;
  return V::object({
      {"format", V::of("grazelab-modes")},
      {"precision", V::of(std::string(core::toString(outcome.precision)))},
      {"chain", values::massChain<V>(in.chain, in.commonPeriod)},
      {"max_impacts", V::of(std::int64_t(outcome.maxImpacts))},
      {"energy_range", V::array({V::number(in.low), V::number(in.high)})},
      {"families", V::array(std::move(families))},
      {"undecided_periods", in.oneFamily ? V::null() : V::of(std::int64_t(in.atlas.undecidedPeriods))},
      {"about", V::object({
        {"columns", V::of(columns)},
        {"undecided_periods", V::of("how many of the 423 periods the 1IPP family's closed form was looked at "
                              "(null: family --impacts, which looks at none) this precision could not decide (a contact too near tangent, or the contact "
                              "search's budget run out): where not 0, parts of the 1IPP family, and the families "
                              "born on them, may be missing or cut short (a wider --precision decides more)")},
        {"class", V::of("the orbit's class from its exact 2N x 2N monodromy: elliptic (every nontrivial "
                  "multiplier on the unit circle: linearly stable), hyperbolic, flip-hyperbolic, "
                  "complex-quadruplet (a Krein collision's outcome), undecided (a multiplier within its error "
                  "of the circle and of another one); in the tables 0 .. 4. muK_re, muK_im: the 2N - 2 "
                  "nontrivial multipliers by angle; muK_krein their Krein signatures (+1, -1; 0 off the circle "
                  "or on the real axis)")},
        {"state", V::of("u1..uN, v1..vN: the orbit's state just after an impact (u_s = gap)")},
        {"min_impact_speed", V::of("the slowest impact's |v_s| before it [length/time]")},
        {"born_at", V::of("one-periodic: a part of the 1IPP family, from its closed form (rows in increasing "
                    "period); period-doubling: born at bifurcation `bifurcation` of family `family` and "
                    "followed away from it; given-orbit: followed both ways from the orbit found from "
                    "the guess (family --impacts)")},
        {"start", V::of("a 1IPP part's end of shorter period; a given orbit's family: the end met going down "
                  "in energy (null for a family born at a doubling: it starts there)")},
        {"end", V::of("grazing-orbit (every impact speed tends to 0: a linear orbit grazing the stop), "
                "impact-fades (one impact's speed tends to 0), interior-grazing (a flight touches the stop), "
                "meets-doubling (the orbit becomes one of half the impacts run twice: bifurcation "
                "`bifurcation` of family `family`), undecided (a contact just beyond cannot be decided in "
                "this precision), not-converging, energy-limit (the energy range), step-limit (the most "
                "orbits per family); `orbit` is the family's last orbit there")},
        {"bifurcations", V::of("where the family's stability changes, along the family from its start: "
                         "period-doubling (a real negative pair at -1), fold (a real positive pair at +1: fold "
                         "or branch point), krein-collision (two pairs of opposite Krein signatures meet on the "
                         "circle and leave it as a complex quadruplet, or come back), other (several at once); "
                         "leaves_the_circle the way the family is followed; energy and T with the half width of "
                         "their last bracket. At a period doubling: branch born (the family born there), "
                         "reached (a family followed from elsewhere came back to it), not-found (problem says "
                         "why), beyond-impacts (its family would have more than max_impacts)")},
        {"one_period", V::of("true: every orbit of the family has the period of the first to 1e-9 while its "
                       "energy moves by more than 1e-3 (an isochronous family: at that period its orbits are "
                       "not isolated, and it may lie in a wider sheet of them)")},
        {"unsearched", V::of("pairs of consecutive orbits between which a pair of changes that undo each other "
                       "could not be ruled out within the search's budget")}})},
      {"generator", V::of(std::string("grazelab-cli ") + kVersion)}});
}

#define GRAZELAB_INSTANTIATE(S)                                                                      \
  template std::vector<double> chainModesTable(const ChainAtlasIn<S>&, std::size_t);               \
  template JsonValue chainModesDocument(const ChainAtlasIn<S>&, const ModesOutcome&,               \
                                       const std::optional<std::string>&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(core::Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::cli
