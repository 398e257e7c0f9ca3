// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/widgets/chain_editor.h"

#include "ui/widgets/eliding_combo_box.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <numeric>

#include "ui/widgets/batched_layout.h"
#include "ui/widgets/slider_spin.h"

namespace grazelab::ui {
namespace {

ParamSpec massSpec(int index) {
  ParamSpec spec = paramSpec(ParamKey::M1);
  spec.label = QObject::tr("m%1").arg(subscriptDigits(index));
  spec.toolTip = QObject::tr("Mass %1 (counted from the left wall).").arg(index);
  spec.sliderMin = 0.01;
  spec.sliderMax = 100;
  spec.spinMin = 1e-6;
  spec.spinMax = 1e6;
  spec.logarithmic = true;
  spec.marks = {};
  return spec;
}

ParamSpec springSpec(int index) {
  ParamSpec spec = paramSpec(ParamKey::K1);
  spec.label = QObject::tr("k%1").arg(subscriptDigits(index));
  spec.toolTip =
      index == 1 ? QObject::tr("The spring from the wall to mass 1 (the chain's stiffness scale).")
                 : QObject::tr("The spring between masses %1 and %2.").arg(index - 1).arg(index);
  spec.sliderMin = 0.01;
  spec.sliderMax = 100;
  spec.spinMin = 1e-6;
  spec.spinMax = 1e6;
  spec.logarithmic = true;
  spec.marks = {};
  return spec;
}

ParamSpec wallSpec(int masses) {
  ParamSpec spec = springSpec(masses + 1);
  spec.toolTip = QObject::tr("The spring from mass %1 to the right wall (kept as given when the springs are designed).")
                     .arg(masses);
  return spec;
}

ParamSpec weightSpec(int index) {
  ParamSpec spec = paramSpec(ParamKey::Lambda);
  spec.label = QObject::tr("λ%1").arg(subscriptDigits(index));
  spec.toolTip = QObject::tr(
                     "The weight of mode %1 (mode 1 the fastest) in the grazing linear orbit "
                     "GLO(λ) = Σ λⱼ GLOMⱼ the run starts on, at its touch of the stop. The "
                     "first weight (the fastest mode's) is 1 minus the others.")
                     .arg(index);
  spec.sliderMin = -1;
  spec.sliderMax = 2;
  spec.spinMin = -1e3;
  spec.spinMax = 1e3;
  spec.marks = {0.0, 1.0};
  return spec;
}

}  // namespace

QString resonanceName(const std::vector<int>& harmonics) {
  if (harmonics.empty()) return QObject::tr("none: springs as given");
  QStringList parts;
  for (auto it = harmonics.rbegin(); it != harmonics.rend(); ++it)
    parts.append(QString::number(*it));
  return parts.join(QLatin1Char(':'));
}

QList<std::vector<int>> ChainEditor::resonancesFor(int masses) {
  QList<std::vector<int>> list{{}};
  if (masses == 2) list.append({{2, 1}, {3, 1}, {3, 2}, {4, 1}});
  if (masses == 3) list.append({{3, 2, 1}, {4, 2, 1}, {5, 3, 1}, {4, 3, 2}});
  if (masses >= 4 && masses <= 6) {
    std::vector<int> chain(static_cast<std::size_t>(masses));
    std::iota(chain.rbegin(), chain.rend(), 1);  // N : ... : 1
    list.append(chain);
  }
  return list;
}

ChainEditor::ChainEditor(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* form = new QFormLayout;
  m_form = form;
  form->setContentsMargins(0, 0, 0, 0);
  m_count = new QSpinBox(this);
  m_count->setObjectName(QStringLiteral("chainMassCount"));
  m_count->setRange(1, MassChainParams::kMaxMasses);
  m_count->setToolTip(tr("How many masses the chain has (1 to %1), from the left wall.")
                          .arg(MassChainParams::kMaxMasses));
  m_stop = new QSpinBox(this);
  m_stop->setObjectName(QStringLiteral("chainStopMass"));
  m_stop->setToolTip(
      tr("The mass the rigid stop acts on, at its gap d to the right of that mass's rest."));
  auto* countRow = new QHBoxLayout;
  countRow->addWidget(m_count);
  countRow->addWidget(new QLabel(tr("stop on"), this));
  countRow->addWidget(m_stop);
  countRow->addStretch(1);
  form->addRow(tr("masses"), countRow);
  m_shown = new QSpinBox(this);
  m_shown->setObjectName(QStringLiteral("chainShownMass"));
  m_shown->setToolTip(
      tr("The mass whose phase portrait (with its state at each contact) is drawn, and whose "
         "trace is drawn beside the stopped mass's; the stopped mass by default."));
  auto* shownRow = new QHBoxLayout;
  shownRow->addWidget(m_shown);
  shownRow->addStretch(1);
  form->addRow(tr("phase of"), shownRow);
  m_shownRow = shownRow;
  m_sectionX = new QComboBox(this);
  m_sectionX->setObjectName(QStringLiteral("chainSectionX"));
  m_sectionY = new QComboBox(this);
  m_sectionY->setObjectName(QStringLiteral("chainSectionY"));
  for (QComboBox* axis : {m_sectionX, m_sectionY}) {
    axis->setToolTip(
        tr("The two coordinates of the state the Poincaré points on H are drawn on: at each "
           "contact the stopped mass is on the stop (u_s = d), and the other masses' positions "
           "and the velocities (before the contact) say where the motion is."));
  }
  auto* sectionRow = new QHBoxLayout;
  sectionRow->addWidget(m_sectionX);
  sectionRow->addWidget(new QLabel(tr("against"), this));
  sectionRow->addWidget(m_sectionY);
  sectionRow->addStretch(1);
  form->addRow(tr("section on"), sectionRow);
  m_sectionRow = sectionRow;
  m_resonance = new ElidingComboBox(this);
  m_resonance->setObjectName(QStringLiteral("chainResonance"));
  m_resonance->setToolTip(
      tr("The frequency ratio asked for, slowest mode first (1:2:3: ω₃ : ω₂ : ω₁ = 1 : 2 : 3). "
         "The springs k₂ … k_N are then designed for it, k₁ kept; a ratio no chain "
         "with these masses has is refused with the reason."));
  m_design = new ElidingComboBox(this);
  m_design->setObjectName(QStringLiteral("chainDesign"));
  m_design->setToolTip(
      tr("A resonance usually has several designs of the springs for the same masses "
         "(ordered by k₂, stiffest first): pick one."));
  // narrow: a projector's panel has little room (the popups show the whole texts)
  for (QComboBox* combo : {m_resonance, m_design}) {
    combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    combo->setMinimumContentsLength(10);
  }
  // no text of its own: a long one widened the panel past a projector's column
  m_wall = new QCheckBox(this);
  m_wall->setObjectName(QStringLiteral("chainRightWall"));
  m_wall->setToolTip(tr("A right wall: the last mass held by one more spring, k_(N+1), to a wall on the right. "
                        "Designs keep it as given."));
  form->addRow(tr("right wall"), m_wall);
  form->addRow(tr("resonance"), m_resonance);
  m_designLabel = new QLabel(tr("springs"), this);
  form->addRow(m_designLabel, m_design);
  layout->addLayout(form);
  m_rows = new QVBoxLayout;
  m_rows->setContentsMargins(0, 0, 0, 0);
  m_rows->setSpacing(2);
  layout->addLayout(m_rows);
  m_summary = new QLabel(this);
  m_summary->setObjectName(QStringLiteral("chainSummary"));
  m_summary->setWordWrap(true);
  m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(m_summary);

  connect(m_count, &QSpinBox::valueChanged, this, [this](int count) {
    const bool resonant = !m_chain.harmonics.empty();
    m_chain = m_chain.resized(count);
    // a resonant chain stays resonant: N : ... : 1, the first resonance offered for that many
    // masses (1:2:3 became "none" without a word); where none is offered the summary says so
    const QList<std::vector<int>> offered = resonancesFor(count);
    if (resonant && offered.size() > 1) m_chain.harmonics = offered[1];
    fillResonances();
    rebuildRows();
    changed();
  });
  connect(m_stop, &QSpinBox::valueChanged, this, [this](int stop) {
    m_chain.stopMass = stop == m_chain.size() ? 0 : stop;
    fillSection();  // the default pair follows the stop
    if (m_chain.shownMass == 0) {
      // so does the phase portrait's mass, and the box says which (it said 3 while 2 was drawn)
      const QSignalBlocker block(m_shown);
      m_shown->setValue(m_chain.stopped());
    }
    changed();
  });
  connect(m_shown, &QSpinBox::valueChanged, this, [this](int shown) {
    m_chain.shownMass = shown == m_chain.stopped() ? 0 : shown;
    changed();
  });
  connect(m_wall, &QCheckBox::toggled, this, [this](bool wall) {
    if (!wall && m_chain.rightSpring > 0) m_lastWall = m_chain.rightSpring;
    m_chain.rightSpring = wall ? m_lastWall : 0.0;
    rebuildRows();
    changed();
  });
  connect(m_sectionX, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index < 0) return;
    m_chain.sectionX = index + 1 == m_chain.sectionMass() ? 0 : index + 1;
    changed();
  });
  connect(m_sectionY, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index < 0) return;
    m_chain.sectionY = index + 1 == m_chain.size() + m_chain.sectionMass() ? 0 : index + 1;
    changed();
  });
  connect(m_resonance, &QComboBox::currentIndexChanged, this, [this](int index) {
    const QList<std::vector<int>> offered = resonancesFor(m_chain.size());
    if (index < 0 || index >= offered.size()) return;
    m_chain.harmonics = offered[index];
    m_chain.designBranch = 1;
    rebuildRows();
    changed();
  });
  connect(m_design, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index < 0) return;
    m_chain.designBranch = index + 1;
    changed();
  });
  setChain(m_chain);
}

