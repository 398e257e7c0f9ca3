// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/accuracy_view.h"

#include "ui/plots/csv_table.h"

#include <QComboBox>

#include "ui/widgets/eliding_combo_box.h"
#include <QHBoxLayout>
#include <QLabel>
#include <QLegend>
#include <QVBoxLayout>

#include <algorithm>
#include <map>

#include "ui/plots/log_log_chart.h"

namespace grazelab::ui {
namespace {

QString text(std::string_view view) { return QString::fromUtf8(view.data(), qsizetype(view.size())); }

/// The setting overlaid before the user picks one: the coarsest Moreau-Jean step, where a
/// class sees a time stepper miss a graze or invent an impact.
constexpr auto kDefaultOverlay = core::methods::MethodKind::MoreauJean;

/// The method as a class says it (the command line's ids, "moreau-jean-theta1", are for files).
QString methodInWords(core::methods::MethodKind kind) {
  using core::methods::MethodKind;
  switch (kind) {
    case MethodKind::Exact: return AccuracyView::tr("exact solver");
    case MethodKind::MoreauJean: return AccuracyView::tr("Moreau–Jean, θ = 1/2");
    case MethodKind::MoreauJeanTheta1: return AccuracyView::tr("Moreau–Jean, θ = 1");
    case MethodKind::SchatzmanPaoli: return AccuracyView::tr("Schatzman–Paoli");
    case MethodKind::Dopri5Events: return AccuracyView::tr("Dormand–Prince 5(4) with events");
    case MethodKind::CvodeAdams: return AccuracyView::tr("CVODE Adams");
    case MethodKind::CvodeBdf: return AccuracyView::tr("CVODE BDF");
    case MethodKind::Penalty: return AccuracyView::tr("penalty spring");
  }
  return text(core::methods::methodName(kind));
}

/// Its setting in words: "step h = 0.01", "tolerance 1e-06", "stiffness 1e+06", "in binary128".
QString settingInWords(const core::methods::MethodSetting& setting) {
  using core::methods::MethodKind;
  const QString value = QString::number(setting.parameterValue(), 'g', 2);
  switch (setting.kind) {
    case MethodKind::Exact:
      return AccuracyView::tr("in %1").arg(text(core::toString(setting.precision)));
    case MethodKind::MoreauJean:
    case MethodKind::MoreauJeanTheta1:
    case MethodKind::SchatzmanPaoli: return AccuracyView::tr("step h = %1").arg(value);
    case MethodKind::Dopri5Events:
    case MethodKind::CvodeAdams:
    case MethodKind::CvodeBdf: return AccuracyView::tr("tolerance %1").arg(value);
    case MethodKind::Penalty: return AccuracyView::tr("stiffness %1").arg(value);
  }
  return value;
}

}  // namespace

QString accuracyLabel(const core::methods::WorkPrecisionPoint& point) {
  const auto& setting = point.setting;
  const QString label = methodInWords(setting.kind) + QStringLiteral(", ") + settingInWords(setting);
  if (point.status != core::methods::RunStatus::Completed) {
    return label + QStringLiteral(": %1").arg(text(core::methods::toString(point.status)));
  }
  return label + QStringLiteral(": error %1, %2 ms")
                     .arg(point.errors.state, 0, 'e', 1)
                     .arg(point.secondsMin * 1e3, 0, 'g', 2);
}

void AccuracyView::appendCsv(CsvTable& table) const {
  const QString plot = tr("Error against run time");
  table.describe(plot, tr("run time [s] (the fastest of its timed runs)"),
                 tr("state error at the end (max |Δu|/X, |Δv|/V against binary128)"),
                 tr("contact-time error (max |Δt|/T₂ over the matched contacts)"));
  if (!m_shown) return;
  for (const auto& p : m_shown->points) {
    const core::methods::WorkPrecisionPoint& point = p.point;
    if (point.status != core::methods::RunStatus::Completed) continue;
    const QString series = methodInWords(point.setting.kind) + QStringLiteral(", ") + settingInWords(point.setting);
    table.add(plot, series, point.secondsMin, point.errors.state, point.errors.contactTime);
  }
}

AccuracyView::AccuracyView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  m_chart = new LogLogChart(tr("Error against run time"), tr("run time [s]"),
                            tr("state error at the end"), this);
  m_chart->setToolTip(tr("Every method on the same start, timed on this machine and measured "
                         "against the exact solver in binary128. Lower is more accurate, left is "
                         "faster; each point is one step size or tolerance."));
  layout->addWidget(m_chart, 1);
  auto* row = new QHBoxLayout;
  auto* label = new QLabel(tr("Overlay on u₂(t):"), this);
  m_overlay = new ElidingComboBox(this);
  m_overlay->setToolTip(tr("Draw this method's u₂(t) and its contacts over the exact ones: "
                           "watch a time stepper miss a graze or invent an impact."));
  m_overlay->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  m_overlay->setMinimumContentsLength(16);
  label->setBuddy(m_overlay);
  m_summary = new QLabel(this);
  // the summary takes what room is left (in presentation mode its text would widen the window)
  m_summary->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  row->addWidget(label);
  row->addWidget(m_overlay, 1);
  row->addWidget(m_summary);
  layout->addLayout(row);
  connect(m_overlay, &QComboBox::activated, this, [this](int) {
    m_chosenLabel = m_overlay->currentText().section(':', 0, 0);
    emitOverlay();
  });
}

