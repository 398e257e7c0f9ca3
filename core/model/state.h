// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <ostream>

namespace grazelab::core {

/// Position and velocity of the chain (docs/model.md section 1). Displacements are measured from
/// the spring equilibrium, so the stop sits at u2 = gap. The same struct carries nondimensional
/// states inside the solver (docs/model.md section 7: x = u / L, y = v / (w2 L)).
template <typename S>
struct BasicState {
  S u1 = 0;  ///< displacement of mass 1 [length]
  S u2 = 0;  ///< displacement of mass 2 [length]; u2 <= gap
  S v1 = 0;  ///< velocity of mass 1 [length/time]
  S v2 = 0;  ///< velocity of mass 2 [length/time]; v2 > 0 moves toward the stop

  friend bool operator==(const BasicState&, const BasicState&) = default;
};

using State = BasicState<double>;

template <typename S>
BasicState<S> operator+(const BasicState<S>& a, const BasicState<S>& b) {
  return {a.u1 + b.u1, a.u2 + b.u2, a.v1 + b.v1, a.v2 + b.v2};
}

template <typename S>
BasicState<S> operator*(S s, const BasicState<S>& a) {
  return {s * a.u1, s * a.u2, s * a.v1, s * a.v2};
}

/// The same state in another precision (exact when widening).
template <typename To, typename From>
BasicState<To> convertState(const BasicState<From>& s) {
  return {To(s.u1), To(s.u2), To(s.v1), To(s.v2)};
}

template <typename S>
std::ostream& operator<<(std::ostream& out, const BasicState<S>& s) {
  return out << "State{u1=" << s.u1 << ", u2=" << s.u2 << ", v1=" << s.v1 << ", v2=" << s.v2
             << "}";
}

}  // namespace grazelab::core
