// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>
#include <stop_token>
#include <vector>

#include "core/numbers/scalar.h"

namespace grazelab::core {

/// One design of a chain's springs: the chain wall --k1-- [m1] --k2-- ... --kN-- [mN] with
/// these springs has the frequencies w_j = n_j w0 (fastest first).
struct ChainDesign {
  std::vector<double> springs;  ///< k_1 ... k_N; k_1 as asked
  double omega0 = 0;            ///< w0 [1/time]: T = 2 pi / w0 is the period of every free motion
  /// the largest relative error of the designed chain's frequencies against n_j w0, as its
  /// binary128 spectrum (chainModes) finds them
  double ratioError = 0;
};

enum class DesignOutcome {
  Designed,            ///< every positive design found (at least one)
  NoPositiveDesign,    ///< every design was found and none has all its springs positive
  BadRequest,          ///< no masses, a mass or k1 not positive and finite, ratios not N
                       ///< positive integers, non-increasing, or more masses than kMaxDesignMasses
  Incomplete,          ///< the search could not follow every solution: no list can be promised
  Stopped,             ///< the stop token was triggered
};

/// The springs of a chain with masses `masses` (no right wall: see below for one) whose frequencies are in the
/// ratio `harmonics[0] : ... : harmonics[N-1]` (fastest first, strictly decreasing), `k1`
/// fixing the scale (docs/model.md section 11).
///
/// The N unknowns k_2 ... k_N and w0 make a square polynomial system with N! solutions counted
/// in the complex numbers (its Bezout number: with the compliances 1/k_i as unknowns, each of
/// the N eigenvalue conditions is affine in each of them). All of them are followed from a
/// start system with N! known roots (a linear-product homotopy with a random complex gamma);
/// the positive real ones are polished in binary128 and kept when the designed chain's own
/// spectrum is in the ratio to 1e-13. Two paths meeting at a regular root (a path jump) or a
/// path that cannot be followed restart the whole search with another gamma; if that keeps
/// happening the outcome is Incomplete, never a shorter list. Paths meeting where F's Jacobian
/// is singular are a multiple root (two designs merging: N = 2, 1:2 at m2/m1 = 9/16), one design.
///
/// Designs are ordered by k_2 descending (then k_3 ...): for N = 2 and 1:2, design 1 is the
/// note's upper branch and design 2 its lower one, and none exists when m2/m1 > 9/16.
struct ChainDesigns {
  DesignOutcome outcome = DesignOutcome::BadRequest;
  std::vector<ChainDesign> designs;
  int paths = 0;          ///< paths followed in the successful search (N!; 2 N! with a right wall)
  int complexEnds = 0;    ///< distinct solutions with a complex or non-positive compliance
  int infiniteEnds = 0;   ///< paths that went to infinity (solutions the system lacks)
  // (a multiple root, where designs meet, is reached by several paths and counted once)
};

/// Above this many masses the N! paths take too long for an interactive answer (8! = 40 320).
inline constexpr int kMaxDesignMasses = 7;

/// Its cost grows as N!: N = 3 in 2.6 ms, N = 5 in 0.17 s, N = 6 in 1.6 s, N = 7 in tens
/// of seconds (grazelab_core_bench --benchmark_filter=DesignSprings); `stop` is checked
/// between paths.
ChainDesigns designSprings(const std::vector<double>& masses, double k1, const std::vector<int>& harmonics,
                           std::stop_token stop = {});

/// The same with a right wall: k_1 and the wall's k_(N+1) = `rightSpring` as given (0: none),
/// k_2 ... k_N designed. The wall makes the equations quadratic in 1/k_1 (the ratio of the two
/// walls' compliances is fixed), so 2 N! paths are followed; everything else is as above.
ChainDesigns designSprings(const std::vector<double>& masses, double k1, double rightSpring,
                           const std::vector<int>& harmonics, std::stop_token stop = {});

/// One of those designs for a chain whose numbers are given in binary128 (the masses, k_1 and the
/// wall read from their decimal text in it, which double rounds): the same root of the design
/// equations polished by Newton with every number in binary128, from `design` (found for the
/// chain rounded to double). The springs k_1 ... k_N then put the binary128 chain's frequencies in
/// the ratio to binary128's rounding, where the double design is off by double's. Empty when
/// Newton leaves the design (it moves each compliance by double's error, or its square root
/// where two designs meet), or when the refined chain's own binary128 spectrum is not in the
/// ratio to 1e-28 (a chain just past the edge where two designs meet, which double rounds back).
std::optional<std::vector<Quad>> refinedSprings(const std::vector<Quad>& masses, const Quad& k1,
                                                const Quad& rightSpring, const std::vector<int>& harmonics,
                                                const ChainDesign& design);

/// Why a chain's springs could not be designed as asked (chooseDesign).
enum class DesignChoiceProblem {
  None,
  NoPositiveDesign,  ///< DesignOutcome::NoPositiveDesign
  Incomplete,        ///< DesignOutcome::Incomplete
  Stopped,           ///< DesignOutcome::Stopped
  BadRequest,        ///< DesignOutcome::BadRequest
  NoSuchDesign,      ///< designs were found, fewer than the number asked for
};

/// Springs designed for requested frequency ratios, as every face asks for them (the command
/// line's --frequencies and --design-branch, the explorer's resonance and design, Python's
/// frequencies and design_branch): the design search's whole answer, and which design the chain
/// takes. Made once per chain; its numbers in a wider precision come from it (designedSpringsIn).
struct DesignChoice {
  std::vector<int> harmonics;  ///< as asked, fastest first
  ChainDesigns designs;
  int number = 1;  ///< the design taken, 1-based
  DesignChoiceProblem problem = DesignChoiceProblem::None;

  const ChainDesign& chosen() const { return designs.designs[std::size_t(number - 1)]; }
};

/// The designs of a chain of these masses, k_1 and right wall (0: none) for the ratios
/// `harmonics`, and design `number` (1-based) taken (designSprings; the problem when there is none
/// or fewer than `number`). The designs of the last 8 chains asked for are kept (thread-safe):
/// asking again for the same numbers returns them without searching.
DesignChoice chooseDesign(const std::vector<double>& masses, double k1, double rightSpring,
                          const std::vector<int>& harmonics, int number, std::stop_token stop = {});

/// The chosen design's springs for a chain whose masses, k_1 and wall are these numbers in S: in
/// double the design itself; in long double and binary128 its root polished for those numbers in
/// binary128 (refinedSprings), then rounded to S. Empty when it cannot be refined there.
template <typename S>
std::optional<std::vector<S>> designedSpringsIn(const std::vector<S>& masses, const S& k1, const S& rightSpring,
                                                const DesignChoice& choice);

}  // namespace grazelab::core
