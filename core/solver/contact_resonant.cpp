// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The first contact of a resonant flight, from the gap written as a quartic in tan(theta/2).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/solver/contact.h"
#include "core/numbers/roots.h"

namespace grazelab::core {
namespace {

// Two charts cover the period: x = tan(theta/2) everywhere but near theta = pi, where it runs
// off to infinity, and y = cot(theta/2) = 1/x around pi. Time increases with x on each half of
// the first chart (x > 0: from the start; x < 0: up to the return) and decreases with y: the far
// chart is scanned in z = -y.
enum class Chart { Tangent, Cotangent };

template <typename S>
Contact<S> tangentAt(const Flight<S>& flight, const FlightTime<S>& time, bool undecided) {
  using std::abs;
  return {ContactKind::Tangent, time, abs(flight.gapAndRate(time).first), undecided};
}

// A scan of the period in time order over one polynomial per chart. In the first chart the
// polynomial is H = G / x^m (the m-fold zero of a start on the stop divided out exactly), whose
// sign is the gap's for x > 0 and (-1)^m times it for x < 0; in the far chart it is
// R(z) = z^4 G(-1/z), of the gap's sign.
template <typename S>
class ResonantScan {
 public:
  explicit ResonantScan(const Flight<S>& flight)
      : m_flight(flight),
        m_order(flight.contactOrder()),
        m_tolerance(flight.gapTolerance()),
        m_window(flight.taylorRadius() / S(2)) {}

  Contact<S> run();

 private:
  // gap = p(x) * factor(x)
  S factor(Chart chart, const S& x) const {
    using std::abs;
    const S square = S(1) + x * x;
    S power = 1;
    if (chart == Chart::Tangent) {
      for (int i = 0; i < m_order; ++i) power *= abs(x);
    }
    return power / (square * square);
  }
  // values of p at a stationary point within this of zero cannot be told from a touch. Near the
  // start and the return the low coefficients are the exact derivatives there, and the
  // decision is made to relative precision.
  S band(Chart chart, const S& x) const {
    using std::abs;
    if (chart == Chart::Tangent && abs(x) <= m_window) return S(0);
    return m_tolerance / factor(chart, x);
  }
  static FlightTime<S> timeAt(Chart chart, const S& x) {
    using std::atan;
    using std::atan2;
    // offsets from the start, or from the return: relative precision however close to either
    if (chart == Chart::Tangent) return {x < 0 ? 1 : 0, S(S(2) * atan(x))};
    if (x <= 0) return {0, S(S(2) * atan2(S(1), S(-x)))};  // y = -x >= 0: theta <= pi
    return {1, S(S(-2) * atan2(S(1), x))};
  }
  bool scan(Chart chart, const std::array<S, 5>& p, int sign, const S& lo, const S& hi,
            const IntervalRoots<S>& stationary);
  bool visit(Chart chart, const std::array<S, 5>& p, int sign, const S& x, bool flat);
  Contact<S> touchNear(const FlightTime<S>& start, bool undecided) const;

