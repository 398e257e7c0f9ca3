// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/window/main_window.h"

#include <QAction>
#include <QApplication>
#include <QActionGroup>
#include <QGuiApplication>
#include <QCloseEvent>
#include <QElapsedTimer>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QIcon>
#include <QLabel>
#include <QMenuBar>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "core/model/two_mass_form.h"
#include "core/model/model.h"
#include "core/solver/chain_run.h"
#include "ui/compute/derived.h"
#include "ui/widgets/parameter_panel.h"
#include "ui/window/presentation_style.h"
#include "ui/window/status_line.h"
#include "ui/plots/modes_plot.h"
#include "ui/plots/accuracy_view.h"
#include "ui/plots/landscape_view.h"
#include "ui/plots/chain_view.h"
#include "ui/plots/curve_plot.h"
#include "ui/plots/scene_view.h"
#include "ui/plots/plot_view.h"
#include "ui/plots/phase_plot.h"
#include "ui/plots/poincare_plot.h"
#include "ui/plots/trace_plot.h"
#include "ui/widgets/readout_panel.h"
#include "ui/widgets/wheel_scrolls_panel.h"
#include "ui/compute/sim_controller.h"
#include "ui/window/wrapped_tooltips.h"

namespace grazelab::ui {
namespace {

const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kStateKey = QStringLiteral("window/state");
const QString kSessionKey = QStringLiteral("session/last");


}  // namespace

MainWindow::MainWindow(Options options, QWidget* parent)
    : QMainWindow(parent), m_options(options), m_scenes(makeScenes()) {
  installPresentationStyle();  // before the panel's widgets (and their style sheets) exist
  setWindowIcon(QIcon::fromTheme(QStringLiteral("grazelab"), QIcon(QStringLiteral(":/icons/grazelab.svg"))));
  for (const auto& scene : m_scenes) m_sceneParams.push_back(scene->defaults());
  m_validParams = m_sceneParams;

  m_controller = new SimController(this);
  m_controller->setSynchronous(options.synchronous);
  connect(m_controller, &SimController::updated, this, &MainWindow::onUpdate);
  connect(m_controller, &SimController::idle, this, [this] { setProgressVisible(false); });

  // left: parameters and read-outs, scrollable on small screens
  m_panel = new ParameterPanel;
  m_readout = new ReadoutPanel;
  auto* left = new QWidget;
  auto* leftLayout = new QVBoxLayout(left);
  leftLayout->setContentsMargins(6, 6, 6, 6);
  leftLayout->addWidget(m_panel);
  auto* readoutBox = new QGroupBox(tr("Derived (mode 1 = fast, mode 2 = slow)"));
  m_readoutBox = readoutBox;
  readoutBox->setToolTip(tr("Mode 1 is the FAST mode and mode 2 the SLOW one: the proofs need "
                            "ω₁ = 2 ω₂, so T₂ = 2 T₁ and every free motion repeats after T₂."));
  auto* readoutLayout = new QVBoxLayout(readoutBox);
  readoutLayout->setContentsMargins(4, 4, 4, 4);
  readoutLayout->addWidget(m_readout);
  leftLayout->addWidget(readoutBox);
  leftLayout->addStretch(1);
  auto* scroll = new QScrollArea;
  scroll->setWidget(left);
  scroll->setWidgetResizable(true);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  // always there: a message that made the panel scroll narrowed it, every text wrapped anew and
  // the controls moved under the pointer
  scroll->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOn);
  // narrow enough that a 1024-pixel projector holds the panel and three columns of plots
  scroll->setMinimumWidth(320);
  qApp->installEventFilter(new WheelScrollsPanel(scroll));
  m_side = scroll;

  m_plotArea = new QWidget;
  m_plotGrid = new QGridLayout(m_plotArea);
  m_plotGrid->setContentsMargins(2, 2, 2, 2);
  m_plotGrid->setSpacing(4);

  auto* splitter = new QSplitter;
  splitter->setObjectName(QStringLiteral("mainSplitter"));
  splitter->addWidget(scroll);
  splitter->addWidget(m_plotArea);
  splitter->setStretchFactor(1, 1);
  splitter->setSizes({400, 1200});
  setCentralWidget(splitter);

