// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The file side of MainWindow: snapshots, CSV, sessions, clipboard. Every write goes through
// QSaveFile (ui/export.h); a failure is shown and leaves the old file and the session intact.
#include <QApplication>
#include <QClipboard>
#include <QFileDialog>
#include <QDir>
#include <QFileInfo>
#include <QInputDialog>
#include <QJsonDocument>
#include <QScopeGuard>
#include <QStandardPaths>
#include <QMessageBox>
#include <QMimeData>

#include "ui/export.h"
#include "ui/main_window.h"
#include "ui/number_box.h"
#include "ui/plots/plot_view.h"
#include "ui/plots/scene_view.h"
#include "ui/scene.h"

namespace grazelab::ui {

bool MainWindow::writeSnapshot(QWidget* widget, const QString& path, QString* error) {
  const Session shown = displayedSession();
  const QByteArray json = sessionToJson(shown);
  // the picture shows the run of its session, which is valid: no "stale" banner in it
  QList<PlotView*> stale;
  for (PlotView* plot : m_plots) {
    if (plot->isStale()) stale.append(plot);
  }
  for (PlotView* plot : stale) plot->setStale(false);
  const auto restore = qScopeGuard([&stale] {
    for (PlotView* plot : stale) plot->setStale(true);
  });
  // the picture first: a session file beside a missing picture would only confuse
  if (!saveSnapshot(widget, path, json, sessionTitle(shown), error)) return false;
  return saveFileAtomically(sessionPathFor(path), json, error);
}

bool MainWindow::saveWindowSnapshot(const QString& path, QString* error) {
  return writeSnapshot(this, path, error);
}

bool MainWindow::savePlotSnapshot(const QString& path, QString* error, QSize size) {
  if (!m_currentPlot) {
    if (error) *error = tr("there is no plot to save");
    return false;
  }
  if (!size.isValid() || size == m_currentPlot->size() || !m_displayed) {
    return writeSnapshot(m_currentPlot, path, error);
  }
  // at another size: the same view made again off screen, laid out for that size (its text
  // keeps its size; a scaled picture would only enlarge it)
  const qsizetype index = m_plots.indexOf(m_currentPlot);
  PlotKind kind = PlotKind::TraceU2;
  for (int i = 0, seen = 0; i < int(scene().plots().size()); ++i) {
    SceneView* view = m_sceneViews.value(i);
    if (!view || !qobject_cast<PlotView*>(view->widget())) continue;
    if (seen++ == index) kind = scene().plots()[i];
  }
  std::unique_ptr<SceneView> copy(makeView(kind));
  QWidget* widget = copy->widget();
  widget->setAttribute(Qt::WA_DontShowOnScreen);
  widget->resize(size);
  widget->show();
  copy->setPresentation(m_presentation, m_presentationText);
  copy->setWholeRun(m_wholeRunAction->isChecked());
  copy->show(*m_displayed);
  if (auto* plot = qobject_cast<PlotView*>(widget)) plot->refreshNow();
  return writeSnapshot(widget, path, error);
}

QString MainWindow::plottedDataCsv() const {
  // the parameters first, as comments (pandas: comment="#"; R: comment.char = "#")
  const Session shown = displayedSession();
  QString csv = QStringLiteral("# %1\n# session: %2\nplot,series,x,y\n")
                    .arg(sessionTitle(shown),
                         QString::fromUtf8(QJsonDocument::fromJson(sessionToJson(shown))
                                               .toJson(QJsonDocument::Compact)));
  for (const PlotView* plot : m_plots) plot->appendCsv(csv);
  return csv;
}

bool MainWindow::exportCsv(const QString& path, QString* error) {
  if (!saveFileAtomically(path, plottedDataCsv().toUtf8(), error)) return false;
  return saveFileAtomically(sessionPathFor(path), sessionToJson(displayedSession()), error);
}

Session MainWindow::displayedSession() const {
  // a picture or its data carry the parameters of the run they show, which differ from the
  // panel's while a new value computes or after an infeasible one
  if (m_displayed) return {m_displayed->request->sceneName, m_displayed->request->params};
  return session();
}

bool MainWindow::saveSession(const QString& path, QString* error) {
  return saveFileAtomically(path, sessionToJson(session()), error);
}

bool MainWindow::openSession(const QString& path, QString* error) {
  const auto loaded = readSessionFile(path, Params{}, error);
  return loaded && applySession(*loaded, error);
}

void MainWindow::reportFailure(const QString& what, const QString& error, FileAction action) {
  const QString consequence =
      action == FileAction::Write
          ? tr("The window keeps its state; a file that could not be written was left as it was.")
          : tr("The window keeps its state: nothing was changed.");
  QMessageBox::warning(this, what, tr("%1 failed:\n%2\n\n%3").arg(what, error, consequence));
}

QString MainWindow::saveDirectory() const {
  // a directory that cannot be written is not offered again (the dialog hung listing /proc)
  for (const QString& candidate :
       {m_lastDirectory, QStandardPaths::writableLocation(QStandardPaths::PicturesLocation),
        QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation), QDir::homePath(),
        QDir::currentPath()}) {
    const QFileInfo info(candidate);
    if (!candidate.isEmpty() && info.isDir() && info.isWritable() &&
        !info.absoluteFilePath().startsWith(QStringLiteral("/proc")) &&
        !info.absoluteFilePath().startsWith(QStringLiteral("/sys"))) {
      return info.absoluteFilePath();
    }
  }
  return QDir::tempPath();
}