void ChainEditor::setChain(const MassChainParams& chain) {
  // the same rows with other values (a weight dragged in a plot, a session of the same shape):
  // the values set in place, not every row rebuilt on each move of the mouse
  const bool sameRows = chain.size() == m_chain.size() && chain.harmonics == m_chain.harmonics &&
                        (chain.rightSpring > 0) == (m_chain.rightSpring > 0) &&
                        m_masses.size() == chain.size() && m_firstWeight;
  if (sameRows) {
    m_chain = chain;
    const int n = chain.size();
    for (int i = 0; i < n; ++i) m_masses[i]->setValue(chain.masses[std::size_t(i)]);
    for (int i = 0; i < m_springs.size(); ++i) m_springs[i]->setValue(chain.springs[std::size_t(i)]);
    if (m_wallSpring) m_wallSpring->setValue(chain.rightSpring);
    for (int j = 0; j < m_weights.size(); ++j) m_weights[j]->setValue(chain.weights[std::size_t(j) + 1]);
    showFirstWeight();
    const QSignalBlocker blockStop(m_stop);
    const QSignalBlocker blockShown(m_shown);
    m_stop->setValue(chain.stopped());
    m_shown->setValue(chain.shown());
    fillSection();
    return;
  }
  m_chain = chain;
  {
    const QSignalBlocker blockCount(m_count);
    const QSignalBlocker blockStop(m_stop);
    m_count->setValue(chain.size());
    m_stop->setRange(1, chain.size());
    m_stop->setValue(chain.stopMass > 0 ? chain.stopMass : chain.size());
  }
  {
    const QSignalBlocker blockWall(m_wall);
    m_wall->setChecked(chain.rightSpring > 0);
  }
  fillResonances();
  rebuildRows();
}

