// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/window/headless.h"

#include <QCoreApplication>

#include <algorithm>

#include "ui/window/main_window.h"
#include "ui/plots/plot_view.h"
#include "ui/compute/scene.h"

namespace grazelab::ui {

QStringList sceneNames() {
  QStringList names;
  for (const auto& scene : makeScenes()) names.append(scene->alias());
  return names;
}

QStringList sceneList() {
  // "id  title": the id --scene takes, the title as the Scenes menu shows it (with its key)
  QStringList lines;
  int index = 0;
  int width = 0;
  const auto scenes = makeScenes();
  for (const auto& scene : scenes) width = std::max(width, int(scene->alias().size()));
  for (const auto& scene : scenes) {
    ++index;
    const QString key = sceneShortcut(index - 1);
    lines.append(QStringLiteral("%1  %2  %3").arg(scene->alias(), -width).arg(key, -6).arg(scene->title()));
  }
  return lines;
}

bool renderSceneSnapshot(const QString& sceneName, const QString& sessionPath,
                         const QString& outputPath, QSize size, QString* error,
                         bool presentation) {
  MainWindow window({.synchronous = true, .useSettings = false});
  Session session = window.session();
  if (!sessionPath.isEmpty()) {
    const auto loaded = readSessionFile(sessionPath, Params{}, error);
    if (!loaded) return false;
    session = *loaded;
  }
  if (!sceneName.isEmpty()) {
    const int index = findScene(window.scenes(), sceneName);
    if (index < 0) {
      if (error) {
        *error = QStringLiteral("unknown scene \"%1\"; known scenes: %2")
                     .arg(sceneName, sceneNames().join(QStringLiteral(", ")));
      }
      return false;
    }
    session.scene = window.scenes()[std::size_t(index)]->name();
    if (sessionPath.isEmpty()) session.params = window.scenes()[std::size_t(index)]->defaults();
  }
  if (!window.applySession(session, error)) return false;
  if (!window.problem().isEmpty()) {
    if (error) *error = window.problem();
    return false;
  }

  // lay the window out at its final size without mapping it, then let the plots re-decimate
  window.setAttribute(Qt::WA_DontShowOnScreen);
  // the picture stands for a projected screen of its own height; the look first, then the
  // size (larger text on the old size would widen the window past the size asked)
  if (presentation) window.setPresentation(true, size.height(), false);
  window.resize(size);
  // and the panel's share again, now of the final width
  if (presentation) window.setPresentation(true, size.height(), false);
  window.show();
  QCoreApplication::processEvents();
  for (PlotView* plot : window.plots()) plot->refreshNow();
  QCoreApplication::processEvents();
  return window.saveWindowSnapshot(outputPath, error);
}

}  // namespace grazelab::ui
