// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <stop_token>
#include <type_traits>
#include <vector>

#include "core/model/mass_chain.h"
#include "core/orbits/special_orbits.h"
#include "core/solver/chain_flight.h"

namespace grazelab::core {

/// A one-impact-per-period (1IPP) orbit of a chain of N masses (docs/model.md section 11; Legrand,
/// Junca & Heng 2017): with Phi_j(T) = cot(w_j T / 2) / w_j, a_kj = m_s P[k][j] P[s][j] and g_k(T)
/// = sum_j a_kj Phi_j(T), the data right after the impact are v = V e_s, V = d / g_s(T), u =
/// V g(T) (u_s = d). Admissible when V < 0 and the exact flight from them first meets the stop
/// at T (certified search). The refusals are the two-mass ones.
template <typename S>
struct BasicChainOnePeriodicOrbit {
  OnePeriodicRefusal refusal = OnePeriodicRefusal::BadPeriod;
  BasicChainState<S> postImpact;  ///< u = V g(T), v = V e_s
  S V = 0;                        ///< the stopped mass's velocity after the impact
  S energy = 0;
  bool admissible() const { return refusal == OnePeriodicRefusal::None; }
};
using ChainOnePeriodicOrbit = BasicChainOnePeriodicOrbit<double>;
/// In the chain's precision S (double, long double or binary128): the data, and the flight
/// that checks them, computed in S from the chain's numbers in S.
template <typename S>
BasicChainOnePeriodicOrbit<S> chainOnePeriodicOrbitIn(const BasicMassChain<S>& chain, std::type_identity_t<S> T);
/// The same from the chain's dynamics made once (a family's rows, a ready chain's orbits);
/// without `checkReturn` the data alone (admissible when V < 0, the flight not searched).
template <typename S>
BasicChainOnePeriodicOrbit<S> chainOnePeriodicOrbitIn(const BasicMassChain<S>& chain,
                                                      const BasicChainDynamics<S>& dynamics,
                                                      std::type_identity_t<S> T, bool checkReturn = true);
inline ChainOnePeriodicOrbit chainOnePeriodicOrbit(const MassChain& chain, double T) {
  return chainOnePeriodicOrbitIn<double>(chain, T);
}

/// The GLO the 1IPP data tend to as T tends to a common period T* of the modes in I (those whose
/// period divides T*; the modes with a node at the stop left out): weights lambda_j = a_sj w_j^-2
/// / sum_(i in I) a_si w_i^-2 for j in I, 0 for the others (Theorem 2.1 and Lemma 2.2 for any N:
/// a convex combination). Fastest mode first.
std::vector<double> onePeriodicGrazingWeights(const MassChain& chain, double periodStar);

/// The 1IPP family for `count` periods evenly spaced in (0, T_max), T_max k / (count + 1), and
/// for T_max (1 - 2^-k), k = 8 ... 30, towards its grazing end, sorted by T: T_max is the common
/// period of a commensurate chain, else the slowest mode's period. A stop ends it early.
/// T_max: the common period of a commensurate chain, else its slowest mode's period.
double chainOnePeriodicEnd(const MassChain& chain);

struct ChainFamilyRow {
  double T = 0;
  ChainOnePeriodicOrbit orbit;
};
/// A family in which kFamilySearchBudgetRows rows ran out of the search budget
/// (OnePeriodicRefusal::SearchBudget) before any row was admissible or undecided stops there: the
/// flights of such a chain (a stiff one, its fast modes turning millions of times a period) cannot
/// be searched.
constexpr int kFamilySearchBudgetRows = 8;
std::vector<ChainFamilyRow> chainOnePeriodicFamily(const MassChain& chain, std::int64_t count,
                                                   std::stop_token stop = {});

}  // namespace grazelab::core