  m_status = new StatusLine;
  m_status->setObjectName(QStringLiteral("statusText"));
  m_statusExplanation = tr("Work done and its accuracy: contacts computed, compute time, the "
                           "largest relative energy drift at contacts and the largest |u₂ − d| "
                           "at the contact times found (both should be near round-off), and "
                           "trust: the estimated error of the final state and contact times "
                           "from a shadow run in long double (ok below 1e-9, degraded below "
                           "1e-6, else unreliable: the run went past its predictability "
                           "horizon).");
  m_status->setExplanation(m_statusExplanation);
  m_progress = new QProgressBar;
  m_progress->setRange(0, 1000);
  m_progress->setMaximumWidth(200);
  m_cancel = new QPushButton(tr("Cancel"));
  m_cancel->setToolTip(tr("Stop the running computation and keep what is done (Esc)."));
  connect(m_cancel, &QPushButton::clicked, m_controller, &SimController::cancel);
  statusBar()->addWidget(m_status, 1);
  statusBar()->addPermanentWidget(m_progress);
  statusBar()->addPermanentWidget(m_cancel);
  setProgressVisible(false);

  m_applyTimer.setSingleShot(true);
  connect(&m_applyTimer, &QTimer::timeout, this, &MainWindow::applyPending);
  // a real timer: QTimer::singleShot(0, …) posts an event, and posted events run back to back
  // in one turn of the event loop, which would put the whole switch back into one stall
  m_switchTimer.setInterval(0);
  connect(&m_switchTimer, &QTimer::timeout, this, &MainWindow::continueSwitch);
  connect(m_panel, &ParameterPanel::paramsChanged, this, &MainWindow::onParamsChanged);
  connect(m_panel, &ParameterPanel::inputRefused, m_status, &StatusLine::setMessage);

  buildMenus();
  wrapToolTips();
  // 1600x1000, or less on a smaller screen: the status bar and legends must stay on it
  QSize size(1600, 1000);
  if (const QScreen* screen = QGuiApplication::primaryScreen()) {
    size = size.boundedTo(screen->availableGeometry().size() * 0.95);
  }
  resize(size);

  std::optional<Session> restored;
  if (m_options.useSettings) {
    QSettings settings;
    restoreGeometry(settings.value(kGeometryKey).toByteArray());
    restoreState(settings.value(kStateKey).toByteArray());
    QString ignored;
    restored = sessionFromJson(settings.value(kSessionKey).toByteArray(), Params{}, &ignored);
  }
  QString error;
  if (!restored || !applySession(*restored, &error)) selectScene(0);
}

