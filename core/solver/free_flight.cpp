// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/free_flight.h"

#include <cmath>
#include <limits>

namespace grazelab::core {
namespace {

template <typename S>
struct InverseFactorials {
  std::array<S, Flight<S>::kMaxTaylorOrder + 2> values;
  InverseFactorials() {
    S factorial = 1;
    for (int n = 0; n < int(values.size()); ++n) {
      if (n > 0) factorial *= S(n);
      values[n] = S(1) / factorial;
    }
  }
};

template <typename S>
const S& inverseFactorial(int n) {
  static const InverseFactorials<S> table;
  return table.values[n];
}

// (sin x, cos x - 1) without cancellation for small x
template <typename S>
void phaseOf(const S& x, S& sine, S& cosineMinusOne) {
  using std::cos;
  using std::sin;
  const S half = x / S(2);
  const S halfSine = sin(half);
  const S halfCosine = cos(half);
  sine = S(2) * halfSine * halfCosine;
  cosineMinusOne = S(-2) * halfSine * halfSine;
}

// Taylor order by precision: (ratio |s|)^(n+1) / (n+1)! far below the unit roundoff at the
// window's edge ratio |s| = 1/20
template <typename S>
constexpr int taylorOrderFor() {
  if constexpr (std::is_same_v<S, double>) return 11;
  if constexpr (std::is_same_v<S, long double>) return 13;
  return 18;
}

}  // namespace

template <typename S>
FlightTime<S> FlightTime<S>::nearest(const S& tau) {
  using std::fma;
  using std::llround;
  FlightTime time;
  time.periods = static_cast<long long>(llround(toDouble(tau / twoPi<S>())));
  time.offset = fma(-S(time.periods), twoPi<S>(), tau);
  return time;
}

template <typename S>
Flight<S>::Flight(const TwoMassForm<S>& chain, const S& gap, const BasicState<S>& start,
                  const S& u1Residual)
    : m_chain(&chain),
      m_gap(gap),
      m_start(start),
      m_startU1Residual(u1Residual),
      m_startStretch((start.u1 - start.u2) + u1Residual),
      m_startsOnStop(start.u2 == gap) {
  using std::abs;
  using std::hypot;
  using std::sqrt;
  m_taylorOrder = taylorOrderFor<S>();
  Anchor& origin = m_anchors[0];
  origin.periods = 0;
  origin.state = start;
  // modal amplitudes with unit mass-2 components: x = c_f (rho_f, 1) + c_s (rho_s, 1)
  const S denominator = chain.rhoFast - chain.rhoSlow;  // < 0, no cancellation
  origin.c = {(start.u1 - chain.rhoSlow * start.u2) / denominator,
              (chain.rhoFast * start.u2 - start.u1) / denominator};
  origin.a = {(start.v1 - chain.rhoSlow * start.v2) / denominator / chain.ratio,
              (chain.rhoFast * start.v2 - start.v1) / denominator};

  if (start.u2 != gap) {
    m_contactOrder = 0;
  } else if (start.v2 != 0) {
    m_contactOrder = 1;  // the common case, decided without the series
  } else {
    m_contactOrder = 2;
    while (m_contactOrder <= m_taylorOrder && gapDerivative(m_contactOrder) == 0) ++m_contactOrder;
  }

  m_taylorRadius = S(1) / (S(20) * chain.ratio);
  const S omegaSquared[2] = {chain.ratio * chain.ratio, S(1)};
  S amplitudeSum = 0;
  for (int j = 0; j < 2; ++j) {
    // hypot only where the squares would overflow or lose digits to underflow (it costs as
    // much as the rest of the constructor)
    const S square = origin.c[j] * origin.c[j] + origin.a[j] * origin.a[j];
    const bool plain = square >= std::numeric_limits<S>::min() / epsilon<S>() && isFinite(square);
    const S amplitude = plain ? S(sqrt(square)) : S(hypot(origin.c[j], origin.a[j]));
    amplitudeSum += amplitude;
    m_accelerationBound += amplitude * omegaSquared[j];
  }
  m_gapTolerance = S(16) * epsilon<S>() * (S(2) * amplitudeSum + abs(start.u2 - gap));
  // (x2 = sum_j c_j cos + a_j sin about 0: x2 = c_f + c_s at the start)
  m_neverReachesStop = !m_startsOnStop && amplitudeSum + m_gapTolerance < gap;
}

template <typename S>
const typename Flight<S>::Anchor& Flight<S>::newAnchor(long long periods) const {
  Anchor& cached = m_anchors[1];
  using std::round;
  const Anchor& origin = m_anchors[0];
  // the fast phase slips by 2 pi k (w1/w2 - 2) per k slow periods; k times the detuning is
  // formed exactly (its rounding by fma) before the whole turns are taken off, so that the slip
  // keeps full relative precision however many periods a flight lasts (its rounding grew with k
  // and, the same in every shadow of the same precision, stayed out of the error estimate)
  using std::fma;
  const S turns = S(periods);
  const S product = turns * m_chain->detuning;
  const S productError = fma(turns, m_chain->detuning, S(-product));
  const S slip = (product - round(product)) + productError;
  S sine, cosineMinusOne;
  phaseOf(twoPi<S>() * slip, sine, cosineMinusOne);
  const S dc = origin.c[0] * cosineMinusOne + origin.a[0] * sine;
  const S da = -origin.c[0] * sine + origin.a[0] * cosineMinusOne;
  // fields set one by one: Anchor{} would zero the Taylor rows, once per period of a march
  cached.taylorReady = false;
  cached.periods = periods;
  cached.c = {origin.c[0] + dc, origin.c[1]};
  cached.a = {origin.a[0] + da, origin.a[1]};
  const S r = m_chain->ratio;
  cached.state = {m_start.u1 + m_chain->rhoFast * dc, m_start.u2 + dc,
                  m_start.v1 + r * m_chain->rhoFast * da, m_start.v2 + r * da};
  // keep the gap as (x2(0) - delta) + dc: the anchor's x2 alone would round it
  cached.gapValue = (m_start.u2 - m_gap) + dc;
  return cached;
}

namespace {
// d^n x / dtau^n from d^(n-2): x1'' = -(p x1 + q (x1 - x2)), x2'' = w (x1 - x2), the spring
// stretch kept as one difference. One definition, so that every use rounds alike.
template <typename S>
std::array<S, 2> taylorRowOfStretch(const TwoMassForm<S>& chain, const S& first, const S& stretch) {
  return {-(chain.p * first + chain.q * stretch), chain.w * stretch};
}
template <typename S>
std::array<S, 2> nextTaylorRow(const TwoMassForm<S>& chain, const std::array<S, 2>& twoBefore) {
  return taylorRowOfStretch(chain, twoBefore[0], S(twoBefore[0] - twoBefore[1]));
}

// a + b = sum + error exactly (Knuth's TwoSum)
template <typename S>
S additionError(const S& a, const S& b, const S& sum) {
  const S bPart = sum - a;
  return (a - (sum - bPart)) + (b - bPart);
}
}  // namespace

template <typename S>
std::array<S, 5> Flight<S>::lowGapDerivatives() const {
  const std::array<S, 2> d2 = taylorRowOfStretch(*m_chain, m_start.u1, m_startStretch);
  const std::array<S, 2> d3 = nextTaylorRow(*m_chain, {m_start.v1, m_start.v2});
  const std::array<S, 2> d4 = nextTaylorRow(*m_chain, d2);
  return {m_start.u2 - m_gap, m_start.v2, d2[1], d3[1], d4[1]};
}

template <typename S>
void Flight<S>::fillTaylor(const Anchor& anchor) const {
  if (anchor.taylorReady) return;
  Anchor& target = const_cast<Anchor&>(anchor);
  target.taylorReady = true;
  const TwoMassForm<S>& chain = *m_chain;
  auto& d = target.derivatives;
  d[0] = {anchor.state.u1, anchor.state.u2};
  d[1] = {anchor.state.v1, anchor.state.v2};
  // x1'' = -(p x1 + q (x1 - x2)), x2'' = w (x1 - x2): the spring stretch stays one difference
  // (at the start, the exact one)
  d[2] = &anchor == &m_anchors[0] ? taylorRowOfStretch(chain, anchor.state.u1, m_startStretch)
                                   : nextTaylorRow(chain, d[0]);
  for (int n = 3; n < m_taylorOrder + 2; ++n) d[n] = nextTaylorRow(chain, d[n - 2]);
}

template <typename S>
S Flight<S>::gapDerivative(int n) const {
  if (n == 0) return m_start.u2 - m_gap;
  if (n == 1) return m_start.v2;
  fillTaylor(m_anchors[0]);
  return m_anchors[0].derivatives[n][1];
}

template <typename S>
int Flight<S>::taylorTerms(const S& s) const {
  using std::abs;
  const S x = m_chain->ratio * abs(s);
  const int order = m_taylorOrder;
  if (x <= S(0.01)) return order - 3 - (order > 11 ? 1 : 0) - (order > 13 ? 1 : 0);
  if (x <= S(0.03)) return order - 2;
  return order;
}

template <typename S>
inline void Flight<S>::modalPhases(const S& s, std::array<S, 2>& sine,
                            std::array<S, 2>& cosineMinusOne) const {
  if (m_chain->resonant) {
    // the fast phase is exactly twice the slow one: one sincos serves both
    phaseOf(s, sine[1], cosineMinusOne[1]);
    sine[0] = S(2) * sine[1] * (S(1) + cosineMinusOne[1]);
    cosineMinusOne[0] = S(-2) * sine[1] * sine[1];
  } else {
    phaseOf(m_chain->ratio * s, sine[0], cosineMinusOne[0]);
    phaseOf(s, sine[1], cosineMinusOne[1]);
  }
}

template <typename S>
BasicState<S> Flight<S>::modalAt(const Anchor& anchor, const S& s, S* u1Residual) const {
  std::array<S, 2> sine, cosineMinusOne;
  modalPhases(s, sine, cosineMinusOne);
  return stateFromPhases(anchor, sine, cosineMinusOne, u1Residual);
}

template <typename S>
void Flight<S>::statesOnGrid(const S& first, const S& step, std::span<BasicState<S>> out) const {
  constexpr std::size_t kExactEvery = 16;
  const Anchor& start = m_anchors[0];
  const S omega[2] = {m_chain->ratio, S(1)};
  // the rotation by one step, as (sin, cos - 1): small steps keep their precision
  std::array<S, 2> stepSine, stepCosineMinusOne;
  for (int j = 0; j < 2; ++j) phaseOf(omega[j] * step, stepSine[j], stepCosineMinusOne[j]);
  std::array<S, 2> sine{}, cosineMinusOne{};
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (k % kExactEvery == 0) {
      // a resonant flight repeats after 2 pi: its phase from the offset to the nearest return
      // keeps full precision over many periods (a detuned one's loses ~ its number of periods)
      const S s = first + S(k) * step;
      modalPhases(m_chain->resonant ? FlightTime<S>::nearest(s).offset : s, sine, cosineMinusOne);
    } else {
      for (int j = 0; j < 2; ++j) {
        // (c, s) turned by (C, S): c' - 1 = (c - 1) + (C - 1) c - s S, s' = s C + c S
        const S cosine = S(1) + cosineMinusOne[j];
        const S turned = sine[j] + sine[j] * stepCosineMinusOne[j] + cosine * stepSine[j];
        cosineMinusOne[j] += cosine * stepCosineMinusOne[j] - sine[j] * stepSine[j];
        sine[j] = turned;
      }
    }
    out[k] = stateFromPhases(start, sine, cosineMinusOne, nullptr);
  }
}