  const Flight<S>& m_flight;
  int m_order;
  S m_tolerance;
  S m_window;
  // the last break visited: where, p there, and whether it is a stationary point of p
  S m_previous = 0;
  S m_previousValue = 0;
  bool m_previousFlat = false;
  Contact<S> m_contact;
};

// Visits the breaks of [lo, hi] in time order: the stationary points of p inside, then hi. The
// gap is monotone between breaks, so the first break where it rises above the stop closes the
// piece that holds the crossing, and a maximum within rounding of the stop is a touch.
template <typename S>
bool ResonantScan<S>::scan(Chart chart, const std::array<S, 5>& p, int sign, const S& lo,
                           const S& hi, const IntervalRoots<S>& stationary) {
  m_previous = lo;
  m_previousValue = evaluateQuartic(p, lo).value;
  m_previousFlat = false;
  for (const S& x : stationary) {
    if (x > lo && x < hi && visit(chart, p, sign, x, true)) return true;
  }
  return visit(chart, p, sign, hi, false);
}

template <typename S>
bool ResonantScan<S>::visit(Chart chart, const std::array<S, 5>& p, int sign, const S& x,
                            bool flat) {
  using std::abs;
  const PolynomialJet<S> jet = evaluateQuartic(p, x);
  const S value = S(sign) * jet.value;
  const S tie = flat ? band(chart, x) : S(0);
  if (value > tie) {
    // a crossing between the previous break and this one; toward the return (x = 0, a root
    // that may be tiny) the tangent line there is the first iterate
    S guess = S(std::numeric_limits<double>::quiet_NaN());
    if (x == 0 && jet.slope != 0) guess = -jet.value / jet.slope;
    const S root = rootInMonotonePiece(p, m_previous, x, m_previousValue, jet.value,
                                       m_previousFlat, flat, guess)
                       .first;
    // G rounds like the sum of its terms, several times the modal form's rounding: one Newton
    // step on the flight's own gap (modal, or Taylor near an end) gives the root that form
    // defines, for one evaluation
    FlightTime<S> time = timeAt(chart, root);
    const auto [gap, rate] = m_flight.gapAndRate(time);
    if (rate != 0) {
      const S step = gap / rate;
      if (abs(step) <= S(1e-6) * abs(time.offset)) time.offset -= step;
    }
    m_contact = {ContactKind::Crossing, time, abs(gap), false};
    return true;
  }
  if (flat && value >= -tie && S(sign) * jet.curvature <= 0) {
    m_contact = touchNear(timeAt(chart, x), tie > 0);
    return true;
  }
  m_previous = x;
  m_previousValue = jet.value;
  m_previousFlat = flat;
  return false;
}

// The polynomial's stationary points are those of (1 + x^2)^2 x^-m gap: at a touch the gap's
// own maximum is a hair away. Newton on the gap's rate finds it.
template <typename S>
Contact<S> ResonantScan<S>::touchNear(const FlightTime<S>& start, bool undecided) const {
  using std::abs;
  using std::max;
  const S eps = epsilon<S>();
  FlightTime<S> peak = start;
  for (int iteration = 0; iteration < 8; ++iteration) {
    const S curvature = m_flight.acceleration2(peak);
    if (!(curvature < 0)) break;
    const S move = -m_flight.gapAndRate(peak).second / curvature;
    peak.offset += move;
    if (abs(move) <= eps * max(abs(peak.offset), m_window)) break;
  }
  // a run that wandered off (a flat top) keeps the stationary point
  if (!(abs(peak.offset - start.offset) <= m_window)) peak = start;
  return tangentAt(m_flight, peak, undecided);
}

template <typename S>
Contact<S> ResonantScan<S>::run() {
  using std::abs;
  using std::max;
  const std::array<S, 5> g = resonantGapPolynomial(m_flight);
  if (m_order > 4) {
    // all five derivatives vanish: the gap is zero throughout (a chain at rest on the stop)
    return {ContactKind::Tangent, {1, S(0)}, S(0), true};
  }
  std::array<S, 5> reduced{};
  for (int i = m_order; i <= 4; ++i) reduced[i - m_order] = g[i];
  if (reduced[0] > 0) {
    // not a flight: the start is beyond the stop or moving into it (the stepper never asks)
    return {ContactKind::Crossing, {0, S(0)}, S(0), true};
  }
  const int returnSign = m_order % 2 == 0 ? 1 : -1;
  const S largest = max(max(abs(g[0]), abs(g[1])), max(abs(g[2]), abs(g[3])));
  bool found = false;
  if (S(15) * abs(g[4]) >= largest) {
    // theta = pi is far from a root: Cauchy's bound 1 + max |g_i / g_4| <= 16 holds every root,
    // and every stationary point (Gauss-Lucas); one chart serves
    const S bound = S(1) + largest / abs(g[4]);
    const IntervalRoots<S> stationary = stationaryPointsInInterval(reduced, -bound, bound);
    found = scan(Chart::Tangent, reduced, 1, S(0), bound, stationary) ||
            scan(Chart::Tangent, reduced, returnSign, -bound, S(0), stationary);
  } else {
    // theta = pi is near a root: |x| <= 1 in the first chart, the far quarter-circles in z = -y
    std::array<S, 5> far;
    for (int j = 0; j <= 4; ++j) far[j] = j % 2 == 0 ? g[4 - j] : S(-g[4 - j]);
    const IntervalRoots<S> near = stationaryPointsInInterval(reduced, S(-1), S(1));
    found = scan(Chart::Tangent, reduced, 1, S(0), S(1), near) ||
            scan(Chart::Cotangent, far, 1, S(-1), S(1),
                 stationaryPointsInInterval(far, S(-1), S(1))) ||
            scan(Chart::Tangent, reduced, returnSign, S(-1), S(0), near);
  }
  if (found) return m_contact;
  if (m_order == 0) return {};  // below the stop at 2 pi as at 0: the periodic motion never touches
  // back at the start, on the stop: the flight returns tangentially at 2 pi (a grazing orbit)
  return {ContactKind::Tangent, {1, S(0)}, S(0), false};
}

}  // namespace

template <typename S>
std::array<S, 5> resonantGapPolynomial(const Flight<S>& flight) {
  // x2 - delta = E + a1 (cos 2th - 1) + b1 sin 2th + a2 (cos th - 1) + b2 sin th; with
  // x = tan(th/2) the rational forms of cos and sin make (1 + x^2)^2 (x2 - delta) a quartic, and
  // writing a1, b1, a2, b2 through the derivatives g_n at the start gives its coefficients
  const std::array<S, 5> d = flight.lowGapDerivatives();
  return {d[0], S(2) * d[1], S(2) * (d[0] + d[2]), (S(10) * d[1] + S(4) * d[3]) / S(3),
          d[0] + (S(8) * d[2] + S(2) * d[4]) / S(3)};
}

template <typename S>
Contact<S> nextContactResonant(const Flight<S>& flight) {
  return ResonantScan<S>(flight).run();
}

#define GRAZELAB_INSTANTIATE(S)                                                  \
  template std::array<S, 5> resonantGapPolynomial<S>(const Flight<S>&);          \
  template Contact<S> nextContactResonant<S>(const Flight<S>&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
