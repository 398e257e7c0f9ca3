// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>
#include <QImage>
#include <QRect>
#include <QString>

class QWidget;

namespace grazelab::ui {

/// Renders a widget (or its `area`: empty, all of it) to an image at `pixelRatio` times its size
/// (crisp on paper and HiDPI).
QImage renderImage(QWidget* widget, qreal pixelRatio = 2.0, QRect area = {});

/// Writes a widget as a PNG (2x pixel ratio), SVG or PDF picture through the one picture
/// writer (ui/pictures/picture_file.h): the session travels inside it (PNG text
/// "GrazeLabSession", SVG description, PDF metadata and attachment) and `title` is the
/// document's title. Returns false and a reason in `error` on failure; no partial file is left.
/// `area`: the part of the widget the picture shows (empty: all of it; a view's controls are
/// left out, SceneView::pictureArea).
bool saveSnapshot(QWidget* widget, const QString& path, const QByteArray& sessionJson,
                  const QString& title, QString* error, QRect area = {});

/// Writes bytes atomically (QSaveFile): the old file stays intact if anything fails.
bool saveFileAtomically(const QString& path, const QByteArray& data, QString* error);

}  // namespace grazelab::ui
