// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include "io/map_files.h"

namespace grazelab::cli::map {

/// Loads what drawing text needs (the font configuration, a glyph cache): ~0.1 s that a map
/// does on a thread of its own while its points are computed. Safe in any thread.
void prepareFonts();

/// PREFIX.png and PREFIX.svg: the quantity named in the spec ("picture") as a viridis colour
/// map with labelled axes and a colour bar; NaN cells grey, infinite ones white.
bool writeMapPicture(const QString& prefix, const StoredMap& map, QString& error);

}  // namespace grazelab::cli::map
