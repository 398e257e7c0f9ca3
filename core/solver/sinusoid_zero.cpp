// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/sinusoid_zero.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "core/numbers/vector_state.h"

namespace grazelab::core {
namespace {

template <typename S>
constexpr S epsilonOf() {
  return std::numeric_limits<S>::epsilon();
}

// cos x and sin x less their Taylor polynomials of degree below m (m = 0 .. 4): C_m and S_m.
// C_m' = -S_(m-1), S_m' = C_(m-1). Below |x| = 1/2 from their series, so that each keeps its
// relative precision as x -> 0; above, by subtraction (no cancellation there).
template <typename S>
struct Remainders {
  S C[5], S_[5];
};
// the series' coefficients (-1)^m / (2m + 4)! for C_3 / y^2 and (-1)^(m+1) / (2m + 3)! for S_2 / (x y),
// as many as S's precision needs below |x| = 1/2 (the first left out under 2^-digits of the lead)
template <typename S>
struct SeriesCoefficients {
  static constexpr int kTerms = std::numeric_limits<S>::digits > 64 ? 15 : std::numeric_limits<S>::digits > 53 ? 10 : 8;
  std::array<S, kTerms> cosine{}, sine{};
  SeriesCoefficients() {
    S factorial = 1;  // (i)! built up as i grows
    for (int i = 1; i <= 2 * kTerms + 3; ++i) {
      factorial *= i;
      const int m = (i - 3) / 2;
      if (i >= 3 && i % 2 == 1 && m < kTerms) sine[std::size_t(m)] = (m % 2 == 0 ? S(-1) : S(1)) / factorial;
      const int c = (i - 4) / 2;
      if (i >= 4 && i % 2 == 0 && c < kTerms) cosine[std::size_t(c)] = (c % 2 == 0 ? S(1) : S(-1)) / factorial;
    }
  }
};

template <typename S>
Remainders<S> remainders(const S& x, const S& c, const S& s) {
  using std::abs;
  Remainders<S> r{{c, c - 1, c - 1, c - 1 + x * x / 2, c - 1 + x * x / 2},
                  {s, s, s - x, s - x, s - x + x * x * x / 6}};
  if (abs(x) < S(0.5)) {
    // the series in y = x^2 by Horner: C_3 = C_4 = y^2 sum_m (-1)^m y^m / (2m+4)!, S_2 = S_3 =
    // x y sum_m (-1)^(m+1) y^m / (2m+3)!, and S_4 = S_2 + x^3/6 the same sum from m = 1 (its
    // tail, so that no leading term cancels)
    static const SeriesCoefficients<S> series;
    constexpr int terms = SeriesCoefficients<S>::kTerms;
    const S y = x * x;
    S cosine = series.cosine[terms - 1], tail = series.sine[terms - 1];
    for (int m = terms - 2; m >= 0; --m) cosine = cosine * y + series.cosine[std::size_t(m)];
    for (int m = terms - 2; m >= 1; --m) tail = tail * y + series.sine[std::size_t(m)];
    const S sine = tail * y + series.sine[0];
    r.C[3] = r.C[4] = y * y * cosine;
    r.C[1] = r.C[2] = r.C[3] - y / 2;
    r.S_[2] = r.S_[3] = x * y * sine;
    r.S_[4] = x * y * y * tail;
  }
  return r;
}

// bounds of |C_m(x)| and |S_m(x)| for m = 0 .. 4, and the scale their rounding is relative to
template <typename S>
struct RemainderScales {
  S of[5];
};
template <typename S>
RemainderScales<S> remainderScales(const S& x) {
  using std::abs;
  const S ax = abs(x);
  if (ax < S(0.5)) return {{S(1), ax, ax * ax / 2, ax * ax * ax / 6, ax * ax * ax * ax / 24}};
  return {{S(2), S(2), 2 + ax, 2 + ax + ax * ax / 2, 2 + ax + ax * ax / 2 + ax * ax * ax / 6}};
}

// f, its first two derivatives with their rounding errors, and bounds of |f'|, |f''|, |f'''|
template <typename S>
struct Evaluator {
  using Vector = Eigen::Matrix<S, Eigen::Dynamic, 1>;
  const BasicSinusoidSum<S>& sum;
  S period = 0;
  Vector& amplitude;  // R_j = hypot(a_j, b_j), in a buffer reused by the thread's searches
  S bound2 = 0, bound3 = 0, bound4 = 0, bound5 = 0;
  S fastest = 0;  // the largest w_j
  int highest = 0;  // the highest harmonic, 0 when evaluated mode by mode
  // the plain sum's rounding bounds of f, f', f'' are linear in |t|: roundings[m] + |t| growth[m]
  // (sum_j w_j^m R_j (2 + 2 n_j) and sum_j w_j^(m+1) R_j), summed once here
  S roundings[4] = {0, 0, 0, 0}, growth[4] = {0, 0, 0, 0};
  // sum_j w_j^m R_j, m = 0 .. 4: what an error in each mode's phase (a rotated evaluation's)
  // moves f and its derivatives by
  S powers[5] = {0, 0, 0, 0, 0};
  // evaluated mode by mode at t itself (no harmonics, not periodic): each mode's cos and sin
  // can then be kept and turned to a nearby time (rotated)
  bool rotates = false;