MainWindow::~MainWindow() {
  // the worker first: it may be running a scene's computation, which reads this window's
  // scenes and must not outlive them (the controller, a child, would go only after them)
  delete m_controller;
  m_controller = nullptr;
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  auto add = [this](QMenu* menu, const QString& text, const QList<QKeySequence>& keys,
                    const QString& tip, auto slot) {
    QAction* action = menu->addAction(text);
    action->setShortcuts(keys);
    action->setToolTip(tip);
    action->setStatusTip(tip);
    connect(action, &QAction::triggered, this, slot);
    return action;
  };
  add(file, tr("&Open session…"), {QKeySequence::Open}, tr("Open saved parameters (JSON)"),
      &MainWindow::openSessionInteractive);
  add(file, tr("Save session &as…"), {QKeySequence(tr("Ctrl+Shift+S"))},
      tr("Save the scene and its parameters as JSON"), &MainWindow::saveSessionInteractive);
  file->addSeparator();
  add(file, tr("&Save snapshot of the window…"), {QKeySequence(tr("Ctrl+S"))},
      tr("Save the whole window as PNG, SVG or PDF, with its session beside it"),
      &MainWindow::saveWindowSnapshotInteractive);
  add(file, tr("Save a &plot…"), {QKeySequence(tr("Ctrl+Shift+P"))},
      tr("Save one view of the scene (chosen in a list: charts, the map, the animation) as PNG, SVG "
         "or PDF, at its size on screen or a figure's, with its session beside it"),
      &MainWindow::savePlotSnapshotInteractive);
  add(file, tr("&Export plotted data as CSV…"), {QKeySequence(tr("Ctrl+E"))},
      tr("Write the data of every plot at full resolution"), &MainWindow::exportCsvInteractive);
  add(file, tr("&Copy current plot"), {QKeySequence(tr("Ctrl+Shift+C"))},
      tr("Copy the current plot to the clipboard as a picture and its data as text"),
      &MainWindow::copyCurrentPlot);
  file->addSeparator();
  add(file, tr("&Quit"), {QKeySequence::Quit}, tr("Close GrazeLab"), &QWidget::close);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  add(view, tr("&Reset view"), {QKeySequence(Qt::Key_R), QKeySequence(tr("Ctrl+0"))},
      tr("Undo zoom and pan in every plot"), &MainWindow::resetViews);
  add(view, tr("&Cancel computation"), {QKeySequence(Qt::Key_Escape)},
      tr("Leave presentation mode; otherwise stop the running computation (and put an enlarged "
         "plot back)"),
      [this] {
        if (m_presentation) {
          m_presentationAction->trigger();  // Esc is how everyone leaves full screen
          return;
        }
        m_controller->cancel();
        if (m_enlarged) toggleEnlarged(m_enlarged);
      });
  m_wholeRunAction = add(
      view, tr("Show the &whole run"), {QKeySequence(Qt::Key_W)},
      tr("u₂(t) and the phase portraits: the whole run, or a window of a few slow periods at the "
         "animation's time (a long run drawn whole fills the plot); N masses: the trace, the "
         "portrait and the animation over the whole run, or its first four slowest periods"),
      [this](bool whole) {
        for (SceneView* view : m_sceneViews) view->setWholeRun(whole);
        // a chain's grid spans what is shown: computed again over the whole run, or its start
        const bool chains = m_displayed && !m_displayed->request->job.spec.chains.empty();
        if (scene().massChain() || chains) recompute();
      });
  m_wholeRunAction->setCheckable(true);
  add(view, tr("Play / &pause the motion"), {QKeySequence(Qt::Key_Space)},
      tr("Start or stop the animated chain (scenes that show it)"), [this] {
        if (m_chain) m_chain->setPlaying(!m_chain->playing());
      });
  view->addSeparator();
  m_presentationAction = add(
      view, tr("&Presentation mode"), {QKeySequence(Qt::Key_F5), QKeySequence(Qt::Key_F11)},
      tr("Full screen for a projector: large text, thick lines, white page. PageDown and PageUp "
         "step through the scenes; double-click a plot to enlarge it."),
      [this](bool on) {
        const QScreen* screen = this->screen() ? this->screen() : QGuiApplication::primaryScreen();
        setPresentation(on, screen ? screen->geometry().height() : height(), true);
      });
  m_presentationAction->setCheckable(true);
  m_panelAction = add(view, tr("Show the &parameters"), {QKeySequence(Qt::Key_F9)},
                      tr("Show or hide the parameter panel (more room for the plots)"),
                      &MainWindow::setPanelVisible);
  m_panelAction->setCheckable(true);
  m_panelAction->setChecked(true);
  add(view, tr("&Next scene"), {QKeySequence(Qt::Key_PageDown)},
      tr("The next scene in the order of the note (a presenter's clicker sends this key)"),
      [this] { stepScene(+1); });
  add(view, tr("P&revious scene"), {QKeySequence(Qt::Key_PageUp)},
      tr("The previous scene in the order of the note"), [this] { stepScene(-1); });

  QMenu* scenes = menuBar()->addMenu(tr("S&cenes"));
  add(scenes, tr("Reset to scene &defaults"), {QKeySequence(tr("Ctrl+Shift+R"))},
      tr("Put every parameter of this scene, the chain included, back to the values the scene "
         "starts with"),
      &MainWindow::resetToSceneDefaults);
  scenes->addSeparator();
  m_sceneActions = new QActionGroup(this);
  for (std::size_t index = 0; index < m_scenes.size(); ++index) {
    QAction* action = scenes->addAction(m_scenes[index]->title());
    action->setCheckable(true);
    action->setToolTip(m_scenes[index]->description());
    if (const QString key = sceneShortcut(int(index)); !key.isEmpty()) action->setShortcut(QKeySequence(key));
    m_sceneActions->addAction(action);
    connect(action, &QAction::triggered, this, [this, index] { selectScene(int(index)); });
  }

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  add(help, tr("&Guide to this scene"), {QKeySequence(Qt::Key_F1)},
      tr("What the scene on screen shows and what to look for"), &MainWindow::showSceneGuide);
  add(help, tr("Keyboard &shortcuts"), {QKeySequence(tr("Ctrl+F1"))}, tr("Every key the window takes"),
      &MainWindow::showShortcuts);
  add(help, tr("&About GrazeLab"), {}, tr("What this program shows, and its version"),
      &MainWindow::showAbout);
}

