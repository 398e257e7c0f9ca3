// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/window/status_line.h"

#include <QEvent>
#include <QFontMetrics>

namespace grazelab::ui {
namespace {

const QString kSeparator = QStringLiteral(" · ");

}  // namespace

StatusLine::StatusLine(QWidget* parent) : QLabel(parent) {
  setWordWrap(true);
  setTextFormat(Qt::PlainText);
  // its width is the window's, not its text's (a long message must not widen the window)
  setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
  fit();
}

void StatusLine::setMessage(const QString& message) {
  m_message = message;
  fit();
}

void StatusLine::setExplanation(const QString& explanation) {
  m_explanation = explanation;
  fit();
}

void StatusLine::resizeEvent(QResizeEvent* event) {
  QLabel::resizeEvent(event);
  fit();
}

void StatusLine::changeEvent(QEvent* event) {
  QLabel::changeEvent(event);
  if (event->type() == QEvent::FontChange) fit();
}

void StatusLine::fit() {
  const QFontMetrics metrics(font());
  // two lines as the text engine lays them out (a little more than twice a line)
  const int height = metrics.boundingRect(QRect(0, 0, 1000, 1000), Qt::TextWordWrap, QStringLiteral("X\nX")).height() + 2;
  if (minimumHeight() != height || maximumHeight() != height) setFixedHeight(height);
  const int width = std::max(1, contentsRect().width());
  const auto fits = [&](const QString& text) {
    return metrics.boundingRect(QRect(0, 0, width, 100 * height), Qt::TextWordWrap, text).height() <=
           height - 2;
  };
  QString shown = m_message;
  if (!fits(shown)) {
    // whole parts from the end, so that what remains reads as it was
    QStringList parts = m_message.split(kSeparator);
    while (parts.size() > 1) {
      parts.removeLast();
      shown = parts.join(kSeparator) + kSeparator + QStringLiteral("…");
      if (fits(shown)) break;
    }
  }
  if (text() != shown) setText(shown);
  QString tip = m_explanation;
  if (shown != m_message) tip = m_message + QStringLiteral("\n\n") + tip;
  if (toolTip() != tip) setToolTip(tip);
}

}  // namespace grazelab::ui