  Evaluator(const BasicSinusoidSum<S>& f, const S& periodOfF, Vector& buffer)
      : sum(f), period(periodOfF), amplitude(buffer) {
    using std::sqrt;
    amplitude.resize(f.a.size());
    for (int n : f.harmonics) highest = std::max(highest, n);
    if (highest > 64 || f.harmonics.size() != std::size_t(f.a.size())) highest = 0;
    for (Eigen::Index j = 0; j < f.a.size(); ++j) {
      const S w = f.w[j];
      amplitude[j] = sqrt(f.a[j] * f.a[j] + f.b[j] * f.b[j]);
      bound2 += w * w * amplitude[j];
      bound3 += w * w * w * amplitude[j];
      bound4 += w * w * w * w * amplitude[j];
      bound5 += w * w * w * w * w * amplitude[j];
      if (w > fastest) fastest = w;
    }
    for (Eigen::Index j = 0; j < f.a.size(); ++j) {
      const S w = f.w[j];
      const int n = highest > 0 ? f.harmonics[std::size_t(j)] : 0;
      S power = amplitude[j];  // w^m R_j
      for (int m = 0; m < 4; ++m, power *= w) {
        roundings[m] += power * (2 + 2 * n);
        growth[m] += power * w;
        powers[m] += power;
      }
      powers[4] += power;
    }
    rotates = highest == 0 && !(period > 0);
  }
  struct Value {
    S f, df, error, dfError;
    S d2f = 0, d2fError = 0;
    S d3f = 0, d3fError = 0;
    bool kept = false;  ///< each mode's cos and sin were kept (at(t, keep))
  };
  // One mode's term and its first three derivatives from its cos and sin, added to `value`.
  void addPlain(Value& value, Eigen::Index j, const S& c, const S& s) const {
    const S w = sum.w[j], a = sum.a[j], b = sum.b[j];
    value.f += a * c + b * s;
    value.df += w * (b * c - a * s);
    value.d2f -= w * w * (a * c + b * s);
    value.d3f += w * w * w * (a * s - b * c);
  }
  // The plain sum's rounding bounds at t (each mode's cos and sin within an ulp or so, and the
  // argument's rounding, |x| eps, moving a term by that times its derivative), plus a phase
  // error of `phase` (relative, each mode's) and a time off by `shift`.
  void plainErrors(Value& value, const S& t, const S& phase, const S& shift) const {
    using std::abs;
    constexpr S kEps = epsilonOf<S>();
    const S at = abs(t);
    value.error = plainError(t) + phase * powers[0] + shift * powers[1];
    value.dfError = 8 * kEps * (roundings[1] + at * growth[1] + abs(sum.slope)) + phase * powers[1] + shift * powers[2];
    value.d2fError = 8 * kEps * (roundings[2] + at * growth[2]) + phase * powers[2] + shift * powers[3];
    value.d3fError = 8 * kEps * (roundings[3] + at * growth[3]) + phase * powers[3] + shift * powers[4];
  }
  // The plain sum's rounding bound of f at t.
  S plainError(const S& t) const {
    using std::abs;
    return 8 * epsilonOf<S>() * (abs(sum.offset) + abs(sum.slope * t) + (roundings[0] + abs(t) * growth[0]));
  }
  // f about t from each mode's cos and sin at a time nearby (`from`: n cosines, then n sines),
  // each turned by the angle w_j delta (`turn`: cos w_j delta, then sin; `sign` -1 turns back):
  // no sine or cosine evaluated. The turned values go to `to`. The phases carry `turns` roundings
  // of a turn (6 eps each: the turn's own cos and sin, and the product's), and the time they are
  // at is within `shift` of t.
  Value rotated(const S* from, const S* turn, int sign, S* to, const S& t, int turns, const S& shift) const {
    constexpr S kEps = epsilonOf<S>();
    const Eigen::Index n = sum.a.size();
    Value value{sum.offset + sum.slope * t, sum.slope, S(0), S(0)};
    for (Eigen::Index j = 0; j < n; ++j) {
      const S cosTurn = turn[j], sinTurn = sign > 0 ? turn[n + j] : S(-turn[n + j]);
      const S c = from[j] * cosTurn - from[n + j] * sinTurn;
      const S s = from[n + j] * cosTurn + from[j] * sinTurn;
      to[j] = c;
      to[n + j] = s;
      addPlain(value, j, c, s);
    }
    plainErrors(value, t, 6 * kEps * S(turns), shift);
    value.kept = true;
    return value;
  }
  /// f and its derivatives at t; with `keep` (2n numbers), where f is the plain sum at t itself
  /// (rotates, away from the Taylor form near 0), each mode's cos then sin put there (kept).
  Value at(const S& t, S* keep = nullptr) const {
    using std::abs;
    using std::cos;
    using std::sin;
    constexpr S kEps = epsilonOf<S>();
    // a periodic f at the nearest multiple of its period: f(T + tau) = f(tau), and near its
    // return to the start f keeps the precision it has near t = 0
    const S tau = period > 0 && t > period / 2 ? S(t - period) : t;
    // the Taylor form only where it matters: away from 0 (every |w_j tau| >= 1/2) f is of the
    // size of its terms and the plain sum is as precise, and cheaper
    const int k = abs(tau) * fastest < S(0.5) ? sum.startTerms : 0;
    Value value{k == 0 ? sum.offset : S(0), S(0), S(0), S(0)};
    S size = k == 0 ? S(abs(sum.offset)) : S(0), dSize = 0, d2Size = 0;
    // a drift is f's first Taylor term: kept in the plain sum and at k = 1, 0 exactly above
    if (k <= 1) {
      value.f += sum.slope * tau;
      value.df += sum.slope;
      size += abs(sum.slope * tau);
      dSize += abs(sum.slope);
    }
    // cos and sin of each mode's angle: directly, or by the recurrence up to the highest harmonic
    S cosines[64], sines[64];
    if (highest > 0) {
      const S c1 = cos(sum.omega0 * tau), s1 = sin(sum.omega0 * tau);
      S c = c1, s = s1;
      for (int h = 1; h <= highest; ++h) {
        cosines[h - 1] = c;
        sines[h - 1] = s;
        const S next = c * c1 - s * s1;
        s = s * c1 + c * s1;
        c = next;
      }
    }
    for (Eigen::Index j = 0; j < sum.a.size(); ++j) {
      const S w = sum.w[j], a = sum.a[j], b = sum.b[j], x = w * tau;
      const int n = highest > 0 ? sum.harmonics[std::size_t(j)] : 0;
      const S c = n > 0 ? cosines[n - 1] : S(cos(x));
      const S s = n > 0 ? sines[n - 1] : S(sin(x));
      // each product and sum rounds once, the recurrence about twice a harmonic; the argument's
      // rounding (|x| eps) moves a term by that times its derivative
      const S termRoundings = 2 + 2 * n;
      if (k == 0) {
        addPlain(value, j, c, s);
        if (keep) {
          keep[j] = c;
          keep[sum.a.size() + j] = s;
        }
        continue;  // its rounding bound after the loop
      }
      // f's first k Taylor coefficients at 0 are 0 exactly: f = sum a_j C_k + b_j S_k
      const Remainders<S> r = remainders<S>(x, c, s);
      const int k1 = k - 1, k2 = std::max(k - 2, 0);
      value.f += a * r.C[k] + b * r.S_[k];
      value.df += w * (b * r.C[k1] - a * r.S_[k1]);
      value.d2f -= w * w * (a * r.C[k2] + b * r.S_[k2]);
      value.d3f += w * w * w * (a * s - b * c);  // the Taylor terms below degree 3 add nothing to f'''
      const RemainderScales<S> scale = remainderScales<S>(x);
      const S ax = abs(x);
      size += amplitude[j] * (termRoundings * scale.of[k] + ax * scale.of[k1]);
      dSize += w * amplitude[j] * (termRoundings * scale.of[k1] + ax * scale.of[k2]);
      d2Size += w * w * amplitude[j] * (termRoundings * scale.of[k2] + ax * scale.of[std::max(k2 - 1, 0)]);
    }
    if (k == 0) {
      plainErrors(value, tau, S(0), S(0));
      value.kept = keep && rotates;
      return value;
    }
    value.error = 8 * kEps * size;
    value.dfError = 8 * kEps * dSize;
    value.d2fError = 8 * kEps * d2Size;
    value.d3fError = 8 * kEps * (roundings[3] + abs(tau) * growth[3]);
    return value;
  }
};

// Windows a piece's halvings make, depth by depth: each mode's phase at a window's middle is its
// parent's turned by w_j times a fixed offset (a piece of width P: P/4 at depth 1, P/8 at 2, ...),
// and a piece's middle is the one before's turned by w_j P (depth -1), so that the cos and sin
// of those angles, made once per depth, replace each mode's sin and cos (most of a long search's
// time). Kept per thread for the chain searched last (a run's flights have the same frequencies
// and pieces).
template <typename S>
class Turns {
 public:
  static constexpr int kDepths = 48;  // deeper windows are evaluated directly
  /// Ready for the frequencies `w` and pieces of width `piece`.
  void prepare(const Eigen::Matrix<S, Eigen::Dynamic, 1>& w, const S& piece) {
    if (m_piece == piece && m_w.size() == w.size() && m_w == w) return;
    m_w = w;
    m_piece = piece;
    m_table.assign(std::size_t(kDepths + 1) * 2 * std::size_t(w.size()), S(0));
    m_made.assign(kDepths + 1, false);
  }
  /// The offset of a window's middle from its parent's at `depth` (>= 1): P / 2^(depth + 1);
  /// at depth -1, of a piece's middle from the one before's: P.
  S offset(int depth) const { return timesPowerOfTwo(m_piece, -(depth + 1)); }
  /// cos w_j offset, then sin w_j offset, for every mode.
  const S* at(int depth) {
    using std::cos;
    using std::sin;
    const std::size_t n = std::size_t(m_w.size());
    S* turn = m_table.data() + std::size_t(depth + 1) * 2 * n;
    if (!m_made[std::size_t(depth + 1)]) {
      const S delta = offset(depth);
      for (std::size_t j = 0; j < n; ++j) {
        const S angle = m_w[Eigen::Index(j)] * delta;
        turn[j] = cos(angle);
        turn[n + j] = sin(angle);
      }
      m_made[std::size_t(depth + 1)] = true;
    }
    return turn;
  }

