// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/map_document.h"

#include "core/version.h"
#include "io/cli_output.h"

namespace grazelab::cli::map {
namespace {

using V = JsonValue;

V stateArray(const core::State& s) {
  return V::array({V::number(s.u1), V::number(s.u2), V::number(s.v1), V::number(s.v2)});
}

V axisJson(const core::MapAxis& axis) {
  return V::object({{"variable", V::of(std::string(core::toString(axis.variable)))},
                    {"from", V::number(axis.from)},
                    {"to", V::number(axis.to)},
                    {"count", V::of(std::int64_t(axis.count))},
                    {"values", V::of("numpy.linspace(from, to, count)")}});
}

V startJson(const core::MapSpec& spec) {
  using Kind = core::StartSpec<double>::Kind;
  V start;
  if (!spec.start) {
    start = V::object({{"kind", V::of("grazing-start plane")}, {"u2", V::of("gap")}, {"v2", V::of(std::int64_t(0))},
                       {"note", V::of("u1 and v1 are 0 where no axis sets them")}});
  } else {
    switch (spec.start->kind) {
      case Kind::Glo: start = V::object({{"kind", V::of("glo")}, {"lambda", V::number(spec.start->lambda)}}); break;
      case Kind::Glom: start = V::object({{"kind", V::of("glom")}, {"mode", V::of(std::int64_t(spec.start->mode))}}); break;
      case Kind::OnePeriodic: start = V::object({{"kind", V::of("onepp")}, {"T", V::number(spec.start->period)}}); break;
      case Kind::Explicit: start = V::object({{"kind", V::of("state")}, {"state", stateArray(spec.start->state)}}); break;
    }
  }
  const bool epsilonAxis = spec.x.variable == core::MapVariable::Epsilon ||
                           spec.y.variable == core::MapVariable::Epsilon;
  if (spec.perturbation && !epsilonAxis) start.set("perturbation", stateArray(*spec.perturbation));
  if (epsilonAxis) {
    start.set("epsilon_direction", stateArray(spec.perturbation.value_or(core::State{0, 0, 0, -1})));
  }
  return start;
}

}  // namespace

std::string axisVariable(const V& spec, const char* which) {
  const V* axis = spec.find(which);
  const V* variable = axis ? axis->find("variable") : nullptr;
  return variable ? variable->text : std::string();
}

core::MapAxis axisOf(const V& spec, const char* which) {
  core::MapAxis result;
  const V* axis = spec.find(which);
  if (!axis) return result;
  result.variable = core::parseMapVariable(axisVariable(spec, which)).value_or(core::MapVariable::U1);
  const auto number = [axis](const char* name) {
    const V* value = axis->find(name);
    return value ? value->toDouble() : 0.0;
  };
  result.from = number("from");
  result.to = number("to");
  result.count = std::int64_t(number("count"));
  return result;
}

V specJson(const core::MapSpec& spec, double period, const std::string& pictureQuantity) {
  const core::Model& m = spec.model;
  V model = V::object({{"m1", V::number(m.m1)}, {"m2", V::number(m.m2)}, {"k1", V::number(m.k1)},
                       {"gap", V::number(m.gap)}, {"T2", V::number(period)}});
  if (m.design) {
    model.set("branch", V::of(std::string(core::toString(*m.design))));
    model.set("k2", V::of("1:2 design of the branch (follows m2/m1)"));
  } else {
    model.set("k2", V::number(m.k2));
  }
  std::vector<V::Field> quantities;
  for (const core::QuantityInfo& info : core::quantities()) {
    quantities.emplace_back(JsonKey::owned(std::string(info.name)),
                            V::object({{"unit", V::of(std::string(info.unit))},
                                       {"dtype", V::of(info.integer ? "int64" : "float64")},
                                       {"meaning", V::of(std::string(info.meaning))}}));
  }
  return V::object(
      {{"format", V::of("grazelab-map")},
       {"generator", V::of(std::string("grazelab-cli ") + kVersion)},
       {"layout", V::of("PREFIX-QUANTITY.npy: row index = y index, column index = x index")},
       {"x", axisJson(spec.x)},
       {"y", axisJson(spec.y)},
       {"model", std::move(model)},
       {"start", startJson(spec)},
       {"contacts", V::of(std::int64_t(spec.contacts))},
       {"contacts_note", V::of("each run makes this many contacts, and more (at most 3) if its first "
                               "flight from the stop has not ended by then")},
       {"horizon", V::of(spec.estimateHorizon ? "estimated per point (--trust auto)"
                                              : "not estimated (--trust off): NaN; give --trust auto")},
       {"missing_values", V::of("NaN: not defined at that point (no such flight or impact in the "
                                "run, or the model or start is unusable there); inf: the run proved "
                                "it never comes (a resonant flight that never returns, or a start whose "
                                "modes cannot reach the stop); the counts "
                                "are -1 where the model or start is unusable (no run)")},
       {"picture", V::of(pictureQuantity)},
       {"quantities", V::object(std::move(quantities))}});
}

// The spec object of an N-mass map (the two-mass one's fields, the chain instead of the model)
V chainSpecJson(const core::ChainMapSpec& spec, double period, const std::string& pictureQuantity) {
  using V = JsonValue;
  V object = specJson(core::MapSpec{}, period, pictureQuantity);
  object.remove("model");
  object.set("horizon", V::of(spec.estimateHorizon ? "estimated per point (--trust auto: a shadow run one precision "
                                                     "up, compared event by event)"
                                                   : "not estimated (--trust off): NaN; give --trust auto"));
  const auto axisJson = [](const core::ChainMapAxis& axis) {
    return V::object({{"variable", V::of(axis.name())}, {"from", V::number(axis.range.from)},
                      {"to", V::number(axis.range.to)}, {"count", V::of(std::int64_t(axis.range.count))},
                      {"values", V::of("numpy.linspace(from, to, count)")}});
  };
  // the flights' ratios are to the chain's period, not T2
  if (V* quantities = object.find("quantities")) {
    for (V::Field& quantity : quantities->fields) {
      if (V* unit = quantity.second.find("unit"); unit && unit->text == "T2") *unit = V::of("period");
    }
  }
  object.set("x", axisJson(spec.x));
  object.set("y", axisJson(spec.y));
  object.set("chain", massChainValue(spec.chain, period));
  const auto numbers = [](const Eigen::VectorXd& values) {
    std::vector<V> items;
    for (Eigen::Index i = 0; i < values.size(); ++i) items.push_back(V::number(values[i]));
    return V::array(std::move(items));
  };
  if (spec.x.weight()) {
    const Eigen::VectorXd weights = spec.weights.empty() ? Eigen::VectorXd::Zero(spec.chain.size())
                                                         : Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(
                                                               spec.weights.data(), Eigen::Index(spec.weights.size())));
    object.set("start", V::object({{"glo_weights", numbers(weights)},
                                   {"balancing_weight", V::of(std::string("w").append(std::to_string(core::balancingWeight(spec) + 1)))},
                                   {"push", V::object({{"u", numbers(spec.push.u)}, {"v", numbers(spec.push.v)}})},
                                   {"set_by_axes", V::of("each run starts on GLO_lambda at its touch plus the push: lambda "
                                                         "these weights (fastest mode first) with the axes' set and the "
                                                         "balancing weight 1 minus the others; no run where a weight falls "
                                                         "on a mode with a node at the stopped mass")}}));
  } else {
    object.set("start", V::object({{"u", numbers(spec.start.u)},
                                   {"v", numbers(spec.start.v)},
                                   {"set_by_axes", V::of("each run's start is this one with the axes' coordinates set")}}));
  }
  object.set("missing_values", V::of("NaN: not defined at that point (no flight from the stop or no impact in the run, or "
                                     "no run there); inf: the run proved it never comes (a commensurate chain's flight "
                                     "that stays below the stop, or any start whose modes' amplitudes together fall "
                                     "short of it); the counts are -1 where there is no run: the start "
                                     "past the stop, or a run undecided even in binary128"));
  object.set("contacts", V::of(std::int64_t(spec.contacts)));
  object.set("contacts_note", V::of("each run makes this many contacts"));
  object.set("period", V::number(period));
  object.set("period_note", V::of("fft_min, fft_max and fft_mean are in units of this period: the common period T of "
                                  "a commensurate chain, else the slowest mode's period"));
  return object;
}

V mapDocument(const StoredMap& map, V files) {
  V run = map.description.run;
  run.set("rows", V::array({V::of(std::int64_t(map.rows.rowBegin)), V::of(std::int64_t(map.rows.rowEnd))}));
  run.set("total_rows", V::of(std::int64_t(map.totalRows)));
  run.set("shape", V::array({V::of(std::int64_t(map.rows.rowEnd - map.rows.rowBegin)), V::of(std::int64_t(map.columns))}));
  if (files.kind == V::Kind::Object) run.set("files", std::move(files));
  V spec = map.description.spec;
  return V::object({{"spec", std::move(spec)}, {"run", std::move(run)}});
}

}  // namespace grazelab::cli::map
