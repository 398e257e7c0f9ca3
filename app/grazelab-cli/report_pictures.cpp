// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The report's two pictures, drawn by the explorer's own chart class (built with the explorer).
#include <QJsonDocument>

#include <algorithm>

#include "report_internal.h"
#include "ui/export.h"
#include <QFileInfo>

#include "ui/plots/log_log_chart.h"

namespace grazelab::cli::report {
namespace {

using core::methods::ErrorMeasure;

bool savePictures(ui::LogLogChart& chart, const QString& stem, const QByteArray& json,
                  QString& error) {
  chart.resize(1200, 760);
  for (const char* suffix : {".svg", ".png"}) {
    QString reason;
    const QString title = QStringLiteral("GrazeLab report: %1").arg(QFileInfo(stem).fileName());
    if (!ui::saveSnapshot(&chart, stem + suffix, json, title, &reason)) {
      error = reason;
      return false;
    }
  }
  return true;
}

/// One curve per method, and a second one for the penalty method's tolerance sweep.
std::vector<std::pair<MethodKind, bool>> curveKeys(
    const std::vector<MethodKind>& methods,
    const std::map<MethodKind, std::vector<WorkPrecisionPoint>>& byMethod) {
  std::vector<std::pair<MethodKind, bool>> keys;
  for (MethodKind kind : methods) {
    keys.push_back({kind, false});
    const auto& points = byMethod.at(kind);
    if (std::any_of(points.begin(), points.end(),
                    [](const auto& p) { return p.setting.penaltyToleranceSweep; })) {
      keys.push_back({kind, true});
    }
  }
  return keys;
}

}  // namespace

/// The two pictures: the same chart class as the explorer's Accuracy scene.
bool writePictures(const QString& dir, const ReportInput& input,
                   const std::vector<MethodKind>& methods,
                   const std::map<MethodKind, std::vector<WorkPrecisionPoint>>& byMethod,
                   QString& error) {
  using core::methods::RunStatus;
  const QByteArray json = QJsonDocument(metadata(input)).toJson(QJsonDocument::Compact);
  ui::LogLogChart work("Error against run time", "run time [s] (minimum of repeated runs)",
                       "state error at t_end");
  ui::LogLogChart convergence("Convergence", "h / T2, rtol, eps or k1 / k_c (finer to the left)",
                              "contact-time error / T2");
  for (const auto& [kind, toleranceSweep] : curveKeys(methods, byMethod)) {
    std::vector<WorkPrecisionPoint> points = byMethod.at(kind);
    std::sort(points.begin(), points.end(),
              [](const auto& a, const auto& b) { return a.secondsMin < b.secondsMin; });
    const QString label = toleranceSweep ? name(kind) + " (rtol, k_c = 1e12 k1)" : name(kind);
    ui::LogLogCurve curve{label, {}};
    ui::LogLogCurve order{label, {}};
    for (const WorkPrecisionPoint& p : points) {
      if (p.status != RunStatus::Completed || p.setting.penaltyToleranceSweep != toleranceSweep) continue;
      curve.points.push_back({p.secondsMin, p.errors.state});
      // an error of 0 (binary128 against binary128, seen in double) tells nothing about order
      if (p.errors.contactTime > 0) {
        order.points.push_back({fineness(p.setting, input.period, input.task.model.k1), p.errors.contactTime});
      }
    }
    std::sort(order.points.begin(), order.points.end(),
              [](const QPointF& a, const QPointF& b) { return a.x() < b.x(); });
    const auto slope = core::methods::fittedSlope(byMethod.at(kind), ErrorMeasure::ContactTime);
    if (slope && !toleranceSweep) order.name += QStringLiteral(" (slope %1)").arg(slope->value, 0, 'f', 2);
    const int index = work.addCurve(curve.name);
    for (const QPointF& p : curve.points) work.addPoint(index, p);
    const int orderIndex = convergence.addCurve(order.name);
    for (const QPointF& p : order.points) convergence.addPoint(orderIndex, p);
  }
  return savePictures(work, dir + "/work_precision", json, error) &&
         savePictures(convergence, dir + "/convergence", json, error);
}

}  // namespace grazelab::cli::report
