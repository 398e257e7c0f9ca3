// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <string>

#include "core/model/two_mass_form.h"
#include "core/model/linear_modes.h"
#include "core/model/state.h"

namespace grazelab::core {

/// Which of the two modes: 1 is the fast mode, 2 the slow one (docs/model.md "Labelling").
enum class Mode { Fast = 1, Slow = 2 };

/// GLOM_i data on H (docs/model.md section 5): u1 = gap u1/u2 of mode i, u2 = gap, v = 0.
template <typename S>
BasicState<S> glomData(const TwoMassForm<S>& chain, Mode mode);

/// What the motion from GLO_lambda data does (Lemma 2.1), decided from lambda itself
/// (lambda = 4/3 is compared exactly, not with a rounded 4/3).
enum class GloKind {
  Grazing,        ///< lambda in [0, 4/3]: a grazing linear orbit, no impact ever
  ImpactsFollow,  ///< lambda < 0: the linear motion would cross the stop, so impacts follow
  StickingStart,  ///< lambda > 4/3: u1 > gap, the motion starts pressed on the stop
};
template <typename S>
GloKind classifyGlo(const S& lambda);
/// A short sentence for the kind, for command lines and tooltips.
std::string describe(GloKind kind);

/// GLO_lambda data: (1 - lambda) GLOM1 + lambda GLOM2, for any real lambda. For a resonant chain
/// it is built as u1 = gap [1 + (4/3 - lambda)(rho_fast - rho_slow)] (the same number, by the
/// resonance identity), which puts u1 on the side of the gap that classifyGlo(lambda) says:
/// u1 <= gap for lambda <= 4/3, u1 > gap beyond, whatever the rounding.
template <typename S>
BasicState<S> gloData(const TwoMassForm<S>& chain, const S& lambda);

/// lambda* = a22 w2^-2 / (a21 w1^-2 + a22 w2^-2), a_kj = m2 P_kj P_2j (Theorem 2.1, Lemma 2.2):
/// the GLO_lambda that one-impact-per-period orbits tend to as their period tends to T2.
template <typename S>
S lambdaStar(const TwoMassForm<S>& chain);

/// Why the closed-form data of a period give no admissible 1IPP orbit.
enum class OnePeriodicRefusal {
  None,              ///< admissible
  BadPeriod,         ///< T not positive and finite
  MultipleOfPeriod,  ///< T a multiple of T1 or T2: no data
  LeavesIntoStop,    ///< V >= 0 (through 0: the impact fades; through infinity: g2(T) = 0)
  NotDecided,        ///< the flight's return cannot be decided in this precision
  NeverReturns,      ///< the flight from the data never comes back to the stop
  ReturnsEarly,      ///< the flight touches or crosses the stop before T
  SearchBudget,      ///< the certified search for the flight's return ran out of its windows
                     ///< before T (a stiff chain's fast modes): undecided, not a refusal of the flight
};

/// One-impact-per-period (1IPP) orbit of period T (docs/model.md section 5): the one type of a
/// point of the two-mass 1IPP family, whether computed alone, along the family or at its end.
template <typename S>
struct OnePeriodicOrbit {
  S T = 0;                  ///< period [time]
  bool admissible = false;
  OnePeriodicRefusal refusal = OnePeriodicRefusal::None;
  std::string reason;       ///< why not, when not admissible, in words
  BasicState<S> postImpact; ///< data right after the impact: u = (gap g1/g2, gap), v = (0, V)
  S V = 0;                  ///< post-impact velocity of mass 2, gap / g2(T); < 0 when admissible
  S energy = 0;             ///< energy of postImpact (constant along the orbit); 0 without data
  /// whether there are data at all (not at a multiple of T1 or T2, nor for a bad period)
  bool hasData() const {
    return refusal != OnePeriodicRefusal::BadPeriod && refusal != OnePeriodicRefusal::MultipleOfPeriod;
  }
};

/// 1IPP data for period T (physical time): g_k(T) = sum_j a_kj Phi_j(T), Phi_j = cot(w_j T/2)/w_j.
/// Admissible when T is not a multiple of T1 or T2, V < 0, and the free flight from the data
/// stays below the stop on (0, T) (checked with the exact contact search: its first contact is
/// at T).
template <typename S>
OnePeriodicOrbit<S> onePeriodicOrbit(const TwoMassForm<S>& chain, const S& T);

// Double-precision conveniences for the explorer (they form the chain themselves).
State glomData(const Model& model, const Modes& modes, Mode mode);
State gloData(const Model& model, const Modes& modes, double lambda);
double lambdaStar(const Modes& modes);
OnePeriodicOrbit<double> onePeriodicOrbit(const Model& model, const Modes& modes, double T);

/// The lower end T_lo of the 1IPP family that ends at T2 (Theorem 2.1): every period in
/// (T_lo, T2) has an admissible 1IPP orbit; just below T_lo the orbit would penetrate the stop
/// or leave into it. Found by walking down from T2 in steps of T2/256 and bisecting the first
/// inadmissible step (to 1e-12 T2), so a short inadmissible window below T2 is not jumped over.
double onePeriodicLowerEnd(const Model& model, const Modes& modes);

}  // namespace grazelab::core
