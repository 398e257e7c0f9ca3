// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QList>
#include <QString>

#include "ui/compute/params.h"

namespace grazelab::ui {

/// How a parameter is shown: its label with symbol, range, precision and meaning in words.
struct ParamSpec {
  ParamKey key;
  QString label;    ///< e.g. "λ" or "m₂"
  QString toolTip;  ///< what the quantity means, in words
  double sliderMin = 0;  ///< the slider covers [sliderMin, sliderMax]
  double sliderMax = 1;
  double spinMin = 0;    ///< the spin box accepts [spinMin, spinMax] (may be wider)
  double spinMax = 1;
  int decimals = 3;
  bool logarithmic = false;   ///< slider position maps to log(value)
  QList<double> marks;        ///< values marked under the slider
};

/// The spec of each parameter (translated labels and tooltips).
ParamSpec paramSpec(ParamKey key);

/// A number in subscript digits, for labels (m₁, λ₁₂).
QString subscriptDigits(int number);

}  // namespace grazelab::ui
