// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QPointF>
#include <QRectF>
#include <QString>

#include <vector>

class QPainter;

namespace grazelab::pictures {

/// The grazing set of two modes (Lemma 2.1 for any resonance): the top of u_s / d over a
/// period of GLO_lambda against lambda (`curve`: (lambda, top) pairs), the line top = 1 dashed,
/// the grazing interval [low, high] shaded and its ends labelled. `modes` names the two
/// weights' modes in the axis title ("(1 − λ) GLOM₁ + λ GLOM₂").
void paintGrazingInterval(QPainter& painter, const QRectF& area, const std::vector<QPointF>& curve,
                          double low, double high, const QString& title, const QString& modes);

/// The grazing set of three modes in the plane of (lambda2, lambda3): the region inside its
/// `boundary` (points along rays, in order) shaded, the simplex (every weight >= 0) dashed, the
/// pure modes GLOM₁ (0, 0), GLOM₂ (1, 0), GLOM₃ (0, 1) marked.
void paintGrazingRegion(QPainter& painter, const QRectF& area, const std::vector<QPointF>& boundary,
                        const QString& title);

}  // namespace grazelab::pictures
