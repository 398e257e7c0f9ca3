// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>
#include <QString>

#include <map>
#include <vector>

#include "core/methods/work_precision.h"
#include "io/json_value.h"

// What the parts of `report` share: its input, and the pieces that write its files.
namespace grazelab::cli::report {

using core::methods::MethodKind;
using core::methods::WorkPrecisionPoint;
using PointsByMethod = std::map<MethodKind, std::vector<WorkPrecisionPoint>>;

/// What the files of a report say about its problem, for the note's chain or any chain. The
/// names are the note's for every chain: w1 its fastest frequency, T2 its slowest period.
struct ReportInput {
  QString chainLine;         ///< "m1 = 1, m2 = 0.5, k1 = 1, k2 = ... (1:2 design, upper branch), gap d = 1"
  QString startLine;         ///< "(u1, u2, v1, v2) = (...)"
  QString startDescription;  ///< how the start was given, in words
  QString horizonNote;
  JsonValue chain;           ///< the chain's numbers, for the pictures' metadata
  JsonValue start;           ///< the start, likewise
  double period = 0;         ///< T2 [time]
  double k1 = 0;             ///< the wall's spring: the penalty's k_c are relative to it
  double tEnd = 0;           ///< the horizon [time]
  std::int64_t referenceContacts = 0;
  double referenceSeconds = 0;
};

/// "moreau-jean", ...
QString name(MethodKind kind);
/// "h=0.001", "rtol=1e-08 (k_c=1e+12)", "double".
QString parameterText(const core::methods::MethodSetting& setting);
/// Smaller is finer, dimensionless: h / T2, rtol, k1 / k_c, or the unit roundoff.
double fineness(const core::methods::MethodSetting& setting, double period, double k1);
/// The model, start and version, embedded in the pictures.
JsonValue metadata(const ReportInput& input);

/// DIR/report.md.
QByteArray reportMarkdown(const ReportInput& input, const core::methods::ComparisonEnd& end,
                          const std::vector<MethodKind>& methods, const PointsByMethod& byMethod,
                          const core::methods::TimingPolicy& timing, bool quick);

/// DIR/work_precision.svg/.png and DIR/convergence.svg/.png (only where the explorer is built).
bool writePictures(const QString& dir, const ReportInput& input,
                   const std::vector<MethodKind>& methods, const PointsByMethod& byMethod,
                   QString& error);

}  // namespace grazelab::cli::report
