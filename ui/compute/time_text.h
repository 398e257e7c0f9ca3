// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <optional>
#include <utility>

namespace grazelab::ui {

/// A time as a class reads it: three significant digits and no exponent from 0.001 to 99 999
/// ("0.00123", "26.7", "3554"), a power of ten beyond ("8.9×10⁶", "2.5×10⁻⁴"; "3.55e+03" was
/// read as a code).
QString timeText(double t);

/// The time axis' title of a view of a long run: `axis` and what it shows, a window
/// (`shown`, in the axis' units) of the run (to `runEnd`) or of its samples (to `sampledTo`,
/// when they stop before the run's end and go past the window), or the whole and where the
/// samples stop. Short: a longer title wrapped to three lines in presentation and was cut.
QString runAxisTitle(const QString& axis, std::optional<std::pair<double, double>> shown, double sampledTo,
                     double runEnd);

}  // namespace grazelab::ui
