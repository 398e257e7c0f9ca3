// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/model/mass_chain.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/numbers/eigen_quad.h"
#include "core/numbers/scalar.h"

namespace grazelab::core {
namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// "m3", "k1": built by appending (GCC 12 warns, wrongly, of an overlapping copy in
// "m" + std::to_string(i) at -O3)
std::string indexed(char letter, std::size_t index) {
  std::string name(1, letter);
  name += std::to_string(index);
  return name;
}

void checkPositive(std::vector<Problem>& problems, const std::string& field, double value) {
  if (!(value > 0) || !std::isfinite(value)) {
    problems.push_back({field, "must be positive and finite (got " + number(value) + ")"});
  }
}

}  // namespace

std::vector<Problem> validate(const MassChain& chain) {
  std::vector<Problem> problems;
  if (chain.masses.empty()) problems.push_back({"masses", "must list at least one mass"});
  if (chain.springs.size() != chain.masses.size()) {
    problems.push_back({"springs", "must list one spring per mass (" + std::to_string(chain.masses.size()) +
                                       "), got " + std::to_string(chain.springs.size())});
  }
  for (std::size_t i = 0; i < chain.masses.size(); ++i) checkPositive(problems, indexed('m', i + 1), chain.masses[i]);
  // k1 = 0: the left end free (no wall there); the springs between masses hold the chain together
  if (!chain.springs.empty() && !(chain.springs[0] >= 0 && std::isfinite(chain.springs[0]))) {
    problems.push_back({"k1", "must be >= 0 and finite, 0 for no left wall (got " + number(chain.springs[0]) + ")"});
  }
  for (std::size_t i = 1; i < chain.springs.size(); ++i) checkPositive(problems, indexed('k', i + 1), chain.springs[i]);
  if (!(chain.rightSpring >= 0) || !std::isfinite(chain.rightSpring)) {
    problems.push_back({"right spring", "must be >= 0 and finite (got " + number(chain.rightSpring) + ")"});
  }
  checkPositive(problems, "gap", chain.gap);
  if (chain.stopMass < 0 || chain.stopMass > chain.size()) {
    problems.push_back({"stop mass", "must be a mass of the chain, 1 to " + std::to_string(chain.size()) +
                                         " (got " + std::to_string(chain.stopMass) + ")"});
  }
  return problems;
}

MassChain massChainOf(const Model& model) {
  return {{model.m1, model.m2}, {model.k1, model.k2}, 0.0, 2, model.gap};
}

namespace {

// A floating chain of equal masses m and equal springs k (a bar lumped into N masses): its modes
// in closed form, the discrete cosine transform's vectors, w_j = 2 sqrt(k/m) sin(j pi / 2N) and
// P[i][j] = cos(j pi (2i + 1) / 2N) / sqrt(m N / 2) (j = 0, the rigid body's: 1 / sqrt(m N)),
// j = 0 .. N-1; a node where j (2s + 1) = N mod 2N, exactly. No eigensolve: N^2 work where the
// solver's binary128 arithmetic costs N^3 (minutes for a thousand masses).
bool uniformFloating(const BasicMassChain<Quad>& chain) {
  if (!chain.floats() || chain.size() < 2) return false;
  for (const Quad& m : chain.masses) {
    if (m != chain.masses[0]) return false;
  }
  for (std::size_t i = 2; i < chain.springs.size(); ++i) {
    if (chain.springs[i] != chain.springs[1]) return false;
  }
  return true;
}

template <typename S>
BasicChainModes<S> uniformModes(const BasicMassChain<Quad>& chain) {
  const int n = chain.size();
  const int s = chain.stopped() - 1;
  const Quad m = chain.masses[0], k = chain.springs[1];
  const Quad pi = 4 * atan(Quad(1));
  // cos(r pi / 2N) for r = 0 .. 4N-1: every angle j (2i + 1) pi / 2N is one of them
  std::vector<Quad> cosine(std::size_t(4 * n));
  for (int r = 0; r < 4 * n; ++r) cosine[std::size_t(r)] = cos(Quad(r) * pi / Quad(2 * n));
  BasicChainModes<S> modes;
  modes.omega.resize(n);
  modes.P.resize(n, n);
  modes.nodeAtStop.assign(std::size_t(n), false);
  const Quad rate = 2 * sqrt(k / m);
  for (int c = 0; c < n; ++c) {
    const int j = n - 1 - c;  // fastest first
    modes.omega(c) = static_cast<S>(rate * sin(Quad(j) * pi / Quad(2 * n)));
    const Quad norm = j == 0 ? sqrt(m * Quad(n)) : sqrt(m * Quad(n) / 2);
    const bool node = long(j) * (2 * s + 1) % (2 * n) == n;
    // signed so that P[s][j] > 0; a node's mode by its first mass (cos(j pi / 2N) > 0)
    const int signer = node ? 0 : s;
    const Quad sign = cosine[std::size_t(long(j) * (2 * signer + 1) % (4 * n))] < 0 ? Quad(-1) : Quad(1);
    for (int i = 0; i < n; ++i) {
      modes.P(i, c) = static_cast<S>(sign * cosine[std::size_t(long(j) * (2 * i + 1) % (4 * n))] / norm);
    }
    modes.nodeAtStop[std::size_t(c)] = node;
    if (node) modes.P(s, c) = S(0);
  }
  return modes;
}

}  // namespace

