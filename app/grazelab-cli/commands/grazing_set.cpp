// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/grazing_set.h"

#include <cstdio>
#include <numbers>

#include "core/numbers/scalar.h"
#include "io/cli_output.h"

namespace grazelab::cli {

using V = JsonValue;

GloSetOutcome grazingSet(const core::MassChain& chain, const GloSetRequest& request, std::stop_token stop) {
  GloSetOutcome outcome;
  outcome.chain = chain;
  if (chain.floats()) {
    outcome.problem = "glo-set needs commensurate frequencies: a floating chain (no wall at either end) never has them (its rigid mode has no period)";
    return outcome;
  }
  // the modes that move the stopped mass (the others have no GLOM) and their ratios
  const core::GrazingModes grazing = core::grazingModes(chain);
  const core::SpectrumRatios& ratios = grazing.ratios;
  outcome.modes = grazing.modes;
  outcome.harmonics = ratios.harmonics;
  outcome.period = ratios.commensurate ? 2 * std::numbers::pi / ratios.omega0 : 0;
  const std::size_t used = grazing.modes.size();
  if (used > 3) {
    outcome.problem = "glo-set answers for two or three modes: " + std::to_string(used) +
                      " modes of this chain move the stopped mass";
    return outcome;
  }
  if (used > 1 && !ratios.commensurate) {
    char text[224];
    std::snprintf(text, sizeof text,
                  "glo-set needs commensurate frequencies (a flight then repeats after T): this chain's are "
                  "not, within 1e-9 (detuned by %.3g from the nearest small ratios)",
                  ratios.detuning);
    outcome.problem = text;
    return outcome;
  }
  if (used == 2) outcome.interval = core::grazingInterval(ratios.harmonics[0], ratios.harmonics[1]);
  if (used == 3) {
    outcome.boundary =
        core::grazingRegion(ratios.harmonics[0], ratios.harmonics[1], ratios.harmonics[2], request.directions, stop);
    if (stop.stop_requested()) {
      outcome.status = GloSetStatus::Interrupted;
      return outcome;
    }
  }
  outcome.status = GloSetStatus::Computed;
  return outcome;
}

JsonValue gloSetDocument(const GloSetOutcome& outcome) {
  std::vector<V> modeNumbers;
  for (int j : outcome.modes) modeNumbers.push_back(V::of(std::int64_t(j + 1)));
  std::vector<V> harmonics;
  for (int n : outcome.harmonics) harmonics.push_back(V::of(std::int64_t(n)));
  V set = V::null();
  if (outcome.modes.size() == 1) {
    set = V::object({{"kind", V::of("point")},
                     {"in_words", V::of("one mode moves the stopped mass: its GLOM is the only grazing linear orbit")}});
  } else if (outcome.interval) {
    const core::GrazingInterval& interval = *outcome.interval;
    const std::string words =
        "(1 - lambda) GLOM_" + std::to_string(outcome.modes[0] + 1) + " + lambda GLOM_" +
        std::to_string(outcome.modes[1] + 1) + " is a grazing linear orbit exactly for lambda in [" +
        core::formatScalar(interval.low) + ", " + core::formatScalar(interval.high) + "]" +
        (interval.high == interval.flatPoint ? ": its upper end is the flat point, where the touch turns fourth order"
                                             : "");
    set = V::object({{"kind", V::of("interval")},
                     {"weights", V::of("(1 - lambda, lambda) on the modes listed")},
                     {"low", V::number(interval.low)},
                     {"low_out", V::number(interval.lowOut)},
                     {"high", V::number(interval.high)},
                     {"high_out", V::number(interval.highOut)},
                     {"flat_point", V::number(interval.flatPoint)},
                     {"in_words", V::of(words)}});
  } else {
    std::vector<V> points;
    for (const core::GrazingRegionPoint& point : outcome.boundary) {
      points.push_back(V::object({{"angle", V::number(point.angle)},
                                  {"lambda2", V::number(point.lambda2)},
                                  {"lambda3", V::number(point.lambda3)},
                                  {"radius", V::number(point.radius)},
                                  {"radius_out", V::number(point.radiusOut)}}));
    }
    set = V::object(
        {{"kind", V::of("region")},
         {"weights", V::of("(1 - lambda2 - lambda3, lambda2, lambda3) on the modes listed")},
         {"boundary", V::array(std::move(points))},
         {"in_words", V::of("a convex region of the (lambda2, lambda3) plane holding the simplex; its boundary "
                            "along rays from (1/3, 1/3): each point grazes, radius_out along its ray does not")}});
  }
  return V::object({{"chain", massChainValue(outcome.chain, outcome.period)},
                    {"modes", V::array(std::move(modeNumbers))},
                    {"harmonics", V::array(std::move(harmonics))},
                    {"grazing_set", std::move(set)}});
}

}  // namespace grazelab::cli
