// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/model/model.h"
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
  /// Estimated error of the final state: the largest over u1, u2, v1, v2 of the error relative
  /// to that component's scale (its largest size at the events of the run).
  double stateError = 0;
  /// Estimated error of the worst contact time, in units of T2.
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
/// binary128 run is shadowed by another binary128 run on the chain scaled 3x in length and
/// 1/sqrt(3) in time, which changes every rounding (the physics is scale-free) but not the answer.
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

/// Which parameters of the model were read exactly (a decimal like 0.5 is exact in binary,
/// 0.1 is not). A shadow of the same precision nudges the others by one rounding, so that
/// their representation counts as error (near m2/m1 = 9/16 the design amplifies it ~1e7).
struct ExactParameters {
  bool m1 = false, m2 = false, k1 = false, k2 = false, gap = false;
};

/// Estimates the error of a run of the note's chain (its kernel: runChain on readyChain(model))
/// in precision S by running the same algorithm beside it on a shadow (ShadowOf), in lockstep
/// event by event, so that it costs no memory however long the run. Feed it every event of the
/// run (observe), then finish with the run.
/// Holds its own shadow run: neither copied nor moved.
template <typename S>
class TrustMonitor {
 public:
  using H = ShadowScalar<S>;

  /// `model` and `start` are the run's chain and start read in precision H from the same input
  /// (so that the input's own rounding counts as error); `maxContacts`, `tEnd` (0: none) and
  /// `searchSteps` are the run's (runChain's). The shadow watches `stop` as the run does (an
  /// interrupt ends both). `shadowChain`: `model` made ready already (readyChain), which the
  /// shadow then runs instead of making it ready again (a map's thousands of shadows, each an
  /// eigensolve otherwise); it must outlive the monitor.
  TrustMonitor(const BasicModel<H>& model, const BasicChainState<H>& start, long maxContacts,
               std::type_identity_t<H> tEnd, TrustMode mode, std::stop_token stop = {},
               ExactParameters exact = {}, std::int64_t searchSteps = 0,
               const BasicReadyChain<H>* shadowChain = nullptr);
  TrustMonitor(const TrustMonitor&) = delete;
  TrustMonitor& operator=(const TrustMonitor&) = delete;

  /// The next event of the primary run.
  void observe(const BasicChainEvent<S>& event);
  /// The estimate, once the primary run ended (or was interrupted).
  Trust finish(const BasicChainRun<S>& primary);

 private:
  struct GrowthPoint {
    double t = 0;
    double error = 0;
  };

  Trust estimate(const BasicChainRun<S>& primary);
  /// A double run judged unreliable by its long double shadow: a binary128 run of the same input
  /// decides whether the run or its shadow left the path (a shadow's own rounding can take it
  /// through a near-tangent contact another way, a false alarm); short runs only.
  void arbitrate(const BasicChainRun<S>& primary, Trust& trust);
  bool shadowing() const { return m_shadow != nullptr && m_active; }
  /// the shadow ended at a contact it cannot decide: the comparison stops there, no path taken
  void shadowUndecided();
  bool withinBudget();
  std::optional<BasicEvent<H>> nextShadowEvent();
  void widenScales(const BasicState<H>& state);
  double relativeStateError(const BasicState<H>& primary, const BasicState<H>& shadow) const;
  void compare(const H& t, double stateError, double timeError);
  /// The state error of a phase off by eps times the run's length (relative to the scales).
  double phaseRounding(const BasicChainRun<S>& primary) const;
  std::string shadowName() const;

  TrustMode m_mode;
  std::stop_token m_stop;
  H m_lengthFactor = 1;  ///< the shadow's lengths are this many times the primary's
  H m_timeFactor = 1;    ///< the shadow's times are the primary's divided by this
  std::unique_ptr<BasicChainSimulator<H>> m_shadow;
  std::optional<TwoMassForm<H>> m_shadowForm;  ///< the shadow's chain, as its kernel runs it
  /// the input as the shadow read it (unscaled), for a binary128 arbiter
  std::optional<BasicModel<H>> m_inputModel;
  BasicChainState<H> m_inputStart;
  long m_maxContacts = 0;
  H m_tEnd = 0;
  std::deque<BasicEvent<H>> m_pending;  ///< shadow events not yet matched (at most a few)
  bool m_active = true;
  bool m_shadowUndecided = false;
  std::string m_stopNote;  ///< why the shadow stopped early, if it did
  std::string m_failure;   ///< a structural mismatch (another event type, an extra contact)
  std::int64_t m_observed = 0;

  H m_period = 0;            ///< T2 [time]
  H m_scale[4] = {0, 0, 0, 0};  ///< largest |u1|, |u2|, |v1|, |v2| seen (u2 at least the gap)
  H m_omega = 1;
  double m_worstTime = 0;    ///< worst contact time error / T2
  double m_lastState = 0;    ///< state error at the last compared event
  double m_envelope = 0;     ///< max error so far (state and time)
  H m_lastCompared = 0;      ///< time of the last compared event
  H m_heldUntil = 0;         ///< time of the last event with the envelope within tolerance
  bool m_crossed = false;
  std::vector<GrowthPoint> m_growth;  ///< the envelope at geometrically spaced times
};

}  // namespace grazelab::core
