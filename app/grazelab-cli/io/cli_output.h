// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "io/cli_input.h"
#include "io/cli_io.h"
#include "io/json_value.h"
#include "core/solver/trust.h"

namespace grazelab::cli {

/// A number as JSON with the digits of its precision; null when it is not finite.
template <typename S>
std::string jsonNumber(const S& value) {
  return core::isFinite(value) ? core::formatScalar(value) : std::string("null");
}

/// A string as JSON (quotes and backslashes escaped).
std::string jsonQuoted(const std::string& text);

/// The note's model of a two-mass chain with its derived quantities (k2 and where it comes from,
/// w1, w2, T1, T2, P, lambda*), and the precision asked for.
template <typename S>
JsonValue modelValue(const ModelInput<S>& model, const std::string& precision);
/// `info` of the note's chain: {"model": modelValue}.
template <typename S>
JsonValue infoValue(const ModelInput<S>& model);

/// `info` of a chain of N masses: the chain, each mode (frequency, period, shape, whether it has
/// a node at the stop, its harmonic number) and the frequencies' ratios, in double; for a
/// designed chain also its `design`: the ratios asked, the design used and every design found.
JsonValue massChainInfoValue(const core::MassChain& chain, const std::optional<core::DesignChoice>& design = std::nullopt);
/// A command's one JSON document, written to stdout one field per line.
void emitDocument(const Io& io, JsonValue document);
/// A run's error estimate: estimated_state_error, estimated_time_error, horizon, horizon_method
/// (null when not estimated), verdict, reason.
JsonValue trustValue(const core::Trust& trust);
/// A chain of N masses as the other commands' documents name it: masses, springs, right_spring
/// (null: none), stop_mass, gap and the common `period` of a commensurate chain (null: none), to
/// the digits of the chain's precision.
template <typename S>
JsonValue massChainValue(const core::BasicMassChain<S>& chain, const S& period);

}  // namespace grazelab::cli
