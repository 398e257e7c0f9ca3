// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/output_files.h"

#include <QDir>
#include <QFileInfo>

#include <QFont>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>

#include "io/cli_io.h"
#include "ui/pictures/picture_file.h"

namespace grazelab::cli {

std::optional<QString> parseOutputPrefix(const OptionValues& parser, const char* files,
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
  // the folder is made when the first file is written (a refusal after this leaves none): here
  // only whether it can be, from the nearest folder that exists
  QFileInfo existing(info.absolutePath());
  while (!existing.exists() && existing.absoluteFilePath() != existing.absolutePath()) {
    existing = QFileInfo(existing.absolutePath());
  }
  if (!existing.isDir() || !existing.isWritable()) {
    error = QStringLiteral("--out: cannot make the folder %1").arg(info.absolutePath());
    return std::nullopt;
  }
  return prefix;
}

namespace {

// the folder of an --out prefix is made when something is written into it: a command refused
// before it writes leaves no empty folder behind
bool makeFolderOf(const QString& path, QString& error) {
  const QString folder = QFileInfo(path).absolutePath();
  if (QDir().mkpath(folder)) return true;
  error = QStringLiteral("cannot make the folder %1").arg(folder);
  return false;
}

}  // namespace

bool saveAtomically(const QString& path, const QByteArray& bytes, QString& error) {
  return makeFolderOf(path, error) && pictures::saveFileAtomically(path, bytes, &error);
}

bool picturesAvailable() { return qobject_cast<QGuiApplication*>(QCoreApplication::instance()) != nullptr; }

bool savePngAndSvg(const QString& prefix, QSize size, const QString& title, const QString& textKey,
                   const QByteArray& description, const std::function<void(QPainter&)>& paint,
                   QString& error) {
  // every text in DejaVu Sans at 15 px, on whatever platform draws it
  const auto draw = [&](QPainter& painter) {
    QFont font("DejaVu Sans");
    font.setPixelSize(15);
    painter.setFont(font);
    paint(painter);
  };
  QImage image(size, QImage::Format_RGB32);
  {
    QPainter painter(&image);
    draw(painter);
  }
  const pictures::PictureMetadata metadata{title, textKey, description};
  return makeFolderOf(prefix, error) && pictures::writePng(prefix + ".png", image, metadata, &error) &&
         pictures::writeSvg(prefix + ".svg", size, draw, metadata, &error);
}

}  // namespace grazelab::cli
