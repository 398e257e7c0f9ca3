// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <stop_token>
#include <string>
#include <variant>
#include <vector>

#include "commands/simulation.h"
#include "core/model/mass_chain.h"
#include "core/model/two_mass_form.h"
#include "core/orbits/chain_kipp.h"
#include "core/orbits/chain_monodromy.h"
#include "core/orbits/periodic_orbit.h"
#include "io/json_value.h"

// `orbit` as a typed command, the one both faces call (as `simulate` is, commands/simulation.h):
// the command line reads its options into an OrbitRequest and writes the outcome's document; the
// Python module hands the same document over as values. No Qt: a refusal is a status and its
// line, the orbit a struct in the precision that found it.
namespace grazelab::cli {

class PreparedMassChain;

/// One periodic impacting orbit of any chain: the 1IPP orbit of period `period` (`impacts` 0), or
/// the orbit of `impacts` impacts per period at energy `energy` (or, `energy` empty, of period
/// `period`) that Newton finds from `guess`: the point just after an impact on H, u then v of
/// every mass but the stopped one (two masses: u1, v1), and at a fixed period the stopped mass's
/// v_s last. Numbers as decimal text, read in the precision that runs (0.1 is 0.1 to binary128's
/// digits).
struct OrbitRequest {
  std::string period;
  int impacts = 0;
  std::string energy;
  /// what an orbit of `impacts` keeps fixed: `energy`, or `period`
  core::ChainOrbitConstraint fixed = core::ChainOrbitConstraint::Energy;
  std::vector<std::string> guess;
  PrecisionChoice precision = PrecisionChoice::Auto;
};

enum class OrbitStatus {
  Found,
  Refused,    ///< bad input, or no admissible orbit: `problem` says why
  Undecided,  ///< no precision asked for could decide it (`problem`: which would)
};

/// An orbit found in precision S, with the chain's form it was found on.
template <typename S>
struct FoundOrbit {
  core::TwoMassForm<S> chain;
  core::PeriodicOrbit<S> orbit;
};

/// An orbit found by the 2N x 2N monodromy (a 1IPP orbit or a kIPP orbit by Newton, of N masses, of
/// two masses not in the note's shape, or of the note's chain at a fixed period) in precision S,
/// with the chain and its common period (0: not commensurate).
template <typename S>
struct FoundChainOrbit {
  core::BasicMassChain<S> chain;
  S commonPeriod = 0;
  core::BasicChainPeriodicOrbit<S> orbit;
};

struct OrbitOutcome {
  OrbitStatus status = OrbitStatus::Refused;
  std::string problem;  ///< why not found, one line
  core::Precision precision = core::Precision::Double;  ///< the precision that answered (or tried last)
  std::variant<std::monostate, FoundOrbit<double>, FoundOrbit<long double>, FoundOrbit<core::Quad>,
               FoundChainOrbit<double>, FoundChainOrbit<long double>, FoundChainOrbit<core::Quad>>
      found;
};

/// The orbit `request` asks for on `chain`: on the note's two-mass form where the chain has it
/// (a kIPP orbit at a fixed energy by the note's Newton), else by the 2N x 2N monodromy
/// (core/orbits/chain_monodromy.h) and Newton on the return map of N masses
/// (core/orbits/chain_kipp.h); in the precision asked for; PrecisionChoice::Auto: double, then long double and binary128 while a contact too near
/// tangent or the class leaves it undecided. `stop` ends a Newton search.
OrbitOutcome solveOrbit(const PreparedMassChain& chain, const OrbitRequest& request, std::stop_token stop = {});

/// The kIPP orbit (request.impacts) Newton finds on the return map of any chain
/// (core/orbits/chain_kipp.h) from the request's guess, at its fixed energy or period, in S.
template <typename S>
OrbitOutcome chainOrbitByNewton(const core::BasicReadyChain<S>& chain, const OrbitRequest& request,
                                std::stop_token stop = {});

/// The document of an orbit found (OrbitStatus::Found): the model, period, energy, impacts, state,
/// events, trace, multipliers, stability, symmetry and checks, every number to the digits of its
/// precision; for a chain of N masses the chain, period, energy, state, events, the 2N - 2
/// multipliers with their error bars, circle flags and Krein signatures, stability and checks.
JsonValue orbitDocument(const OrbitOutcome& outcome);

}  // namespace grazelab::cli