 private:
  Eigen::Matrix<S, Eigen::Dynamic, 1> m_w;
  S m_piece = 0;
  std::vector<S> m_table;
  std::vector<bool> m_made;
};

template <typename S>
struct Search {
  using Value = typename Evaluator<S>::Value;
  using Zero = BasicFirstZero<S>;
  const Evaluator<S>& f;
  long windows = 0;
  long maxWindows = 0;
  S resolution = 0;  // windows narrower than this are not halved again
  // Turning phases (f.rotates): the turns by depth, a slot of 2n numbers per depth for the phases
  // of the window being searched at that depth, and the width of the piece being searched (0:
  // a piece of another width, the last one, evaluated directly)
  Turns<S>* turns = nullptr;
  S* slots = nullptr;
  S piece = 0;
  // A window's middle, with its modes' phases when kept (in its depth's slot): how many turns
  // they carry and how far the time they are at may be from the middle.
  struct Phases {
    const S* phases = nullptr;
    S middle = 0;
    int turns = 0;
    S shift = 0;
  };
  static constexpr int kMostTurns = 40;  // then evaluated directly again
  // a piece's middle turned from the one before's at most this many times in a row (each
  // piece's windows then turn from it, kMostTurns in all)
  static constexpr int kMarchTurns = 16;
  // the middle of the piece searched last, with its phases (in slot 0) when kept
  Phases lastPiece;
  // where f came within rounding of 0 while rising, undecided until f is seen again resolvably
  // above 0 (a crossing there) or below it (a touch there: its top within rounding of 0)
  std::optional<S> pending;

