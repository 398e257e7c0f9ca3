// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QList>
#include <QPointer>

class QLayout;
class QWidget;

namespace grazelab::ui {

/// Holds the layouts of `widget` and of its ancestors off while a batch of widgets inside it is
/// shown, and lays them out once when it goes.
///
/// Showing a widget lays out every visible ancestor at once (QWidgetPrivate::setVisible
/// activates their layouts before it returns): a scene switch that shows eight controls laid out
/// the whole side panel eight times, word-wrapped labels and all, and stalled the window for
/// 4–8 ms. A disabled layout skips that; the one layout pass happens when this object goes.
class BatchedLayout {
 public:
  explicit BatchedLayout(QWidget* widget);
  ~BatchedLayout();
  BatchedLayout(const BatchedLayout&) = delete;
  BatchedLayout& operator=(const BatchedLayout&) = delete;

 private:
  QList<QPointer<QLayout>> m_held;  ///< innermost first; only those that were enabled
};

}  // namespace grazelab::ui
