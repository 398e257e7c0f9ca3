// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The window in front of a class: presentation mode (large text, scaled controls, a white
// page, full screen), one plot enlarged, the panel hidden, scenes stepped with a clicker.
#include <QApplication>
#include <QFontInfo>
#include <QScreen>
#include <QSplitter>

#include <algorithm>

#include "ui/window/main_window.h"
#include "ui/plots/scene_view.h"
#include "ui/window/presentation_style.h"

namespace grazelab::ui {

void MainWindow::toggleEnlarged(QWidget* view) {
  m_enlarged = m_enlarged == view ? nullptr : view;
  layoutViews();
}

void MainWindow::stepScene(int step) {
  const int count = int(m_scenes.size());
  selectScene(((m_sceneIndex + step) % count + count) % count);
}

void MainWindow::setPanelVisible(bool visible) {
  m_side->setVisible(visible);
  if (m_panelAction) m_panelAction->setChecked(visible);
}

void MainWindow::setPresentation(bool on, int screenHeight, bool fullScreen) {
  if (on && !m_presentation) {
    m_deskFont = QApplication::font();
    m_deskPalette = QApplication::palette();
  }
  m_presentation = on;
  m_presentationText = std::max(12, (screenHeight + 49) / 50);  // at least 1/50 of the height
  if (m_presentationAction) m_presentationAction->setChecked(on);
  // the controls grow with the text: the style's scale, read again when the font change below
  // lays every widget out anew (replacing the application's style at run time instead broke
  // the style sheets' hold on it: a heap corruption)
  if (auto* scaled = qobject_cast<PresentationStyle*>(QApplication::style())) {
    const double scale = double(m_presentationText) / std::max(1, QFontInfo(m_deskFont).pixelSize());
    scaled->setScale(on ? std::max(1.0, scale) : 1.0);
  }
  if (on) {
    QFont font = m_deskFont;
    font.setPixelSize(m_presentationText);
    QApplication::setFont(font);
    // a white page with black text: the projector profile
    QPalette palette = m_deskPalette;
    palette.setColor(QPalette::Window, Qt::white);
    palette.setColor(QPalette::Base, Qt::white);
    palette.setColor(QPalette::WindowText, Qt::black);
    palette.setColor(QPalette::Text, Qt::black);
    QApplication::setPalette(palette);
  } else if (m_deskFont != QFont()) {
    QApplication::setFont(m_deskFont);
    QApplication::setPalette(m_deskPalette);
  }
  if (!on && m_viewsBuiltPresenting) {
    // made under the large font, their desk look would keep it: made again at the desk's,
    // showing what they showed
    // (made one per turn outside headless mode: the last one made draws the run again)
    buildPlots();
    if (m_displayed && viewsBuilt()) {
      for (SceneView* view : m_sceneViews) view->show(*m_displayed);
    }
  }
  for (SceneView* view : m_sceneViews) view->setPresentation(on, m_presentationText);
  if (fullScreen) {
    if (on) {
      m_deskGeometry = geometry();
      showFullScreen();
      // without a window manager (a bare X server, a kiosk) full screen is only a wish: the
      // window takes the screen's size itself
      if (const QScreen* screen = this->screen()) setGeometry(screen->geometry());
    } else {
      showNormal();
      if (m_deskGeometry.isValid()) setGeometry(m_deskGeometry);
    }
  }
  // the larger text needs a wider panel: about 24 characters' worth, at most 40 % of the window
  if (auto* splitter = qobject_cast<QSplitter*>(centralWidget())) {
    const int side = on ? std::max(320, std::min(24 * m_presentationText, width() * 2 / 5)) : 400;
    splitter->setSizes({side, std::max(1, width() - side)});
  }
}

}  // namespace grazelab::ui