  static int sign(const S& value, const S& error) { return value > error ? 1 : value < -error ? -1 : 0; }

  // a unit in the last place of x, or up to twice it (cheaper than nextafter, and only a scale)
  static S ulp(const S& x) {
    using std::abs;
    const S a = abs(x);
    return (a > std::numeric_limits<S>::min() ? a : std::numeric_limits<S>::min()) * epsilonOf<S>();
  }

  // The crossing of f in (left, right], where f(left) < 0 < f(right) and f is monotone. Newton's
  // method from the root of f's Taylor cubic about the window's middle (no evaluation: within
  // B4 r^4 / (24 |f'|) of the crossing), kept inside the sign bracket [low, high] (a step that
  // leaves it bisects instead), until its step is within a few ulps of the iterate: that iterate
  // is the crossing to the rounding of f (two or three evaluations; from the secant's guess it
  // took four or five, by bisection to adjacent doubles 50). A bracket that closes first ends it
  // at its upper end, where f >= 0.
  S crossing(const S& left, const S& right, const S& middle, const Value& m) const {
    using std::abs;
    S low = left, high = right;
    S s = 0;
    for (int step = 0; step < 4; ++step) {
      const S p = m.f + s * (m.df + s * (m.d2f / 2 + s * m.d3f / 6));
      const S dp = m.df + s * (m.d2f + s * m.d3f / 2);
      s -= p / dp;
    }
    S t = middle + s;
    if (!(t > low && t < high)) t = low + (high - low) / 2;
    for (int step = 0; step < 100; ++step) {
      const Value v = f.at(t);
      (v.f < 0 ? low : high) = t;
      if (!(high - low > 4 * ulp(high))) break;
      const S next = t - v.f / v.df;
      if (abs(next - t) <= 2 * ulp(t)) return next < low ? low : next > high ? high : next;
      t = next > low && next < high ? next : low + (high - low) / 2;
    }
    return high;
  }

