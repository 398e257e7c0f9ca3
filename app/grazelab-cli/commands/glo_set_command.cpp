// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/glo_set_command.h"

#include <QPainter>
#include <QPointF>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "commands/grazing_set.h"
#include "core/orbits/chain_glo.h"
#include "exit_codes.h"
#include "io/cli_input.h"
#include "io/cli_output.h"
#include "io/json_value.h"
#include "io/output_files.h"
#include "ui/pictures/glo_set_picture.h"

namespace grazelab::cli {
namespace {

// The top of u_s / d over a period of the weights (1 - lambda, lambda), for the picture: 4096
// phases of the common period (a picture's accuracy, ~1e-5; the set's ends drawn are the
// certified search's)
std::vector<QPointF> topCurve(int fast, int slow, double from, double to) {
  std::vector<QPointF> curve;
  for (const auto& [lambda, top] : core::gloTopCurve(fast, slow, from, to, 400, 4096)) curve.emplace_back(lambda, top);
  return curve;
}

// PREFIX.png and PREFIX.svg of the set (two or three modes), with the JSON as their text
int writePicture(const OptionValues& options, const Io& io, const std::vector<int>& used,
                 const std::vector<int>& harmonics, const core::GrazingInterval* interval,
                 const std::vector<core::GrazingRegionPoint>& boundary, const std::string& json, QString& error) {
  if (!picturesAvailable()) {
    error = "--out: pictures are drawn by the grazelab-cli program (this caller has no fonts)";
    return kExitInvalidInput;
  }
  const auto prefix = parseOutputPrefix(options, "PREFIX.png, PREFIX.svg", "glo-set", error);
  if (!prefix) return kExitInvalidInput;
  QStringList ratio;
  for (int n : harmonics) ratio << QString::number(n);
  const QSize size(1000, 720);
  QString title;
  std::function<void(QPainter&)> paint;
  if (interval) {
    title = QStringLiteral("Grazing set of the %1 resonance: which GLO(λ) touch the stop").arg(ratio.join(':'));
    const double width = interval->high - interval->low;
    const double from = std::min(-0.5, interval->low - 0.25 * width);
    const double to = std::max(1.5, interval->high + 0.25 * width);
    const std::vector<QPointF> curve = topCurve(harmonics[0], harmonics[1], from, to);
    // the modes' numbers as subscripts, as the pictures write GLOM₁
    const auto subscript = [](int number) {
      QString digits = QString::number(number);
      for (QChar& digit : digits) digit = QChar(0x2080 + digit.digitValue());
      return digits;
    };
    const QString modes =
        QStringLiteral("(1 − λ) GLOM%1 + λ GLOM%2").arg(subscript(used[0] + 1), subscript(used[1] + 1));
    paint = [=](QPainter& painter) {
      pictures::paintGrazingInterval(painter, QRectF(QPointF(0, 0), size), curve, interval->low, interval->high,
                                     title, modes);
    };
  } else {
    title = QStringLiteral("Grazing set of the %1 resonance in the (λ₂, λ₃) plane").arg(ratio.join(':'));
    std::vector<QPointF> points;
    for (const core::GrazingRegionPoint& point : boundary) points.emplace_back(point.lambda2, point.lambda3);
    paint = [=](QPainter& painter) {
      pictures::paintGrazingRegion(painter, QRectF(QPointF(0, 0), size), points, title);
    };
  }
  if (!savePngAndSvg(*prefix, size, title, "GrazeLabGrazingSet", QByteArray::fromStdString(json), paint, error)) {
    return 1;
  }
  std::fprintf(io.messages, "grazelab-cli: glo-set: %s.png, %s.svg\n", qPrintable(*prefix), qPrintable(*prefix));
  return kExitOk;
}

}  // namespace

Parsed<core::MassChain> gloSetChainOf(const OptionValues& options, std::stop_token stop) {
  if (options.isSet("masses")) {
    const auto chain = parseMassChain(options, stop);
    if (!chain.value) return {std::nullopt, chain.error};
    return {chain.value->chain, {}};
  }
  for (const char* name : {"springs", "right-spring", "stop-mass", "frequencies", "design-branch"}) {
    if (options.isSet(name)) {
      return {std::nullopt, "--springs, --right-spring, --stop-mass and --frequencies describe a chain given by --masses"};
    }
  }
  const auto model = parseModel<double>(options);
  if (!model.value) return {std::nullopt, model.error};
  return {core::massChainOf(model.value->model), {}};
}

std::optional<GloSetRequest> readGloSetRequest(const OptionValues& options, QString& error) {
  GloSetRequest request;
  if (options.isSet("directions")) {
    bool ok = false;
    request.directions = options.value("directions").toInt(&ok);
    if (!ok || request.directions < 3 || request.directions > GloSetRequest::kMaxDirections) {
      error = QStringLiteral("--directions: a whole number from 3 to %1").arg(GloSetRequest::kMaxDirections);
      return std::nullopt;
    }
  }
  if (options.isSet("precision") && options.value("precision") != "double" && options.value("precision") != "auto") {
    error = "--precision: glo-set is computed in double (give double or auto)";
    return std::nullopt;
  }
  return request;
}

int runGloSet(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  const std::optional<GloSetRequest> request = readGloSetRequest(options, error);
  if (!request) return kExitInvalidInput;
  const Parsed<core::MassChain> chain = gloSetChainOf(options, stop);
  if (!chain.value) {
    error = chain.error;
    return chain.error.isEmpty() ? kExitInterrupted : kExitInvalidInput;  // (empty: the design was interrupted)
  }
  const GloSetOutcome outcome = grazingSet(*chain.value, *request, stop);
  if (outcome.status == GloSetStatus::Interrupted) return kExitInterrupted;
  if (outcome.status == GloSetStatus::Refused) {
    error = QString::fromStdString(outcome.problem);
    return kExitInvalidInput;
  }
  if (options.isSet("out") && outcome.modes.size() < 2) {
    error = "--out: one mode moves the stopped mass: its grazing set is a point, with no picture to draw";
    return kExitInvalidInput;
  }
  const JsonValue document = gloSetDocument(outcome);
  if (options.isSet("out")) {
    const int code = writePicture(options, io, outcome.modes, outcome.harmonics,
                                  outcome.interval ? &*outcome.interval : nullptr, outcome.boundary,
                                  fieldPerLine(document, "  ", ""), error);
    if (code != kExitOk) return code;
  }
  emitDocument(io, document);
  return 0;
}

}  // namespace grazelab::cli
