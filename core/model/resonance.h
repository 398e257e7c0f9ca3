// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>
#include <string_view>

namespace grazelab::core {

/// The two stiffness branches of the 1:2 design (docs/model.md section 2): "+" root is Upper.
enum class Branch { Upper, Lower };

/// Largest mass ratio m2/m1 for which a 1:2 resonant chain exists; the branches meet there.
inline constexpr double kMaxResonantMassRatio = 9.0 / 16.0;

/// True when m2/m1 <= 9/16, decided exactly (no rounding of the ratio).
template <typename S>
bool designFeasible(const S& m1, const S& m2);

/// kappa = k2/k1 of the 1:2 resonant chain for beta = m2/m1 <= 9/16:
///   kappa = beta [(17 - 8 beta) +- 5 sqrt(9 - 16 beta)] / (8 (1 + beta)^2),
/// the lower root taken from the product of the roots, beta^2 / (1 + beta)^2, so that it keeps
/// its relative precision as beta -> 0.
template <typename S>
S designKappa(const S& beta, Branch branch);

/// The stiffness k2 that makes w_fast = 2 w_slow. Returns nothing when m2/m1 > 9/16 (no resonant
/// chain) or an input is not positive and finite.
std::optional<double> resonantK2(double m1, double m2, double k1, Branch branch);

/// k2 for which the chain's frequencies have the ratio w_fast / w_slow = ratio (> 1): a
/// detuned chain near 1:2 for ratio near 2. With beta = m2/m1, kappa = k2/k1, r = ratio:
/// r^2 (1+beta)^2 kappa^2 + [2 r^2 beta (1+beta) - beta (1+r^2)^2] kappa + r^2 beta^2 = 0
/// (r = 2 gives the 1:2 design). Nothing when no positive k2 gives that ratio.
std::optional<double> k2ForFrequencyRatio(double m1, double m2, double k1, double ratio,
                                          Branch branch);

/// The resonance defect of a chain given by its numbers, computed exactly from them (rational
/// arithmetic on the binary values, then rounded once):
///   D / beta^2 = (lambdaFast - 4 lambdaSlow)(4 lambdaFast - lambdaSlow),
/// with lambda = w^2 m1 / k1 and D = 4 (1+beta)^2 kappa^2 - beta (17 - 8 beta) kappa + 4 beta^2,
/// the 1:2 condition of docs/model.md section 2. Zero exactly when the chain is exactly resonant.
template <typename S>
S resonanceDefect(const S& m1, const S& m2, const S& k1, const S& k2);

/// "upper" / "lower".
std::string_view toString(Branch branch);

/// Parses "upper" / "lower"; nothing for anything else.
std::optional<Branch> parseBranch(std::string_view text);

}  // namespace grazelab::core