  // f at a window's end, evaluated when a decision first needs it (NaN until then): a window
  // cleared by the bounds about its middle never needs its ends
  S known(const S& t, S& value) const {
    if (!(value == value)) value = f.at(t).f;
    return value;
  }

  // f at a window's middle at `depth`: turned from its parent's phases where it can, else
  // evaluated (and its phases kept where they can be turned from)
  // (`turnAt`: the depth whose offset parts the two middles, -1 from one piece to the next)
  Value middleValue(const S& middle, int depth, int turnAt, const Phases& parent, int side, Phases& mine) {
    using std::abs;
    constexpr S kEps = epsilonOf<S>();
    S* slot = piece > 0 && depth < Turns<S>::kDepths ? slots + std::size_t(depth) * 2 * std::size_t(f.sum.a.size()) : nullptr;
    mine = {nullptr, middle, 0, S(0)};
    // (near t = 0 a sum that starts on 0 is evaluated in its Taylor form, which keeps no phases)
    const bool plainThere = f.sum.startTerms == 0 || abs(middle) * f.fastest >= S(0.5);
    if (slot && parent.phases && parent.turns < (turnAt < 0 ? kMarchTurns : kMostTurns) && plainThere) {
      // the parent's middle turned by the offset is within `gap` of this middle (the halving
      // rounds each end and middle, the march each piece's ends), and the parent's own phases
      // were within its shift
      const S offset = turns->offset(turnAt);
      const S gap = abs(S(S(parent.middle - middle) + side * offset)) + 2 * kEps * offset;
      mine = {slot, middle, parent.turns + 1, S(parent.shift + gap)};
      return f.rotated(parent.phases, turns->at(turnAt), side, slot, middle, mine.turns, mine.shift);
    }
    const Value value = f.at(middle, slot);
    if (value.kept) mine.phases = slot;
    return value;
  }

