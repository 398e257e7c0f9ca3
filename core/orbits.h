// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <string>

#include "core/model.h"
#include "core/modes.h"
#include "core/state.h"

namespace grazelab::core {

/// Which of the two modes: 1 is the fast mode, 2 the slow one (MODEL.md "Labelling").
enum class Mode { Fast = 1, Slow = 2 };

/// GLOM_i data on H (MODEL.md section 5): u1 = gap P1i / P2i, u2 = gap, v = 0. Its linear motion
/// u(t) = (gap / P2i) P e_i cos(w_i t) touches the stop at t = 0 and never crosses it.
State glomData(const Model& model, const Modes& modes, Mode mode);

/// GLO_lambda data: (1 - lambda) GLOM1 + lambda GLOM2, for any real lambda. Its linear motion is
/// u2(t) = gap [(1 - lambda) cos(w1 t) + lambda cos(w2 t)] for a resonant chain.
State gloData(const Model& model, const Modes& modes, double lambda);

/// What the motion from GLO_lambda data does (Lemma 2.1).
enum class GloKind {
  Grazing,        ///< lambda in [0, 4/3]: a grazing linear orbit, no impact ever
  ImpactsFollow,  ///< lambda < 0: the linear motion would cross the stop, so impacts follow
  StickingStart,  ///< lambda > 4/3: u1 > gap, the motion starts pressed on the stop
};
GloKind classifyGlo(double lambda);
/// A short sentence for the kind, for command lines and tooltips.
std::string describe(GloKind kind);

/// lambda* = a22 w2^-2 / (a21 w1^-2 + a22 w2^-2), a_kj = m2 P_kj P_2j (Theorem 2.1, Lemma 2.2):
/// the GLO_lambda that one-impact-per-period orbits tend to as their period tends to T2.
/// For a resonant chain this is 4 P22^2 / (P21^2 + 4 P22^2), in (0, 1].
double lambdaStar(const Modes& modes);

/// One-impact-per-period (1IPP) orbit of period T (MODEL.md section 5).
struct OnePeriodicOrbit {
  bool admissible = false;
  std::string reason;  ///< why not, when not admissible
  State postImpact;    ///< data right after the impact: u = (gap g1/g2, gap), v = (0, V)
  double V = 0;        ///< post-impact velocity of mass 2, gap / g2(T); < 0 when admissible
};

/// 1IPP data for period T: g_k(T) = sum_j a_kj Phi_j(T) with Phi_j = sin(w_j T) / (w_j (1 -
/// cos(w_j T))) = cot(w_j T / 2) / w_j. Admissible when T is not a multiple of T1 or T2, V < 0,
/// and the free flight from the data stays below the stop on (0, T) (checked with the exact
/// contact search: its first contact is at T).
OnePeriodicOrbit onePeriodicOrbit(const Model& model, const Modes& modes, double T);

}  // namespace grazelab::core
