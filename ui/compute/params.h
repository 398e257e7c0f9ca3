// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QJsonObject>
#include <QString>

#include <optional>
#include <vector>

#include "core/model/resonance.h"

namespace grazelab::ui {

/// The numeric parameters a user can drag. Which of them a scene exposes is the scene's choice.
enum class ParamKey {
  Lambda,        ///< lambda of GLO_lambda, the grazing orbit the run starts near
  M1,            ///< mass 1
  M2,            ///< mass 2 (the one that hits the stop)
  Gap,           ///< distance d from equilibrium of mass 2 to the stop
  K1,            ///< stiffness wall--m1
  K2,            ///< stiffness m1--m2, only when the 1:2 design is off
  Perturbation,  ///< signed size of the push off the chosen orbit
  Horizon,       ///< number of contacts to compute
  Period,        ///< T / T2 for the one-impact-per-period orbit
  FrequencyRatio,  ///< w_fast / w_slow of a detuned chain (the detuned-contrast scene)
  ChainPeriod,     ///< T / T* of an N-mass chain's 1IPP orbit (T* its common period)
  ModeFamily,      ///< the family of an atlas of modes followed (its index in the atlas)
  ModeEnergy,      ///< where along that family's energies (0 its lowest, 1 its highest, log scale)
};

/// Which component of the start state the perturbation moves.
enum class PerturbDirection { V2, U2, U1, V1 };

/// A chain of N masses (the N-mass scenes): its masses, its springs as given or designed for a
/// resonance, the stop's mass, and the grazing linear orbit its runs start from.
struct MassChainParams {
  static constexpr int kMaxMasses = 8;
  std::vector<double> masses{1.0, 0.2, 0.05};  ///< m1 ... mN
  std::vector<double> springs{1.0, 1.0, 1.0};  ///< k1 ... kN as given (designed: only k1 is used)
  double rightSpring = 0;  ///< k(N+1) from mN to a right wall, kept as given when designing; 0: no wall
  /// the resonance asked for, fastest mode first (3, 2, 1 for 1:2:3); empty: the springs as given
  std::vector<int> harmonics{3, 2, 1};
  int designBranch = 1;  ///< which design of the resonance (1-based, ordered by k2)
  int stopMass = 0;      ///< 1-based; 0: the last mass
  /// GLO_lambda's weights, fastest mode first, summing to 1: the run starts on it at its touch
  /// (pushed by Params::perturbation along v_s)
  std::vector<double> weights{0.5, 0.3, 0.2};
  /// the mass whose phase portrait and Poincaré points are drawn (1-based; 0: the stopped mass)
  int shownMass = 0;
  /// the coordinates the Poincaré points on H are projected on, 1-based in the state (u1 ... uN,
  /// v1 ... vN: 1 ... 2N); 0: the default pair (u, v) of mass 1, or of mass 2 when mass 1 is stopped
  int sectionX = 0, sectionY = 0;

  int size() const { return int(masses.size()); }
  /// the stopped mass and the shown one, 1-based, with their defaults resolved
  int stopped() const { return stopMass > 0 ? stopMass : size(); }
  int shown() const { return shownMass > 0 ? shownMass : stopped(); }
  /// the section's coordinates, 1-based in the state, with their defaults resolved
  int sectionXResolved() const { return sectionX > 0 ? sectionX : sectionMass(); }
  int sectionYResolved() const { return sectionY > 0 ? sectionY : size() + sectionMass(); }
  /// the default section's mass: 1, or 2 when mass 1 is the stopped one
  int sectionMass() const { return stopped() == 1 && size() > 1 ? 2 : 1; }
  /// The chain with `count` masses: new masses copy the last, new springs 1, the weights
  /// spread evenly, a resonance of another length dropped (springs as given).
  MassChainParams resized(int count) const;
  friend bool operator==(const MassChainParams&, const MassChainParams&) = default;
};

/// Everything that decides a run, as plain values. Scenes read what they need.
struct Params {
  double lambda = 0.5;
  double m1 = 1.0;
  double m2 = 0.5;
  double gap = 1.0;
  double k1 = 1.0;
  double k2 = 0.5;  ///< used only when resonantDesign is false
  double perturbation = -0.05;
  PerturbDirection direction = PerturbDirection::V2;
  double horizon = 200;         ///< contacts
  double periodFraction = 0.9;  ///< T / T2 of the 1IPP orbit
  double frequencyRatio = 2.05; ///< w_fast / w_slow of the detuned chain
  double chainPeriodFraction = 0.9;  ///< T / T* of the N-mass 1IPP orbit
  double modeFamily = 0;    ///< the atlas's family followed (a whole number)
  double modeEnergy = 0.5;  ///< the position along its energies, 0 to 1
  bool resonantDesign = true;   ///< k2 from the 1:2 design (core::resonantK2)
  /// The landscape's region of the grazing-start plane, u1 in units of the gap d and v1 in
  /// units of d w2 (so that it frames the grazing family whatever the chain)
  struct MapRegion {
    double u1From = -1.5, u1To = 2.0, v1From = -2.2, v1To = 2.2;
    friend bool operator==(const MapRegion&, const MapRegion&) = default;
  };
  MapRegion mapRegion;
  core::Branch branch = core::Branch::Upper;
  MassChainParams massChain;  ///< the N-mass scenes' chain (the others ignore it)

  double value(ParamKey key) const;
  void setValue(ParamKey key, double value);

  friend bool operator==(const Params&, const Params&) = default;
};

/// Short stable key used in session files ("lambda", "m1", ...).
QString jsonKey(ParamKey key);
QString jsonKey(PerturbDirection direction);

QJsonObject toJson(const Params& params);
/// Reads parameters written by toJson(); missing fields keep their defaults from `base`.
/// Returns nothing and sets `error` when a field has the wrong type or an unknown value.
std::optional<Params> paramsFromJson(const QJsonObject& object, const Params& base, QString* error);

}  // namespace grazelab::ui
