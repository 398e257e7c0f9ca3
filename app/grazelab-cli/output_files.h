// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>
#include <QSize>
#include <QString>

#include <functional>

class QPainter;

namespace grazelab::cli {

/// Writes a file whole or not at all (QSaveFile); false with "cannot write PATH: reason".
bool saveAtomically(const QString& path, const QByteArray& bytes, QString& error);

/// PREFIX.png and PREFIX.svg of one drawing of `size`: `paint` draws on a painter whose font is
/// DejaVu Sans at 15 px; the PNG carries `description` as the text `textKey`, the SVG as its
/// (escaped) description. Only in builds with pictures (GRAZELAB_CLI_PICTURES).
bool savePngAndSvg(const QString& prefix, QSize size, const QString& title, const QString& textKey,
                   const QByteArray& description, const std::function<void(QPainter&)>& paint,
                   QString& error);

}  // namespace grazelab::cli
