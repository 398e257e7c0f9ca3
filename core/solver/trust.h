// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/model/model.h"
#include "core/model/mass_chain.h"
#include "core/solver/chain_run.h"

namespace grazelab::core {

/// How much a run may spend on its error estimate: none, a shadow run while it is cheap (about
/// the cost of the run itself, then extrapolation), or a shadow run to the end.
enum class TrustMode { Off, Auto, Full };
std::string_view toString(TrustMode mode);
std::optional<TrustMode> parseTrustMode(std::string_view text);

/// ok: the estimated errors are below 1e-9 of their scales; degraded: below 1e-6; unreliable: the
/// run goes past its predictability horizon (or its shadow took another path). unchecked: no
/// estimate was made (--trust off).
enum class Verdict { Ok, Degraded, Unreliable, Unchecked };
std::string_view toString(Verdict verdict);

/// The accuracy a run is held to within its predictability horizon.
inline constexpr double kHorizonTolerance = 1e-6;
/// Below this estimated error a run is "ok".
inline constexpr double kOkTolerance = 1e-9;

/// How far a run can be trusted (issue 7, docs/design.md "Numerical contract").
struct Trust {
  Verdict verdict = Verdict::Unchecked;
  /// Estimated error of the final state: the largest over the masses' displacements and
  /// velocities of the error relative to that component's scale (its largest size at the events
  /// of the run).
  double stateError = 0;
  /// Estimated error of the worst contact time, in units of the slowest period (T2 for the
  /// note's chain).
  double timeError = 0;
  /// The time up to which the run holds kHorizonTolerance [time]: observed when the shadow
  /// run saw the error pass it, else extrapolated conservatively from the error's growth (as
  /// if exponential, at most twice the time the shadow compared), the same for the same run.
  double horizon = 0;
  bool horizonObserved = false;
  std::string horizonMethod;  ///< e.g. "shadow run in long double; power-law extrapolation"
  std::string reason;         ///< one line
  std::int64_t shadowEvents = 0;  ///< events the shadow run was compared on
};

/// The scalar of the shadow run: one precision up (double -> long double -> binary128); a
/// binary128 run is shadowed by another binary128 run on the chain scaled 3x in length, 5x in
/// mass and 1/sqrt(3) in time, which changes every rounding (the physics is scale-free) but not
/// the answer.
template <typename S>
struct ShadowOf {
  using type = long double;
};
template <>
struct ShadowOf<long double> {
  using type = Quad;
};
template <>
struct ShadowOf<Quad> {
  using type = Quad;
};
template <typename S>
using ShadowScalar = typename ShadowOf<S>::type;

/// Which of a chain's numbers were read exactly (a decimal like 0.5 is exact in binary, 0.1 is
/// not). A shadow of the same precision nudges the others by four ulps (the start by half an
/// ulp), so that their representation counts as error (near m2/m1 = 9/16 the note's design amplifies it ~1e7). A mass
/// or spring not listed counts as exact; the start counts as rounded (a state read or computed in
/// the run's precision) unless `start` says otherwise.
struct ExactParameters {
  std::vector<bool> masses, springs;  ///< per mass, per spring (k1 first)
  bool rightSpring = true, gap = true;
  bool start = false;
};

/// How many events a shadow compares under TrustMode::Auto: a number fixed by the precisions
/// alone, so that the same run always gets the same estimate (a wall-clock budget gave 9e7 one
/// time and 4e8 the next): about twice the run's own cost, at most a second or so (a long double
/// shadow costs about as much as a double run; binary128 about fifteen times a long double run).
template <typename S>
constexpr std::int64_t autoShadowEvents() {
  if constexpr (std::is_same_v<S, double>) return std::int64_t(1) << 18;
  else if constexpr (std::is_same_v<S, long double>) return std::int64_t(1) << 14;
  else return std::int64_t(1) << 16;
}

/// The shadow of a chain's runs in S, made once for every run of the chain: the chain as read
/// one precision up from the same input (ShadowScalar), or, in binary128, that chain scaled 3x
/// in length, 5x in mass and 1/sqrt(3) in time, its inexact numbers nudged by a rounding
/// (ExactParameters): every rounding changes, the motion does not (the physics is scale-free).
/// Copyable; the chain it was made from (`input`) must outlive it.
template <typename S>
struct ChainShadow {
  using H = ShadowScalar<S>;
  /// the chain read in H, as the run's input gives it (the binary128 arbiter reads it); none: no
  /// shadow (TrustMode::Off, or `problem`)
  const BasicReadyChain<H>* input = nullptr;
  /// the scaled chain, in binary128 (the shadow runs `input` itself otherwise)
  std::optional<BasicReadyChain<H>> scaledChain;
  H length = 1;  ///< the shadow's lengths are the primary's times this
  H time = 1;    ///< the shadow's times are the primary's divided by this
  ExactParameters exact;
  std::string problem;  ///< why there is no shadow, when `input` could not be scaled