void MainWindow::buildPlots() {
  // out of the layout and out of sight now (headless mode has no event loop running yet, so a
  // deferred delete alone would leave them drawn); deleted later, one per turn
  for (QWidget* view : m_views) {
    m_plotGrid->removeWidget(view);
    view->hide();
    view->disconnect(this);
    m_retired.append(view);
  }
  m_views.clear();
  m_sceneViews.clear();
  m_viewCosts.clear();
  m_plots.clear();
  m_accuracy = nullptr;
  m_chain = nullptr;
  m_landscape = nullptr;
  m_currentPlot = nullptr;
  m_enlarged = nullptr;
  m_viewsBuiltPresenting = m_presentation;
  for (PlotKind kind : scene().plots()) {
    if (m_options.synchronous) {
      m_views.append(addView(kind)->widget());
      continue;
    }
    // made one per turn of the event loop (continueSwitch); meanwhile a bare widget of a
    // plot's size policy holds its cell, so the others need no new layout as each comes
    auto* placeholder = new QWidget(m_plotArea);
    placeholder->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    placeholder->setMinimumSize(PlotView::kMinimumSize);
    m_views.append(placeholder);
  }
  if (m_options.synchronous) linkViews();
  layoutViews();
  if (!viewsBuilt() || !m_retired.isEmpty()) m_switchTimer.start();
}

SceneView* MainWindow::addView(PlotKind kind) {
  SceneView* view = makeView(kind, m_plotArea);
  m_sceneViews.append(view);
  if (m_presentation) view->setPresentation(true, m_presentationText);
  // the user's choice (W) holds across scenes
  view->setWholeRun(m_wholeRunAction->isChecked());
  // the few views with more to say than show(): found by their type
  if (auto* accuracy = dynamic_cast<AccuracyView*>(view)) m_accuracy = accuracy;
  if (auto* chain = dynamic_cast<ChainView*>(view)) m_chain = chain;
  if (auto* landscape = dynamic_cast<LandscapeView*>(view)) {
    m_landscape = landscape;
    landscape->setBackEnabled(!m_regionHistory.empty());
    connect(landscape, &LandscapeView::startRequested, this,
            [this](const core::State& start) { startFromClick(core::chainStateOf(start)); });
    connect(landscape, &LandscapeView::regionRequested, this, &MainWindow::showMapRegion);
    connect(landscape, &LandscapeView::backRequested, this, [this] { mapRegionBack(); });
  }
  if (auto* modes = dynamic_cast<ModesPlot*>(view)) {
    connect(modes, &ModesPlot::orbitChosen, this, [this](int family, int orbit, const core::ChainState& start) {
      // a scene that follows a family along an energy slider: the click moves both to that orbit
      // (the slider then goes on along the family); any other follows the start clicked
      const std::shared_ptr<const AtlasFigure> atlas = m_displayed ? m_displayed->request->job.atlas : nullptr;
      if (!scene().parameters().contains(ParamKey::ModeFamily) || !atlas || family >= int(atlas->families.size()) ||
          orbit >= int(atlas->families[std::size_t(family)].orbits.size())) {
        startFromClick(start);
        return;
      }
      const AtlasFigure::Family& chosen = atlas->families[std::size_t(family)];
      Params moved = params();
      moved.modeFamily = family;
      moved.modeEnergy = energyPosition(chosen, chosen.orbits[std::size_t(orbit)].energy);
      setParams(moved);
    });
    connect(modes, &ModesPlot::missed, this, [this] {
      m_status->setMessage(tr("Click within %1 pixels of a family's dots to follow that orbit.")
                               .arg(ModesPlot::kChoiceRadius));
    });
  }
  if (auto* plot = dynamic_cast<PlotView*>(view)) {
    m_plots.append(plot);
    if (!m_currentPlot) m_currentPlot = plot;
    connect(plot, &PlotView::activated, this, [this](PlotView* active) { m_currentPlot = active; });
    connect(plot, &PlotView::enlargeRequested, this, [this](PlotView* plot) { toggleEnlarged(plot); });
    // a band a hand hits on a projector: kStopLineBand pixels either side of the stop line
    const auto stopLineBand = [](PlotView* portrait) {
      const double perPixel = std::abs(portrait->chart()->mapToValue(QPointF(100, 0)).x() -
                                       portrait->chart()->mapToValue(QPointF(0, 0)).x()) / 100;
      return kStopLineBand * perPixel;
    };
    auto* curve = qobject_cast<CurvePlot*>(plot);
    auto* phase = qobject_cast<PhasePlot*>(plot);
    if (qobject_cast<PoincarePlot*>(plot)) {
      connect(plot, &PlotView::clickedAt, this, [this](QPointF value) { startFromSection(value); });
    } else if (phase && phase->mass() == PhasePlot::Mass::Chosen) {
      connect(plot, &PlotView::clickedAt, this,
              [this, plot, stopLineBand](QPointF value) { startFromStopLine(value, stopLineBand(plot)); });
    } else if (curve) {
      connect(curve, &CurvePlot::referenceDragged, this, &MainWindow::setGloWeightsFrom);
      connect(curve, &PlotView::clickedAt, this, [this, curve](QPointF value) {
        if (curve->draggable()) setGloWeightsFrom(value);
      });
    }
  }
  return view;
}

