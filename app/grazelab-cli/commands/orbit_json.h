// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QJsonObject>
#include <QJsonValue>
#include <QString>

#include <type_traits>

#include "core/model/state.h"
#include "core/numbers/scalar.h"
#include "core/orbits/onepp_family_points.h"

// The JSON of orbits and their special points, as `family` and `modes` both write it.
namespace grazelab::cli {

/// A number of precision S: a JSON number in double; in long double and binary128 the exact
/// decimal text (a JSON double would lose its digits); null when not finite.
template <typename S>
QJsonValue scalarJson(const S& value) {
  if (!core::isFinite(value)) return QJsonValue();
  if constexpr (std::is_same_v<S, double>) return value;
  else return QString::fromStdString(core::formatScalar(value));
}

template <typename S>
QJsonObject stateJson(const core::BasicState<S>& x) {
  return {{"u1", scalarJson(x.u1)}, {"u2", scalarJson(x.u2)}, {"v1", scalarJson(x.v1)}, {"v2", scalarJson(x.v2)}};
}

/// A flip, fold or branch point of a family of orbits with one impact a period: its kind,
/// period (also over T2, the chain's slow period), energy, trace, the energy's error estimate
/// and the orbit's state after its impact; a point the search could not solve to its definition
/// in S says so ("checked" false and a note).
template <typename S>
QJsonObject bifurcationJson(const core::FamilyBifurcation<S>& b, const S& T2) {
  QJsonObject point{{"kind", QString::fromUtf8(core::toString(b.kind).data())},
                    {"T", scalarJson(b.T)},
                    {"T_over_T2", scalarJson(S(b.T / T2))},
                    {"energy", scalarJson(b.energy)},
                    {"trace", scalarJson(b.trace)},
                    {"energy_error", scalarJson(b.energyError)},
                    {"checked", b.checked},
                    {"state", stateJson(b.state)}};
  if (!b.checked) {
    point["note"] = "not solved to its definition in this precision (the trace is not within rounding "
                    "of +-2 here): where the search stopped, not a result";
  }
  return point;
}

}  // namespace grazelab::cli
