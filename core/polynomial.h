// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <array>

namespace grazelab::core {

/// Real roots of a polynomial of degree <= 4, in no particular order.
struct RealRoots {
  std::array<double, 4> values{};
  int count = 0;

  void add(double x) { values[count++] = x; }
  const double* begin() const { return values.data(); }
  const double* end() const { return values.data() + count; }
};

/// Real roots of c[4] x^4 + c[3] x^3 + c[2] x^2 + c[1] x + c[0] (Ferrari's method through the
/// resolvent cubic, each root then polished by one Newton step on the original polynomial unless
/// `polish` is false). Leading coefficients negligible against the others lower the degree. A
/// real double root may be reported once, twice or, when rounding pushes it off the real axis,
/// not at all: callers must treat tangencies on their own terms.
RealRoots realRootsQuartic(const std::array<double, 5>& c, bool polish = true);

/// Real roots of c[3] x^3 + c[2] x^2 + c[1] x + c[0] (degree drops as for the quartic).
RealRoots realRootsCubic(const std::array<double, 4>& c);

/// Real roots of c[2] x^2 + c[1] x + c[0], computed without cancellation.
RealRoots realRootsQuadratic(double c2, double c1, double c0);

}  // namespace grazelab::core