void MainWindow::linkViews() {
  if (m_accuracy) {
    // the chosen method's run is drawn over the exact u2(t)
    for (PlotView* plot : m_plots) {
      if (auto* trace = qobject_cast<TracePlot*>(plot)) {
        connect(m_accuracy, &AccuracyView::overlayChosen, trace, &TracePlot::setOverlay);
      }
    }
  }
  if (m_chain) {
    // the animation's time is the cursor of every view
    connect(m_chain, &ChainView::timeChanged, this, [this](double t) {
      for (SceneView* view : m_sceneViews) view->setTimeCursor(t);
    });
  }
}

bool MainWindow::viewsBuilt() const { return m_sceneViews.size() == m_views.size(); }

void MainWindow::buildNextView() {
  const qsizetype index = m_sceneViews.size();
  const std::unique_ptr<QWidget> placeholder(m_views[index]);
  QWidget* view = addView(scene().plots()[std::size_t(index)])->widget();
  m_views[index] = view;
  // in its cell (replaceWidget alone asks for no new layout: the view would keep the size it
  // was made with); the show lays it out at once
  delete m_plotGrid->replaceWidget(placeholder.get(), view);
  m_plotGrid->invalidate();
  view->setVisible(!m_enlarged);
  if (viewsBuilt()) linkViews();
}

void MainWindow::continueSwitch() {
  if (!viewsBuilt()) {
    buildNextView();
    if (viewsBuilt()) {
      // the run that came meanwhile, in a turn of its own; or, views made again (leaving
      // presentation), the run they showed
      if (!m_pending && m_displayed) m_pending = m_displayed;
      if (m_pending) m_applyTimer.start(0);
    }
  } else if (!m_retired.isEmpty()) {
    m_retired.takeFirst()->deleteLater();
  }
  if (viewsBuilt() && m_retired.isEmpty()) m_switchTimer.stop();
}

void MainWindow::buildAllViews() {
  if (!viewsBuilt()) {
    while (!viewsBuilt()) buildNextView();
    if (!m_pending && m_displayed) m_pending = m_displayed;  // as continueSwitch
  }
  applyPending();
}

void MainWindow::layoutViews() {
  const QList<QWidget*>& views = m_views;
  for (QWidget* view : views) m_plotGrid->removeWidget(view);
  for (int row = 0; row < 2; ++row) m_plotGrid->setRowStretch(row, 1);
  for (int column = 0; column < 3; ++column) m_plotGrid->setColumnStretch(column, 1);
  if (m_enlarged) {
    // one view over the whole area; the others wait hidden
    for (QWidget* view : views) view->setVisible(view == m_enlarged);
    m_plotGrid->addWidget(m_enlarged, 0, 0, 2, 3);
    return;
  }
  for (QWidget* view : views) view->setVisible(true);
  if (views.size() == 6) {
    for (int index = 0; index < 6; ++index) m_plotGrid->addWidget(views[index], index / 3, index % 3);
  } else if (views.size() == 5) {
    // the time trace is wide; the three portraits of state space sit side by side
    m_plotGrid->addWidget(views[0], 0, 0, 1, 2);
    m_plotGrid->addWidget(views[1], 0, 2);
    m_plotGrid->addWidget(views[2], 1, 0);
    m_plotGrid->addWidget(views[3], 1, 1);
    m_plotGrid->addWidget(views[4], 1, 2);
  } else if (views.size() == 2) {
    // two subjects side by side, each half the width and the full height
    m_plotGrid->setColumnStretch(2, 0);
    m_plotGrid->addWidget(views[0], 0, 0, 2, 1);
    m_plotGrid->addWidget(views[1], 0, 1, 2, 1);
  } else if (views.size() == 4) {
    // two rows of two: the scene's curves above, the motion below
    m_plotGrid->setColumnStretch(2, 0);
    for (int index = 0; index < 4; ++index) m_plotGrid->addWidget(views[index], index / 2, index % 2);
  } else if (views.size() == 3) {
    // the first plot is the scene's subject: give it most of the room
    m_plotGrid->addWidget(views[0], 0, 0, 2, 2);
    m_plotGrid->addWidget(views[1], 0, 2);
    m_plotGrid->addWidget(views[2], 1, 2);
  } else {
    for (int index = 0; index < views.size(); ++index) {
      m_plotGrid->addWidget(views[index], index / 3, index % 3);
    }
  }
}