int AccuracyView::overlayCount() const { return m_overlay->count(); }

void AccuracyView::chooseOverlay(int index) {
  if (index < 0 || index >= m_overlay->count()) return;
  m_overlay->setCurrentIndex(index);
  m_chosenLabel = m_overlay->currentText().section(':', 0, 0);
  emitOverlay();
}

void AccuracyView::setPresentation(bool on, int textPixels) {
  m_chart->setPresentation(on, textPixels);
}

void AccuracyView::show(const SimUpdate& update) {
  if (!update.accuracy || update.accuracy == m_shown) {
    if (!update.accuracy && m_shown) {
      // a new run started: its sweep comes later
      m_shown.reset();
      m_chart->clear();
      m_overlay->clear();
      m_summary->clear();
      emit overlayChosen(nullptr, {});
    }
    return;
  }
  const AccuracyProgress& progress = *update.accuracy;
  // one curve per method, points by run time (the chart of the report)
  std::map<core::methods::MethodKind, std::vector<QPointF>> curves;
  for (const AccuracyPoint& p : progress.points) {
    if (p.point.status != core::methods::RunStatus::Completed) continue;
    curves[p.point.setting.kind].push_back({p.point.secondsMin, p.point.errors.state});
  }
  // every method has its curve from the start (empty until its first point), so that each
  // keeps its colour, the one it has in the report's pictures
  std::vector<LogLogCurve> all;
  for (core::methods::MethodKind kind : core::methods::kAllMethods) {
    std::vector<QPointF>& points = curves[kind];
    std::sort(points.begin(), points.end(),
              [](const QPointF& a, const QPointF& b) { return a.x() < b.x(); });
    all.push_back({methodInWords(kind), points});
  }
  m_chart->setCurves(all);
  // the picker: every finished setting, the user's choice kept
  m_overlay->blockSignals(true);
  m_overlay->clear();
  int chosen = -1, fallback = -1;
  for (std::size_t i = 0; i < progress.points.size(); ++i) {
    const QString label = accuracyLabel(progress.points[i].point);
    m_overlay->addItem(label, int(i));
    if (label.section(':', 0, 0) == m_chosenLabel) chosen = int(i);
    if (fallback < 0 && progress.points[i].point.setting.kind == kDefaultOverlay) fallback = int(i);
  }
  m_overlay->setCurrentIndex(chosen >= 0 ? chosen : fallback);
  m_overlay->blockSignals(false);
  m_summary->setText(tr("%1 of %2 settings, t ≤ %3")
                         .arg(progress.points.size())
                         .arg(progress.total)
                         .arg(progress.tEnd, 0, 'g', 4));
  m_shown = update.accuracy;
  emitOverlay();
}

void AccuracyView::emitOverlay() {
  const int index = m_overlay->currentIndex();
  if (!m_shown || index < 0 || index >= int(m_shown->points.size())) {
    emit overlayChosen(nullptr, {});
    return;
  }
  const AccuracyPoint& point = m_shown->points[std::size_t(index)];
  emit overlayChosen(point.run, m_overlay->currentText().section(':', 0, 0));
}

}  // namespace grazelab::ui
