// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/widgets/readout_panel.h"

#include <QEvent>
#include <QFontMetrics>
#include <QFormLayout>
#include <QLabel>

#include "ui/compute/derived.h"

namespace grazelab::ui {
namespace {

QString number(double value) { return QString::number(value, 'g', 8); }

}  // namespace

ReadoutPanel::ReadoutPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QFormLayout(this);
  layout->setLabelAlignment(Qt::AlignRight);
  addRow(QStringLiteral("k2"), tr("k₂"),
         tr("Stiffness between the masses; from the 1:2 design when it is on."));
  addRow(QStringLiteral("omega1"), tr("ω₁ (fast)"),
         tr("Angular frequency of mode 1. Mode 1 is the FAST mode: ω₁ = 2 ω₂ in 1:2 resonance."));
  addRow(QStringLiteral("omega2"), tr("ω₂ (slow)"),
         tr("Angular frequency of mode 2, the slow mode."));
  addRow(QStringLiteral("T1"), tr("T₁"), tr("Period of the fast mode, 2π/ω₁ (= T₂/2 in resonance)."));
  addRow(QStringLiteral("T2"), tr("T₂"),
         tr("Period of the slow mode, 2π/ω₂. Every free motion of a resonant chain repeats "
            "after T₂, and no free flight lasts longer (Theorem 2.3)."));
  addRow(QStringLiteral("lambdaStar"), tr("λ*"),
         tr("The grazing orbit GLO(λ*) that one-impact-per-period orbits tend to as their period "
            "tends to T₂ (Theorem 2.1)."));
  addRow(QStringLiteral("energy"), tr("energy E"),
         tr("Mechanical energy of the start state, ½ vᵀMv + ½ uᵀKu; conserved by the motion "
            "(impacts are elastic)."));
  fixValueSizes();
}

// Each value keeps one size, wide enough for any number it prints: a label whose size may
// change makes every new text re-lay out the whole side panel (its wrapped scene text
// included), a tenth of the GUI thread's time in a drag; a fixed-size one does not.
void ReadoutPanel::fixValueSizes() {
  for (QLabel* value : m_values) {
    const QFontMetrics metrics(value->font());
    const QSize widest = metrics.size(Qt::TextSingleLine, number(-8.8888888e-188));
    value->setFixedSize(widest + QSize(2 * value->margin() + 4, 2 * value->margin()));
  }
}

void ReadoutPanel::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() == QEvent::FontChange) fixValueSizes();
}

QLabel* ReadoutPanel::addRow(const QString& name, const QString& label, const QString& toolTip) {
  auto* title = new QLabel(label, this);
  auto* value = new QLabel(QStringLiteral("—"), this);
  value->setObjectName(name);
  value->setTextInteractionFlags(Qt::TextSelectableByMouse);
  title->setToolTip(toolTip);
  value->setToolTip(toolTip);
  static_cast<QFormLayout*>(layout())->addRow(title, value);
  m_values.append(value);
  return value;
}

void ReadoutPanel::showModel(const DerivedModel& derived, double energy) {
  const double values[] = {derived.model.k2, derived.modes.omegaFast, derived.modes.omegaSlow,
                           derived.modes.T1, derived.modes.T2, derived.lambdaStar, energy};
  for (int index = 0; index < m_values.size(); ++index) {
    m_values[index]->setText(number(values[index]));
  }
  setStale(false);
}

void ReadoutPanel::setStale(bool stale) { setEnabled(!stale); }

QString ReadoutPanel::text(const QString& name) const {
  for (const QLabel* label : m_values) {
    if (label->objectName() == name) return label->text();
  }
  return {};
}

}  // namespace grazelab::ui
