// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>
#include <QSize>
#include <QString>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/option_values.h"

class QPainter;

namespace grazelab::cli {

struct Io;

/// --out PREFIX of a command that writes PREFIX.* files (`files` names them in the message for a
/// missing --out; `example` ends the suggested prefix): not a folder, and in a folder that exists
/// or can be made (it is made when the first file is written: a refusal leaves none behind).
std::optional<QString> parseOutputPrefix(const OptionValues& parser, const char* files,
                                         const char* example, QString& error);

/// Writes a file whole or not at all (QSaveFile); false with "cannot write PATH: reason".
bool saveAtomically(const QString& path, const QByteArray& bytes, QString& error);

/// True when this process draws pictures: it has a QGuiApplication (fonts need one). The
/// command line makes one for the commands that draw; the Python module does not, and its
/// commands write no pictures.
bool picturesAvailable();

/// PREFIX.png and PREFIX.svg of one drawing of `size`: `paint` draws on a painter whose font is
/// DejaVu Sans at 15 px; the PNG carries `description` as the text `textKey`, the SVG as its
/// (escaped) description, both with the title and the program's version (the one picture
/// writer, ui/pictures/picture_file.h). Call only when picturesAvailable().
bool savePngAndSvg(const QString& prefix, QSize size, const QString& title, const QString& textKey,
                   const QByteArray& description, const std::function<void(QPainter&)>& paint,
                   QString& error);

}  // namespace grazelab::cli
