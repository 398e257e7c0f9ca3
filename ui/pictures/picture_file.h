// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>
#include <QColor>
#include <QImage>
#include <QSize>
#include <QString>

#include <functional>
#include <optional>

class QPainter;

namespace grazelab::pictures {

/// The one writer of picture files, for the explorer's snapshots and the command line's maps,
/// families, atlases and report charts: every file is written whole or not at all (QSaveFile)
/// and carries what made it.

enum class PictureFormat { Png, Svg, Pdf };

/// The format named by a file's suffix (.png, .svg, .pdf), case-insensitive.
std::optional<PictureFormat> pictureFormat(const QString& path);

/// What a picture carries besides its drawing.
struct PictureMetadata {
  QString title;    ///< the document's title: PNG text "Title", SVG <title>, PDF title
  QString jsonKey;  ///< the PNG text that holds `json` ("GrazeLabSession", "GrazeLabMap", ...)
  QByteArray json;  ///< what made the picture: compacted to one line in a PNG, escaped in an
                    ///< SVG's <desc>, a PDF's XMP description and its attachment session.json
};

/// Draws a picture on the painter it is given (its size is the caller's).
using Painting = std::function<void(QPainter&)>;

/// PNG of `image`, the metadata as its texts (with "Software": GrazeLab and its version).
bool writePng(const QString& path, const QImage& image, const PictureMetadata& metadata, QString* error);
/// SVG of `size` logical pixels; fonts sized as on a screen of `dpi` logical dots per inch
/// (the one the painting's text was laid out for).
bool writeSvg(const QString& path, QSize size, const Painting& paint, const PictureMetadata& metadata,
              QString* error, int dpi = 96);
/// One PDF page the size of `size` seen at 96 dpi (nothing cropped or distorted), 300 dpi.
bool writePdf(const QString& path, QSize size, const Painting& paint, const PictureMetadata& metadata,
              QString* error);
/// By the path's suffix; a PNG drawn at `pixelRatio` times `size` over `background`.
bool writePicture(const QString& path, QSize size, const Painting& paint, const PictureMetadata& metadata,
                  QString* error, double pixelRatio = 2.0, const QColor& background = Qt::white);

/// Bytes written whole or not at all: the old file stays intact if anything fails.
bool saveFileAtomically(const QString& path, const QByteArray& data, QString* error);

}  // namespace grazelab::pictures
