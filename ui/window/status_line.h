// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QLabel>

namespace grazelab::ui {

/// The window's status line: at most two lines, wrapped between words. A message too long for
/// them loses whole " · " parts from its end (marked "…"), never part of a number: a number cut
/// at the window's edge or under the progress bar read as another number ("5.72e+09" as
/// "5.72"). The whole message is in the tooltip.
class StatusLine : public QLabel {
  Q_OBJECT

 public:
  explicit StatusLine(QWidget* parent = nullptr);

  void setMessage(const QString& message);
  QString message() const { return m_message; }
  /// What the status line explains whatever it shows (the first part of the tooltip).
  void setExplanation(const QString& explanation);

 protected:
  void resizeEvent(QResizeEvent* event) override;
  void changeEvent(QEvent* event) override;

 private:
  void fit();

  QString m_message;
  QString m_explanation;
};

}  // namespace grazelab::ui
