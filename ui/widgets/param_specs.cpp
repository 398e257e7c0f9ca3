// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/widgets/param_specs.h"

#include <QCoreApplication>

namespace grazelab::ui {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("grazelab::ui::ParamSpec", text); }

}  // namespace

ParamSpec paramSpec(ParamKey key) {
  switch (key) {
    case ParamKey::Lambda:
      return {key, tr("λ"),
              tr("Which grazing linear orbit GLO(λ) the run starts from: a mix (1 − λ) of the fast "
                 "mode and λ of the slow mode that just touches the stop. λ in [0, 1] gives the "
                 "convex family, (1, 4/3] the non-convex one; beyond 4/3 the motion starts stuck."),
              -0.5, 2.0, -0.5, 2.0, 4, false, {0.0, 1.0, 4.0 / 3.0}};
    case ParamKey::M1:
      return {key, tr("m₁"), tr("Mass 1, tied to the wall by the spring k₁."), 0.1, 4.0, 0.01,
              100.0, 4, false, {}};
    case ParamKey::M2:
      return {key, tr("m₂"),
              tr("Mass 2, the one that hits the stop. A 1:2 resonant chain needs m₂/m₁ ≤ 9/16: the "
                 "slider covers that range (for m₁ = 1); type a larger value for a detuned chain."),
              0.01, 0.5625, 0.001, 100.0, 4, false, {0.5625}};
    case ParamKey::Gap:
      return {key, tr("gap d"),
              tr("Distance from the rest position of mass 2 to the rigid stop."), 0.1, 4.0,
              1e-6, 1e6, 6, false, {1.0}};
    case ParamKey::K1:
      return {key, tr("k₁"), tr("Stiffness of the spring between the wall and mass 1."), 0.1, 4.0,
              0.001, 100.0, 4, false, {}};
    case ParamKey::K2:
      return {key, tr("k₂"),
              tr("Stiffness of the spring between the masses. Typed by hand only when the 1:2 "
                 "design is off (a detuned chain)."),
              0.05, 4.0, 0.001, 100.0, 4, false, {}};
    case ParamKey::Perturbation:
      return {key, tr("perturbation δ"),
              tr("Signed size of the push applied to the start state along the chosen direction. "
                 "A push of v₂ below 0 makes the motion impact; lowering u₂ below d usually gives "
                 "a motion that never reaches the stop; a push along the plane (u₁, v₁) only "
                 "gives another grazing orbit."),
              -0.2, 0.2, -10.0, 10.0, 4, false, {0.0}};
    case ParamKey::Horizon:
      return {key, tr("contacts"),
              tr("How many contacts with the stop (impacts, grazings, sticks) to compute."), 1,
              1e5, 1, 1e6, 0, true, {}};
    case ParamKey::Period:
      return {key, tr("T / T₂"),
              tr("Period T of the one-impact-per-period orbit as a fraction of T₂, the slow "
                 "period. As T → T₂ from below the orbit tends to GLO(λ*) (Theorem 2.1)."),
              0.5, 0.999, 0.01, 0.999999, 6, false, {}};
    case ParamKey::ChainPeriod:
      return {key, tr("T / T*"),
              tr("Period T of the chain's one-impact-per-period orbit as a fraction of T*, the "
                 "chain's common period. As T → T* from below the orbit tends to a grazing linear "
                 "orbit whose weights the theorem gives (Theorem 2.1 for N masses)."),
              0.3, 0.999, 0.01, 0.999999, 6, false, {}};
    case ParamKey::ModeFamily:
      return {key, tr("family"),
              tr("Which family of the atlas to follow (its number, as the modes picture's CSV names "
                 "it). A click on the picture chooses the family and the orbit clicked."),
              0, 20, 0, 200, 0, false, {}};
    case ParamKey::ModeEnergy:
      return {key, tr("energy along it"),
              tr("Where along the family's energies the orbit shown lies: 0 at its lowest energy, 1 at "
                 "its highest (log scale). Drag it to watch the multipliers move on the unit circle: "
                 "two of opposite Krein signature that meet and leave it are a Krein collision."),
              0, 1, 0, 1, 3, false, {}};
    case ParamKey::FrequencyRatio:
      return {key, tr("ω₁ / ω₂"),
              tr("Ratio of the fast to the slow frequency of the detuned chain (k₂ is chosen to "
                 "give it). At exactly 2 the chain is in 1:2 resonance and every free motion "
                 "repeats after T₂; away from 2 it does not."),
              1.8, 2.2, 1.01, 10.0, 4, false, {2.0}};
  }
  return {key, {}, {}, 0, 1, 0, 1, 3, false, {}};
}

QString subscriptDigits(int number) {
  QString text;
  for (const QChar digit : QString::number(number)) {
    text += digit.isDigit() ? QChar(0x2080 + digit.digitValue()) : digit;
  }
  return text;
}

}  // namespace grazelab::ui
