// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QString>

#include <vector>

class QPainter;

namespace grazelab::pictures {

/// One family of periodic orbits as the frequency-energy picture draws it.
struct ModesPictureFamily {
  int impacts = 1;
  std::vector<QPointF> points;  ///< (log10 E, 2 pi / T), in the order of the family
  std::vector<bool> stable;     ///< per point: elliptic (drawn solid) or not (dashed)
};

/// A special point: a flip, a fold, an end.
struct ModesPictureMark {
  QPointF at;     ///< (log10 E, 2 pi / T)
  QString label;  ///< "flip", "fold", "grazing", ...
};

/// The frequency-energy picture of nonsmooth modal analysis: every family as 2 pi / T against
/// the energy (log scale), coloured by its impacts per period, stable parts solid and unstable
/// parts dashed, its special points marked and named.
void paintModes(QPainter& painter, const QRectF& area, const std::vector<ModesPictureFamily>& families,
                const std::vector<ModesPictureMark>& marks, const QString& title);

/// The colour of the families with `impacts` impacts per period.
QColor modesColor(int impacts);

}  // namespace grazelab::pictures
