// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/window/wrapped_tooltips.h"

#include <QApplication>
#include <QHelpEvent>
#include <QTextDocument>
#include <QToolTip>
#include <QWidget>

namespace grazelab::ui {
namespace {

class ToolTipWrapper : public QObject {
 public:
  using QObject::QObject;

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() != QEvent::ToolTip) return false;
    auto* widget = qobject_cast<QWidget*>(watched);
    if (widget == nullptr) return false;
    const QString text = widget->toolTip();
    // empty: Qt asks the parent next; rich text already wraps
    if (text.isEmpty() || Qt::mightBeRichText(text)) return false;
    // rich text wraps at a readable width; the line breaks the text has are kept
    QString html = text.toHtmlEscaped();
    html.replace('\n', QStringLiteral("<br>"));
    QToolTip::showText(static_cast<QHelpEvent*>(event)->globalPos(),
                       QStringLiteral("<p>%1</p>").arg(html), widget);
    return true;
  }
};

}  // namespace

void wrapToolTips() {
  if (qApp == nullptr || qApp->findChild<ToolTipWrapper*>(QStringLiteral("grazelabToolTips"))) {
    return;
  }
  auto* wrapper = new ToolTipWrapper(qApp);
  wrapper->setObjectName(QStringLiteral("grazelabToolTips"));
  qApp->installEventFilter(wrapper);
}

}  // namespace grazelab::ui
