// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QObject>
#include <QPointer>

class QScrollArea;

namespace grazelab::ui {

/// The mouse wheel over the parameter panel scrolls the panel: its sliders, number boxes and
/// lists take the wheel only when they have the focus (clicked or tabbed to). Scrolling down a
/// long panel in front of a class changed k6 and re-ran; a value now changes only when asked.
/// Installed on the application (the panel's rows are made and remade as chains change), it
/// acts on the controls inside `area` only.
class WheelScrollsPanel final : public QObject {
 public:
  explicit WheelScrollsPanel(QScrollArea* area);
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  QPointer<QScrollArea> m_area;
};

}  // namespace grazelab::ui
