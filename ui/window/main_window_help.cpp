// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The Help menu: what the program is (with its version), every shortcut, and the guide of the
// scene on screen.
#include <QAction>
#include <QApplication>
#include <QMenuBar>
#include <QMessageBox>

#include "ui/window/main_window.h"
#include "ui/compute/scene.h"

namespace grazelab::ui {

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

void MainWindow::showShortcuts() {
  QMessageBox box(this);
  box.setWindowTitle(tr("Keyboard shortcuts"));
  box.setTextFormat(Qt::RichText);
  box.setText(shortcutsText());
  box.exec();
}

void MainWindow::showSceneGuide() {
  QMessageBox box(this);
  box.setWindowTitle(scene().title());
  box.setTextFormat(Qt::RichText);
  box.setText(QStringLiteral("<h3>%1</h3><p>%2</p><p>%3</p>")
                  .arg(scene().title(), scene().description(),
                       tr("A click on the Poincaré points (H), on the stop line of mass 2's portrait, on "
                          "the Landscape map or on the modes picture starts a run from there (the panel "
                          "says so; any edit goes back to the scene's start). Ctrl+Shift+R puts every "
                          "value of this scene back; W shows the whole run in u₂(t) and the phase "
                          "portraits; F1 shows this guide, Ctrl+F1 every key.")));
  box.exec();
}

}  // namespace grazelab::ui
