// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "core/solver/events.h"
#include "core/model/state.h"

namespace grazelab::core {

/// True when a state on the stop at rest (x2 = delta, y2 = 0) is pressed into it (docs/model.md
/// section 4): the spring pushes mass 2 toward the stop, u1 > gap, or u1 = gap with v1 > 0.
/// Works in physical or scaled units alike (`gap` in the same units as the state).
/// `u1Residual` is what u1 lost to rounding (exact u1 minus state.u1): a u1 a hair below the
/// gap, rounded to it, must not change the state's class.
template <typename S>
bool pressedOnStop(const BasicState<S>& state, const S& gap, const S& u1Residual = S(0)) {
  if (state.u2 != gap || state.v2 != 0) return false;
  const S offset = (state.u1 - gap) + u1Residual;
  return offset > 0 || (offset == 0 && state.v1 > 0);
}

/// What a contact does, and the state after it.
template <typename S>
struct ContactOutcome {
  EventType type = EventType::Impact;
  BasicState<S> before;  ///< on the stop (u2 = gap); v2 = 0 unless an impact
  BasicState<S> after;
};

/// Newton's impact law with e = 1 and the touch rules of docs/model.md section 4, in one place:
/// mass 2 arrives on the stop (`arrival.u2` is set to the gap) with velocity v2. A crossing with
/// v2 > 0 is an impact (v2 -> -v2, everything else continuous). A tangent touch, or an arrival
/// with no speed left, has v2 = 0: pressed into the stop it sticks, else it grazes and the
/// flight goes on unchanged.
template <typename S>
ContactOutcome<S> applyImpactLaw(BasicState<S> arrival, const S& gap, bool tangent,
                                 const S& u1Residual = S(0)) {
  arrival.u2 = gap;
  if (!tangent && arrival.v2 > 0) {
    BasicState<S> after = arrival;
    after.v2 = -arrival.v2;
    return {EventType::Impact, arrival, after};
  }
  arrival.v2 = 0;
  return {pressedOnStop(arrival, gap, u1Residual) ? EventType::Stick : EventType::Grazing, arrival,
          arrival};
}

}  // namespace grazelab::core
