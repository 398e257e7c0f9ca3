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

/// The task of a report and the words that describe it.
struct ReportInput {
  core::methods::Task task;
  QString startDescription;
  QString horizonNote;
  double period = 0;
};

/// The task of the report from the command line: the default problem unless told otherwise.

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
                          const core::methods::Reference& reference,
                          const std::vector<MethodKind>& methods, const PointsByMethod& byMethod,
                          const core::methods::TimingPolicy& timing, bool quick);

/// DIR/work_precision.svg/.png and DIR/convergence.svg/.png (only where the explorer is built).
bool writePictures(const QString& dir, const ReportInput& input,
                   const std::vector<MethodKind>& methods, const PointsByMethod& byMethod,
                   QString& error);

}  // namespace grazelab::cli::report
