// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/chain_glo.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <utility>

#include "core/numbers/roots.h"
#include "core/solver/sinusoid_zero.h"

namespace grazelab::core {

namespace {

// GLO_lambda's data from the mode shapes P (fastest first), their nodes at the stopped mass s
// (0-based) and the gap
template <typename S>
BasicChainGloStart<S> gloStart(const Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>& P,
                               const std::vector<bool>& nodeAtStop, int s, const S& gap,
                               const std::vector<S>& weights) {
  using std::abs;
  BasicChainGloStart<S> start;
  const Eigen::Index n = P.cols();
  // (dynamics made by hand without their nodes are refused, not read past their end)
  if (Eigen::Index(weights.size()) != n || Eigen::Index(nodeAtStop.size()) != n) {
    start.problem = GloStartProblem::WrongCount;
    return start;
  }
  S sum = 0;
  for (std::size_t j = 0; j < weights.size(); ++j) {
    if (!isFinite(weights[j])) {
      start.problem = GloStartProblem::NotFinite;
      return start;
    }
    if (nodeAtStop[j] && weights[j] != 0) {
      start.problem = GloStartProblem::WeightOnNode;
      return start;
    }
    sum += weights[j];
  }
  if (!(abs(sum - 1) <= S(1e-12))) {
    start.problem = GloStartProblem::NotAffine;
    return start;
  }
  start.state.u = ChainVector<S>::Zero(n);
  start.state.v = ChainVector<S>::Zero(n);
  start.stillModes.assign(std::size_t(n), false);
  for (Eigen::Index j = 0; j < n; ++j) {
    start.stillModes[std::size_t(j)] = weights[std::size_t(j)] == 0;
    if (weights[std::size_t(j)] == 0) continue;
    start.state.u += weights[std::size_t(j)] * gap / P(s, j) * P.col(j);
  }
  start.state.u[s] = gap;  // on the stop exactly: sum lambda_j d = d up to rounding
  return start;
}

}  // namespace

template <typename S>
BasicChainGloStart<S> chainGloStartIn(const BasicMassChain<S>& chain, const std::vector<S>& weights) {
  const BasicChainModes<S> modes = chainModesIn<S>(chain);
  return gloStart<S>(modes.P, modes.nodeAtStop, chain.stopped() - 1, chain.gap, weights);
}

template <typename S>
BasicChainGloStart<S> chainGloStartIn(const BasicChainDynamics<S>& dynamics, const std::vector<S>& weights) {
  return gloStart<S>(dynamics.P, dynamics.nodeAtStop, dynamics.stop, dynamics.gap, weights);
}

#define GRAZELAB_INSTANTIATE_GLO_START(S)                                                              \
  template BasicChainGloStart<S> chainGloStartIn<S>(const BasicMassChain<S>&, const std::vector<S>&); \
  template BasicChainGloStart<S> chainGloStartIn<S>(const BasicChainDynamics<S>&, const std::vector<S>&);
GRAZELAB_INSTANTIATE_GLO_START(double)
GRAZELAB_INSTANTIATE_GLO_START(long double)
GRAZELAB_INSTANTIATE_GLO_START(Quad)
#undef GRAZELAB_INSTANTIATE_GLO_START

GloGrazing gloGrazing(const std::vector<int>& harmonics, const std::vector<double>& weights) {
  // f(theta) = sum_j lambda_j cos(n_j theta) - 1, 2 pi periodic, f(0) = f'(0) = 0
  SinusoidSum f;
  const Eigen::Index n = Eigen::Index(weights.size());
  f.a.resize(n);
  f.b = Eigen::VectorXd::Zero(n);
  f.w.resize(n);
  double curvature = 0, scale = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double h = harmonics[std::size_t(j)];
    f.a[j] = weights[std::size_t(j)];
    f.w[j] = h;
    curvature -= weights[std::size_t(j)] * h * h;
    scale += std::abs(weights[std::size_t(j)]) * h * h;
  }
  f.offset = -1;
  f.harmonics = harmonics;
  f.omega0 = 1;
  f.startTerms = 2;
  const double period = 2 * std::numbers::pi;
  const FirstZero zero = firstZero(f, period, period);
  switch (zero.kind) {
    case ZeroKind::Crossing: return GloGrazing::Crosses;
    case ZeroKind::None: return GloGrazing::Grazes;
    case ZeroKind::Budget: return GloGrazing::Boundary;  // not expected over one period
    case ZeroKind::Touch:
      if (zero.t >= period) return GloGrazing::Grazes;  // the flight's return: the GLO's touch
      if (zero.t > 0) return GloGrazing::Boundary;
      // a start the search cannot see leave: rising (outside) or flat within rounding (the edge)
      return curvature > 16 * std::numeric_limits<double>::epsilon() * scale ? GloGrazing::Crosses
                                                                              : GloGrazing::Boundary;
  }
  return GloGrazing::Boundary;
}