template <typename S>
BasicState<S> Flight<S>::stateFromPhases(const Anchor& anchor, const std::array<S, 2>& sine,
                                         const std::array<S, 2>& cosineMinusOne,
                                         S* u1Residual) const {
  const S omega[2] = {m_chain->ratio, S(1)};
  S dc[2], dRate[2];
  for (int j = 0; j < 2; ++j) {
    dc[j] = anchor.c[j] * cosineMinusOne[j] + anchor.a[j] * sine[j];
    dRate[j] = omega[j] * (-anchor.c[j] * sine[j] + anchor.a[j] * cosineMinusOne[j]);
  }
  const TwoMassForm<S>& chain = *m_chain;
  const S increment1 = chain.rhoFast * dc[0] + chain.rhoSlow * dc[1];
  const S u1 = anchor.state.u1 + increment1;
  if (u1Residual) {
    *u1Residual = additionError(anchor.state.u1, increment1, u1) +
                  (&anchor == &m_anchors[0] ? m_startU1Residual : S(0));
  }
  return {u1,
          anchor.state.u2 + (dc[0] + dc[1]),
          anchor.state.v1 + (chain.rhoFast * dRate[0] + chain.rhoSlow * dRate[1]),
          anchor.state.v2 + (dRate[0] + dRate[1])};
}

