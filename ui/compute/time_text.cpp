// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/compute/time_text.h"

#include <QObject>

#include <algorithm>
#include <cmath>

namespace grazelab::ui {

QString timeText(double t) {
  const double size = std::abs(t);
  if (size == 0 || !std::isfinite(t)) return QString::number(t);
  const int exponent = int(std::floor(std::log10(size)));
  if (exponent >= -3 && exponent < 5) {
    // three significant digits in fixed notation: 0.00123, 0.534, 26.7, 3554
    QString text = QString::number(t, 'f', std::max(0, 2 - exponent));
    // "26.70" -> "26.7", "5.00" -> "5"
    if (text.contains(QLatin1Char('.'))) {
      while (text.endsWith(QLatin1Char('0'))) text.chop(1);
      if (text.endsWith(QLatin1Char('.'))) text.chop(1);
    }
    return text;
  }
  static const QString superscripts = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
  QString power = exponent < 0 ? QStringLiteral("⁻") : QString();
  for (QChar digit : QString::number(std::abs(exponent))) power += superscripts[digit.digitValue()];
  return QStringLiteral("%1×10%2").arg(QString::number(t / std::pow(10.0, exponent), 'g', 2), power);
}

QString runAxisTitle(const QString& axis, std::optional<std::pair<double, double>> shown, double sampledTo,
                     double runEnd) {
  const bool cut = runEnd > sampledTo * (1 + 1e-9) + 1e-12;
  if (!shown) {
    return cut ? QObject::tr("%1 (sampled to %2 of the run's %3)").arg(axis, timeText(sampledTo), timeText(runEnd))
               : axis;
  }
  // every number a time, the same as W's: what is shown, of what was sampled, of the run
  // (short: a longer title wrapped to three lines and was cut; W is in the tooltip and menu)
  const QString window = QStringLiteral("%1–%2").arg(timeText(shown->first), timeText(shown->second));
  // of the samples when they stop before the run and the window shows a part of them; else of
  // the run (a chain's first periods: all that was sampled, of how long a run)
  const bool ofSamples = cut && shown->second < sampledTo * (1 - 1e-9);
  return ofSamples ? QObject::tr("%1 (%2 of %3 sampled)").arg(axis, window, timeText(sampledTo))
                   : QObject::tr("%1 (%2 of %3)").arg(axis, window, timeText(runEnd));
}

}  // namespace grazelab::ui
