// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The status line and the problem banner: what was computed, at what cost and how far it can
// be trusted, in words; why nothing was computed.
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

#include <algorithm>
#include <cmath>

#include "core/solver/trust.h"
#include "ui/window/main_window.h"
#include "ui/widgets/parameter_panel.h"
#include "ui/plots/plot_view.h"
#include "ui/widgets/readout_panel.h"
#include "ui/window/status_line.h"

namespace grazelab::ui {
namespace {

QString scientific(double value) { return QString::number(value, 'g', 3); }

QString number(double value, int digits = 4) { return QString::number(value, 'g', digits); }

QString stopInWords(core::StopReason stop) {
  switch (stop) {
    case core::StopReason::ContactLimit:
      return MainWindow::tr("the contacts asked for");
    case core::StopReason::TimeLimit:
      return MainWindow::tr("its end time");
    case core::StopReason::NoFurtherContact:
      return MainWindow::tr("no further contact (the flight stays below the stop)");
    case core::StopReason::Undecided:
      return MainWindow::tr(
          "undecided: a contact within the rounding of binary128 too (a top of the stopped mass "
          "at the stop, or at rest there with no force either way)");
    case core::StopReason::SearchBudget:
      return MainWindow::tr("the contact search's budget: no contact decided within 1000 of the slowest "
                            "periods (not commensurate: no period bounds the next one)");
    case core::StopReason::Cancelled:
      return MainWindow::tr("cancelled");
    case core::StopReason::InvalidInput: break;
  }
  return {};
}

// A run of N masses in words for the status line: contacts by kind, its end and why, energy drift.
QString chainStatusOf(const core::experiments::ChainSeries& series) {
  const core::ChainRun& run = series.run;
  const auto counted = [](long n, const QString& one, const QString& many) {
    return QStringLiteral("%1 %2").arg(n).arg(n == 1 ? one : many);
  };
  const double drift =
      std::abs(run.energyFinal - run.energyInitial) / std::max(std::abs(run.energyInitial), 1e-300);
  if (run.contacts == 0 && run.stop == core::StopReason::SearchBudget) {
    // ("0 contacts until t = 0, ended by the search's budget" read as a run that never began)
    return MainWindow::tr("%1: no contact of the stopped mass in its first 1000 slowest periods (a chain with "
                          "no common period: nothing bounds when it comes back; a search goes no further)")
        .arg(counted(series.chain.size(), MainWindow::tr("mass"), MainWindow::tr("masses")));
  }
  return MainWindow::tr("%1: %2 (%3, %4, %5) until t = %6, ended by %7 · energy drift %8")
      .arg(counted(series.chain.size(), MainWindow::tr("mass"), MainWindow::tr("masses")))
      .arg(counted(run.contacts, MainWindow::tr("contact"), MainWindow::tr("contacts")),
           counted(run.impacts, MainWindow::tr("impact"), MainWindow::tr("impacts")),
           counted(run.grazings, MainWindow::tr("grazing"), MainWindow::tr("grazings")),
           counted(run.sticks, MainWindow::tr("stick"), MainWindow::tr("sticks")))
      .arg(number(run.tFinal, 6), stopInWords(run.stop), QString::number(drift, 'e', 1));
}

}  // namespace

void MainWindow::showProblem(const QString& message) {
  // the last valid result stays on screen; only the message and the read-outs change
  m_problem = message;
  m_panel->setMessage(message);
  m_readout->setStale(true);
  // the scene's last valid run stays, greyed; a scene with none yet says why in its views (they
  // showed bare -1..1 axes, and the status line a last valid result that was not there)
  const bool shown = m_displayed.has_value() && m_displayed->request->sceneName == scene().name();
  for (PlotView* plot : m_plots) plot->setStale(shown);
  for (SceneView* view : m_sceneViews) view->setEmptyNote(shown ? QString() : tr("Nothing computed: %1").arg(message));
  m_status->setMessage(shown ? tr("Not computed: %1 (showing the last valid result)").arg(message)
                             : tr("Not computed: %1").arg(message));
}

void MainWindow::showStatus(const SimUpdate& update) {
  if (!update.request->job.spec.chains.empty() || scene().massChain()) {
    // an experiment of chains: the scene's words, then its first run's (no two-mass run is
    // made); the linear motion alone (a free series) has no run to tell
    const SceneJob& job = update.request->job;
    QString text = job.ok ? job.status : tr("Not computed: %1").arg(job.message);
    const bool free = job.spec.chains.empty() || job.spec.chains.front().free;
    if (job.ok && !update.chains.empty() && !free) {
      const core::experiments::ChainSeries& shown = *update.chains.front();
      text += (text.isEmpty() ? QString() : QStringLiteral(" · ")) + chainStatusOf(shown);
      if (job.spec.chains.front().trust == core::TrustMode::Off) {
        text += tr(" · no error estimate here (its shadow run in long double would take seconds on a "
                   "chain with no common period: grazelab-cli simulate --masses … --trust auto gives it)");
      }
      if (shown.precision != core::Precision::Double) {
        text += tr(" · run in %1 (double could not decide a contact)")
                    .arg(shown.precision == core::Precision::Long ? tr("long double") : tr("binary128"));
      }
      const core::Trust& trust = shown.trust;
      if (trust.verdict == core::Verdict::Unchecked) {
        // not asked for (the scene says why), or not yet there
      } else if (trust.shadowEvents == 0 && trust.verdict == core::Verdict::Ok && shown.run.contacts == 0) {
        // a run with no event gives its shadow nothing to compare ("ok ... until t = 0" said nothing)
        text += QStringLiteral(" · ") + tr("no error estimate (no contact to compare)");
      } else {
        text += QStringLiteral(" · ") + trustInWords(trust, shown.run.tFinal);
      }
    }
    m_status->setExplanation(m_statusExplanation + (update.precisionNote.empty()
                                                        ? QString()
                                                        : QStringLiteral("\n\n") +
                                                              QString::fromStdString(update.precisionNote)));
    if (update.trustPending && !update.superseded) {
      text += tr(" · trust: estimating…");
    } else if (!update.final || update.superseded) {
      text += tr(" · computing…");
    }
    if (!m_droppedNote.isEmpty()) text += QStringLiteral(" · ") + m_droppedNote;
    if (!m_problem.isEmpty()) text = tr("Not computed: %1 (showing the last valid result)").arg(m_problem);
    m_status->setMessage(text);
    return;
  }
  const core::Result& result = *update.result;
  const core::Cost& cost = result.cost;
  // "1 stick", "2 sticks": the count decides the word
  auto counted = [](std::int64_t n, const QString& one, const QString& many) {
    return QStringLiteral("%1 %2").arg(n).arg(n == 1 ? one : many);
  };
  QString text = tr("%1 (%2, %3, %4) · %5 ms · energy drift %6 · max |u₂ − d| at contacts %7")
                     .arg(counted(cost.contacts, tr("contact"), tr("contacts")),
                          counted(cost.impacts, tr("impact"), tr("impacts")),
                          counted(cost.grazings, tr("grazing"), tr("grazings")),
                          counted(cost.sticks, tr("stick"), tr("sticks")))
                     .arg(cost.wallSeconds * 1e3, 0, 'f', 1)
                     .arg(scientific(cost.maxRelEnergyDrift))
                     .arg(scientific(cost.maxContactResidual));
  // a run raised to a higher precision says so early in the line; why, in the tooltip
  m_status->setExplanation(m_statusExplanation + (update.precisionNote.empty()
                                                      ? QString()
                                                      : QStringLiteral("\n\n") +
                                                            QString::fromStdString(update.precisionNote)));
  if (update.attempt > 0) {
    const int counts = int(text.indexOf(QStringLiteral(" · ")));
    text.insert(counts, tr(" in %1").arg(update.attempt == 1 ? tr("long double") : tr("binary128")));
  }
  if (update.trust) text += QStringLiteral(" · ") + trustInWords(*update.trust, result.tFinal);
  // a superseded run (shown during a drag) gets no estimate: the newest value's run follows
  if (update.trustPending && !update.superseded) text += tr(" · trust: estimating…");
  if (update.accuracy) {
    text += tr(" · methods: %1 of %2 settings measured")
                .arg(update.accuracy->points.size())
                .arg(update.accuracy->total);
  }
  if (!update.final || update.superseded) {
    text += tr(" · computing…");
  } else if (result.stop == core::StopReason::Cancelled) {
    text += tr(" · cancelled");
  } else if (!result.message.empty()) {
    text += QStringLiteral(" · ") + QString::fromStdString(result.message);
  }
  if (!m_droppedNote.isEmpty()) text += QStringLiteral(" · ") + m_droppedNote;
  if (!m_problem.isEmpty()) text = tr("Not computed: %1 (showing the last valid result)").arg(m_problem);
  m_status->setMessage(text);
}

QString MainWindow::trustInWords(const core::Trust& trust, double tEnd) {
  const QString error = scientific(std::max(trust.stateError, trust.timeError));
  const QString horizon = scientific(trust.horizon);
  if (trust.verdict == core::Verdict::Unreliable && trust.horizon > 0 && trust.horizon < tEnd) {
    // the usual case on ordinary settings: chaos, not a fault; say what still holds
    return tr("chaotic: after t ≈ %1 the exact path depends on rounding (error ≈ %2 at the end); "
              "the statistics shown still hold")
        .arg(horizon, error);
  }
  switch (trust.verdict) {
    // an extrapolated horizon is a conservative lower bound, and is said to be one
    case core::Verdict::Ok:
      return trust.horizonObserved
                 ? tr("trust: ok (error ≈ %1; the path holds to 1e-6 until t ≈ %2, observed)").arg(error, horizon)
                 : tr("trust: ok (error ≈ %1; the path holds to 1e-6 at least until t ≈ %2, extrapolated)")
                       .arg(error, horizon);
    case core::Verdict::Degraded:
      return trust.horizonObserved
                 ? tr("trust: degraded (error ≈ %1; the path holds to 1e-6 until t ≈ %2, observed)").arg(error, horizon)
                 : tr("trust: degraded (error ≈ %1; the path holds to 1e-6 at least until t ≈ %2, extrapolated)")
                       .arg(error, horizon);
    case core::Verdict::Unreliable:
      return tr("trust: unreliable (error ≈ %1): %2").arg(error, QString::fromStdString(trust.reason));
    case core::Verdict::Unchecked: break;
  }
  return tr("trust: not checked");
}

void MainWindow::setProgressVisible(bool visible) {
  m_progress->setVisible(visible);
  m_cancel->setVisible(visible);
}

QString MainWindow::statusText() const { return m_status->message(); }

QString MainWindow::problem() const { return m_problem; }

}  // namespace grazelab::ui