namespace {

// The edge along weights(r), r from `in` (grazes) to `out` (crosses), as a bracket
// [certainly grazes, certainly crosses]: between them lie the points the search calls Boundary
// (a touch within rounding), so it is bisected twice, Boundary counted once on each side; each
// bisection runs to adjacent doubles
//
// Where the edge is the flat point (sum lambda_j n_j^2 = 0: the touch at theta = 0 turns from
// second to fourth order, the note's lambda = 4/3), the search cannot see the start leave within
// about 1e-12 of it; that point, `flat` along the ray (NaN: none), is then the edge exactly
template <typename Weights>
std::pair<double, double> bisectEdge(const std::vector<int>& harmonics, const Weights& weights, double in, double out,
                                     double flat = std::numeric_limits<double>::quiet_NaN()) {
  const auto bisect = [&](double inside, double outside, bool boundaryInside) {
    double lastOutside = outside;  // where the bracket's outer end ends: the last point outside
    const auto grazes = [&](double middle) {
      const GloGrazing answer = gloGrazing(harmonics, weights(middle));
      const bool in = answer == GloGrazing::Grazes || (boundaryInside && answer == GloGrazing::Boundary);
      if (!in) lastOutside = middle;
      return in;
    };
    const double lastInside = bisectBoundary(inside, outside, grazes, [] { return false; });
    return std::pair{lastInside, lastOutside};
  };
  const double firstCrossing = bisect(in, out, true).second;
  const double lastGrazing = bisect(in, out, false).first;
  if (std::min(lastGrazing, firstCrossing) <= flat && flat <= std::max(lastGrazing, firstCrossing)) {
    return {flat, firstCrossing};
  }
  return {lastGrazing, firstCrossing};
}

}  // namespace

GrazingModes grazingModes(const MassChain& chain) {
  const ChainModes modes = chainModes(chain);
  GrazingModes result;
  for (int j = 0; j < int(modes.omega.size()); ++j) {
    if (!modes.nodeAtStop[std::size_t(j)]) result.modes.push_back(j);
  }
  Eigen::VectorXd omega(Eigen::Index(result.modes.size()));
  for (std::size_t i = 0; i < result.modes.size(); ++i) omega[Eigen::Index(i)] = modes.omega[result.modes[i]];
  result.ratios = detectRatios(omega);
  return result;
}

std::vector<std::pair<double, double>> gloTopCurve(int fast, int slow, double from, double to, int points,
                                                   int phases) {
  std::vector<std::pair<double, double>> curve;
  // the two cosines at each phase once, then every lambda from them
  std::vector<double> fastCos(std::size_t(std::max(phases, 1))), slowCos(fastCos.size());
  for (std::size_t k = 0; k < fastCos.size(); ++k) {
    const double theta = 2 * std::numbers::pi * double(k) / double(fastCos.size());
    fastCos[k] = std::cos(fast * theta);
    slowCos[k] = std::cos(slow * theta);
  }
  for (int i = 0; i <= points; ++i) {
    const double lambda = from + (to - from) * i / std::max(points, 1);
    double top = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < fastCos.size(); ++k) top = std::max(top, (1 - lambda) * fastCos[k] + lambda * slowCos[k]);
    curve.emplace_back(lambda, top);
  }
  return curve;
}

GrazingInterval grazingInterval(int fast, int slow) {
  const std::vector<int> harmonics{fast, slow};
  const auto weights = [](double lambda) { return std::vector<double>{1 - lambda, lambda}; };
  GrazingInterval interval;
  // [0, 1] grazes (every convex combination does); beyond lambda = n1^2 / (n1^2 - n2^2) the
  // flight rises at once (u_s'' > 0 at the touch), and below lambda = -1 it crosses where
  // cos(n1 theta) = 1 and cos(n2 theta) < 1 (theta = 2 pi / n1)
  const double flat = double(fast) * fast / (double(fast) * fast - double(slow) * slow);
  interval.flatPoint = flat;
  std::tie(interval.high, interval.highOut) = bisectEdge(harmonics, weights, 1.0, flat + 1, flat);
  std::tie(interval.low, interval.lowOut) = bisectEdge(harmonics, weights, 0.0, -1.0);
  return interval;
}

std::vector<GrazingRegionPoint> grazingRegion(int n1, int n2, int n3, int directions, std::stop_token stop) {
  const std::vector<int> harmonics{n1, n2, n3};
  std::vector<GrazingRegionPoint> boundary;
  for (int k = 0; k < directions; ++k) {
    if (stop.stop_requested()) return {};
    const double angle = 2 * std::numbers::pi * k / directions;
    const double dx = std::cos(angle), dy = std::sin(angle);
    const auto weights = [&](double r) {
      const double l2 = 1.0 / 3 + r * dx, l3 = 1.0 / 3 + r * dy;
      return std::vector<double>{1 - l2 - l3, l2, l3};
    };
    // the region is bounded (a direction along which it were unbounded would give a zero-mean
    // trigonometric sum <= 0 everywhere): double the radius until the ray leaves it
    double out = 1;
    while (gloGrazing(harmonics, weights(out)) != GloGrazing::Crosses && out < 1e6) out *= 2;
    // where the ray meets sum lambda_j n_j^2 = 0 (lambda1 = 1 - lambda2 - lambda3)
    const double q1 = double(n1) * n1, q2 = double(n2) * n2, q3 = double(n3) * n3;
    const double slope = (q2 - q1) * dx + (q3 - q1) * dy;
    const double atCentre = (q1 + q2 + q3) / 3;
    const double flat = slope < 0 ? -atCentre / slope : std::numeric_limits<double>::quiet_NaN();
    const auto [in, outside] = bisectEdge(harmonics, weights, 0.0, out, flat);
    GrazingRegionPoint point;
    point.angle = angle;
    point.radius = in;
    point.radiusOut = outside;
    const std::vector<double> edge = weights(in);
    point.lambda2 = edge[1];
    point.lambda3 = edge[2];
    boundary.push_back(point);
  }
  return boundary;
}

}  // namespace grazelab::core
