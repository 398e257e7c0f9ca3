// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/resonance.h"

#include <cmath>

namespace grazelab::core {

std::optional<double> resonantK2(double m1, double m2, double k1, Branch branch) {
  const bool usable = std::isfinite(m1) && std::isfinite(m2) && std::isfinite(k1) && m1 > 0 &&
                      m2 > 0 && k1 > 0;
  if (!usable) return std::nullopt;
  const double beta = m2 / m1;
  if (beta > kMaxResonantMassRatio) return std::nullopt;
  // 9 - 16 beta can round slightly negative exactly at the merge point
  const double root = std::sqrt(std::max(0.0, 9.0 - 16.0 * beta));
  const double sign = branch == Branch::Upper ? 1.0 : -1.0;
  const double onePlusBeta = 1.0 + beta;
  const double kappa =
      beta * ((17.0 - 8.0 * beta) + sign * 5.0 * root) / (8.0 * onePlusBeta * onePlusBeta);
  return kappa * k1;
}

std::string_view toString(Branch branch) { return branch == Branch::Upper ? "upper" : "lower"; }

std::optional<Branch> parseBranch(std::string_view text) {
  if (text == "upper") return Branch::Upper;
  if (text == "lower") return Branch::Lower;
  return std::nullopt;
}

}  // namespace grazelab::core
