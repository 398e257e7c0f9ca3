// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>
#include <QStringList>

#include <optional>

namespace grazelab::ui {

/// What the views of a scene show, as one CSV table (pandas: read_csv(path, comment="#")):
///   plot,series,x,y,value
/// one row per drawn point, map cell or measured setting; `value` is empty where a plot has
/// none. Each plot says once, in the file's header, what its x, y and value are, with units.
class CsvTable {
 public:
  /// What x, y and value mean in `plot` (value: empty when the plot has none).
  void describe(const QString& plot, const QString& x, const QString& y, const QString& value = {});
  void add(const QString& plot, const QString& series, double x, double y,
           std::optional<double> value = std::nullopt);
  /// The file: `header` as comment lines, the columns' meanings, the column names, the rows.
  QString text(const QStringList& header) const;
  bool empty() const { return m_rows.isEmpty(); }

 private:
  QStringList m_meanings;
  QString m_rows;
};

}  // namespace grazelab::ui
