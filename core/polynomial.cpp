// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/polynomial.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grazelab::core {
namespace {

// a leading coefficient below this fraction of the largest one is treated as zero
constexpr double kNegligibleLeading = 1e-14;

template <std::size_t N>
double largestMagnitude(const std::array<double, N>& c) {
  double largest = 0;
  for (double value : c) largest = std::max(largest, std::abs(value));
  return largest;
}

template <std::size_t N>
double evaluate(const std::array<double, N>& c, double x, double* derivative) {
  double value = 0;
  double slope = 0;
  for (int n = static_cast<int>(N) - 1; n >= 0; --n) {
    slope = slope * x + value;
    value = value * x + c[n];
  }
  *derivative = slope;
  return value;
}

// one Newton step, kept only when it lowers |p| (closed forms are already close)
template <std::size_t N>
double polish(const std::array<double, N>& c, double x) {
  double slope = 0;
  double residual = std::abs(evaluate(c, x, &slope));
  for (int step = 0; step < 1 && residual > 0 && slope != 0; ++step) {
    const double candidate = x - evaluate(c, x, &slope) / slope;
    double unused = 0;
    const double candidateResidual = std::abs(evaluate(c, candidate, &unused));
    if (!(candidateResidual < residual)) break;
    x = candidate;
    residual = candidateResidual;
    evaluate(c, x, &slope);
  }
  return x;
}

// largest real root of the monic cubic x^3 + a x^2 + b x + c
double largestRealRootMonicCubic(double a, double b, double c) {
  const double q = (a * a - 3.0 * b) / 9.0;
  const double r = (2.0 * a * a * a - 9.0 * a * b + 27.0 * c) / 54.0;
  const double q3 = q * q * q;
  double root;
  if (r * r < q3) {
    // three real roots: the trigonometric form; k = 0 gives the largest
    const double angle = std::acos(std::clamp(r / std::sqrt(q3), -1.0, 1.0));
    root = -2.0 * std::sqrt(q) * std::cos(angle / 3.0) - a / 3.0;
  } else {
    const double big = -std::copysign(std::cbrt(std::abs(r) + std::sqrt(r * r - q3)), r);
    const double small = big == 0 ? 0 : q / big;
    root = big + small - a / 3.0;
  }
  return root;
}

}  // namespace

RealRoots realRootsQuadratic(double c2, double c1, double c0) {
  RealRoots roots;
  if (c2 == 0) {
    if (c1 != 0) roots.add(-c0 / c1);
    return roots;
  }
  const double discriminant = c1 * c1 - 4.0 * c2 * c0;
  if (discriminant < 0) return roots;
  const double q = -0.5 * (c1 + std::copysign(std::sqrt(discriminant), c1));
  if (q == 0) {
    roots.add(0.0);
    roots.add(0.0);
    return roots;
  }
  roots.add(q / c2);
  roots.add(c0 / q);
  return roots;
}

RealRoots realRootsCubic(const std::array<double, 4>& c) {
  if (std::abs(c[3]) <= kNegligibleLeading * largestMagnitude(c)) {
    return realRootsQuadratic(c[2], c[1], c[0]);
  }
  const double a = c[2] / c[3];
  const double b = c[1] / c[3];
  const double d = c[0] / c[3];
  const double root = polish(c, largestRealRootMonicCubic(a, b, d));
  // deflate: x^3 + a x^2 + b x + d = (x - root)(x^2 + (a + root) x + (b + root (a + root)))
  RealRoots roots;
  roots.add(root);
  const double p1 = a + root;
  const double p0 = b + root * p1;
  for (double x : realRootsQuadratic(1.0, p1, p0)) roots.add(polish(c, x));
  return roots;
}

RealRoots realRootsQuartic(const std::array<double, 5>& c, bool polishRoots) {
  if (std::abs(c[4]) <= kNegligibleLeading * largestMagnitude(c)) {
    return realRootsCubic({c[0], c[1], c[2], c[3]});
  }
  // monic x^4 + b x^3 + cc x^2 + d x + e, depressed by x = y - b/4 to y^4 + p y^2 + q y + r
  const double b = c[3] / c[4];
  const double cc = c[2] / c[4];
  const double d = c[1] / c[4];
  const double e = c[0] / c[4];
  const double shift = b / 4.0;
  const double b2 = b * b;
  const double p = cc - 3.0 * b2 / 8.0;
  const double q = d - b * cc / 2.0 + b2 * b / 8.0;
  const double r = e - b * d / 4.0 + b2 * cc / 16.0 - 3.0 * b2 * b2 / 256.0;

  RealRoots depressed;
  const double scale = std::max({std::abs(p), std::sqrt(std::abs(r)), 1e-300});
  if (std::abs(q) <= 1e-14 * scale * std::sqrt(scale)) {
    // biquadratic: y^2 = z with z^2 + p z + r = 0
    for (double z : realRootsQuadratic(1.0, p, r)) {
      if (z < 0) continue;
      const double y = std::sqrt(z);
      depressed.add(y);
      depressed.add(-y);
    }
  } else {
    // Ferrari: with m > 0 a root of m^3 + p m^2 + (p^2/4 - r) m - q^2/8 = 0,
    // y^4 + p y^2 + q y + r = (y^2 + s y + p/2 + m - q/(2s)) (y^2 - s y + p/2 + m + q/(2s)),
    // s = sqrt(2m)
    const double m = largestRealRootMonicCubic(p, p * p / 4.0 - r, -q * q / 8.0);
    if (m > 0) {
      const double s = std::sqrt(2.0 * m);
      for (double y : realRootsQuadratic(1.0, s, p / 2.0 + m - q / (2.0 * s))) depressed.add(y);
      for (double y : realRootsQuadratic(1.0, -s, p / 2.0 + m + q / (2.0 * s))) depressed.add(y);
    }
  }
  RealRoots roots;
  for (double y : depressed) roots.add(polishRoots ? polish(c, y - shift) : y - shift);
  return roots;
}

}  // namespace grazelab::core