void ChainEditor::fillResonances() {
  const QSignalBlocker block(m_resonance);
  m_resonance->clear();
  int chosen = 0;
  const QList<std::vector<int>> offered = resonancesFor(m_chain.size());
  for (int i = 0; i < offered.size(); ++i) {
    m_resonance->addItem(resonanceName(offered[i]));
    if (offered[i] == m_chain.harmonics) chosen = i;
  }
  if (!m_chain.harmonics.empty() && !offered.contains(m_chain.harmonics)) {
    // a resonance from a session file that the menu does not list: shown as it is
    m_resonance->addItem(resonanceName(m_chain.harmonics));
    chosen = m_resonance->count() - 1;
  }
  m_resonance->setCurrentIndex(chosen);
}

void ChainEditor::rebuildRows() {
  const BatchedLayout oneLayoutPass(this);
  // taken out of the layout by hand: a held (disabled) layout ignores its children's removal
  // and would keep their dead items
  const auto discard = [this](QWidget* widget) {
    m_rows->removeWidget(widget);
    delete widget;
  };
  for (QList<SliderSpin*>* list : {&m_masses, &m_springs, &m_weights}) {
    for (SliderSpin* control : *list) discard(control);
    list->clear();
  }
  if (m_firstWeight) discard(m_firstWeight);
  m_firstWeight = nullptr;
  if (m_wallSpring) discard(m_wallSpring);
  m_wallSpring = nullptr;
  {
    const QSignalBlocker blockStop(m_stop);
    const QSignalBlocker blockShown(m_shown);
    m_stop->setRange(1, m_chain.size());
    m_stop->setValue(m_chain.stopMass > 0 ? m_chain.stopMass : m_chain.size());
    m_shown->setRange(1, m_chain.size());
    m_shown->setValue(m_chain.shownMass > 0 ? m_chain.shownMass : m_chain.stopped());
  }
  fillSection();
  const auto add = [this](const ParamSpec& spec, double value, auto store) {
    auto* control = new SliderSpin(spec, this);
    control->setValue(value);
    m_rows->addWidget(control);
    connect(control, &SliderSpin::valueChanged, this, [this, store](double typed) {
      store(typed);
      changed();
    });
    connect(control, &SliderSpin::refused, this, &ChainEditor::inputRefused);
    return control;
  };
  const int n = m_chain.size();
  for (int i = 0; i < n; ++i) {
    m_masses.append(add(massSpec(i + 1), m_chain.masses[std::size_t(i)],
                        [this, i](double value) { m_chain.masses[std::size_t(i)] = value; }));
  }
  // designed: only k1 is the user's (the scale); the others come back in the summary
  const int springs = m_chain.harmonics.empty() ? n : 1;
  for (int i = 0; i < springs; ++i) {
    m_springs.append(add(springSpec(i + 1), m_chain.springs[std::size_t(i)],
                         [this, i](double value) { m_chain.springs[std::size_t(i)] = value; }));
  }
  if (m_chain.rightSpring > 0) {
    m_wallSpring = add(wallSpec(n), m_chain.rightSpring, [this](double value) { m_chain.rightSpring = value; });
  }
  // λ2 ... λN on sliders, the fastest mode's λ1 balancing them: the note's λ of two modes (the
  // slow mode's weight) and the (λ2, λ3) plane of three are the sliders themselves, and move the
  // grazing set's dot the way they move
  m_firstWeight = new QLabel(this);
  m_firstWeight->setObjectName(QStringLiteral("chainFirstWeight"));
  m_firstWeight->setToolTip(weightSpec(1).toolTip);
  showFirstWeight();
  m_rows->addWidget(m_firstWeight);
  for (int j = 1; j < n; ++j) {
    m_weights.append(add(weightSpec(j + 1), m_chain.weights[std::size_t(j)], [this, j, n](double value) {
      m_chain.weights[std::size_t(j)] = value;
      double others = 0;
      for (int k = 1; k < n; ++k) others += m_chain.weights[std::size_t(k)];
      m_chain.weights.front() = 1 - others;  // the weights of GLO(λ) sum to 1
      showFirstWeight();
    }));
  }
  setWeightsShown(m_weightsShown);
  m_design->setVisible(!m_chain.harmonics.empty());
  m_designLabel->setVisible(!m_chain.harmonics.empty());
}

