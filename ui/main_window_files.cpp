// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The file side of MainWindow: snapshots, CSV, sessions, clipboard. Every write goes through
// QSaveFile (ui/export.h); a failure is shown and leaves the old file and the session intact.
#include <QApplication>
#include <QClipboard>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QMimeData>

#include "ui/export.h"
#include "ui/main_window.h"
#include "ui/plots/plot_view.h"

namespace grazelab::ui {

bool MainWindow::writeSnapshot(QWidget* widget, const QString& path, QString* error) {
  const QByteArray json = sessionToJson(displayedSession());
  // the picture first: a session file beside a missing picture would only confuse
  if (!saveSnapshot(widget, path, json, error)) return false;
  return saveFileAtomically(sessionPathFor(path), json, error);
}

bool MainWindow::saveWindowSnapshot(const QString& path, QString* error) {
  return writeSnapshot(this, path, error);
}

bool MainWindow::savePlotSnapshot(const QString& path, QString* error) {
  if (!m_currentPlot) {
    if (error) *error = tr("there is no plot to save");
    return false;
  }
  return writeSnapshot(m_currentPlot, path, error);
}

QString MainWindow::plottedDataCsv() const {
  QString csv = QStringLiteral("plot,series,x,y\n");
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

QString MainWindow::askSavePath(const QString& title, const QString& filters, const QString& suffix) {
  QString selected;
  QString path = QFileDialog::getSaveFileName(this, title, m_lastDirectory, filters, &selected);
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
      tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"), QStringLiteral(".png"));
  QString error;
  if (!path.isEmpty() && !saveWindowSnapshot(path, &error)) reportFailure(tr("Saving the snapshot"), error);
}

void MainWindow::savePlotSnapshotInteractive() {
  const QString path = askSavePath(
      tr("Save current plot"), tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"),
      QStringLiteral(".png"));
  QString error;
  if (!path.isEmpty() && !savePlotSnapshot(path, &error)) reportFailure(tr("Saving the plot"), error);
}

void MainWindow::exportCsvInteractive() {
  const QString path =
      askSavePath(tr("Export plotted data"), tr("CSV table (*.csv)"), QStringLiteral(".csv"));
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
                                   QStringLiteral(".json"));
  QString error;
  if (!path.isEmpty() && !saveSession(path, &error)) reportFailure(tr("Saving the session"), error);
}

void MainWindow::openSessionInteractive() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Open session"), m_lastDirectory,
                                                    tr("GrazeLab session (*.json)"));
  if (path.isEmpty()) return;
  m_lastDirectory = QFileInfo(path).absolutePath();
  QString error;
  if (!openSession(path, &error)) reportFailure(tr("Opening the session"), error, FileAction::Read);
}

}  // namespace grazelab::ui
