// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>
#include <QImage>
#include <QString>

#include <optional>

class QWidget;

namespace grazelab::ui {

enum class SnapshotFormat { Png, Svg, Pdf };

/// The format named by a file's suffix (.png, .svg, .pdf), case-insensitive.
std::optional<SnapshotFormat> snapshotFormat(const QString& path);

/// Renders a widget to an image at `pixelRatio` times its size (crisp on paper and HiDPI).
QImage renderImage(QWidget* widget, qreal pixelRatio = 2.0);

/// Writes a widget as PNG (2x pixel ratio, the session embedded as text "GrazeLabSession"),
/// SVG (QSvgGenerator, session in the description) or PDF (QPdfWriter), atomically through
/// QSaveFile. Returns false and a reason in `error` on failure; no partial file is left.
/// Writes the widget as a PNG, SVG or PDF picture; the session travels inside it (PNG text,
/// SVG description, PDF metadata and attachment) and `title` is the document's title.
bool saveSnapshot(QWidget* widget, const QString& path, const QByteArray& sessionJson,
                  const QString& title, QString* error);

/// Writes bytes atomically (QSaveFile): the old file stays intact if anything fails.
bool saveFileAtomically(const QString& path, const QByteArray& data, QString* error);

}  // namespace grazelab::ui
