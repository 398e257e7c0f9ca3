// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>
#include <string_view>

namespace grazelab::core {

/// The two stiffness branches of the 1:2 design (MODEL.md section 2): "+" root is Upper.
enum class Branch { Upper, Lower };

/// Largest mass ratio m2/m1 for which a 1:2 resonant chain exists; the branches meet there.
inline constexpr double kMaxResonantMassRatio = 9.0 / 16.0;

/// The stiffness k2 that makes w_fast = 2 w_slow, from
///   k2/k1 = beta [(17 - 8 beta) +- 5 sqrt(9 - 16 beta)] / (8 (1 + beta)^2),  beta = m2/m1.
/// Returns nothing when m2/m1 > 9/16 (no resonant chain) or an input is not positive and finite.
std::optional<double> resonantK2(double m1, double m2, double k1, Branch branch);

/// "upper" / "lower".
std::string_view toString(Branch branch);

/// Parses "upper" / "lower"; nothing for anything else.
std::optional<Branch> parseBranch(std::string_view text);

}  // namespace grazelab::core
