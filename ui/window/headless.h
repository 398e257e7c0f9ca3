// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QSize>
#include <QString>
#include <QStringList>

namespace grazelab::ui {

/// The English scene names, in menu order (for --list-scenes).
QStringList sceneNames();
/// One line per scene, in menu order: the id `--scene` accepts, its menu shortcut and its title
/// as the Scenes menu shows it.
QStringList sceneList();

/// Renders a scene into a picture without a display: builds the window off screen, computes
/// synchronously, writes `outputPath` (.png, .svg or .pdf) and its session file beside it.
/// `sceneName` may be empty when a session file names the scene; when both are given the
/// session's parameters are used with the named scene. Returns false and a reason on failure.
bool renderSceneSnapshot(const QString& sceneName, const QString& sessionPath,
                         const QString& outputPath, QSize size, QString* error,
                         bool presentation = false);

}  // namespace grazelab::ui
