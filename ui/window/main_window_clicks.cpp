// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Starts chosen with the mouse: a click on the section H or on the stop line of the (u2, v2)
// portrait starts a run there on the same energy; the landscape's rectangles and its way back.
#include <QLabel>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/model/model.h"
#include "core/orbits/starts.h"
#include "core/solver/chain_run.h"
#include "ui/compute/derived.h"
#include "ui/window/main_window.h"
#include "ui/widgets/parameter_panel.h"
#include "ui/plots/landscape_view.h"
#include "ui/plots/shown_run.h"
#include "ui/window/status_line.h"

namespace grazelab::ui {

void MainWindow::setGloWeightsFrom(QPointF value) {
  if (!m_displayed) return;
  const Figures& figures = m_displayed->request->job.figures;
  const auto found = figures.find(PlotKind::GrazingSet);
  if (found == figures.end()) return;
  const std::vector<int>& modes = found->second.draggedModes;
  Params next = params();
  std::vector<double>& weights = next.massChain.weights;
  if (modes.size() < 2 || modes.size() > 3) return;
  for (int mode : modes) {
    if (mode < 0 || mode >= int(weights.size())) return;
  }
  // to the plot's resolution: a weight the panel shows in three decimals, not sixteen
  const auto rounded = [](double x) { return std::round(x * 1000) / 1000; };
  const double x = rounded(value.x()), y = modes.size() == 3 ? rounded(value.y()) : 0.0;
  std::fill(weights.begin(), weights.end(), 0.0);
  weights[std::size_t(modes[1])] = x;
  if (modes.size() == 3) weights[std::size_t(modes[2])] = y;
  weights[std::size_t(modes[0])] = rounded(1 - x - y);  // not 0.41200000000000003
  if (weights == params().massChain.weights) return;
  setParams(next);
}

bool MainWindow::startFromSection(QPointF value) {
  if (!m_displayed) return false;
  if (scene().massChain()) return startChainFromSection(value);
  // the section's units: u1 over d, v1 over d w1 (the fast frequency)
  const core::Model& model = m_displayed->request->job.spec.model;
  const QPointF u1v1(value.x() * model.gap, value.y() * model.gap * core::computeModes(model).omegaFast);
  const double level = core::energy(model, m_displayed->request->job.spec.run.initial);
  const std::optional<core::State> start = core::sectionStateAtEnergy(model, level, u1v1.x(), u1v1.y());
  if (!start) {
    m_status->setMessage(tr("No state of this energy (E = %1) at u₁ = %2, v₁ = %3 on H: the "
                         "springs and mass 1 alone would hold more. Click inside the points.")
                          .arg(level, 0, 'g', 6)
                          .arg(u1v1.x(), 0, 'g', 4)
                          .arg(u1v1.y(), 0, 'g', 4));
    return false;
  }
  startFromClick(core::chainStateOf(*start));
  return true;
}

bool MainWindow::startFromStopLine(QPointF value, double tolerance) {
  if (!m_displayed) return false;
  if (scene().massChain()) return startChainFromStopLine(value, tolerance);
  // the portrait's units: u2 over d, v2 over d w1 (the fast frequency)
  const core::Model& model = m_displayed->request->job.spec.model;
  if (!(std::abs(value.x() - 1) <= tolerance)) {
    m_status->setMessage(tr("Click within %1 pixels of the stop line u₂ = d (dashed) to start mass 2 "
                            "from the stop at that speed.")
                             .arg(kStopLineBand));
    return false;
  }
  const double speed = value.y() * model.gap * core::computeModes(model).omegaFast;
  const core::State& shown = m_displayed->request->job.spec.run.initial;
  const double level = core::energy(model, shown);
  const std::optional<core::State> start = core::stopLineStateAtEnergy(model, level, shown.u1, speed, shown.v1);
  if (!start) {
    m_status->setMessage(tr("No state of this energy (E = %1) with mass 2 leaving the stop at "
                         "speed %2 and mass 1 at u₁ = %3: click nearer v₂ = 0.")
                          .arg(level, 0, 'g', 6)
                          .arg(std::abs(speed), 0, 'g', 4)
                          .arg(shown.u1, 0, 'g', 4));
    return false;
  }
  startFromClick(core::chainStateOf(*start));
  return true;
}

bool MainWindow::startChainFromSection(QPointF value) {
  const auto& chains = m_displayed->request->job.spec.chains;
  if (chains.empty()) return false;
  const core::MassChain& chain = chains.front().chain;
  const core::ChainState& shown = chains.front().start;
  const int n = chain.size();
  if (n == 1) {
    m_status->setMessage(tr("A chain of one mass has no section to start from: on H its place is the "
                            "stop and its speed is the energy's. Click the stop line of its portrait."));
    return false;
  }
  // the plot's pair and units (displacements over d, velocities over d w1, the fastest
  // frequency), as the plot reads them
  const std::optional<ShownRun> run = shownRun(*m_displayed);
  if (!run) return false;
  const double speed = run->speed;
  const auto unscaled = [&](int c, double plotted) { return plotted * (c < n ? chain.gap : speed); };
  const int a = run->sectionX, b = run->sectionY;
  const double level = core::chainEnergy(chain, shown);
  // the other coordinates as at the run's contact drawn nearest the click (on the energy level
  // and on H, as the click is): the start's own, far from the section's points, held more than
  // the energy almost everywhere (eight masses: every click was refused)
  core::ChainState base = shown;
  const PointSpan points = run->sectionPoints();
  if (!points.empty()) {
    // distances in the plot's proportions: each coordinate over the points' spread
    double spreadX = 1e-300, spreadY = 1e-300;
    for (std::size_t k = 0; k < points.size(); ++k) {
      spreadX = std::max(spreadX, std::abs(points[k].x() - points[0].x()));
      spreadY = std::max(spreadY, std::abs(points[k].y() - points[0].y()));
    }
    double nearest = std::numeric_limits<double>::infinity();
    std::size_t at = 0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const double distance = std::hypot((points[k].x() - value.x()) / spreadX, (points[k].y() - value.y()) / spreadY);
      if (distance < nearest) {
        nearest = distance;
        at = k;
      }
    }
    const core::experiments::StateRecords& section = m_displayed->chains.front()->section;
    for (int i = 0; i < n; ++i) {
      base.u[i] = section.u(at, i);
      base.v[i] = section.v(at, i);
    }
  }
  const core::ChainSectionStart start = core::chainSectionStateAtEnergy(
      chain, level, base, a, unscaled(a, value.x()), b, unscaled(b, value.y()));
  switch (start.problem) {
    case core::ChainSectionProblem::None:
      break;
    case core::ChainSectionProblem::StoppedMassCoordinate:
      m_status->setMessage(tr("The section shows mass %1's own coordinate, which H fixes (u%1 = d) or "
                              "the energy decides (v%1): choose other coordinates in 'section on' "
                              "to start from a click.")
                               .arg(chain.stopped()));
      return false;
    case core::ChainSectionProblem::EnergyTooLow:
      m_status->setMessage(tr("No state of this energy (E = %1) there: with the other masses as at the "
                              "nearest contact, the springs already hold more. Click nearer the points.")
                               .arg(level, 0, 'g', 6));
      return false;
  }
  startFromClick(start.state);
  return true;
}

