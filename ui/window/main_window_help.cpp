// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The Help menu: what the program is (with its version), every shortcut, and the guide of the
// scene on screen.
#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>

#include "ui/window/main_window.h"
#include "ui/compute/scene.h"

namespace grazelab::ui {
namespace {

// rich text in a dialog that fits the screen, and scrolls where the text is taller (the list of
// shortcuts was 1038 px tall in a message box on a 720-line screen, its Close button off it)
void showText(QWidget* parent, const QString& title, const QString& html) {
  QDialog dialog(parent);
  dialog.setObjectName(QStringLiteral("helpText"));
  dialog.setWindowTitle(title);
  auto* text = new QTextBrowser(&dialog);
  text->setHtml(html);
  text->setFrameShape(QFrame::NoFrame);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, &dialog);
  QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  auto* layout = new QVBoxLayout(&dialog);
  layout->addWidget(text);
  layout->addWidget(buttons);
  const QScreen* screen = parent->screen();
  const QRect room = screen ? screen->availableGeometry() : QRect(0, 0, 1280, 720);
  const int width = std::min(int(room.width() * 0.9), 60 * dialog.fontMetrics().averageCharWidth() + 200);
  text->document()->setTextWidth(width - 40);
  const int height = int(text->document()->size().height()) + buttons->sizeHint().height() + 60;
  dialog.resize(width, std::min(height, int(room.height() * 0.85)));
  dialog.exec();
}

}  // namespace

void MainWindow::showAbout() {
  QMessageBox::about(
      this, tr("About GrazeLab"),
      tr("<p><b>GrazeLab %1</b> explores a two-mass chain against a rigid stop in 1:2 internal "
         "resonance: exact free flight between contacts, elastic impacts, grazing and "
         "sticking.</p><p><b>Mode 1 is the fast mode, mode 2 the slow one</b> (ω₁ = 2 ω₂, so "
         "T₂ = 2 T₁): the proofs of the underlying note need this labelling, and every free "
         "motion of the chain repeats after T₂.</p><p>Help ▸ Keyboard shortcuts lists every "
         "key; F1 explains the scene on screen.</p>")
          .arg(QApplication::applicationVersion()));
}

QString MainWindow::shortcutsText() const {
  // every menu action with a key, as the menus name it, then what the plots and the animation
  // take directly
  QList<std::pair<QString, QString>> rows;
  for (QAction* menu : menuBar()->actions()) {
    if (!menu->menu()) continue;
    for (QAction* action : menu->menu()->actions()) {
      if (action->shortcuts().isEmpty()) continue;
      QStringList keys;
      for (const QKeySequence& key : action->shortcuts()) keys << key.toString(QKeySequence::NativeText);
      rows.append({keys.join(QStringLiteral(", ")), action->text().remove(QLatin1Char('&'))});
    }
  }
  const std::pair<QString, QString> direct[] = {
      {tr("drag"), tr("zoom a plot to the rectangle")},
      {tr("Shift+drag, middle button"), tr("pan a plot")},
      {tr("wheel"), tr("zoom a plot at the pointer")},
      {tr("double-click"), tr("enlarge a plot (again: put it back); it starts no run")},
      {tr("click"), tr("on the Poincaré points (H), the stop line of mass 2's portrait, the Landscape "
                       "map or the modes picture: start a run there")},
      {tr("Esc"), tr("leave presentation mode")},
      {tr("[ and ]"), tr("previous / next contact in the animation")},
      {tr("Enter"), tr("take a typed value (a value that cannot be used is refused, and says why)")},
  };
  for (const auto& row : direct) rows.append(row);
  // two pairs of columns: one long column was taller than a 720-pixel screen
  const qsizetype half = (rows.size() + 1) / 2;
  QString table;
  for (qsizetype i = 0; i < half; ++i) {
    const auto cell = [&](qsizetype j) {
      return j < rows.size() ? QStringLiteral("<td><b>%1</b></td><td>%2</td>").arg(rows[j].first, rows[j].second)
                             : QStringLiteral("<td></td><td></td>");
    };
    table += QStringLiteral("<tr>%1<td width=\"24\"></td>%2</tr>").arg(cell(i), cell(i + half));
  }
  return QStringLiteral("<table cellspacing=\"4\">%1</table>").arg(table);
}

void MainWindow::showShortcuts() { showText(this, tr("Keyboard shortcuts"), shortcutsText()); }

void MainWindow::showSceneGuide() {
  // what the mouse and W do, in this scene's own words (the two-mass text named mass 2's
  // portrait and u2(t) in scenes of N masses)
  const QString mouse =
      scene().massChain()
          ? tr("A click on the Poincaré points (H) or on the stop line of the stopped mass's portrait "
               "starts a run from there (the panel says so; any edit goes back to the scene's "
               "start). Ctrl+Shift+R puts every value of this scene back; W computes and shows the "
               "whole run in the trace, the portrait and the animation (else its first four slowest "
               "periods); F1 shows this guide, Ctrl+F1 every key.")
          : tr("A click on the Poincaré points (H), on the stop line of mass 2's portrait, on "
               "the Landscape map or on the modes picture starts a run from there (the panel "
               "says so; any edit goes back to the scene's start). Ctrl+Shift+R puts every "
               "value of this scene back; W shows the whole run in u₂(t) and the phase "
               "portraits; F1 shows this guide, Ctrl+F1 every key.");
  showText(this, scene().title(),
           QStringLiteral("<h3>%1</h3><p>%2</p><p>%3</p>").arg(scene().title(), scene().description(), mouse));
}

}  // namespace grazelab::ui
