// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QPointF>
#include <QRectF>
#include <QString>

#include <vector>

class QPainter;

namespace grazelab::pictures {

/// The frame of a frequency-energy picture (the 1IPP family's, the modes atlas's): the energy
/// on a log scale across, the frequency 2 pi / T up, with their ticks.
struct EnergyFrame {
  QRectF plot;          ///< the plot area [pixels]
  double eLo = 0, eHi = 1;  ///< log10 E at the left and right edges
  double wLo = 0, wHi = 1;  ///< frequency at the bottom and top edges
  std::vector<double> xTicks;  ///< log10 E of each tick: decades (and 2, 5 when few show)
  std::vector<double> yTicks;

  /// The pixel of (log10 E, frequency).
  QPointF at(double logEnergy, double omega) const;
};

/// A frame over [eLo, eHi] x [wLo, wHi] (already padded) with its ticks.
EnergyFrame makeEnergyFrame(const QRectF& plot, double eLo, double eHi, double wLo, double wHi);

/// The picture's title, bold, centred over its top two lines.
void paintPictureTitle(QPainter& painter, const QRectF& area, const QString& title, double line);

/// The grid lines, under the curves.
void paintEnergyGrid(QPainter& painter, const EnergyFrame& frame);

/// The box, the tick labels and the axis titles, over the curves; `line` is the font's height.
void paintEnergyAxes(QPainter& painter, const EnergyFrame& frame, const QRectF& area, double line);

}  // namespace grazelab::pictures