QString MainWindow::suggestedFileName(const QString& what, const QString& suffix) const {
  // "grazing-lambda0.5-window.png": the scene, its main value and what was saved
  const Params& shown = displayedSession().params;
  const QString value = scene().parameters().contains(ParamKey::Lambda)
                            ? QStringLiteral("-lambda%1").arg(shortestText(shown.lambda))
                            : QString();
  return QStringLiteral("%1%2-%3%4").arg(scene().alias(), value, what, suffix);
}

QString MainWindow::askSavePath(const QString& title, const QString& filters, const QString& suffix,
                                const QString& what) {
  QString selected;
  const QString start = QDir(saveDirectory()).filePath(suggestedFileName(what, suffix));
  QString path = QFileDialog::getSaveFileName(this, title, start, filters, &selected);
  if (path.isEmpty()) return {};
  if (QFileInfo(path).suffix().isEmpty()) {
    // take the suffix from the chosen filter, "PNG image (*.png)" -> ".png"
    const qsizetype star = selected.indexOf(QStringLiteral("*."));
    path += star >= 0 ? selected.mid(star + 1).chopped(1) : suffix;
  }
  m_lastDirectory = QFileInfo(path).absolutePath();
  return path;
}

void MainWindow::saveWindowSnapshotInteractive() {
  const QString path = askSavePath(
      tr("Save snapshot of the window"),
      tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"), QStringLiteral(".png"),
      QStringLiteral("window"));
  QString error;
  if (!path.isEmpty() && !saveWindowSnapshot(path, &error)) reportFailure(tr("Saving the snapshot"), error);
}

void MainWindow::savePlotSnapshotInteractive() {
  if (!m_currentPlot) return;
  // the size first: a figure for a paper or slides has its own
  const QSize onScreen = m_currentPlot->size();
  const QList<QSize> sizes{onScreen, {800, 600}, {1200, 900}, {1600, 1000}, {1920, 1080}};
  QStringList items;
  for (const QSize& size : sizes) {
    items << (size == onScreen ? tr("%1 × %2 (as on screen)") : QStringLiteral("%1 × %2"))
                 .arg(size.width())
                 .arg(size.height());
  }
  bool chosen = false;
  const QString item = QInputDialog::getItem(this, tr("Save current plot"),
                                             tr("Size (pixels; PNG pictures are twice as dense):"),
                                             items, 0, false, &chosen);
  if (!chosen) return;
  const QSize size = sizes.value(items.indexOf(item), onScreen);
  const QString path = askSavePath(
      tr("Save current plot"), tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"),
      QStringLiteral(".png"), QStringLiteral("plot"));
  QString error;
  if (!path.isEmpty() && !savePlotSnapshot(path, &error, size)) reportFailure(tr("Saving the plot"), error);
}

void MainWindow::exportCsvInteractive() {
  const QString path =
      askSavePath(tr("Export plotted data"), tr("CSV table (*.csv)"), QStringLiteral(".csv"),
                  QStringLiteral("data"));
  QString error;
  if (!path.isEmpty() && !exportCsv(path, &error)) reportFailure(tr("Exporting CSV"), error);
}

void MainWindow::copyCurrentPlot() {
  if (!m_currentPlot) return;
  auto* data = new QMimeData;
  data->setImageData(renderImage(m_currentPlot));
  QString csv = QStringLiteral("plot,series,x,y\n");
  m_currentPlot->appendCsv(csv);
  data->setText(csv);
  QApplication::clipboard()->setMimeData(data);
}

void MainWindow::saveSessionInteractive() {
  const QString path = askSavePath(tr("Save session"), tr("GrazeLab session (*.json)"),
                                   QStringLiteral(".json"), QStringLiteral("session"));
  QString error;
  if (!path.isEmpty() && !saveSession(path, &error)) reportFailure(tr("Saving the session"), error);
}

void MainWindow::openSessionInteractive() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Open session"), saveDirectory(),
                                                    tr("GrazeLab session (*.json)"));
  if (path.isEmpty()) return;
  m_lastDirectory = QFileInfo(path).absolutePath();
  QString error;
  if (!openSession(path, &error)) reportFailure(tr("Opening the session"), error, FileAction::Read);
}

}  // namespace grazelab::ui
