// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include "core/model/model.h"
#include "core/model/linear_modes.h"
#include "ui/compute/params.h"

namespace grazelab::ui {

/// The chain a set of parameters describes, with its derived quantities, or why there is none.
struct DerivedModel {
  bool ok = false;
  QString message;  ///< why not ok, in plain words
  core::Model model;
  core::Modes modes;
  double massRatio = 0;   ///< m2 / m1
  double lambdaStar = 0;  ///< the GLO_lambda that 1IPP orbits tend to (Theorem 2.1)
};

/// Builds the model: k2 from the 1:2 design when it is on (no silent clamping: an infeasible
/// mass ratio is reported), validated by core::validate.
DerivedModel deriveModel(const Params& params);

}  // namespace grazelab::ui