template <typename S>
BasicState<S> Flight<S>::taylorAt(const Anchor& anchor, const S& s, S* u1Residual) const {
  fillTaylor(anchor);
  const auto& d = anchor.derivatives;
  S position[2] = {0, 0};
  S velocity[2] = {0, 0};
  for (int n = taylorTerms(s); n >= 1; --n) {
    const S& f = inverseFactorial<S>(n);
    for (int i = 0; i < 2; ++i) {
      position[i] = position[i] * s + d[n][i] * f;
      velocity[i] = velocity[i] * s + d[n + 1][i] * f;
    }
  }
  // the last Horner step (n = 0) by hand: x1's increment and its rounding apart
  const S increment1 = position[0] * s;
  position[0] = d[0][0] + increment1;
  position[1] = position[1] * s + d[0][1];
  velocity[0] = velocity[0] * s + d[1][0];
  velocity[1] = velocity[1] * s + d[1][1];
  if (u1Residual) {
    *u1Residual = additionError(d[0][0], increment1, position[0]) +
                  (&anchor == &m_anchors[0] ? m_startU1Residual : S(0));
  }
  return {position[0], position[1], velocity[0], velocity[1]};
}

template <typename S>
BasicState<S> Flight<S>::at(const FlightTime<S>& time, S* u1Residual) const {
  using std::abs;
  FlightTime<S> t = time;
  if (abs(t.offset) > pi<S>()) t = FlightTime<S>::nearest(time.value());
  const Anchor& a = anchor(t.periods);
  return abs(t.offset) <= m_taylorRadius ? taylorAt(a, t.offset, u1Residual)
                                         : modalAt(a, t.offset, u1Residual);
}

