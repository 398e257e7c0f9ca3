// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/widgets/batched_layout.h"

#include <QLayout>
#include <QWidget>

namespace grazelab::ui {

BatchedLayout::BatchedLayout(QWidget* widget) {
  for (QWidget* at = widget; at; at = at->isWindow() ? nullptr : at->parentWidget()) {
    QLayout* layout = at->layout();
    if (!layout || !layout->isEnabled()) continue;
    layout->setEnabled(false);
    m_held.append(layout);
  }
}

BatchedLayout::~BatchedLayout() {
  for (const QPointer<QLayout>& layout : m_held) {
    if (!layout) continue;
    layout->setEnabled(true);
    // what changed inside while held is laid out now, innermost first, as a show would have
    layout->invalidate();
  }
  for (const QPointer<QLayout>& layout : m_held) {
    // as a show does: only on screen (a hidden window laid out now would grow to its layout's
    // minimum, past a small screen); the rest is laid out when shown
    if (layout && layout->parentWidget() && layout->parentWidget()->isVisible()) layout->activate();
  }
}

}  // namespace grazelab::ui