template <typename S>
BasicChainModes<S> chainModesIn(const BasicMassChain<Quad>& chain) {
  if (uniformFloating(chain)) return uniformModes<S>(chain);
  const int n = chain.size();
  // In binary128: a solver in precision eps finds each w_j^2 to eps * w_1^2 absolutely, so a
  // slow mode of a stiff chain (masses and springs over six decades) loses w_1^2 / w_N^2 of
  // its relative accuracy; double lost up to 1.5e-7 on chains with masses and springs from
  // 1e-3 to 1e3. eps = 1e-34 leaves every frequency exact to double's rounding for spreads up
  // to 1e18 (checked against mpmath at 50 digits, and by the product of the w_j^2 against
  // det K / det M, a sum of positive products).
  using Matrix = Eigen::Matrix<Quad, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Quad, Eigen::Dynamic, 1>;
  Vector invRoot(n);
  for (int i = 0; i < n; ++i) invRoot(i) = Quad(1) / sqrt(chain.masses[std::size_t(i)]);
  // the symmetric form M^-1/2 K M^-1/2: its orthonormal eigenvectors V give P = M^-1/2 V,
  // M-orthonormal
  Matrix A = Matrix::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    const Quad right = i + 1 < n ? chain.springs[std::size_t(i + 1)] : chain.rightSpring;
    A(i, i) = (chain.springs[std::size_t(i)] + right) * invRoot(i) * invRoot(i);
    if (i + 1 < n) A(i, i + 1) = A(i + 1, i) = -right * invRoot(i) * invRoot(i + 1);
  }
  const Eigen::SelfAdjointEigenSolver<Matrix> solver(A);
  BasicChainModes<S> modes;
  modes.omega.resize(n);
  modes.P.resize(n, n);
  modes.nodeAtStop.assign(std::size_t(n), false);
  const int s = chain.stopped() - 1;
  for (int j = 0; j < n; ++j) {
    const int from = n - 1 - j;  // Eigen sorts ascending: the fastest mode is the last
    if (chain.floats() && from == 0) {
      // the rigid body's mode, exactly: K 1 = 0 with no wall at either end, so w = 0 and every
      // mass moves alike (the solver's is within eps w_1^2 of 0, perhaps below it, and its
      // vector within rounding of the constant one)
      Quad total = 0;
      for (const Quad& m : chain.masses) total += m;
      modes.omega(j) = S(0);
      modes.P.col(j).setConstant(static_cast<S>(Quad(1) / sqrt(total)));
      continue;
    }
    const Quad lambda = solver.eigenvalues()(from);
    modes.omega(j) = lambda > 0 ? static_cast<S>(sqrt(lambda)) : S(0);
    const Vector exact = invRoot.asDiagonal() * solver.eigenvectors().col(from);
    Eigen::Matrix<S, Eigen::Dynamic, 1> column(n);
    for (int i = 0; i < n; ++i) column(i) = static_cast<S>(exact(i));
    // a node at the stopped mass: zero within the error of the binary128 eigenvector, 8 n
    // ulps of its largest component times w_1^2 over the distance to the nearest other w^2
    // (an eigenvector is as sensitive as its eigenvalue is close to another). A component that
    // is merely small (1e-17 of the largest: a light mass on a stiff spring far from the stop)
    // still reaches the stop; a node that symmetry makes exact reads as 0.
    Quad largest = 0;
    for (int i = 0; i < n; ++i) largest = std::max(largest, Quad(abs(exact(i))));
    Quad gap = solver.eigenvalues()(n - 1);
    for (int i = 0; i < n; ++i) {
      if (i != from) gap = std::min(gap, Quad(abs(solver.eigenvalues()(i) - lambda)));
    }
    const Quad sensitivity =
        gap > 0 ? std::min(std::max(Quad(1), solver.eigenvalues()(n - 1) / gap), Quad(1e20)) : Quad(1e20);
    const Quad rounding = 8 * n * std::numeric_limits<Quad>::epsilon() * sensitivity * largest;
    const bool node = abs(exact(s)) <= rounding;
    modes.nodeAtStop[std::size_t(j)] = node;
    // signed so that P[s][j] > 0; a node's mode by its first component that moves
    int signer = s;
    if (node) {
      signer = 0;
      while (abs(exact(signer)) <= rounding) ++signer;
    }
    if (column(signer) < 0) column = -column;
    modes.P.col(j) = column;
    if (node) modes.P(s, j) = S(0);  // +0 whatever the sign
  }
  return modes;
}

