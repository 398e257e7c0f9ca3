// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QElapsedTimer>
#include <QList>
#include <QFont>
#include <QHash>
#include <QMainWindow>
#include <QPalette>
#include <QTimer>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "ui/compute/params.h"

namespace grazelab::core {
struct Trust;
}
#include "ui/compute/scene.h"
#include "ui/window/session.h"
#include "ui/compute/sim_types.h"

class QAction;
class QActionGroup;
class QGridLayout;
class QLabel;
class QProgressBar;
class QPushButton;

namespace grazelab::ui {

class ParameterPanel;
class PlotView;
class AccuracyView;
class LandscapeView;
class ChainView;
class SceneView;
class StatusLine;
class ReadoutPanel;
class SimController;

/// The explorer: parameter panel and read-outs on the left, the scene's plots in the middle,
/// the status line below. Parameter edits are turned into requests here (one point where UI
/// intents meet the worker); results are applied to the plots coalesced by a zero timer.
class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  struct Options {
    bool synchronous = false;  ///< compute on the GUI thread (headless snapshots)
    bool useSettings = true;   ///< restore and save geometry and the last session (QSettings)
  };

  explicit MainWindow(Options options, QWidget* parent = nullptr);
  ~MainWindow() override;

  const std::vector<std::unique_ptr<Scene>>& scenes() const { return m_scenes; }
  int sceneIndex() const { return m_sceneIndex; }
  const Scene& scene() const { return *m_scenes[std::size_t(m_sceneIndex)]; }
  void selectScene(int index);
  /// Every parameter of the scene on screen, the chain included, back to the scene's defaults.
  void resetToSceneDefaults();
  /// The error estimate in words a class understands ("chaotic: after t ≈ 292 …").
  /// Every key the window takes, as a rich-text table (Help ▸ Keyboard shortcuts).
  QString shortcutsText() const;
  /// What each view of the scene took to take in the last update drawn [ms], by widget.
  const QHash<const QWidget*, double>& viewCosts() const { return m_viewCosts; }
  static QString trustInWords(const core::Trust& trust, double tEnd);

  const Params& params() const;
  /// Shows these parameters and recomputes.
  void setParams(const Params& params);
  Session session() const;
  /// The scene and parameters of the run on screen (the panel's while nothing is shown yet).
  Session displayedSession() const;
  /// Selects the session's scene and parameters; false (and `error`) for an unknown scene.
  bool applySession(const Session& session, QString* error);

  /// The update the plots show now, if any.
  const SimUpdate* displayed() const { return m_displayed ? &*m_displayed : nullptr; }
  const QList<PlotView*>& plots() const { return m_plots; }
  /// Every view of the scene, in its order (charts, the map, the animation).
  const QList<SceneView*>& sceneViews() const { return m_sceneViews; }
  PlotView* currentPlot() const { return m_currentPlot; }
  AccuracyView* accuracyView() const { return m_accuracy; }
  ChainView* chainView() const { return m_chain; }
  LandscapeView* landscapeView() const { return m_landscape; }
  /// The landscape shows [u1From, u1To] x [v1From, v1To] (physical values) next; the region
  /// before it is kept for Back.
  void showMapRegion(QRectF region);
  /// Back to the region before the last one (false when there is none).
  bool mapRegionBack();
  ParameterPanel* parameterPanel() const { return m_panel; }
  ReadoutPanel* readoutPanel() const { return m_readout; }
  SimController* controller() const { return m_controller; }
  QString statusText() const;
  /// The plain-words problem with the current inputs (empty when there is none).
  QString problem() const;

  bool saveWindowSnapshot(const QString& path, QString* error);
  /// Runs `draw` with the panel showing the displayed run's parameters and start (not values
  /// being typed or refused, nor their refusal), then puts the panel back: a picture of the
  /// window is one state.
  void withDisplayedRunInPanel(const std::function<void()>& draw);
  /// The plot last clicked; at `size` (pixels) when given, laid out anew for it.
  /// One view of the scene (`view`, or the plot last clicked); at `size` (pixels) when given,
  /// laid out anew for it with its text grown to a 40th of its height.
  bool savePlotSnapshot(const QString& path, QString* error, QSize size = {}, SceneView* view = nullptr);
  /// The view "Save current plot" offers first: the plot last clicked or focused.
  SceneView* currentView() const;
  /// What every view of the scene shows, at full resolution, as CSV "plot,series,x,y,value"
  /// (ui/plots/csv_table.h) under csvHeader().
  QString plottedDataCsv() const;
  /// The lines above a CSV export: the run in words, its session, its command line.
  QStringList csvHeader() const;
  /// The last directory used if it can be written, else Pictures, Documents, home.
  QString saveDirectory() const;
  /// "grazing-lambda0.5-window.png"
  QString suggestedFileName(const QString& what, const QString& suffix) const;
  bool exportCsv(const QString& path, QString* error);
  bool saveSession(const QString& path, QString* error);
  bool openSession(const QString& path, QString* error);

