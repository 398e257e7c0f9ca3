// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <ostream>

namespace grazelab::core {

/// Position and velocity of the chain (MODEL.md section 1). Displacements are measured from the
/// spring equilibrium, so the stop sits at u2 = gap.
struct State {
  double u1 = 0;  ///< displacement of mass 1 [length]
  double u2 = 0;  ///< displacement of mass 2 [length]; u2 <= gap
  double v1 = 0;  ///< velocity of mass 1 [length/time]
  double v2 = 0;  ///< velocity of mass 2 [length/time]; v2 > 0 moves toward the stop

  friend bool operator==(const State&, const State&) = default;
};

inline State operator+(const State& a, const State& b) {
  return {a.u1 + b.u1, a.u2 + b.u2, a.v1 + b.v1, a.v2 + b.v2};
}

inline State operator*(double s, const State& a) { return {s * a.u1, s * a.u2, s * a.v1, s * a.v2}; }

inline std::ostream& operator<<(std::ostream& out, const State& s) {
  return out << "State{u1=" << s.u1 << ", u2=" << s.u2 << ", v1=" << s.v1 << ", v2=" << s.v2 << "}";
}

}  // namespace grazelab::core
