// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The file side of MainWindow: snapshots, CSV, sessions, clipboard. Every write goes through
// QSaveFile (ui/export.h); a failure is shown and leaves the old file and the session intact.
#include <utility>

#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFontInfo>
#include <QFormLayout>
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

#include "ui/window/export.h"
#include "ui/window/main_window.h"
#include "ui/widgets/number_box.h"
#include "ui/widgets/parameter_panel.h"
#include "ui/window/reproduce.h"
#include "ui/window/status_line.h"
#include "ui/plots/csv_table.h"
#include "ui/plots/plot_view.h"
#include "ui/plots/scene_view.h"
#include "ui/compute/scene.h"

namespace grazelab::ui {
namespace {

// "Poincaré points on H (u₂ = d)" -> "poincare-points-on-h": a file name part that any system
// and shell takes as it is
QString fileNamePart(const QString& title) {
  QString plain = title.normalized(QString::NormalizationForm_KD);  // é -> e + accent, ₂ -> 2
  plain.replace(QStringLiteral("λ"), QStringLiteral("lambda"));
  QString part;
  int words = 0;
  bool gap = false;
  for (const QChar c : plain) {
    if (c.isLetterOrNumber() && c.unicode() < 128) {
      if (gap && !part.isEmpty()) {
        // four words, and a number after them ("phase-portrait-of-mass-3": the mass was dropped)
        if (++words >= 4 && !c.isDigit()) break;
        part += QLatin1Char('-');
      }
      part += c.toLower();
      gap = false;
    } else if (!c.isMark()) {
      gap = true;
    }
  }
  return part.isEmpty() ? QStringLiteral("plot") : part;
}

}  // namespace

void MainWindow::withDisplayedRunInPanel(const std::function<void()>& draw) {
  if (!m_displayed) {
    draw();
    return;
  }
  const Session shown = displayedSession();
  const Params typed = m_panel->params();
  const QString panelMessage = m_panel->message();
  const QString statusMessage = m_status->message();
  m_panel->setParams(shown.params);
  m_panel->setMessage(QString());
  m_panel->setClickedStart(shown.start);
  // the status line says the run's own words: not a refusal of the panel's values, nor a note
  // left by the last save ("Saved the window to …" was drawn into the next picture)
  const QString problem = std::exchange(m_problem, QString());
  const QString dropped = std::exchange(m_droppedNote, QString());
  showStatus(*m_displayed);
  const auto restore = qScopeGuard([&] {
    m_problem = problem;
    m_droppedNote = dropped;
    m_panel->setParams(typed);
    m_panel->setMessage(panelMessage);
    m_panel->setClickedStart(m_clickedStart);
    m_status->setMessage(statusMessage);
  });
  draw();
}

bool MainWindow::writeSnapshot(QWidget* widget, const QString& path, QString* error, QRect area) {
  buildAllViews();  // a file right after a scene switch holds every view and the run
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
  bool saved = false;
  const auto save = [&] {
    saved = saveSnapshot(widget, path, json, sessionTitle(shown, scene().massChain()), error, area);
  };
  if (widget == this) withDisplayedRunInPanel(save);
  else save();
  return saved && saveFileAtomically(sessionPathFor(path), json, error);
}

bool MainWindow::saveWindowSnapshot(const QString& path, QString* error) {
  return writeSnapshot(this, path, error);
}

SceneView* MainWindow::currentView() const {
  for (SceneView* view : m_sceneViews) {
    if (view->widget() == m_currentPlot) return view;
  }
  return m_sceneViews.isEmpty() ? nullptr : m_sceneViews.first();
}

bool MainWindow::savePlotSnapshot(const QString& path, QString* error, QSize size, SceneView* view) {
  if (!view) view = currentView();
  const qsizetype index = m_sceneViews.indexOf(view);
  if (!view || index < 0) {
    if (error) *error = tr("there is no plot to save");
    return false;
  }
  if (!size.isValid() || size == view->widget()->size() || !m_displayed) {
    return writeSnapshot(view->widget(), path, error, view->pictureArea());
  }
  // at another size: the same view made again off screen, laid out for that size, its text
  // grown with the picture (a 1920 x 1080 figure with the desk's 13 px text reads as a stamp
  // on a slide; a scaled picture would blur instead)
  std::unique_ptr<SceneView> copy(makeView(scene().plots()[std::size_t(index)]));
  QWidget* widget = copy->widget();
  widget->setAttribute(Qt::WA_DontShowOnScreen);
  // the look first, then the size: the chart lays its titles, ticks and legend out for both
  const int deskText = QFontInfo(font()).pixelSize();
  const int textPixels = std::max({m_presentation ? m_presentationText : 0, deskText, size.height() / 40});
  copy->setPresentation(textPixels > deskText, textPixels);
  widget->resize(size);
  widget->show();
  copy->setWholeRun(m_wholeRunAction->isChecked());
  copy->show(*m_displayed);
  // the layout Qt does on its next turn of the event loop (the chart's items, the legend's
  // place under the axis), done now, and the data fitted to it
  QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
  if (auto* plot = qobject_cast<PlotView*>(widget)) {
    plot->refreshNow();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    plot->refreshNow();
  }
  return writeSnapshot(widget, path, error, copy->pictureArea());
}

QStringList MainWindow::csvHeader() const {
  // the parameters first, as comments (pandas: comment="#"; R: comment.char = "#"): in words,
  // as a session to open in the explorer, and as the command line that runs the same run
  const Session shown = displayedSession();
  QStringList header{sessionTitle(shown, scene().massChain()),
                     QStringLiteral("session: %1").arg(QString::fromUtf8(
                         QJsonDocument::fromJson(sessionToJson(shown)).toJson(QJsonDocument::Compact)))};
  if (m_displayed && (scene().massChain() || !m_displayed->request->job.spec.chains.empty())) {
    if (!m_displayed->chains.empty()) {
      header.append(QStringLiteral("the run again: %1").arg(chainSimulateCommand(*m_displayed->chains.front())));
    }
  } else if (m_displayed) {
    header.append(QStringLiteral("the run again: %1").arg(simulateCommand(m_displayed->request->job.spec)));
  }
  return header;
}

QString MainWindow::plottedDataCsv() const {
  CsvTable table;
  for (const SceneView* view : m_sceneViews) view->appendCsv(table);
  return table.text(csvHeader());
}

bool MainWindow::exportCsv(const QString& path, QString* error) {
  buildAllViews();
  if (!saveFileAtomically(path, plottedDataCsv().toUtf8(), error)) return false;
  return saveFileAtomically(sessionPathFor(path), sessionToJson(displayedSession()), error);
}

Session MainWindow::displayedSession() const {
  // a picture or its data carry the parameters of the run they show, which differ from the
  // panel's while a new value computes or after an infeasible one
  if (m_displayed) {
    return {m_displayed->request->sceneName, m_displayed->request->params, m_displayed->request->clickedStart};
  }
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
  if (path.isEmpty()) return;
  QString error;
  if (!saveWindowSnapshot(path, &error)) reportFailure(tr("Saving the snapshot"), error);
  else confirmSaved(tr("the window"), path);
}

void MainWindow::savePlotSnapshotInteractive() {
  if (m_sceneViews.isEmpty()) return;
  // which view (every one of the scene, the map and the animation too: a click on those starts
  // a run, so "the last clicked" cannot be how they are chosen) and the size: a figure for a
  // paper or slides has its own
  QDialog dialog(this);
  dialog.setWindowTitle(tr("Save a plot"));
  auto* form = new QFormLayout(&dialog);
  auto* which = new QComboBox(&dialog);
  for (SceneView* view : m_sceneViews) which->addItem(view->viewTitle());
  which->setCurrentIndex(int(std::max<qsizetype>(0, m_sceneViews.indexOf(currentView()))));
  auto* size = new QComboBox(&dialog);
  const QList<QSize> sizes{{800, 600}, {1200, 900}, {1600, 1000}, {1920, 1080}};
  const auto fillSizes = [&] {
    const QSize onScreen = m_sceneViews[which->currentIndex()]->widget()->size();
    size->clear();
    size->addItem(tr("%1 × %2 (as on screen)").arg(onScreen.width()).arg(onScreen.height()), onScreen);
    for (const QSize& s : sizes) size->addItem(tr("%1 × %2 (text grown with it)").arg(s.width()).arg(s.height()), s);
  };
  fillSizes();
  connect(which, &QComboBox::currentIndexChanged, &dialog, fillSizes);
  form->addRow(tr("&Plot:"), which);
  form->addRow(tr("&Size (pixels; PNG twice as dense):"), size);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  form->addRow(buttons);
  if (dialog.exec() != QDialog::Accepted) return;
  SceneView* view = m_sceneViews[which->currentIndex()];
  const QString path = askSavePath(tr("Save the plot “%1”").arg(view->viewTitle()),
                                   tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"),
                                   QStringLiteral(".png"), fileNamePart(view->viewTitle()));
  if (path.isEmpty()) return;
  QString error;
  if (!savePlotSnapshot(path, &error, size->currentData().toSize(), view)) {
    reportFailure(tr("Saving the plot"), error);
    return;
  }
  confirmSaved(tr("“%1”").arg(view->viewTitle()), path);
}

void MainWindow::confirmSaved(const QString& what, const QString& path) {
  m_status->setMessage(tr("Saved %1 to %2 (its session beside it: %3)")
                           .arg(what, QDir::toNativeSeparators(path), QFileInfo(sessionPathFor(path)).fileName()));
}

void MainWindow::exportCsvInteractive() {
  const QString path =
      askSavePath(tr("Export plotted data"), tr("CSV table (*.csv)"), QStringLiteral(".csv"),
                  QStringLiteral("data"));
  if (path.isEmpty()) return;
  QString error;
  if (!exportCsv(path, &error)) reportFailure(tr("Exporting CSV"), error);
  else confirmSaved(tr("the plotted data"), path);
}

void MainWindow::copyCurrentPlot() {
  buildAllViews();
  if (!m_currentPlot) return;
  auto* data = new QMimeData;
  data->setImageData(renderImage(m_currentPlot));
  CsvTable table;
  m_currentPlot->appendCsv(table);
  data->setText(table.text(csvHeader()));
  QApplication::clipboard()->setMimeData(data);
  m_status->setMessage(tr("Copied “%1” (picture and data) to the clipboard").arg(m_currentPlot->title()));
}

void MainWindow::saveSessionInteractive() {
  const QString path = askSavePath(tr("Save session"), tr("GrazeLab session (*.json)"),
                                   QStringLiteral(".json"), QStringLiteral("session"));
  if (path.isEmpty()) return;
  QString error;
  if (!saveSession(path, &error)) reportFailure(tr("Saving the session"), error);
  else m_status->setMessage(tr("Saved the session to %1").arg(QDir::toNativeSeparators(path)));
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