void MainWindow::selectScene(int index) {
  if (index < 0 || index >= int(m_scenes.size())) return;
  // a refused value stays behind: the scene left goes back to what it last showed (said until
  // the next edit or the next switch)
  m_droppedNote.clear();
  if (m_sceneChosen && index != m_sceneIndex && !m_problem.isEmpty()) {
    m_droppedNote = tr("the refused edit of %1 was dropped (%2): it keeps its last valid values")
                        .arg(scene().title(), m_problem);
    m_sceneParams[std::size_t(m_sceneIndex)] = m_validParams[std::size_t(m_sceneIndex)];
    m_problem.clear();
    m_panel->setMessage(QString());
    m_panel->clearRefusal();
  }
  // the chain comes along; the scene keeps its own start, push and length (an N-mass scene
  // keeps its own chain, and the two-mass one, which it does not use, is not carried into it:
  // an infeasible two-mass chain would refuse a scene that never runs it)
  if (m_sceneChosen && index != m_sceneIndex && !m_scenes[std::size_t(index)]->massChain()) {
    Params& entered = m_sceneParams[std::size_t(index)];
    entered = enterScene(entered, params());
  }
  showScene(index);
}

void MainWindow::showScene(int index) {
  m_sceneChosen = true;
  m_clickedStart.reset();
  m_panel->setClickedStart(std::nullopt);
  m_sceneIndex = index;
  m_displayed.reset();
  m_pending.reset();
  // Qt adds " — GrazeLab" (the application's display name) itself
  setWindowTitle(scene().title());
  if (m_sceneActions && index < m_sceneActions->actions().size()) {
    m_sceneActions->actions()[index]->setChecked(true);
  }
  buildPlots();
  m_panel->setScene(scene());
  m_readoutBox->setVisible(!scene().massChain());  // an N-mass chain says what it is in its editor
  m_panel->setParams(m_sceneParams[std::size_t(index)]);
  recompute();
}

void MainWindow::resetToSceneDefaults() {
  m_regionHistory.clear();
  if (m_landscape) m_landscape->setBackEnabled(false);
  m_panel->clearRefusal();
  setParams(scene().defaults());
  m_status->setMessage(tr("%1: every parameter back to the scene's defaults.").arg(scene().title()));
}

const Params& MainWindow::params() const { return m_sceneParams[std::size_t(m_sceneIndex)]; }

void MainWindow::setParams(const Params& params) {
  m_panel->setParams(params);
  onParamsChanged(params);
}

Session MainWindow::session() const { return {scene().name(), params(), m_clickedStart}; }

bool MainWindow::applySession(const Session& session, QString* error) {
  const int index = findScene(m_scenes, session.scene);
  if (index < 0) {
    if (error) *error = tr("unknown scene \"%1\"").arg(session.scene);
    return false;
  }
  // a start of as many masses as the scene's chain, or none: nothing changes otherwise
  const Scene& target = *m_scenes[std::size_t(index)];
  const Eigen::Index masses = target.massChain() ? Eigen::Index(session.params.massChain.size()) : 2;
  if (session.start && session.start->u.size() != masses) {
    if (error) {
      *error = tr("the start has %1 masses where the chain of \"%2\" has %3")
                   .arg(session.start->u.size())
                   .arg(session.scene)
                   .arg(masses);
    }
    return false;
  }
  // the session's parameters as saved, whatever the scene on screen had
  m_sceneParams[std::size_t(index)] = session.params;
  showScene(index);
  if (session.start) startFromClick(*session.start);
  return true;
}

void MainWindow::onParamsChanged(const Params& params) {
  m_droppedNote.clear();
  m_clickedStart.reset();  // an edit goes back to the scene's own start
  m_panel->setClickedStart(std::nullopt);
  m_sceneParams[std::size_t(m_sceneIndex)] = params;
  // new data in a zoomed window may lie outside it and look blank: the plots fit it again
  followDataFromNextUpdate();
  recompute();
}

