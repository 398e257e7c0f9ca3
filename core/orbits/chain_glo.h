// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <stop_token>
#include <utility>
#include <vector>

#include "core/model/mass_chain.h"
#include "core/solver/chain_flight.h"

namespace grazelab::core {

/// Grazing linear orbits of a chain of N masses (docs/model.md section 11). GLOM_j is mode j
/// alone with its top on the stop: u = d P_j / P[s][j], v = 0 at the touch. GLO_lambda =
/// sum_j lambda_j GLOM_j with sum_j lambda_j = 1 (so that u_s = d); on its flight u_s(t) =
/// d sum_j lambda_j cos(w_j t). Modes with a node at the stopped mass have no GLOM.
enum class GloStartProblem {
  None,
  WrongCount,    ///< not one weight per mode
  NotAffine,     ///< the weights do not sum to 1 (within 1e-12)
  WeightOnNode,  ///< a nonzero weight on a mode that does not move the stopped mass
  NotFinite,
};

template <typename S>
struct BasicChainGloStart {
  GloStartProblem problem = GloStartProblem::None;
  BasicChainState<S> state;  ///< at the touch: u_s = d exactly, v = 0
  /// the modes of weight 0: exactly still (a run from `start()` keeps them so, where the rounded
  /// state alone would hold ~1e-17 of each, and GLOM_1 of a 3:2:1 chain's touch at T/3 would be
  /// undecided in every precision)
  std::vector<bool> stillModes;
  BasicChainStart<S> start() const { return {state, stillModes}; }
};
using ChainGloStart = BasicChainGloStart<double>;

/// GLO_lambda's data of a usable chain, `weights` fastest mode first, in the chain's precision
/// (double, long double or binary128: its modes rounded to S from binary128).
template <typename S>
BasicChainGloStart<S> chainGloStartIn(const BasicMassChain<S>& chain, const std::vector<S>& weights);
/// The same from a ready chain's dynamics (chainDynamicsIn: the same modes, made once), for a
/// caller that starts many runs of one chain: the modes cost more than a short run (24 us of a
/// 70 us call from Python for three masses, most of it binary128).
template <typename S>
BasicChainGloStart<S> chainGloStartIn(const BasicChainDynamics<S>& dynamics, const std::vector<S>& weights);
inline ChainGloStart chainGloStart(const MassChain& chain, const std::vector<double>& weights) {
  return chainGloStartIn<double>(chain, weights);
}

/// Whether sum_j lambda_j cos(n_j theta) <= 1 for every theta (W_lambda is a grazing linear
/// orbit), decided by the certified first-zero search over one period of the flight
/// u_s / d - 1 = sum_j lambda_j cos(n_j theta) - 1, which starts on 0 at rest. `Boundary`: a touch
/// at some theta != 0 within what double resolves, or a flat start (the second derivative
/// -sum lambda_j n_j^2 zero within rounding): on the set's edge.
enum class GloGrazing { Grazes, Boundary, Crosses };
GloGrazing gloGrazing(const std::vector<int>& harmonics, const std::vector<double>& weights);

/// The grazing set of two modes with harmonics n1 > n2 (fastest first): the weights (1 - lambda,
/// lambda) graze exactly for lambda in [low, high] (convex, and it holds [0, 1]). Each end is
/// bracketed by bisection on gloGrazing: `low` and `high` certainly graze, `lowOut` and
/// `highOut` certainly do not; between them (a few 1e-14 at most) the search sees a touch
/// within rounding. An end at the flat point, where sum lambda_j n_j^2 = 0 (1:n resonances:
/// lambda = n^2 / (n^2 - 1), the note's 4/3), is that point exactly.
struct GrazingInterval {
  double low = 0, lowOut = 0;
  double high = 1, highOut = 1;
  double flatPoint = 0;  ///< n1^2 / (n1^2 - n2^2): where sum lambda_j n_j^2 = 0
};
GrazingInterval grazingInterval(int fast, int slow);

/// The top of u_s / d over a period of GLO with weights (1 - lambda, lambda) on harmonics (fast,
/// slow), max_theta (1 - lambda) cos(fast theta) + lambda cos(slow theta), at `points` + 1
/// values of lambda from `from` to `to`, each the largest of `phases` samples of the common
/// period: a picture's accuracy (~ (pi fast / phases)^2 / 2 of the weights), not the set's
/// ends, which grazingInterval certifies. (lambda, top) pairs.
std::vector<std::pair<double, double>> gloTopCurve(int fast, int slow, double from, double to, int points,
                                                   int phases);

/// The modes of a chain that have a GLOM (those that move the stopped mass; 0-based, fastest
/// first) and the ratios of their frequencies: a grazing set is a question about these alone.
struct GrazingModes {
  std::vector<int> modes;
  SpectrumRatios ratios;
};
GrazingModes grazingModes(const MassChain& chain);

/// The grazing set of three modes (n1 > n2 > n3) in the plane of (lambda2, lambda3), lambda1 =
/// 1 - lambda2 - lambda3: a bounded convex region holding the simplex. Its boundary along
/// `directions` rays from the simplex's centre (1/3, 1/3), each bracketed by bisection on
/// gloGrazing as the interval's ends are. Empty when stopped.
struct GrazingRegionPoint {
  double angle = 0;           ///< of the ray, from the lambda2 axis [rad]
  double lambda2 = 0, lambda3 = 0;  ///< the last point on the ray certain to graze
  double radius = 0, radiusOut = 0;  ///< from the centre: certainly grazes at radius, certainly not at radiusOut
};
std::vector<GrazingRegionPoint> grazingRegion(int n1, int n2, int n3, int directions,
                                              std::stop_token stop = {});

}  // namespace grazelab::core