bool MainWindow::startChainFromStopLine(QPointF value, double tolerance) {
  const auto& chains = m_displayed->request->job.spec.chains;
  if (chains.empty()) return false;
  const core::MassChain& chain = chains.front().chain;
  const std::optional<ShownRun> run = shownRun(*m_displayed);
  if (!run || run->chosen != run->stopped) {
    m_status->setMessage(tr("Starts are clicked on the stop line of mass %1's portrait: set 'phase "
                            "of' to %1, or click the Poincaré points.")
                             .arg(chain.stopped()));
    return false;
  }
  if (!(std::abs(value.x() - 1) <= tolerance)) {
    m_status->setMessage(tr("Click within %1 pixels of the stop line u%2 / d = 1 (dashed) to start mass %2 "
                            "from the stop at that speed.")
                             .arg(kStopLineBand)
                             .arg(chain.stopped()));
    return false;
  }
  startFromClick(core::chainStopLineState(chain, chains.front().start, value.y() * run->speed));
  return true;
}

void MainWindow::showMapRegion(QRectF region) {
  Params& current = m_sceneParams[std::size_t(m_sceneIndex)];
  const DerivedModel derived = deriveModel(current);
  if (!derived.ok) return;
  // a region a few ulps wide would have no distinct cells (and no ticks): refused, said
  const auto tooNarrow = [](double low, double high) {
    return !(high - low > 1e-9 * std::max({1.0, std::abs(low), std::abs(high)}));
  };
  if (tooNarrow(region.left(), region.right()) || tooNarrow(region.top(), region.bottom())) {
    m_status->setMessage(tr("That region is too small to compute apart from its neighbours: drag a larger one"));
    return;
  }
  // kept in units of d and d w2, so that it frames the same part of the plane for any chain
  const double d = derived.model.gap;
  const double v = d * derived.modes.omegaSlow;
  m_regionHistory.push_back(current.mapRegion);
  current.mapRegion = {region.left() / d, region.right() / d, region.top() / v, region.bottom() / v};
  if (m_landscape) m_landscape->setBackEnabled(true);
  recompute();
}

bool MainWindow::mapRegionBack() {
  if (m_regionHistory.empty()) return false;
  m_sceneParams[std::size_t(m_sceneIndex)].mapRegion = m_regionHistory.back();
  m_regionHistory.pop_back();
  if (m_landscape) m_landscape->setBackEnabled(!m_regionHistory.empty());
  recompute();
  return true;
}

void MainWindow::startFromClick(const core::ChainState& start) {
  m_clickedStart = start;
  m_panel->setClickedStart(start);
  m_panel->clearRefusal();  // a refused value typed before does not describe this run
  followDataFromNextUpdate();
  recompute();
}

}  // namespace grazelab::ui
