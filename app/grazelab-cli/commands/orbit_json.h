// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "core/model/state.h"
#include "core/numbers/scalar.h"
#include "core/solver/chain_flight.h"
#include "core/orbits/onepp_family_points.h"
#include "io/json_value.h"

// The JSON of orbits and their special points, as `family` and `modes` both write it (through
// the one JSON writer, io/json_value.h: numbers with every digit of their precision).
namespace grazelab::cli {

/// A vector of a chain of N masses (its u, its v) as a JSON array of numbers in S's digits.
template <typename S>
JsonValue numbersValue(const core::ChainVector<S>& x) {
  std::vector<JsonValue> items;
  for (Eigen::Index i = 0; i < x.size(); ++i) items.push_back(JsonValue::number(x[i]));
  return JsonValue::array(std::move(items));
}

template <typename S>
JsonValue orbitStateValue(const core::BasicState<S>& x) {
  return JsonValue::object({{"u1", JsonValue::number(x.u1)},
                            {"u2", JsonValue::number(x.u2)},
                            {"v1", JsonValue::number(x.v1)},
                            {"v2", JsonValue::number(x.v2)}});
}

/// A flip, fold or branch point of a family of orbits: its kind, period (also over T2, the
/// chain's slow period), energy, trace, the energy's error estimate and the orbit's state after
/// its impact, as fields (a caller adds its own); "checked" always with `alwaysChecked`, else
/// only when false; a point the search could not solve to its definition in S says so
/// ("checked" false and a note).
template <typename S>
std::vector<JsonValue::Field> bifurcationFields(const core::FamilyBifurcation<S>& b, const S& T2, bool alwaysChecked) {
  std::vector<JsonValue::Field> fields;
  fields.emplace_back("kind", JsonValue::of(std::string(core::toString(b.kind))));
  fields.emplace_back("T", JsonValue::number(b.T));
  fields.emplace_back("T_over_T2", JsonValue::number(S(b.T / T2)));
  fields.emplace_back("energy", JsonValue::number(b.energy));
  fields.emplace_back("trace", JsonValue::number(b.trace));
  fields.emplace_back("energy_error", JsonValue::number(b.energyError));
  if (alwaysChecked || !b.checked) fields.emplace_back("checked", JsonValue::of(b.checked));
  fields.emplace_back("state", orbitStateValue(b.state));
  if (!b.checked) {
    fields.emplace_back("note", JsonValue::of("not solved to its definition in this precision (the trace is not "
                                              "within rounding of +-2 here): where the search stopped, not a result"));
  }
  return fields;
}

}  // namespace grazelab::cli
