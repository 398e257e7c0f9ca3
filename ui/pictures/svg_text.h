// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>

namespace grazelab::pictures {

/// The SVG Qt's generator writes, with its text made whole for any SVG reader.
///
/// Qt writes one <text> per run of one script and format ("GLO(", "λ), ", "max u₂ / d"), each
/// placed where the screen's layout put it, in the font family it was asked for ("Sans Serif",
/// Qt's own alias, unknown to browsers). A reader with other fonts drew the runs apart or on top
/// of each other. Here the runs that continue one another on one line become one <text> of
/// <tspan>s, as long as Qt laid it out (textLength), and each font family names the family Qt
/// drew with and a generic fallback. Anything else is copied as it is.
QByteArray wholeSvgText(const QByteArray& svg);

}  // namespace grazelab::pictures
