// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "core/model/mass_chain.h"
#include "core/orbits/chain_glo.h"
#include "io/json_value.h"

// `glo-set` as a typed command, the one both faces call (as `orbit` is, commands/periodic_orbit.h):
// the command line reads --directions into a GloSetRequest, writes the outcome's document and,
// with --out, its picture; the Python module hands the same document over as values. No Qt.
namespace grazelab::cli {

/// How finely the region of three modes is drawn: its boundary along `directions` rays.
struct GloSetRequest {
  static constexpr int kDefaultDirections = 72;
  static constexpr int kMaxDirections = 100'000;
  int directions = kDefaultDirections;
};

enum class GloSetStatus {
  Computed,
  Refused,      ///< not commensurate, or more than three modes move the stopped mass: `problem`
  Interrupted,  ///< the stop token ended the region's search
};

/// Which affine combinations of the chain's GLOMs graze: a point (one mode moves the stopped
/// mass), an interval of lambda (two: weights (1 - lambda, lambda)) or a region of the
/// (lambda2, lambda3) plane (three), with the modes (0-based) and their harmonic numbers.
struct GloSetOutcome {
  GloSetStatus status = GloSetStatus::Refused;
  std::string problem;  ///< why refused, one line
  core::MassChain chain;
  double period = 0;  ///< the common period (0: not commensurate)
  std::vector<int> modes;
  std::vector<int> harmonics;
  std::optional<core::GrazingInterval> interval;     ///< two modes
  std::vector<core::GrazingRegionPoint> boundary;    ///< three modes
};

/// The grazing set of `chain` (its modes, ratios and set, core/orbits/chain_glo.h).
GloSetOutcome grazingSet(const core::MassChain& chain, const GloSetRequest& request, std::stop_token stop = {});

/// The document of a set computed: chain, modes (1-based), harmonics, grazing_set.
JsonValue gloSetDocument(const GloSetOutcome& outcome);

}  // namespace grazelab::cli