void MainWindow::recompute() {
  Params& current = m_sceneParams[std::size_t(m_sceneIndex)];
  DerivedModel derived = deriveModel(current);
  // an N-mass scene runs no two-mass chain: one it cannot make (from a session) stands in by
  // the scene's own, which its job never runs
  if (!derived.ok && scene().massChain()) derived = deriveModel(scene().defaults());
  if (!derived.ok) {
    showProblem(derived.message);
    return;
  }
  if (current.resonantDesign && current.k2 != derived.model.k2) {
    // the designed k2 is the chain's k2: sessions and snapshots record it, and unticking the
    // design starts the detuned chain from it (not from a value typed long ago)
    current.k2 = derived.model.k2;
    m_panel->setParams(current);
  }
  m_problem.clear();
  m_panel->setMessage(QString());
  // described here, computed by the worker: the scene's curves and surveys as well as the run
  SimRequest request;
  request.params = current;
  request.sceneName = scene().name();
  request.clickedStart = m_clickedStart;
  request.derived = derived;
  // the scene travels as a copy (texts and a function): the worker never reads the window's
  request.prepare = [scene = *m_scenes[std::size_t(m_sceneIndex)], params = current, derived,
                     clicked = m_clickedStart, cache = m_sceneCache,
                     whole = m_wholeRunAction->isChecked()](std::stop_token stop, const ScenePartial& partial) {
    SceneJob job = scene.build(params, derived, stop, clicked, partial, cache.get());
    // W: a chain's grid goes on over the whole run (the two-mass runs sample it anyway)
    if (whole) {
      for (core::experiments::ChainSeriesSpec& chain : job.spec.chains) chain.maxGridPoints = kWholeRunGridPoints;
    }
    if (clicked && job.ok) {
      // the start clicked in place of the scene's own: a chain's runs (the shown one and its
      // contrast, the same start on a detuned chain), or the two-mass run
      for (core::experiments::ChainSeriesSpec& chain : job.spec.chains) {
        if (chain.chain.size() != clicked->u.size()) continue;
        chain.start = *clicked;
        chain.gloWeights.clear();
      }
      if (job.spec.chains.empty() && clicked->u.size() == 2) {
        job.spec.run.initial = core::twoMassStateOf(*clicked);
        job.spec.stillModes.clear();  // a state clicked on: nothing known still
      }
    }
    return job;
  };
  m_controller->submit(std::move(request));
}

void MainWindow::onUpdate(const SimUpdate& update) {
  const SceneJob& job = update.request->job;
  if (update.scenePartial) {
    // the scene's own computation so far (the atlas, family by family): only the views that
    // draw it take it; the run comes later
    if (update.request->sceneName != scene().name()) return;
    for (SceneView* view : m_sceneViews) {
      if (view->drawsSceneDataOnly()) view->show(update);
    }
    setProgressVisible(true);
    m_progress->setValue(int(update.progress * 1000));
    return;
  }
  if (update.request->sceneName == scene().name()) m_panel->setSliderRanges(job.sliderRanges);
  if (!job.ok && update.result->stop == core::StopReason::Cancelled) {
    setProgressVisible(false);  // stopped before the scene had anything to run
    return;
  }
  if (update.result && update.result->stop == core::StopReason::InvalidInput) {
    setProgressVisible(false);
    showProblem(QString::fromStdString(update.result->message));
    // an N-mass chain that cannot be made says why where it is edited as well (a refused start
    // leaves the summary of the chain, which is fine)
    if (scene().massChain() && update.request->sceneName == scene().name() && job.chain.refused) {
      m_panel->setChainSummary(job.chain.summary, 0, true);
    }
    return;
  }
  // (not while views are made again, or a copy of the shown run waits to be drawn: it would
  // come back over the estimate)
  if (m_displayed && m_displayed->trustPending && update.id == m_displayed->id &&
      update.result == m_displayed->result && update.chains.size() == m_displayed->chains.size() &&
      viewsBuilt() && !(m_pending && m_pending->id == update.id)) {
    // the same result again, now with its error estimate: only the status line changes (of
    // chains of N masses: the same runs, now with their estimates, the last one maybe final)
    const bool becameFinal = update.final && !m_displayed->final;
    m_displayed->trust = update.trust;
    m_displayed->trustPending = update.trustPending;
    m_displayed->chains = update.chains;
    m_displayed->final = update.final;
    m_displayed->progress = update.progress;
    m_displayed->attempt = update.attempt;
    m_displayed->precisionNote = update.precisionNote;
    showStatus(*m_displayed);
    if (becameFinal) {
      // axes fitted to the run as final (a growing run's have room to widen)
      for (PlotView* plot : m_plots) plot->settle();
      setProgressVisible(m_displayed->superseded);
      emit plotsUpdated(m_displayed->id, true);
    }
    return;
  }
  m_pending = update;
  if (m_options.synchronous) {
    applyPending();
    return;
  }
  // a final result is drawn at the next turn of the event loop; partial ones at most every
  // 33 ms and never more often than three times their drawing cost, so that a huge run
  // cannot keep the GUI thread busy drawing
  int delay = 0;
  // the run's first whole update (the Accuracy scene's exact run, before its sweep) at once
  const bool runShown = update.runDone && update.id != m_runShownId;
  if (runShown) m_runShownId = update.id;
  if (!update.final && !runShown && m_lastApply.isValid()) {
    const qint64 spacing = std::max<qint64>(33, 3 * m_lastApplyCost);
    delay = int(std::max<qint64>(0, spacing - m_lastApply.elapsed()));
  }
  if (!m_applyTimer.isActive() || delay < m_applyTimer.remainingTime()) m_applyTimer.start(delay);
}