  // the first zero in (left, right], given f there; windows come from the left, one after the
  // other, so `pending` always refers to a point left of this window. `parent`: the window this
  // one halves (its middle on the `side` -1 or 1 of the parent's)
  std::optional<Zero> first(const S& left, const S& right, S& fLeft, S& fRight, int depth = 0,
                            const Phases& parent = {}, int side = 0) {
    using std::abs;
    using std::min;
    if (++windows > maxWindows) return Zero{ZeroKind::Budget, left};
    const S h = right - left;
    const S middle = left + h / 2;
    Phases phases;
    // a piece turns from the one before (its middle's phases in slot 0, overwritten in place)
    const Value m = depth == 0 ? middleValue(middle, 0, -1, lastPiece, 1, phases)
                               : middleValue(middle, depth, depth, parent, side, phases);
    if (depth == 0) lastPiece = phases;
    // a window's ends are evaluated, never turned: judged by their own rounding bound where the
    // middle's is widened by its turns
    const auto endError = [&](const S& t) { return phases.turns > 0 ? f.plainError(t) : m.error; };
    // Taylor about the middle to third order: f and its first two derivatives are known there,
    // only the third is bounded (by sum w_j^3 R_j)
    const S r = h / 2;
    const S slope = abs(m.df) + m.dfError;
    const S curve = abs(m.d2f) + m.d2fError;
    // no zero: |f| stays away from 0 over the window
    // and to fourth, f''' evaluated there and only the fourth derivative bounded: whichever is
    // tighter (the fourth order in wide windows, where B3 r^3 dominates)
    const S jerk = abs(m.d3f) + m.d3fError;
    const S beyondCurve = min(S(f.bound3 * r * r * r / 6), S(jerk * r * r * r / 6 + f.bound4 * r * r * r * r / 24));
    if (abs(m.f) - m.error > slope * r + curve * r * r / 2 + beyondCurve) {
      if (pending) return Zero{m.f > 0 ? ZeroKind::Crossing : ZeroKind::Touch, *pending};
      return std::nullopt;
    }
    // monotone: a zero exactly when f changes sign (f(left) is never one: it was searched)
    if (abs(m.df) - m.dfError > curve * r + min(S(f.bound3 * r * r / 2), S(jerk * r * r / 2 + f.bound4 * r * r * r / 6))) {
      if (m.df < 0) {
        // falling: after a rise to within rounding of 0, a touch; from above 0 (never, for an f
        // that starts below it) the zero was crossed at the left
        if (pending) return Zero{ZeroKind::Touch, *pending};
        if (sign(known(left, fLeft), endError(left)) > 0) return Zero{ZeroKind::Crossing, left};
        return std::nullopt;
      }
      const int signRight = sign(known(right, fRight), endError(right));
      if (signRight < 0) {
        if (pending) return Zero{ZeroKind::Touch, *pending};
        return std::nullopt;
      }
      if (signRight == 0) {
        if (!pending) pending = right;
        return std::nullopt;
      }
      if (sign(known(left, fLeft), endError(left)) >= 0) return Zero{ZeroKind::Crossing, pending.value_or(left)};
      // from below 0 to above it: the one crossing of the window
      // (Newton's iterate depends on its start: from f evaluated there, not turned, as every
      // crossing is refined, so that the time found does not depend on how f got there)
      return Zero{ZeroKind::Crossing, crossing(left, right, middle, phases.turns > 0 ? f.at(middle) : m)};
    }
    if (h <= resolution) {
      // f and f' both zero within rounding: a touch
      return Zero{ZeroKind::Touch, pending.value_or(middle)};
    }
    // f at the middle, as the halves' end: a turned value is not (its bound is wider than a
    // half's may be, evaluated afresh: the turns' reset, the Taylor form near 0), so evaluated
    // again there if a half needs it
    S fMiddle = phases.turns > 0 ? std::numeric_limits<S>::quiet_NaN() : m.f;
    if (auto found = first(left, middle, fLeft, fMiddle, depth + 1, phases, -1)) return found;
    return first(middle, right, fMiddle, fRight, depth + 1, phases, 1);
  }
};

}  // namespace

template <typename S>
BasicFirstZero<S> firstZero(const BasicSinusoidSum<S>& sum, std::type_identity_t<S> period,
                            std::type_identity_t<S> horizon, long maxWindows,
                            std::optional<BasicLeaving<std::type_identity_t<S>>> leaving) {
  using std::abs;
  using std::max;
  using std::min;
  constexpr S kEps = epsilonOf<S>();
  clearUpperVectorState();  // its SSE arithmetic at full speed, whoever called it
  thread_local typename Evaluator<S>::Vector amplitudes;
  const Evaluator<S> f(sum, period, amplitudes);
  const S end = period > 0 ? period : horizon;
  if (!(end > 0)) return {ZeroKind::Budget, S(0)};
  if (sum.a.size() == 0) {
    // a constant: below 0 forever, or 0 (a touch at the start)
    if (sum.offset < 0) return {period > 0 ? ZeroKind::None : ZeroKind::Budget, end};
    return {ZeroKind::Touch, S(0)};
  }
  const S fastest = twoPi<S>() / sum.w.maxCoeff();
  Search<S> search{f, 0, maxWindows, S(0), nullptr, nullptr, S(0), {}, std::nullopt};
  // the fastest mode's period over 2^(digits - 13) (2^40 in double): below that a window holds
  // f's zero and critical point within the precision's resolution of the time
  search.resolution = timesPowerOfTwo(S(max(end, fastest)), -(std::numeric_limits<S>::digits - 13));
  // f(0) = 0 (on the stop just after an impact, or released at rest) and f leaves it: Taylor's
  // bound keeps f < 0 on (0, t0], with t0 from f'(0) < 0, or from f''(0) < 0 when f'(0) = 0
  typename Evaluator<S>::Value start = f.at(S(0));
  S t0 = 0;
  // a periodic f that starts at rest on 0 (f'(0) = 0, f''(0) < 0) is the same on either side of
  // its period's end: the interval Taylor's bound clears after 0 is clear before T as well, and
  // f's return to 0 at T is that start again (searched up to it, a flat return would only halve
  // windows down to the resolution)
  bool flatReturn = false;
  if (leaving) {
    // f(t) <= D t^k/k! + B_(k+1) t^(k+1)/(k+1)! < 0 below (k+1)|D|/B_(k+1): half of that
    const int k = leaving->order;
    if (!(leaving->value < 0) || (k != 3 && k != 4) || sum.startTerms != k) return {ZeroKind::Touch, S(0)};
    t0 = S(k + 1) * abs(leaving->value) / (2 * (k == 3 ? f.bound4 : f.bound5));
    if (!(period > 0) && t0 >= end) return {ZeroKind::Budget, end};  // cleared to the horizon
    t0 = min(t0, S(end / 2));
    flatReturn = period > 0 && k == 4;
    start = f.at(t0);
    if (!(start.f < -start.error)) return {ZeroKind::Touch, S(0)};
  } else if (abs(start.f) <= start.error) {
    S d2 = 0;
    for (Eigen::Index j = 0; j < sum.a.size(); ++j) d2 -= sum.w[j] * sum.w[j] * sum.a[j];
    if (start.df < -start.dfError) {
      t0 = abs(start.df) / f.bound2;  // f(t) <= f'(0) t + bound2 t^2 / 2 < 0 below 2|f'(0)|/bound2
    } else if (d2 < -8 * kEps * f.bound2 && abs(start.df) <= start.dfError) {
      t0 = S(1.5) * abs(d2) / f.bound3;  // f(t) <= f''(0) t^2 / 2 + bound3 |t|^3 / 6 < 0 below 3|f''(0)|/bound3
      flatReturn = period > 0 && sum.startTerms >= 2;
    } else {
      return {ZeroKind::Touch, S(0)};  // it does not leave 0
    }
    // (t0 is half the interval Taylor's bound clears: one that clears the whole horizon, a
    // floating chain's drift off the stop with little or no vibration, needs no search)
    if (!(period > 0) && t0 >= end) return {ZeroKind::Budget, end};
    t0 = min(t0, S(end / 2));
    start = f.at(t0);
    if (!(start.f < -start.error)) return {ZeroKind::Touch, S(0)};
  }
  // an interval cleared by Taylor's bound that the windows cannot resolve (a pull off the stop
  // of a few ulps: t0 of 1e-16 against windows of 1e-15) would end in a touch made of rounding
  // at the resolution (a loop of touches 1e-12 apart was seen): undecided at the start instead,
  // decided one precision up
  if (t0 > 0 && t0 < search.resolution) return {ZeroKind::Touch, S(0)};
  // periodic: a whole period at most (f(T) = f(0), so the search sees the return); the halving
  // runs over [t0, end] in pieces a fraction of the fastest period wide, so that a long horizon
  // does not start from one huge window
  const S searchEnd = flatReturn ? S(end - t0) : end;
  const S piece = min(S(searchEnd - t0), fastest);
  // a touch is where f comes within rounding of 0 and turns back, found as a window a few ulps
  // of f wide (about sqrt(eps) of the time); its time is f's maximum there: Newton's method on
  // f' (a simple zero where f'' < 0) puts it at the precision's resolution of the time, as a
  // crossing's is. Kept only when it converges close by, to a point where f is still 0 within
  // rounding (else the search's own time stands)
  using Zero = BasicFirstZero<S>;
  const auto refined = [&](Zero found) {
    if (found.kind != ZeroKind::Touch || !(found.t > 0)) return found;
    S t = found.t;
    for (int step = 0; step < 30; ++step) {
      const typename Evaluator<S>::Value v = f.at(t);
      if (!(v.d2f < -v.d2fError)) return found;
      const S next = t - v.df / v.d2f;
      if (!(abs(next - found.t) < S(1e-3) * fastest)) return found;
      const bool done = abs(next - t) <= 4 * Search<S>::ulp(t);
      t = next;
      if (done) {
        const typename Evaluator<S>::Value at = f.at(t);
        if (abs(at.f) > 4 * at.error + 4 * Search<S>::ulp(S(1)) * abs(sum.offset)) return found;
        return Zero{ZeroKind::Touch, t};
      }
    }
    return found;
  };
  S left = t0;
  S fLeft = start.f;
  // a long search mode by mode: the phases turned from window to window (Turns)
  thread_local Turns<S> turns;
  thread_local std::vector<S> slots;
  if (f.rotates) {
    turns.prepare(sum.w, piece);
    slots.resize(std::size_t(Turns<S>::kDepths) * 2 * std::size_t(sum.a.size()));
    search.turns = &turns;
    search.slots = slots.data();
  }
  while (left < searchEnd) {
    const S right = min(searchEnd, S(left + piece));
    // (the last piece, shorter, is halved from its own width: evaluated directly)
    search.piece = f.rotates && S(left + piece) <= searchEnd ? piece : S(0);
    S fRight = std::numeric_limits<S>::quiet_NaN();  // evaluated if needed
    if (auto found = search.first(left, right, fLeft, fRight)) return refined(*found);
    left = right;
    fLeft = fRight;
  }
  // within rounding of 0 at the very end (a periodic orbit's return at T)
  if (search.pending) return refined({ZeroKind::Touch, *search.pending});
  if (flatReturn) return {ZeroKind::Touch, end};
  return {period > 0 ? ZeroKind::None : ZeroKind::Budget, end};
}

#define GRAZELAB_INSTANTIATE(S)                                                                              \
  template BasicFirstZero<S> firstZero<S>(const BasicSinusoidSum<S>&, std::type_identity_t<S>,                 \
                                          std::type_identity_t<S>, long,                                      \
                                          std::optional<BasicLeaving<std::type_identity_t<S>>>);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
