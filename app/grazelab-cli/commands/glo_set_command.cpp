// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/glo_set_command.h"

#include <QPainter>
#include <QPointF>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/orbits/chain_glo.h"
#include "exit_codes.h"
#include "io/cli_input.h"
#include "io/cli_output.h"
#include "io/json_value.h"
#include "io/output_files.h"
#include "ui/pictures/glo_set_picture.h"

namespace grazelab::cli {
namespace {

using V = JsonValue;

constexpr int kDefaultDirections = 72;
constexpr int kMaxDirections = 100'000;

// the chain: --masses ..., or the two-mass chain of --m1 ... (the note's by default)
std::optional<core::MassChain> chainOf(const OptionValues& options, std::stop_token stop, QString& error,
                                       bool& stopped) {
  if (options.isSet("masses")) {
    const auto chain = parseMassChain(options, stop);
    stopped = !chain.value && chain.error.isEmpty();
    if (!chain.value) error = chain.error;
    if (!chain.value) return std::nullopt;
    return chain.value->chain;
  }
  for (const char* name : {"springs", "right-spring", "stop-mass", "frequencies", "design-branch"}) {
    if (options.isSet(name)) {
      error = "--springs, --right-spring, --stop-mass and --frequencies describe a chain given by --masses";
      return std::nullopt;
    }
  }
  const auto model = parseModel<double>(options);
  if (!model.value) error = model.error;
  if (!model.value) return std::nullopt;
  return core::massChainOf(model.value->model);
}

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

int runGloSet(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  int directions = kDefaultDirections;
  if (options.isSet("directions")) {
    bool ok = false;
    directions = options.value("directions").toInt(&ok);
    if (!ok || directions < 3 || directions > kMaxDirections) {
      error = QStringLiteral("--directions: a whole number from 3 to %1").arg(kMaxDirections);
      return kExitInvalidInput;
    }
  }
  if (options.isSet("precision") && options.value("precision") != "double" && options.value("precision") != "auto") {
    error = "--precision: glo-set is computed in double (give double or auto)";
    return kExitInvalidInput;
  }
  bool stopped = false;
  const auto chain = chainOf(options, stop, error, stopped);
  if (stopped) return kExitInterrupted;
  if (!chain) return kExitInvalidInput;
  // the modes that move the stopped mass (the others have no GLOM) and their ratios
  const core::GrazingModes grazing = core::grazingModes(*chain);
  const std::vector<int>& used = grazing.modes;
  const core::SpectrumRatios& ratios = grazing.ratios;
  if (used.size() > 3) {
    error = QStringLiteral("glo-set answers for two or three modes: %1 modes of this chain move the stopped mass")
                .arg(used.size());
    return kExitInvalidInput;
  }
  if (options.isSet("out") && used.size() < 2) {
    error = "--out: one mode moves the stopped mass: its grazing set is a point, with no picture to draw";
    return kExitInvalidInput;
  }
  if (used.size() > 1 && !ratios.commensurate) {
    error = QStringLiteral("glo-set needs commensurate frequencies (a flight then repeats after T): this chain's "
                           "are not, within 1e-9 (detuned by %1 from the nearest small ratios)")
                .arg(ratios.detuning, 0, 'g', 3);
    return kExitInvalidInput;
  }
  std::vector<V> modeNumbers;
  for (int j : used) modeNumbers.push_back(V::of(std::int64_t(j + 1)));
  std::vector<V> harmonics;
  for (int n : ratios.harmonics) harmonics.push_back(V::of(std::int64_t(n)));
  V set = V::null();
  std::optional<core::GrazingInterval> interval;
  std::vector<core::GrazingRegionPoint> boundary;
  if (used.size() == 1) {
    set = V::object({{"kind", V::of("point")},
                     {"in_words", V::of("one mode moves the stopped mass: its GLOM is the only grazing linear orbit")}});
  } else if (used.size() == 2) {
    const int fast = ratios.harmonics[0], slow = ratios.harmonics[1];
    interval = core::grazingInterval(fast, slow);
    const double flat = interval->flatPoint;
    const std::string words =
        "(1 - lambda) GLOM_" + std::to_string(used[0] + 1) + " + lambda GLOM_" + std::to_string(used[1] + 1) +
        " is a grazing linear orbit exactly for lambda in [" + core::formatScalar(interval->low) + ", " +
        core::formatScalar(interval->high) + "]" +
        (interval->high == flat ? ": its upper end is the flat point, where the touch turns fourth order" : "");
    set = V::object({{"kind", V::of("interval")},
                     {"weights", V::of("(1 - lambda, lambda) on the modes listed")},
                     {"low", V::number(interval->low)},
                     {"low_out", V::number(interval->lowOut)},
                     {"high", V::number(interval->high)},
                     {"high_out", V::number(interval->highOut)},
                     {"flat_point", V::number(flat)},
                     {"in_words", V::of(words)}});
  } else {
    boundary =
        core::grazingRegion(ratios.harmonics[0], ratios.harmonics[1], ratios.harmonics[2], directions, stop);
    if (stop.stop_requested()) return kExitInterrupted;
    std::vector<V> points;
    for (const core::GrazingRegionPoint& point : boundary) {
      points.push_back(V::object({{"angle", V::number(point.angle)},
                                  {"lambda2", V::number(point.lambda2)},
                                  {"lambda3", V::number(point.lambda3)},
                                  {"radius", V::number(point.radius)},
                                  {"radius_out", V::number(point.radiusOut)}}));
    }
    set = V::object(
        {{"kind", V::of("region")},
         {"weights", V::of("(1 - lambda2 - lambda3, lambda2, lambda3) on the modes listed")},
         {"boundary", V::array(std::move(points))},
         {"in_words", V::of("a convex region of the (lambda2, lambda3) plane holding the simplex; its boundary "
                            "along rays from (1/3, 1/3): each point grazes, radius_out along its ray does not")}});
  }
  const double period = ratios.commensurate ? 2 * std::numbers::pi / ratios.omega0 : 0;
  const V document = V::object({{"chain", massChainValue(*chain, period)},
                                {"modes", V::array(std::move(modeNumbers))},
                                {"harmonics", V::array(std::move(harmonics))},
                                {"grazing_set", std::move(set)}});
  if (options.isSet("out")) {
    const int code = writePicture(options, io, used, ratios.harmonics, interval ? &*interval : nullptr, boundary,
                                  fieldPerLine(document, "  ", ""), error);
    if (code != kExitOk) return code;
  }
  emitDocument(io, document);
  return 0;
}

}  // namespace grazelab::cli
