// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <optional>
#include <stop_token>
#include <vector>

#include "core/model/model.h"
#include "core/model/linear_modes.h"
#include "core/model/state.h"
#include "core/orbits/special_orbits.h"

/// The computations behind the explorer's theorem scenes, as plain functions of the chain: the
/// scenes (ui/scenes/) only word and draw what these return, and a test or the command line can
/// call them alike. Each takes a stop token and returns early, marked incomplete, when stopped.
/// Their runs are the one run of the chain (core/solver/chain_run.h), raised from double to long
/// double, then binary128, where a contact is one the precision cannot decide (as simulate's
/// --precision auto): a run binary128 cannot decide either ends there.
namespace grazelab::core::experiments {

/// Lemma 2.1: the highest u2 / d of the linear orbit GLO(lambda) over a period,
/// max over s of (1 - lambda) cos 2s + lambda cos s; exactly 1 for lambda in [0, 4/3].
double gloHighestReach(double lambda);

/// Theorem 2.3's survey: random starts below the stop (within 1.5 gaps, and 1.5 w2 gaps per
/// speed), the same ones for a given seed, each run to `contacts` contacts; the free-flight
/// times of every flight that starts on the stop, in units of T2, binned from 0.
struct FlightSurvey {
  std::vector<int> counts;    ///< flights per bin of `binWidth` (T2 units); the last bin holds the rest
  double binWidth = 0;
  int flights = 0;
  int neverTouch = 0;         ///< starts that never reach the stop
  int reachedLimit = 0;       ///< starts that made all `contacts` contacts
  int other = 0;              ///< starts that stopped earlier (budget, stuck for good, ...)
  double longest = 0;         ///< largest FFT / T2 seen (Theorem 2.3: at most 1)
  std::optional<State> firstTouching;  ///< the first start that reached all its contacts
  bool complete = false;      ///< false when stopped
};
FlightSurvey surveyRandomStarts(const Model& model, int starts, std::int64_t contacts,
                                std::uint64_t seed, int bins, double binWidth,
                                std::stop_token stop = {});

/// Theorem 2.2: the largest shortfall 1 - FFT / T2 over the first `contacts` contacts of the
/// run from `start` (0 when no flight ended, or all lasted T2 exactly); nothing when stopped.
std::optional<double> largestShortfall(const Model& model, const State& start,
                                       std::int64_t contacts, std::stop_token stop = {});

/// The admissible orbits of the 1IPP family at `points` periods from just above `lowEnd` up to
/// T2 (crowding towards T2, where the theorem looks), in increasing period; what was computed
/// when stopped.
std::vector<OnePeriodicOrbit<double>> onePeriodicFamilySamples(const Model& model, const Modes& modes,
                                                        double lowEnd, int points,
                                                        std::stop_token stop = {});

}  // namespace grazelab::core::experiments