  bool usable() const { return input != nullptr && problem.empty(); }
  const BasicReadyChain<H>& ready() const { return scaledChain ? *scaledChain : *input; }
};

/// The shadow of runs of `input` (the run's chain read in ShadowScalar<S>); `exact` says which of
/// its numbers were read exactly (used by a binary128 shadow only).
template <typename S>
ChainShadow<S> chainShadow(const BasicReadyChain<ShadowScalar<S>>& input, ExactParameters exact = {});

/// A chain's numbers widened one precision up and made ready: a shadow's input where none is
/// read from text there (a map's parameters, an explorer's chain). The note's chain widens by its
/// model, so that a design stays a design.
template <typename S>
BasicReadyChain<ShadowScalar<S>> widenedChain(const BasicReadyChain<S>& chain) {
  using H = ShadowScalar<S>;
  return chain.notesModel ? readyChain(convertModel<H>(*chain.notesModel)) : readyChain(chainCast<H>(chain.numbers));
}

/// The shadow of runs of a chain whose numbers are exact as they stand (a map's parameters, an
/// explorer's chain): made from `chain` widened (kept in `widened`, which must outlive the
/// shadow), or, in binary128, from `chain` itself (which must too).
template <typename S>
ChainShadow<S> widenedShadow(const BasicReadyChain<S>& chain, std::optional<BasicReadyChain<ShadowScalar<S>>>& widened);

/// Estimates the error of a run of any chain in precision S (runChain, by the kernel the chain
/// takes) by running the same algorithm beside it on its shadow (ChainShadow), in lockstep event
/// by event, so that it costs no memory however long the run (docs/numerics.md). Each event's
/// state is compared against the largest sizes each coordinate reached (floored at 1e-3 of the
/// positions' and velocities' scales), its time against the slowest period; the horizon is where
/// that error first passes kHorizonTolerance, observed, or extrapolated from its growth. For a
/// chain other than the note's, an event's state error is also where the motion goes in the time
/// the event is off by (a stiff light mass). A double run of the note's chain judged unreliable
/// is arbitrated by a binary128 run of the same input. Feed it every event of the run
/// (observe), then finish with the run.
/// Holds its own shadow run: neither copied nor moved.
template <typename S>
class TrustMonitor {
 public:
  using H = ShadowScalar<S>;

  /// `start` is the run's start read in H from the same input (so that the input's own rounding
  /// counts as error; a start known only in S, widened); `maxContacts`, `tEnd` (0: none) and
  /// `searchSteps` are the run's (runChain's). The shadow watches `stop` as the run does (an
  /// interrupt ends both). `shadow` must outlive the monitor.
  TrustMonitor(const ChainShadow<S>& shadow, const BasicChainStart<H>& start, long maxContacts,
               std::type_identity_t<H> tEnd, TrustMode mode, std::stop_token stop = {},
               std::int64_t searchSteps = 0);
  TrustMonitor(const TrustMonitor&) = delete;
  TrustMonitor& operator=(const TrustMonitor&) = delete;

  /// The next event of the primary run.
  void observe(const BasicChainEvent<S>& event);
  /// The estimate, once the primary run ended (or was interrupted).
  Trust finish(const BasicChainRun<S>& primary);

