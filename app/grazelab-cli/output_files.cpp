// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "output_files.h"

#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

#if GRAZELAB_CLI_PICTURES
#include <QBuffer>
#include <QFont>
#include <QImage>
#include <QPainter>
#include <QSvgGenerator>
#endif

namespace grazelab::cli {

std::optional<QString> parseOutputPrefix(const QCommandLineParser& parser, const char* files,
                                         const char* example, QString& error) {
  if (!parser.isSet("out")) {
    error = QStringLiteral("--out PREFIX is required (the files are %1)").arg(files);
    return std::nullopt;
  }
  const QString prefix = parser.value("out");
  const QFileInfo info(prefix);
  if (prefix.isEmpty() || prefix.endsWith('/') || info.isDir()) {
    error = QStringLiteral("--out: '%1' is a folder; give a prefix such as %1/%2").arg(prefix, example);
    return std::nullopt;
  }
  if (!QDir().mkpath(info.absolutePath())) {
    error = QStringLiteral("--out: cannot make the folder %1").arg(info.absolutePath());
    return std::nullopt;
  }
  return prefix;
}

bool saveAtomically(const QString& path, const QByteArray& bytes, QString& error) {
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
    error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  return true;
}

#if GRAZELAB_CLI_PICTURES
bool savePngAndSvg(const QString& prefix, QSize size, const QString& title, const QString& textKey,
                   const QByteArray& description, const std::function<void(QPainter&)>& paint,
                   QString& error) {
  auto draw = [&](QPaintDevice& device) {
    QPainter painter(&device);
    QFont font("DejaVu Sans");
    font.setPixelSize(15);
    painter.setFont(font);
    paint(painter);
  };
  QImage image(size, QImage::Format_RGB32);
  draw(image);
  image.setText(textKey, QString::fromUtf8(description));
  QByteArray png;
  QBuffer pngBuffer(&png);
  pngBuffer.open(QIODevice::WriteOnly);
  image.save(&pngBuffer, "PNG");
  if (!saveAtomically(prefix + ".png", png, error)) return false;
  QByteArray svg;
  QBuffer svgBuffer(&svg);
  QSvgGenerator generator;
  generator.setOutputDevice(&svgBuffer);
  generator.setSize(size);
  generator.setViewBox(QRect(QPoint(0, 0), size));
  generator.setTitle(title);
  // Qt 6.4 writes the description as it is: a "<" in it would make the file unreadable
  generator.setDescription(QString::fromUtf8(description).toHtmlEscaped());
  draw(generator);
  return saveAtomically(prefix + ".svg", svg, error);
}
#else
bool savePngAndSvg(const QString&, QSize, const QString&, const QString&, const QByteArray&,
                   const std::function<void(QPainter&)>&, QString&) {
  return true;
}
#endif

}  // namespace grazelab::cli
