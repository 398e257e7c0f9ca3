// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/sticking.h"

#include <cmath>


namespace grazelab::core {

template <typename S>
StuckMotion<S>::StuckMotion(const TwoMassForm<S>& chain, const S& gap, const BasicState<S>& start,
                            const S& u1Residual)
    : m_gap(gap), m_start(start), m_omega(chain.stuckOmega) {
  using std::atan;
  using std::sqrt;
  // centre = kappa delta / (1 + kappa), so delta - centre = delta / (1 + kappa) exactly-ish
  const S gapAboveCentre = gap / (S(1) + chain.kappa);
  const S excess = (start.u1 - gap) + u1Residual;  // e0 >= 0 for a pressed state
  m_amplitude = excess + gapAboveCentre;
  m_rate = start.v1 / m_omega;
  // with z = tan(W t / 2): (excess) (1 + z^2) - 2 A z^2 + 2 B z = 0, i.e.
  // -(excess + 2 (delta - centre)) z^2 + 2 B z + excess = 0: one root z >= 0, one <= 0
  const S leading = excess + S(2) * gapAboveCentre;  // |e2| > 0
  const S root = sqrt(m_rate * m_rate + excess * leading);
  m_releaseZ = m_rate >= 0 ? S((m_rate + root) / leading) : S(excess / (root - m_rate));
  m_releaseTime = S(2) * atan(m_releaseZ) / m_omega;
}

template <typename S>
BasicState<S> StuckMotion<S>::atPhase(const S& sine, const S& cosineMinusOne) const {
  return {m_start.u1 + m_amplitude * cosineMinusOne + m_rate * sine, m_gap,
          m_start.v1 + m_omega * (-m_amplitude * sine + m_rate * cosineMinusOne), S(0)};
}

template <typename S>
BasicState<S> StuckMotion<S>::at(const S& tau) const {
  using std::cos;
  using std::sin;
  const S half = m_omega * tau / S(2);
  const S halfSine = sin(half);
  return atPhase(S(2) * halfSine * cos(half), S(-2) * halfSine * halfSine);
}

template <typename S>
BasicState<S> StuckMotion<S>::releaseState() const {
  using std::min;
  // sin and cos - 1 of W t rationally from z = tan(W t / 2)
  const S z = m_releaseZ;
  const S denominator = S(1) + z * z;
  BasicState<S> state = atPhase(S(2) * z / denominator, S(-2) * z * z / denominator);
  state.u1 = m_gap;
  state.v1 = min(state.v1, S(0));
  return state;
}

template class StuckMotion<double>;
template class StuckMotion<long double>;
template class StuckMotion<Quad>;

}  // namespace grazelab::core
