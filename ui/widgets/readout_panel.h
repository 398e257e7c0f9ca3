// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QWidget>

class QLabel;

namespace grazelab::ui {

struct DerivedModel;

/// Read-only derived quantities: k2, w1 (fast), w2 (slow), T1, T2, lambda*, energy.
class ReadoutPanel : public QWidget {
  Q_OBJECT

 public:
  explicit ReadoutPanel(QWidget* parent = nullptr);

  /// Shows the quantities of a valid chain; energy is that of the start state.
  void showModel(const DerivedModel& derived, double energy);
  /// Keeps the last values but greys them out (the current inputs admit no chain).
  void setStale(bool stale);
  /// The displayed text of one quantity ("k2", "omega1", ...), for tests.
  QString text(const QString& name) const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void fixValueSizes();

  QLabel* addRow(const QString& name, const QString& label, const QString& toolTip);

  QList<QLabel*> m_values;
};

}  // namespace grazelab::ui
