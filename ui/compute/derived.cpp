// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/compute/derived.h"

#include <QCoreApplication>

#include <cmath>

#include "core/orbits/special_orbits.h"
#include "core/model/resonance.h"
#include "core/orbits/starts.h"

namespace grazelab::ui {

DerivedModel deriveModel(const Params& params) {
  DerivedModel derived;
  derived.model = {params.m1, params.m2, params.k1, params.k2, params.gap, std::nullopt};
  derived.massRatio = params.m2 / params.m1;
  auto tr = [](const char* text) {
    return QCoreApplication::translate("grazelab::ui::DerivedModel", text);
  };

  // the masses and springs first, so that the message names the real culprit
  core::Model probe = derived.model;
  if (params.resonantDesign) probe.k2 = 1.0;
  if (const auto problems = core::validate(probe); !problems.empty()) {
    derived.message = tr("Invalid parameters: %1").arg(QString::fromStdString(core::describe(problems)));
    return derived;
  }
  if (params.resonantDesign) {
    const auto k2 = core::resonantK2(params.m1, params.m2, params.k1, params.branch);
    if (!k2) {
      derived.message =
          tr("No 1:2 resonant chain for m₂/m₁ = %1: the design needs m₂/m₁ ≤ 9/16 = 0.5625. "
             "Lower m₂ or raise m₁ (or switch the 1:2 design off for a detuned chain).")
              .arg(derived.massRatio, 0, 'g', 6);
      return derived;
    }
    // the model remembers the design: the solver then uses the exact 1:2 resonance
    derived.model = *core::designedModel(params.m1, params.m2, params.k1, params.gap, params.branch);
  }
  derived.modes = core::computeModes(derived.model);
  derived.lambdaStar = core::lambdaStar(derived.modes);
  derived.ok = true;
  return derived;
}

}  // namespace grazelab::ui
