// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <array>
#include <optional>
#include <stop_token>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/orbits/chain_monodromy.h"

/// Where the 1IPP family of a chain of N masses changes stability (docs/model.md section 12):
/// between two of its periods whose multipliers sit differently (so many on the unit circle, so
/// many real and positive, real and negative, complex off it), the change located by bisection
/// in T and named by what moved.
namespace grazelab::core {

/// How an orbit's 2N - 2 multipliers sit.
struct MultiplierCensus {
  int onCircle = 0;
  int positive = 0;  ///< real, positive, off the circle
  int negative = 0;  ///< real, negative, off the circle
  int complex = 0;   ///< off the circle and the real axis (quadruplets: four at a time)
  bool decided = true;  ///< false where the class is undecided (a collision within the bars)
  bool operator==(const MultiplierCensus& other) const {
    return onCircle == other.onCircle && positive == other.positive && negative == other.negative &&
           complex == other.complex;
  }
};
template <typename S>
MultiplierCensus censusOf(const ChainMonodromy<S>& monodromy);

enum class ChainBifurcationKind {
  PeriodDoubling,  ///< a real negative pair leaves (or joins) the circle at -1
  Fold,            ///< a real positive pair leaves (or joins) it at +1: a fold or branch point
  KreinCollision,  ///< two pairs of opposite Krein signatures meet on the circle and leave it as
                   ///< a complex quadruplet (Hamiltonian-Hopf), or a quadruplet comes back to it
  Other,           ///< several of these at once within the bisection's resolution
};
/// "period-doubling", "fold", "krein-collision", "other".
std::string_view toString(ChainBifurcationKind kind);
/// Whether two changes of stability that undo each other could hide between two orbits of one
/// family whose multipliers (by angle, as ChainMonodromy orders them) are `a` and `b`: two of
/// opposite Krein signatures swapped places, or a multiplier at either end is nearer a change of
/// the census (its conjugate or one of the other signature, on the circle; the circle, off it
/// and complex; +-1, real) than four times what it and the one it would meet moved in between.
template <typename S>
bool mayHideAPair(const std::vector<ChainMultiplier<S>>& a, const std::vector<ChainMultiplier<S>>& b);

/// What changed from the census `before` to `after` (another number on the circle): the kind of
/// the change, by which of the real negative, real positive and complex counts moved.
ChainBifurcationKind changeKind(const MultiplierCensus& before, const MultiplierCensus& after);

template <typename S>
struct ChainBifurcation {
  ChainBifurcationKind kind = ChainBifurcationKind::Other;
  S T = 0;
  S periodError = 0;  ///< half the last bracket [T-, T+] whose ends were both decided
  S energy = 0;       ///< the orbit's at T
  /// how far the energy at the change may be: half its spread over the last bracket, plus the
  /// closed form's rounding there (its data's conditioning near a multiple of a mode's period)
  S energyError = 0;
  bool leaves = true;  ///< multipliers leave the circle as T grows (false: they come back to it)
};

/// What a search of a family's stability changes found.
template <typename S>
struct ChainBifurcations {
  std::vector<ChainBifurcation<S>> changes;  ///< in increasing T
  /// the stretches [T-, T+] between two rows where the search for a hidden pair of changes ran out
  /// of its budget before it could rule one out (denser rows would look again there)
  std::vector<std::array<S, 2>> unsearched;
};

/// The changes of the number of multipliers on the unit circle between consecutive `periods`
/// (increasing) whose orbits are both admissible and decided, each located by bisection in T
/// until its bracket is 8 ulps of T wide or its middle is undecided, and named by how the rest of
/// the census moved across the last bracket. The bisection asks the closed-form data and
/// monodromy alone (V < 0, the flight not searched); the point found is checked in full (its
/// flight searched, its path run) and dropped when it is not admissible: a change inside a
/// stretch where the flight meets the stop early, or where V >= 0, is not reported. Multipliers
/// that move among themselves off the circle (a quadruplet meeting the real axis as two real
/// pairs) change no stability and are not reported. Two changes between the same two periods that
/// undo each other are looked for where the multipliers could hide them: where, at either row, a
/// multiplier is nearer a change of the census (its conjugate, on the circle; another of the
/// opposite Krein signature; the circle, off it; +-1, real) than four times what it and the one
/// it would meet moved between the rows, where two of opposite signatures swapped places, or
/// where a pole of sigma lies between them, the interval is halved (to 1e-9 of T, at most 256
/// halvings between two rows, beside the bisections' own steps), and each half with a census of
/// its own located as above; where the halvings run out, the stretch is said `unsearched`.
template <typename S>
ChainBifurcations<S> chainOnePeriodicBifurcations(const BasicReadyChain<S>& chain, const std::vector<S>& periods,
                                                  std::stop_token stop = {});

/// A period of the family with its census (none: no admissible orbit there) and its multipliers,
/// as a table that computed them has them.
template <typename S>
struct CensusRow {
  S T = 0;
  std::optional<MultiplierCensus> census;
  std::vector<ChainMultiplier<S>> multipliers;  ///< (empty: not known; only a pole of sigma refines it)
};
/// The same from rows whose censuses are known (only the bisections and refinements are computed).
template <typename S>
ChainBifurcations<S> chainOnePeriodicBifurcations(const BasicReadyChain<S>& chain, const std::vector<CensusRow<S>>& rows,
                                                  std::stop_token stop = {});

}  // namespace grazelab::core