template <typename S>
std::pair<S, S> Flight<S>::gapAndRate(const FlightTime<S>& time) const {
  using std::abs;
  FlightTime<S> t = time;
  if (abs(t.offset) > pi<S>()) t = FlightTime<S>::nearest(time.value());
  const Anchor& a = anchor(t.periods);
  const S& s = t.offset;
  const S gapAtAnchor = t.periods == 0 || m_chain->resonant ? S(m_start.u2 - m_gap) : a.gapValue;
  if (abs(s) <= m_taylorRadius) {
    // value = sum_n c_n s^n / n!,  rate = sum_n c_(n+1) s^n / n!, c_0 the gap at the anchor
    fillTaylor(a);
    S value = 0;
    S rate = 0;
    for (int n = taylorTerms(s); n >= 0; --n) {
      const S& f = inverseFactorial<S>(n);
      value = value * s + (n == 0 ? gapAtAnchor : S(a.derivatives[n][1] * f));
      rate = rate * s + a.derivatives[n + 1][1] * f;
    }
    return {value, rate};
  }
  std::array<S, 2> sine, cosineMinusOne;
  modalPhases(s, sine, cosineMinusOne);
  const S omega[2] = {m_chain->ratio, S(1)};
  S gapIncrement = 0;
  S rateIncrement = 0;
  for (int j = 0; j < 2; ++j) {
    gapIncrement += a.c[j] * cosineMinusOne[j] + a.a[j] * sine[j];
    rateIncrement += omega[j] * (-a.c[j] * sine[j] + a.a[j] * cosineMinusOne[j]);
  }
  return {gapAtAnchor + gapIncrement, a.state.v2 + rateIncrement};
}

template <typename S>
S Flight<S>::acceleration2(const FlightTime<S>& time) const {
  using std::abs;
  FlightTime<S> t = time;
  if (abs(t.offset) > pi<S>()) t = FlightTime<S>::nearest(time.value());
  const Anchor& a = anchor(t.periods);
  const S& s = t.offset;
  if (abs(s) <= m_taylorRadius) {
    fillTaylor(a);
    S acceleration = 0;
    for (int n = m_taylorOrder - 1; n >= 0; --n) {
      acceleration = acceleration * s + a.derivatives[n + 2][1] * inverseFactorial<S>(n);
    }
    return acceleration;
  }
  std::array<S, 2> sine, cosineMinusOne;
  modalPhases(s, sine, cosineMinusOne);
  const S omegaSquared[2] = {m_chain->ratio * m_chain->ratio, S(1)};
  S acceleration = 0;
  for (int j = 0; j < 2; ++j) {
    acceleration -= omegaSquared[j] * (a.c[j] * (S(1) + cosineMinusOne[j]) + a.a[j] * sine[j]);
  }
  return acceleration;
}

template <typename S>
std::pair<S, S> Flight<S>::reducedGapAndRate(long long anchorIndex, const S& s, int m) const {
  using std::abs;
  using std::pow;
  if (m == 0) return gapAndRate({anchorIndex, s});
  if (abs(s) <= m_taylorRadius) {
    // g(s) = sum_{n>=m} c_n s^(n-m) / n!,  g'(s) = sum_{n>m} c_n (n-m) s^(n-m-1) / n!
    const Anchor& a = anchor(anchorIndex);
    fillTaylor(a);
    S value = 0;
    S rate = 0;
    for (int n = std::max(taylorTerms(s), m); n >= m; --n) {
      rate = rate * s + value;
      value = value * s + a.derivatives[n][1] * inverseFactorial<S>(n);
    }
    return {value, rate};
  }
  // divide by the unreduced s^m: the sign of g must follow the sign of the gap over the whole
  // segment
  const auto [gapValue, gapRate] = gapAndRate({anchorIndex, s});
  S power = 1;
  for (int i = 0; i < m; ++i) power *= s;
  return {gapValue / power, (gapRate - S(m) * gapValue / s) / power};
}

template struct FlightTime<double>;
template struct FlightTime<long double>;
template struct FlightTime<Quad>;
template class Flight<double>;
template class Flight<long double>;
template class Flight<Quad>;

}  // namespace grazelab::core