  void resetViews();
  void recompute();

  /// Presentation mode: text at 1/50 of `screenHeight` pixels, lines of 3 px and more, a white
  /// page; full screen when `fullScreen` (not for headless snapshots). Off: the desk look.
  void setPresentation(bool on, int screenHeight, bool fullScreen);
  bool presentation() const { return m_presentation; }
  /// Steps through the scenes in the order of the note (PageDown +1, PageUp -1), wrapping.
  void stepScene(int step);
  /// Shows this view alone over the whole plot area, or puts the views back when it is shown
  /// alone already (double-click).
  void toggleEnlarged(QWidget* view);
  QWidget* enlargedView() const { return m_enlarged; }
  /// Starts a run from a point of the section H as plotted (u / d, v / (d ω₁)): two masses, the
  /// point (u1, v1) with u2 = d and v2 <= 0 (leaving the stop) on the energy level of the run
  /// shown; N masses, the point on the section's two coordinates, the others as at the shown
  /// run's contact nearest it (core::chainSectionStateAtEnergy). False (and why, on the status
  /// line) when no state of that energy lies there. The next parameter edit goes back to the
  /// scene's start.
  bool startFromSection(QPointF scaled);
  /// Starts a run from a click on the stopped mass's portrait, as plotted (u / d, v / (d ω₁),
  /// `tolerance` in those units), within `tolerance` of the stop line u = d: the mass leaves the
  /// stop at the clicked speed (v <= 0). Two masses: mass 1 keeps the position of the run's start
  /// and takes the speed (in the same direction) that keeps the energy level; N masses: the others
  /// as at the shown run's start. False (and why, on the status line) off the line or when no
  /// such state exists.
  bool startFromStopLine(QPointF scaled, double tolerance);
  /// Sets the GLO weights of an N-mass scene from a point of its grazing-set plot (dragged or
  /// clicked): x the second mode's weight, y the third's (three modes), the first balancing
  /// (CurveFigure::draggedModes), each rounded to 1e-3; a plot with nothing to drag changes nothing.
  void setGloWeightsFrom(QPointF value);
  /// Shows or hides the parameter panel (F9).
  void setPanelVisible(bool visible);

 signals:
  /// The plots now show an update of request `id` (final or partial).
  void plotsUpdated(quint64 id, bool final);

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void buildMenus();
  /// Shows scene `index` with the parameters stored for it.
  void showScene(int index);
  void buildPlots();
  void layoutViews();
  /// A view of the scene made, put in its cell and connected to the window.
  SceneView* addView(PlotKind kind);
  /// What joins the scene's views (the accuracy overlay on u2(t), the animation's cursor),
  /// once they are all made.
  void linkViews();
  bool viewsBuilt() const;
  void buildNextView();
  /// One step of a scene switch, at each turn of the event loop until none is left: the next
  /// of the new scene's views made and shown (after the last, the run that came meanwhile
  /// drawn), or else the next of the old scene's views deleted. Each view's first layout and
  /// paint costs a few ms, and deleting one that holds a long run as much: all at once stalled
  /// the window for 40-66 ms.
  void continueSwitch();
  /// Every view of the scene made and the run drawn, now (a file saved right after a switch
  /// holds them all).
  void buildAllViews();
  void onParamsChanged(const Params& params);
  void onUpdate(const SimUpdate& update);
  void applyPending();
  /// Runs from a clicked state until the next parameter edit.
  void startFromClick(const core::ChainState& start);
  /// startFromSection and startFromStopLine on the chain of N masses shown
  bool startChainFromSection(QPointF value);
  bool startChainFromStopLine(QPointF value, double tolerance);
  /// Every plot fits the next result (after an edit; the one on screen is not redrawn).
  void followDataFromNextUpdate();
  void showProblem(const QString& message);
  void showStatus(const SimUpdate& update);
  void setProgressVisible(bool visible);
  bool writeSnapshot(QWidget* widget, const QString& path, QString* error, QRect area = {});
  enum class FileAction { Read, Write };
  /// Says in the status line what was saved where (and the session file beside it).
  void confirmSaved(const QString& what, const QString& path);
  /// A dialog: what failed, why, and what became of the window and the file.
  void reportFailure(const QString& what, const QString& error,
                     FileAction action = FileAction::Write);
  /// A save dialog opened in saveDirectory() on suggestedFileName(what, suffix).
  QString askSavePath(const QString& title, const QString& filters, const QString& suffix,
                      const QString& what);

