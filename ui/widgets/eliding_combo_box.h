// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QComboBox>

namespace grazelab::ui {

/// A combo box that shows its current text elided with "…" where it is too narrow, and the
/// whole text over its own tooltip when it is. Qt's clipped the text at the arrow:
/// "Moreau–Jean, θ = 1/2" read "Moreau–Jean, θ = 1", the name of another method.
class ElidingComboBox : public QComboBox {
  Q_OBJECT

 public:
  explicit ElidingComboBox(QWidget* parent = nullptr);

 protected:
  void paintEvent(QPaintEvent* event) override;
  bool event(QEvent* event) override;

 private:
  bool m_elided = false;  ///< the text last painted was cut
};

}  // namespace grazelab::ui