void ChainEditor::setSummary(const QString& text, int designs, bool refused) {
  // a refusal moves no control (a drag refused half-way moved the slider under the pointer by
  // 115 px): the summary keeps at least the height its text so far needs at its width (not
  // merely its present height, which a relayout under way can have shrunk), the designs row
  // stays, greyed
  const int kept = std::max(m_summary->height(), m_summary->heightForWidth(m_summary->width()));
  m_summary->setMinimumHeight(refused ? kept : 0);
  m_summary->setText(text);
  m_summary->setStyleSheet(refused ? QStringLiteral("QLabel { color: #a01010; font-weight: bold; }")
                                   : QString());
  m_design->setEnabled(!refused);
  if (refused) return;
  const QSignalBlocker block(m_design);
  if (m_design->count() != designs) {
    m_design->clear();
    for (int d = 1; d <= designs; ++d) m_design->addItem(tr("design %1 of %2").arg(d).arg(designs));
  }
  m_design->setCurrentIndex(std::min(m_chain.designBranch, designs) - 1);
  m_design->setVisible(!m_chain.harmonics.empty() && designs > 0);
  m_designLabel->setVisible(m_design->isVisibleTo(this));
}

QString ChainEditor::summary() const { return m_summary->text(); }

void ChainEditor::fillSection() {
  const QSignalBlocker blockX(m_sectionX);
  const QSignalBlocker blockY(m_sectionY);
  const int n = m_chain.size();
  for (QComboBox* axis : {m_sectionX, m_sectionY}) {
    axis->clear();
    for (int i = 1; i <= n; ++i) axis->addItem(tr("u%1").arg(subscriptDigits(i)));
    for (int i = 1; i <= n; ++i) axis->addItem(tr("v%1").arg(subscriptDigits(i)));
  }
  m_sectionX->setCurrentIndex(m_chain.sectionXResolved() - 1);
  m_sectionY->setCurrentIndex(m_chain.sectionYResolved() - 1);
}

void ChainEditor::setSectionOffered(bool offered) { m_form->setRowVisible(m_sectionRow, offered); }

void ChainEditor::setShownMassOffered(bool offered) { m_form->setRowVisible(m_shownRow, offered); }

void ChainEditor::setWeightsShown(bool shown) {
  m_weightsShown = shown;
  for (SliderSpin* weight : m_weights) weight->setVisible(shown);
  if (m_firstWeight) m_firstWeight->setVisible(shown);
}

void ChainEditor::showFirstWeight() {
  m_firstWeight->setText(tr("λ₁ = 1 − the others = %1").arg(QString::number(m_chain.weights.front(), 'g', 6)));
}

void ChainEditor::changed() { emit chainChanged(m_chain); }

}  // namespace grazelab::ui
