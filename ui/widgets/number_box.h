// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QDoubleSpinBox>

namespace grazelab::ui {

/// A spin box that takes a number as a scientist types it and never changes it silently: signs,
/// scientific notation ("-1e-5", "2.5E3") and as many digits as typed. The value is kept exactly
/// (no rounding to a number of decimals) and shown in the shortest text that reads back to the
/// same double. A text that is not a usable value (not a number, out of range, not whole where a
/// count is asked) is refused: refused() says why and the previous value stays.
/// Window shortcuts (Ctrl+letter, Space, PageUp/PageDown) keep working while it has focus.
class NumberBox : public QDoubleSpinBox {
  Q_OBJECT

 public:
  /// `name` is how refusals name the quantity ("m₂"); `whole` asks for whole numbers.
  NumberBox(QString name, double minimum, double maximum, bool whole, QWidget* parent = nullptr);

  QString textFromValue(double value) const override;
  double valueFromText(const QString& text) const override;
  QValidator::State validate(QString& text, int& position) const override;
  void fixup(QString& text) const override;

  /// Arrow keys and the wheel step to multiples rounded to this many decimals (0.1 + 0.2 would
  /// otherwise show as 0.30000000000000004).
  void setStepDecimals(int decimals) { m_stepDecimals = decimals; }
  void stepBy(int steps) override;

  /// Why `text` cannot be used, or an empty string when it can.
  QString refusal(const QString& text) const;

 signals:
  /// A finished edit was refused (and the previous value kept); `reason` is one sentence.
  void refused(const QString& reason) const;

 protected:
  bool event(QEvent* event) override;

 private:
  QString m_name;
  bool m_whole = false;
  int m_stepDecimals = 6;
};

/// The shortest decimal text that reads back to exactly `value` ("0.5625", "-3e-09", "60").
QString shortestText(double value);

/// Reads a number as typed: surrounding spaces, a Unicode minus sign and exponents allowed;
/// nothing when the whole text is not one number.
std::optional<double> readNumber(const QString& text);

}  // namespace grazelab::ui
