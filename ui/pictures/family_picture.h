// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QRectF>
#include <QString>

#include <vector>

class QPainter;

namespace grazelab::pictures {

/// One orbit on a frequency-energy curve.
struct FrequencyEnergyPoint {
  double energy = 0;  ///< [energy]
  double omega = 0;   ///< 2 pi / T [1/time]
  bool admissible = false;
};

/// The frequency-energy curve of the 1IPP family: 2 pi / T against the energy (log scale),
/// admissible orbits a solid line, inadmissible ones grey crosses, the grazing end (T -> T2,
/// V -> 0, GLO_lambda*) a marked point. The window is the admissible part's.
/// `endLabel` names the grazing end in the key (the two-mass chain's by default).
void paintFrequencyEnergy(QPainter& painter, const QRectF& area,
                          const std::vector<FrequencyEnergyPoint>& family,
                          const FrequencyEnergyPoint& grazingEnd, const QString& title,
                          const QString& endLabel = QStringLiteral("grazing end: T → T₂, V → 0, GLO(λ*)"));

}  // namespace grazelab::pictures