 private:
  using Vector = ChainVector<H>;
  struct GrowthPoint {
    double t = 0;
    double error = 0;
  };
  /// a state of the chain, in H, in the primary's units
  struct Point {
    Vector u, v;
  };

  Trust estimate(const BasicChainRun<S>& primary);
  /// A double run judged unreliable by its long double shadow: a binary128 run of the same input
  /// decides whether the run or its shadow left the path (a shadow's own rounding can take it
  /// through a near-tangent contact another way, a false alarm); short runs only.
  void arbitrate(const BasicChainRun<S>& primary, Trust& trust);
  bool shadowing() const { return m_shadow != nullptr && m_active; }
  /// the shadow ended at a contact it cannot decide: the comparison stops there, no path taken
  void shadowUndecided();
  bool withinBudget() const;
  /// the fastest a state error can grow from a time error, per unit time, over the scales
  H fastestRate() const;
  /// the shadow's next event (its time still the shadow's), held until popShadowEvent; none
  /// when the shadow has ended
  const BasicChainEvent<H>* nextShadowEvent();
  void popShadowEvent();
  /// a shadow's state in the primary's units, into `into` (its storage reused)
  void fromShadow(Point& into, const ChainVector<H>& u, const ChainVector<H>& v) const;
  void widenScales(const Point& state);
  double relativeStateError(const Point& primary, const Point& shadow) const;
  void compare(const H& t, double stateError, double timeError);
  /// The state error of a phase off by eps times the run's length (relative to the scales).
  double phaseRounding(const BasicChainRun<S>& primary) const;
  std::string shadowName() const;

  const ChainShadow<S>* m_chain = nullptr;
  TrustMode m_mode;
  std::stop_token m_stop;
  std::unique_ptr<BasicChainSimulator<H>> m_shadow;
  /// the start as the shadow read it (unscaled), for a binary128 arbiter
  BasicChainStart<H> m_inputStart;
  long m_maxContacts = 0;
  H m_tEnd = 0;
  std::int64_t m_searchSteps = 0;
  /// shadow events not yet matched (at most a few), a ring of slots reused from event to event:
  /// no allocation per event
  std::vector<BasicChainEvent<H>> m_pending;
  std::size_t m_pendingFirst = 0, m_pendingCount = 0;
  Point m_before, m_after, m_shadowBefore, m_shadowAfter;  ///< an event's states, compared
  bool m_active = true;
  bool m_shadowUndecided = false;
  std::string m_stopNote;  ///< why the shadow stopped early, if it did
  std::string m_failure;   ///< a structural mismatch (another event type, an extra contact)
  std::int64_t m_observed = 0;
  std::int64_t m_compared = 0;

  Eigen::Index m_stopped = 0;  ///< the stopped mass, 0-based
  H m_period = 0;              ///< the slowest period [time]
  H m_omega = 1;               ///< the slowest angular frequency [1/time]
  H m_fastest = 1;             ///< the fastest angular frequency [1/time]
  Vector m_scaleU, m_scaleV;   ///< largest |u_i|, |v_i| seen (u_s at least the gap)
  double m_worstTime = 0;    ///< worst contact time error / the slowest period
  double m_lastState = 0;    ///< state error at the last compared event
  double m_envelope = 0;     ///< max error so far (state and time)
  H m_lastCompared = 0;      ///< time of the last compared event
  H m_heldUntil = 0;         ///< time of the last event with the envelope within tolerance
  bool m_crossed = false;
  std::vector<GrowthPoint> m_growth;  ///< the envelope at geometrically spaced times
};

/// The estimate of a run made already (its events kept), from `start`, its shadow the chain
/// widened (widenedShadow): what a caller that did not watch the run as it went asks.
template <typename S>
Trust trustOf(const BasicReadyChain<S>& chain, const std::type_identity_t<BasicChainStart<S>>& start,
              const BasicChainRun<S>& run, long maxContacts, std::type_identity_t<S> tEnd, TrustMode mode,
              std::stop_token stop = {});

}  // namespace grazelab::core
