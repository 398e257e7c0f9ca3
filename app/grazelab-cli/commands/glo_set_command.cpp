// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/glo_set_command.h"

#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/orbits/chain_glo.h"
#include "exit_codes.h"
#include "io/cli_input.h"
#include "io/cli_output.h"
#include "io/json_value.h"

namespace grazelab::cli {
namespace {

using V = JsonValue;

constexpr int kDefaultDirections = 72;
constexpr int kMaxDirections = 100'000;

// the chain: --masses ..., or the two-mass chain of --m1 ... (the note's by default)
std::optional<core::MassChain> chainOf(const OptionValues& options, std::stop_token stop, QString& error,
                                       bool& stopped) {
  if (options.isSet("masses")) {
    const auto chain = parseMassChain(options, stop);
    stopped = !chain.value && chain.error.isEmpty();
    if (!chain.value) error = chain.error;
    if (!chain.value) return std::nullopt;
    return chain.value->chain;
  }
  for (const char* name : {"springs", "right-spring", "stop-mass", "frequencies", "design-branch"}) {
    if (options.isSet(name)) {
      error = "--springs, --right-spring, --stop-mass and --frequencies describe a chain given by --masses";
      return std::nullopt;
    }
  }
  const auto model = parseModel<double>(options);
  if (!model.value) error = model.error;
  if (!model.value) return std::nullopt;
  return core::massChainOf(model.value->model);
}

}  // namespace

int runGloSet(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  int directions = kDefaultDirections;
  if (options.isSet("directions")) {
    bool ok = false;
    directions = options.value("directions").toInt(&ok);
    if (!ok || directions < 3 || directions > kMaxDirections) {
      error = QStringLiteral("--directions: a whole number from 3 to %1").arg(kMaxDirections);
      return kExitInvalidInput;
    }
  }
  if (options.isSet("precision") && options.value("precision") != "double" && options.value("precision") != "auto") {
    error = "--precision: glo-set is computed in double (give double or auto)";
    return kExitInvalidInput;
  }
  bool stopped = false;
  const auto chain = chainOf(options, stop, error, stopped);
  if (stopped) return kExitInterrupted;
  if (!chain) return kExitInvalidInput;
  // the modes that move the stopped mass (the others have no GLOM) and their ratios
  const core::GrazingModes grazing = core::grazingModes(*chain);
  const std::vector<int>& used = grazing.modes;
  const core::SpectrumRatios& ratios = grazing.ratios;
  if (used.size() > 3) {
    error = QStringLiteral("glo-set answers for two or three modes: %1 modes of this chain move the stopped mass")
                .arg(used.size());
    return kExitInvalidInput;
  }
  if (used.size() > 1 && !ratios.commensurate) {
    error = QStringLiteral("glo-set needs commensurate frequencies (a flight then repeats after T): this chain's "
                           "are not, within 1e-9 (detuned by %1 from the nearest small ratios)")
                .arg(ratios.detuning, 0, 'g', 3);
    return kExitInvalidInput;
  }
  std::vector<V> modeNumbers;
  for (int j : used) modeNumbers.push_back(V::of(std::int64_t(j + 1)));
  std::vector<V> harmonics;
  for (int n : ratios.harmonics) harmonics.push_back(V::of(std::int64_t(n)));
  V set = V::null();
  if (used.size() == 1) {
    set = V::object({{"kind", V::of("point")},
                     {"in_words", V::of("one mode moves the stopped mass: its GLOM is the only grazing linear orbit")}});
  } else if (used.size() == 2) {
    const int fast = ratios.harmonics[0], slow = ratios.harmonics[1];
    const core::GrazingInterval interval = core::grazingInterval(fast, slow);
    const double flat = interval.flatPoint;
    const std::string words =
        "(1 - lambda) GLOM_" + std::to_string(used[0] + 1) + " + lambda GLOM_" + std::to_string(used[1] + 1) +
        " is a grazing linear orbit exactly for lambda in [" + core::formatScalar(interval.low) + ", " +
        core::formatScalar(interval.high) + "]" +
        (interval.high == flat ? ": its upper end is the flat point, where the touch turns fourth order" : "");
    set = V::object({{"kind", V::of("interval")},
                     {"weights", V::of("(1 - lambda, lambda) on the modes listed")},
                     {"low", V::number(interval.low)},
                     {"low_out", V::number(interval.lowOut)},
                     {"high", V::number(interval.high)},
                     {"high_out", V::number(interval.highOut)},
                     {"flat_point", V::number(flat)},
                     {"in_words", V::of(words)}});
  } else {
    const auto boundary =
        core::grazingRegion(ratios.harmonics[0], ratios.harmonics[1], ratios.harmonics[2], directions, stop);
    if (stop.stop_requested()) return kExitInterrupted;
    std::vector<V> points;
    for (const core::GrazingRegionPoint& point : boundary) {
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
  const double period = ratios.commensurate ? 2 * std::numbers::pi / ratios.omega0 : 0;
  emitDocument(io, V::object({{"chain", massChainValue(*chain, period)},
                              {"modes", V::array(std::move(modeNumbers))},
                              {"harmonics", V::array(std::move(harmonics))},
                              {"grazing_set", std::move(set)}}));
  return 0;
}

}  // namespace grazelab::cli