  void saveWindowSnapshotInteractive();
  void savePlotSnapshotInteractive();
  void exportCsvInteractive();
  void copyCurrentPlot();
  void saveSessionInteractive();
  void openSessionInteractive();
  void showAbout();
  void showShortcuts();
  void showSceneGuide();

  Options m_options;
  std::vector<std::unique_ptr<Scene>> m_scenes;
  /// what the scenes keep between computations (the atlas of modes), shared with the worker
  std::shared_ptr<SceneCache> m_sceneCache = std::make_shared<SceneCache>();
  std::vector<Params> m_sceneParams;
  /// each scene's parameters of the last run it showed: a scene left with a refused value goes
  /// back to them, and the next is entered with their chain (entered with the refused one, it
  /// had nothing to show)
  std::vector<Params> m_validParams;
  /// said after the status until the next edit: the refused value dropped on leaving a scene
  QString m_droppedNote;
  int m_sceneIndex = 0;
  bool m_sceneChosen = false;  ///< a scene is on screen (its parameters carry over to the next)
  ParameterPanel* m_panel = nullptr;
  ReadoutPanel* m_readout = nullptr;
  QWidget* m_readoutBox = nullptr;  ///< the two-mass chain's derived values (hidden for N masses)
  QWidget* m_plotArea = nullptr;
  QGridLayout* m_plotGrid = nullptr;
  QList<PlotView*> m_plots;
  PlotView* m_currentPlot = nullptr;
  AccuracyView* m_accuracy = nullptr;  ///< the work-precision view, when the scene shows it
  ChainView* m_chain = nullptr;        ///< the animation, when the scene shows it
  LandscapeView* m_landscape = nullptr;  ///< the landscape's map, when the scene shows it
  std::vector<Params::MapRegion> m_regionHistory;  ///< the regions before, for Back
  QWidget* m_side = nullptr;           ///< the parameter panel's scroll area
  QWidget* m_enlarged = nullptr;       ///< the view shown alone, if any
  QList<SceneView*> m_sceneViews;      ///< every view of the scene, in its order
  /// Their widgets, for the layout; a view not made yet has a placeholder here (continueSwitch)
  QList<QWidget*> m_views;
  QList<QWidget*> m_retired;  ///< an old scene's views, hidden, waiting to be deleted
  bool m_presentation = false;
  int m_presentationText = 0;          ///< text size in presentation mode [px]
  /// the views were made while presenting: Qt Charts' theme took their "desk" fonts from the
  /// large application font, so leaving presentation makes them anew
  bool m_viewsBuiltPresenting = false;
  QFont m_deskFont;
  QRect m_deskGeometry;  ///< where the window was before presentation mode
  std::optional<core::ChainState> m_clickedStart;  ///< a start chosen on H, until the next edit
  QPalette m_deskPalette;
  QAction* m_presentationAction = nullptr;
  QAction* m_wholeRunAction = nullptr;  ///< checked: time-based views show the whole run
  QAction* m_panelAction = nullptr;
  SimController* m_controller = nullptr;
  QActionGroup* m_sceneActions = nullptr;
  StatusLine* m_status = nullptr;
  /// Pixels either side of the (u2, v2) portrait's stop line that a click counts as on it.
  static constexpr int kStopLineBand = 16;
  QString m_statusExplanation;  ///< what the status line shows, in words (its tooltip)
  QHash<const QWidget*, double> m_viewCosts;
  std::uint64_t m_runShownId = 0;  ///< the request whose whole run was last put on screen
  QProgressBar* m_progress = nullptr;
  QPushButton* m_cancel = nullptr;
  QTimer m_applyTimer;
  QTimer m_switchTimer;  ///< drives continueSwitch
  QElapsedTimer m_lastApply;   // when the plots were last filled
  qint64 m_lastApplyCost = 0;  // how long that took [ms]
  std::optional<SimUpdate> m_pending;
  std::optional<SimUpdate> m_displayed;
  QString m_problem;
  QString m_lastDirectory;
};

}  // namespace grazelab::ui