ChainModes chainModes(const MassChain& chain) { return chainModesIn<double>(chain); }

template BasicChainModes<double> chainModesIn<double>(const BasicMassChain<Quad>&);
template BasicChainModes<long double> chainModesIn<long double>(const BasicMassChain<Quad>&);
template BasicChainModes<Quad> chainModesIn<Quad>(const BasicMassChain<Quad>&);

SpectrumRatios detectRatios(const Eigen::VectorXd& omega, double tolerance, int maxHarmonic) {
  SpectrumRatios ratios;
  const int n = int(omega.size());
  if (n == 0 || !(omega.minCoeff() > 0)) return ratios;
  const double slowest = omega.minCoeff();
  // the ratios with the slowest mode as harmonic q: n_j = round(q w_j / slowest), and how far
  // the modes are from them (w0 fitted to all of them by least squares in w_j = n_j w0)
  const auto fit = [&](int q) {
    SpectrumRatios candidate;
    candidate.harmonics.resize(std::size_t(n));
    double numerator = 0, denominator = 0;
    for (int j = 0; j < n; ++j) {
      const int h = int(std::max(1L, std::lround(q * omega(j) / slowest)));
      candidate.harmonics[std::size_t(j)] = h;
      numerator += h * omega(j);
      denominator += double(h) * h;
    }
    candidate.omega0 = numerator / denominator;
    for (int j = 0; j < n; ++j) {
      candidate.detuning = std::max(candidate.detuning,
                                    std::abs(omega(j) / (candidate.harmonics[std::size_t(j)] * candidate.omega0) - 1));
    }
    return candidate;
  };
  // the smallest harmonics that fit within the tolerance: a commensurate spectrum
  for (int q = 1; q <= maxHarmonic; ++q) {
    SpectrumRatios candidate = fit(q);
    int divisor = 0;
    for (int h : candidate.harmonics) divisor = std::gcd(divisor, h);
    const int largest = *std::max_element(candidate.harmonics.begin(), candidate.harmonics.end());
    if (divisor != 1 || largest > maxHarmonic || candidate.detuning > tolerance) continue;
    candidate.commensurate = true;
    return candidate;
  }
  // none: the nearest small ratios (in lowest terms, the slowest harmonic at most 12): the
  // smallest harmonics within twice the least detuning of any, with how far the chain is
  std::vector<SpectrumRatios> candidates;
  double least = std::numeric_limits<double>::infinity();
  for (int q = 1; q <= std::min(12, maxHarmonic); ++q) {
    SpectrumRatios candidate = fit(q);
    int divisor = 0;
    for (int h : candidate.harmonics) divisor = std::gcd(divisor, h);
    if (divisor != 1) continue;
    least = std::min(least, candidate.detuning);
    candidates.push_back(std::move(candidate));
  }
  for (SpectrumRatios& candidate : candidates) {
    if (candidate.detuning <= 2 * least) return candidate;
  }
  return ratios;
}

}  // namespace grazelab::core
