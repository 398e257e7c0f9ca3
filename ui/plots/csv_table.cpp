// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/csv_table.h"

namespace grazelab::ui {
namespace {

QString quoted(QString text) {
  text.replace(QLatin1Char('"'), QStringLiteral("\"\""));
  return QLatin1Char('"') + text + QLatin1Char('"');
}

// 17 significant digits: a double read back is the double written
QString number(double value) { return QString::number(value, 'g', 17); }

}  // namespace

void CsvTable::describe(const QString& plot, const QString& x, const QString& y, const QString& value) {
  QString line = QStringLiteral("%1: x = %2; y = %3").arg(quoted(plot), x, y);
  if (!value.isEmpty()) line += QStringLiteral("; value = %1").arg(value);
  m_meanings.append(line);
}

void CsvTable::add(const QString& plot, const QString& series, double x, double y, std::optional<double> value) {
  m_rows += quoted(plot) + QLatin1Char(',') + quoted(series) + QLatin1Char(',') + number(x) + QLatin1Char(',') +
            number(y) + QLatin1Char(',') + (value ? number(*value) : QString()) + QLatin1Char('\n');
}

QString CsvTable::text(const QStringList& header) const {
  QString csv;
  for (const QString& line : header) csv += QStringLiteral("# ") + line + QLatin1Char('\n');
  csv += QStringLiteral("# columns: plot, series, x, y, value; in each plot:\n");
  for (const QString& line : m_meanings) csv += QStringLiteral("#   ") + line + QLatin1Char('\n');
  csv += QStringLiteral("plot,series,x,y,value\n");
  return csv + m_rows;
}

}  // namespace grazelab::ui
