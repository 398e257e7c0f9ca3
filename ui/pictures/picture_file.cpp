// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/pictures/picture_file.h"

#include <QBuffer>
#include <QFileInfo>
#include <QImageWriter>
#include <QJsonDocument>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>
#include <QSvgGenerator>

#include "core/version.h"
#include "ui/pictures/svg_text.h"

namespace grazelab::pictures {
namespace {

bool openSaveFile(QSaveFile& file, QString* error) {
  if (file.open(QIODevice::WriteOnly)) return true;
  if (error) *error = QStringLiteral("cannot write %1: %2").arg(file.fileName(), file.errorString());
  return false;
}

bool commit(QSaveFile& file, QString* error) {
  if (file.commit()) return true;
  if (error) *error = QStringLiteral("cannot write %1: %2").arg(file.fileName(), file.errorString());
  return false;
}

QString compactJson(const QByteArray& json) {
  return QString::fromUtf8(QJsonDocument::fromJson(json).toJson(QJsonDocument::Compact));
}

QString software() { return QStringLiteral("GrazeLab %1").arg(QString::fromUtf8(kVersion)); }

// A minimal XMP packet with the JSON as the document's description.
QByteArray xmpMetadata(const QByteArray& json) {
  const QString description = compactJson(json).toHtmlEscaped();
  return QStringLiteral(
             "<?xpacket begin=\"\" id=\"W5M0MpCehiHzreSzNTczkc9d\"?>"
             "<x:xmpmeta xmlns:x=\"adobe:ns:meta/\">"
             "<rdf:RDF xmlns:rdf=\"http://www.w3.org/1999/02/22-rdf-syntax-ns#\">"
             "<rdf:Description rdf:about=\"\" xmlns:dc=\"http://purl.org/dc/elements/1.1/\">"
             "<dc:title><rdf:Alt><rdf:li xml:lang=\"x-default\">GrazeLab snapshot</rdf:li></rdf:Alt></dc:title>"
             "<dc:creator><rdf:Seq><rdf:li>GrazeLab</rdf:li></rdf:Seq></dc:creator>"
             "<dc:description><rdf:Alt><rdf:li xml:lang=\"x-default\">%1</rdf:li></rdf:Alt></dc:description>"
             "</rdf:Description></rdf:RDF></x:xmpmeta><?xpacket end=\"w\"?>")
      .arg(description)
      .toUtf8();
}

}  // namespace

std::optional<PictureFormat> pictureFormat(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix == QStringLiteral("png")) return PictureFormat::Png;
  if (suffix == QStringLiteral("svg")) return PictureFormat::Svg;
  if (suffix == QStringLiteral("pdf")) return PictureFormat::Pdf;
  return std::nullopt;
}

bool writePng(const QString& path, const QImage& image, const PictureMetadata& metadata, QString* error) {
  QSaveFile file(path);
  if (!openSaveFile(file, error)) return false;
  QImageWriter writer(&file, "png");
  // Qt joins a PNG's texts as "key: value" pairs separated by blank lines: the JSON goes in
  // compact, on one line
  writer.setText(metadata.jsonKey, compactJson(metadata.json));
  writer.setText(QStringLiteral("Software"), software());
  writer.setText(QStringLiteral("Title"), metadata.title);
  if (!writer.write(image)) {
    file.cancelWriting();
    if (error) *error = QStringLiteral("cannot encode %1: %2").arg(path, writer.errorString());
    return false;
  }
  return commit(file, error);
}

bool writeSvg(const QString& path, QSize size, const Painting& paint, const PictureMetadata& metadata,
              QString* error, int dpi) {
  QSaveFile file(path);
  if (!openSaveFile(file, error)) return false;
  QBuffer drawn;
  drawn.open(QIODevice::WriteOnly);
  QSvgGenerator generator;
  generator.setOutputDevice(&drawn);
  generator.setSize(size);
  generator.setViewBox(QRect(QPoint(0, 0), size));
  // a font's points become user units at this resolution (Qt's default, 72, wrote a 9 pt label
  // as 9 units where the screen laid it out in 12 pixels: the text came out small, and the runs
  // of a title with symbols, placed by the screen's layout, came apart)
  generator.setResolution(dpi);
  // Qt 6.4 writes the title and the description as they are: a "<" in them would make the
  // file unreadable
  generator.setTitle(metadata.title.toHtmlEscaped());
  generator.setDescription(QString::fromUtf8(metadata.json).toHtmlEscaped());
  QPainter painter(&generator);
  if (!painter.isActive()) {
    file.cancelWriting();
    if (error) *error = QStringLiteral("cannot draw the SVG picture for %1").arg(path);
    return false;
  }
  paint(painter);
  painter.end();
  if (file.write(wholeSvgText(drawn.data())) < 0) {
    file.cancelWriting();
    if (error) *error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  return commit(file, error);
}

bool writePdf(const QString& path, QSize size, const Painting& paint, const PictureMetadata& metadata,
              QString* error) {
  QSaveFile file(path);
  if (!openSaveFile(file, error)) return false;
  QPdfWriter writer(&file);
  writer.setCreator(software());
  // the title is what a viewer shows: words; what made the picture travels inside the document
  // in its XMP metadata (dc:description) and as an attached file
  writer.setTitle(metadata.title);
  writer.setDocumentXmpMetadata(xmpMetadata(metadata.json));
  writer.addFileAttachment(QStringLiteral("session.json"), metadata.json, QStringLiteral("application/json"));
  writer.setResolution(300);
  writer.setPageSize(QPageSize(QSizeF(size) * 25.4 / 96.0, QPageSize::Millimeter));
  writer.setPageMargins(QMarginsF(0, 0, 0, 0));
  QPainter painter(&writer);
  if (!painter.isActive()) {
    file.cancelWriting();
    if (error) *error = QStringLiteral("cannot draw the PDF page for %1").arg(path);
    return false;
  }
  const double scale = double(writer.width()) / size.width();
  painter.scale(scale, scale);
  paint(painter);
  painter.end();
  return commit(file, error);
}

bool writePicture(const QString& path, QSize size, const Painting& paint, const PictureMetadata& metadata,
                  QString* error, double pixelRatio, const QColor& background) {
  const auto format = pictureFormat(path);
  if (!format) {
    if (error) *error = QStringLiteral("unknown picture type for %1: use .png, .svg or .pdf").arg(path);
    return false;
  }
  switch (*format) {
    case PictureFormat::Png: {
      QImage image(size * pixelRatio, QImage::Format_ARGB32_Premultiplied);
      image.setDevicePixelRatio(pixelRatio);
      image.fill(background);
      QPainter painter(&image);
      painter.setRenderHint(QPainter::Antialiasing);
      paint(painter);
      painter.end();
      return writePng(path, image, metadata, error);
    }
    case PictureFormat::Svg: return writeSvg(path, size, paint, metadata, error);
    case PictureFormat::Pdf: return writePdf(path, size, paint, metadata, error);
  }
  return false;
}

bool saveFileAtomically(const QString& path, const QByteArray& data, QString* error) {
  QSaveFile file(path);
  if (!openSaveFile(file, error)) return false;
  if (file.write(data) != data.size()) {
    file.cancelWriting();
    if (error) *error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  return commit(file, error);
}

}  // namespace grazelab::pictures
