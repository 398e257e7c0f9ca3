// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cmath>
#include <limits>

namespace grazelab::core::methods {

/// The root of f in [a, b] with f(a) <= 0 < f(b), by the Illinois variant of regula falsi
/// (superlinear, never leaves the bracket), to the resolution of double. Returns the left end
/// of the final bracket: the last point known not to be past the root.
template <typename F>
double illinoisRoot(F&& f, double a, double fa, double b, double fb) {
  int side = 0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    if (b - a <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b))) {
      break;
    }
    double c = (a * fb - b * fa) / (fb - fa);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const double fc = f(c);
    if (fc > 0) {
      b = c;
      fb = fc;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = c;
      fa = fc;
      if (side == 1) fb *= 0.5;
      side = 1;
    }
    if (fc == 0) break;
  }
  return a;
}

}  // namespace grazelab::core::methods
