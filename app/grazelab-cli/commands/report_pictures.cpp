// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The report's two pictures: log-log charts drawn with QPainter (ui/pictures), PNG and SVG.
#include <QFileInfo>
#include <QFont>
#include <QPainter>

#include <algorithm>

#include "commands/report_internal.h"
#include "ui/pictures/log_log_picture.h"
#include "ui/pictures/picture_file.h"

namespace grazelab::cli::report {
namespace {

using core::methods::ErrorMeasure;

struct Chart {
  QString title, xTitle, yTitle;
  std::vector<pictures::LogLogCurve> curves;
};

bool savePictures(const Chart& chart, const QString& stem, const QByteArray& json, QString& error) {
  const QSize size(1200, 760);
  const pictures::PictureMetadata metadata{
      QStringLiteral("GrazeLab report: %1").arg(QFileInfo(stem).fileName()), QStringLiteral("GrazeLabSession"), json};
  const auto paint = [&](QPainter& painter) {
    QFont font("DejaVu Sans");
    font.setPixelSize(15);
    painter.setFont(font);
    pictures::paintLogLog(painter, QRectF(QPointF(0, 0), size), chart.curves, chart.title, chart.xTitle, chart.yTitle);
  };
  for (const char* suffix : {".svg", ".png"}) {
    if (!pictures::writePicture(stem + suffix, size, paint, metadata, &error)) return false;
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

/// The two pictures: work against precision, and convergence.
bool writePictures(const QString& dir, const ReportInput& input,
                   const std::vector<MethodKind>& methods,
                   const std::map<MethodKind, std::vector<WorkPrecisionPoint>>& byMethod,
                   QString& error) {
  using core::methods::RunStatus;
  const QByteArray json = QByteArray::fromStdString(oneLine(metadata(input)));
  Chart work{"Error against run time", "run time [s] (minimum of repeated runs)", "state error at t_end", {}};
  Chart convergence{"Convergence", "h / T2, rtol, eps or k1 / k_c (finer to the left)", "contact-time error / T2", {}};
  for (const auto& [kind, toleranceSweep] : curveKeys(methods, byMethod)) {
    std::vector<WorkPrecisionPoint> points = byMethod.at(kind);
    std::sort(points.begin(), points.end(),
              [](const auto& a, const auto& b) { return a.secondsMin < b.secondsMin; });
    const QString label = toleranceSweep ? name(kind) + " (rtol, k_c = 1e12 k1)" : name(kind);
    pictures::LogLogCurve curve{label, {}};
    pictures::LogLogCurve order{label, {}};
    for (const WorkPrecisionPoint& p : points) {
      if (p.status != RunStatus::Completed || p.setting.penaltyToleranceSweep != toleranceSweep) continue;
      curve.points.push_back({p.secondsMin, p.errors.state});
      // an error of 0 (binary128 against binary128, seen in double) tells nothing about order
      if (p.errors.contactTime > 0) {
        order.points.push_back({fineness(p.setting, input.period, input.k1), p.errors.contactTime});
      }
    }
    std::sort(order.points.begin(), order.points.end(),
              [](const QPointF& a, const QPointF& b) { return a.x() < b.x(); });
    const auto slope = core::methods::fittedSlope(byMethod.at(kind), ErrorMeasure::ContactTime);
    if (slope && !toleranceSweep) order.name += QStringLiteral(" (slope %1)").arg(slope->value, 0, 'f', 2);
    work.curves.push_back(std::move(curve));
    convergence.curves.push_back(std::move(order));
  }
  return savePictures(work, dir + "/work_precision", json, error) &&
         savePictures(convergence, dir + "/convergence", json, error);
}

}  // namespace grazelab::cli::report