void MainWindow::applyPending() {
  if (!m_pending) return;
  // a new scene's first run is drawn once all its views are up (continueSwitch draws it then):
  // drawn into hidden views it would add their whole layout to one turn of the event loop
  if (!viewsBuilt()) return;
  // a pending update of another scene (switched meanwhile) is dropped
  if (m_pending->request->sceneName != scene().name()) {
    m_pending.reset();
    return;
  }
  m_displayed = std::move(m_pending);
  m_pending.reset();
  if (m_displayed->request->job.ok) m_validParams[std::size_t(m_sceneIndex)] = m_displayed->request->params;
  m_panel->setNotes(m_displayed->request->job.notes);
  if (scene().massChain()) {
    const SceneJob& job = m_displayed->request->job;
    m_panel->setChainSummary(job.chain.summary, job.chain.designs, job.chain.refused);
  } else if (const SimRequest& shown = *m_displayed->request; shown.derived.ok) {
    // the energy of the run shown: the note's run, or the first chain's of an experiment of two
    // masses (the detuned contrast's 1:2 design, whatever the panel's design box says)
    const std::vector<core::experiments::ChainSeriesSpec>& chains = shown.job.spec.chains;
    m_readout->showModel(shown.derived, chains.empty()
                                            ? core::energy(shown.job.spec.model, shown.job.spec.run.initial)
                                            : core::chainEnergy(chains.front().chain, chains.front().start));
  }
  QElapsedTimer cost;
  cost.start();
  // a result that is not the panel's (an infeasible edit came after it) stays marked stale
  const bool stale = !m_problem.isEmpty();
  // each view's share is kept (grazelab --bench names the slowest)
  QElapsedTimer viewClock;
  for (SceneView* view : m_sceneViews) {
    viewClock.start();
    view->setEmptyNote(QString());  // a run to show: no reason for nothing
    view->show(*m_displayed);
    m_viewCosts[view->widget()] = viewClock.nsecsElapsed() * 1e-6;
  }
  // after every show: the accuracy view may have changed the trace's overlay
  for (PlotView* plot : m_plots) {
    viewClock.start();
    plot->setStale(stale);
    // a whole run is fitted tightly at once, even while a sweep, a map or a contrast's run
    // goes on after it: fitted loosely first, its axes moved twice for every edit
    plot->setGrowing(!m_displayed->final && !m_displayed->runDone);
    plot->refreshNow();
    m_viewCosts[plot] += viewClock.nsecsElapsed() * 1e-6;
  }
  if (m_chain) m_chain->setTime(m_chain->time());  // the cursors again, on the refitted axes
  m_lastApplyCost = cost.elapsed();
  m_lastApply.start();
  showStatus(*m_displayed);
  // a superseded run is shown while the newest request still computes
  setProgressVisible(!m_displayed->final || m_displayed->superseded);
  m_progress->setValue(int(m_displayed->progress * 1000));
  emit plotsUpdated(m_displayed->id, m_displayed->final);
}


void MainWindow::followDataFromNextUpdate() {
  for (PlotView* plot : m_plots) plot->followDataFromNextUpdate();
}

void MainWindow::resetViews() {
  for (PlotView* plot : m_plots) plot->resetView();
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (m_options.useSettings) {
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
    settings.setValue(kSessionKey, sessionToJson(session()));
  }
  m_controller->cancel();
  event->accept();
}

}  // namespace grazelab::ui
