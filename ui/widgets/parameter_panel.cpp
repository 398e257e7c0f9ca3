// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/widgets/batched_layout.h"
#include "ui/widgets/parameter_panel.h"

#include <QEvent>

#include <QCheckBox>
#include <QComboBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include "core/model/resonance.h"
#include "ui/widgets/chain_editor.h"
#include "ui/widgets/eliding_combo_box.h"
#include "ui/widgets/param_specs.h"
#include "ui/compute/scene.h"
#include "ui/widgets/slider_spin.h"

namespace grazelab::ui {

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  m_sceneText = new QLabel(this);
  m_sceneText->setWordWrap(true);
  m_sceneText->setObjectName(QStringLiteral("sceneText"));
  layout->addWidget(m_sceneText);

  auto addControl = [this](QLayout* box, ParamKey key) {
    auto* control = new SliderSpin(paramSpec(key), this);
    m_controls.insert(key, control);
    box->addWidget(control);
    connect(control, &SliderSpin::valueChanged, this, [this, key](double value) {
      m_params.setValue(key, value);
      changed();
    });
    connect(control, &SliderSpin::refused, this, [this](const QString& reason) {
      m_refusal->setText(reason);
      m_refusal->show();
      emit inputRefused(reason);
    });
  };

  // the chain
  auto* chain = new QGroupBox(tr("Chain"), this);
  auto* chainLayout = new QVBoxLayout(chain);
  for (ParamKey key : {ParamKey::M1, ParamKey::M2, ParamKey::K1, ParamKey::Gap}) {
    addControl(chainLayout, key);
  }
  auto* designRow = new QHBoxLayout;
  // short: the row also holds the branch, and a projector panel is narrow (the tooltip says more)
  m_design = new QCheckBox(tr("1:2 design"), chain);
  m_design->setObjectName(QStringLiteral("designCheck"));
  m_design->setToolTip(tr("Choose k₂ so that the fast mode has exactly twice the frequency of "
                          "the slow one (ω₁ = 2 ω₂). Off: type k₂ yourself (a detuned chain)."));
  m_branch = new QComboBox(chain);
  m_branch->setObjectName(QStringLiteral("branchCombo"));
  // short items: the row also holds the design box, and a squeezed combo read "upper branc"
  m_branch->addItem(tr("upper k₂"), int(core::Branch::Upper));
  m_branch->addItem(tr("lower k₂"), int(core::Branch::Lower));
  m_branch->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
  m_branch->setToolTip(tr("The 1:2 design has two solutions for k₂ (they meet at m₂/m₁ = 9/16): "
                          "the upper (stiffer) and the lower one."));
  designRow->addWidget(m_design);
  designRow->addWidget(m_branch);
  chainLayout->addLayout(designRow);
  addControl(chainLayout, ParamKey::K2);
  addControl(chainLayout, ParamKey::FrequencyRatio);
  m_feasibility = new QLabel(chain);
  m_feasibility->setObjectName(QStringLiteral("feasibility"));
  m_feasibility->setWordWrap(true);
  m_feasibility->setToolTip(tr("A 1:2 resonant chain exists only for m₂/m₁ ≤ 9/16."));
  chainLayout->addWidget(m_feasibility);
  layout->addWidget(chain);
  m_chainBox = chain;

  // the chain of N masses (the N-mass scenes, in place of the two-mass chain)
  auto* massChain = new QGroupBox(tr("Chain of N masses"), this);
  massChain->setObjectName(QStringLiteral("massChainBox"));
  auto* massChainLayout = new QVBoxLayout(massChain);
  m_chainEditor = new ChainEditor(massChain);
  massChainLayout->addWidget(m_chainEditor);
  layout->addWidget(massChain);
  m_chainLayout = chainLayout;
  m_massChainLayout = massChainLayout;
  m_massChainBox = massChain;
  connect(m_chainEditor, &ChainEditor::chainChanged, this, [this](const MassChainParams& chain) {
    m_params.massChain = chain;
    changed();
  });
  connect(m_chainEditor, &ChainEditor::inputRefused, this, [this](const QString& reason) {
    m_refusal->setText(reason);
    m_refusal->show();
    emit inputRefused(reason);
  });

  // where the run starts
  auto* start = new QGroupBox(tr("Start"), this);
  m_startBox = start;
  auto* startLayout = new QVBoxLayout(start);
  addControl(startLayout, ParamKey::Lambda);
  addControl(startLayout, ParamKey::Period);
  addControl(startLayout, ParamKey::ChainPeriod);
  addControl(startLayout, ParamKey::ModeFamily);
  addControl(startLayout, ParamKey::ModeEnergy);
  addControl(startLayout, ParamKey::Perturbation);
  auto* directionRow = new QHBoxLayout;
  m_directionLabel = new QLabel(tr("direction"), start);
  m_directionLabel->setMinimumWidth(92);
  m_direction = new ElidingComboBox(start);
  m_direction->setObjectName(QStringLiteral("directionCombo"));
  // the long item texts must not widen the panel past its scroll area (the popup shows them)
  m_direction->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  m_direction->setMinimumContentsLength(14);
  m_direction->addItem(tr("v₂ (off the plane: impacts)"), int(PerturbDirection::V2));
  m_direction->addItem(tr("u₂ (start below the stop: few or no contacts)"), int(PerturbDirection::U2));
  m_direction->addItem(tr("u₁ (along the plane: grazing)"), int(PerturbDirection::U1));
  m_direction->addItem(tr("v₁ (along the plane: grazing)"), int(PerturbDirection::V1));
  m_direction->setToolTip(tr("Which start value the perturbation δ changes. Pushing v₂ below 0 "
                             "sends mass 2 at the stop: impacts follow. Lowering u₂ below d "
                             "starts mass 2 away from the stop: the motion usually never reaches "
                             "it (the plots then show the free orbit alone); u₂ above d is inside "
                             "the stop and refused. Pushing u₁ or v₁ only moves to another "
                             "grazing orbit."));
  directionRow->addWidget(m_directionLabel);
  directionRow->addWidget(m_direction, 1);
  startLayout->addLayout(directionRow);
  layout->addWidget(start);

  // how long
  auto* run = new QGroupBox(tr("Run"), this);
  m_runBox = run;
  auto* runLayout = new QVBoxLayout(run);
  addControl(runLayout, ParamKey::Horizon);
  layout->addWidget(run);

  // the panel's messages: hidden until there is something to say
  auto note = [this](const char* name, const char* style) {
    auto* label = new QLabel(this);
    label->setObjectName(QString::fromLatin1(name));
    label->setWordWrap(true);
    label->setStyleSheet(QString::fromLatin1(style));
    label->hide();
    return label;
  };
  m_message = note("message", "QLabel { color: #a01010; font-weight: bold; }");
  m_refusal = note("refusal", "QLabel { color: #a01010; }");
  m_clickedStart = note("clickedStart", "QLabel { background: #e8f1f8; padding: 3px; }");
  m_notes = note("startNotes", "QLabel { background: #fff3cd; padding: 3px; }");
  layout->addWidget(m_message);
  layout->addWidget(m_refusal);
  // under the scene's text, where the eye looks for what is running
  layout->insertWidget(1, m_clickedStart);
  layout->insertWidget(2, m_notes);

  connect(m_design, &QCheckBox::toggled, this, [this](bool on) {
    m_params.resonantDesign = on;
    changed();
  });
  connect(m_branch, &QComboBox::currentIndexChanged, this, [this](int index) {
    m_params.branch = core::Branch(m_branch->itemData(index).toInt());
    changed();
  });
  connect(m_direction, &QComboBox::currentIndexChanged, this, [this](int index) {
    m_params.direction = PerturbDirection(m_direction->itemData(index).toInt());
    changed();
  });
  setParams(m_params);
}

void ParameterPanel::setScene(const Scene& scene) {
  const BatchedLayout oneLayoutPass(this);
  m_sceneKeys = scene.parameters();
  m_sceneText->setText(scene.description());
  for (auto it = m_controls.begin(); it != m_controls.end(); ++it) {
    it.value()->setVisible(m_sceneKeys.contains(it.key()));
  }
  // a chain of N masses is edited in its own box, the gap with it
  m_massChainScene = scene.massChain();
  m_chainBox->setVisible(!m_massChainScene);
  m_massChainBox->setVisible(m_massChainScene);
  m_chainEditor->setWeightsShown(scene.gloWeights());
  m_chainEditor->setShownMassOffered(scene.plots().contains(PlotKind::Phase));
  m_chainEditor->setSectionOffered(scene.plots().contains(PlotKind::Poincare));
  if (SliderSpin* gap = m_controls.value(ParamKey::Gap)) {
    if (m_massChainScene) m_massChainLayout->addWidget(gap);
    else m_chainLayout->insertWidget(3, gap);  // after m1, m2, k1, as built
  }
  // an N-mass run is pushed along the stopped mass's velocity only
  const bool perturb = m_sceneKeys.contains(ParamKey::Perturbation);
  m_direction->setVisible(perturb && !m_massChainScene);
  m_directionLabel->setVisible(perturb && !m_massChainScene);
  // a box with nothing the scene exposes is not shown empty (the random starts pick their own)
  m_startBox->setVisible(perturb || m_sceneKeys.contains(ParamKey::Lambda) ||
                         m_sceneKeys.contains(ParamKey::Period) || m_sceneKeys.contains(ParamKey::ChainPeriod) ||
                         m_sceneKeys.contains(ParamKey::ModeFamily));
  m_runBox->setVisible(m_sceneKeys.contains(ParamKey::Horizon));
  updateFeasibility();
}

void ParameterPanel::setParams(const Params& params) {
  m_params = params;
  for (auto it = m_controls.begin(); it != m_controls.end(); ++it) {
    it.value()->setValue(params.value(it.key()));
  }
  const QSignalBlocker blockDesign(m_design);
  const QSignalBlocker blockBranch(m_branch);
  const QSignalBlocker blockDirection(m_direction);
  m_design->setChecked(params.resonantDesign);
  m_branch->setCurrentIndex(m_branch->findData(int(params.branch)));
  m_direction->setCurrentIndex(m_direction->findData(int(params.direction)));
  if (m_chainEditor->chain() != params.massChain) m_chainEditor->setChain(params.massChain);
  updateFeasibility();
}

void ParameterPanel::setChainSummary(const QString& text, int designs, bool refused) {
  m_chainEditor->setSummary(text, designs, refused);
}

void ParameterPanel::setSliderRanges(const std::map<ParamKey, std::pair<double, double>>& ranges) {
  for (auto it = m_controls.begin(); it != m_controls.end(); ++it) {
    const auto found = ranges.find(it.key());
    const ParamSpec spec = paramSpec(it.key());
    const auto [low, high] = found != ranges.end() ? found->second
                                                   : std::pair(spec.sliderMin, spec.sliderMax);
    it.value()->setSliderRange(low, high);
  }
}

void ParameterPanel::setMessage(const QString& message) {
  m_message->setText(message);
  m_message->setVisible(!message.isEmpty());
}

QString ParameterPanel::message() const { return m_message->isVisible() ? m_message->text() : QString(); }

void ParameterPanel::setClickedStart(const std::optional<core::ChainState>& start) {
  if (!start) {
    m_clickedStart->hide();
    return;
  }
  // u₁ = …, u₂ = …, then v₁ = …, as the session writes them
  QStringList parts;
  for (const auto& [name, values] : {std::pair(QStringLiteral("u"), &start->u), std::pair(QStringLiteral("v"), &start->v)}) {
    for (Eigen::Index i = 0; i < values->size(); ++i) {
      parts.append(QStringLiteral("%1%2 = %3").arg(name, subscriptDigits(int(i) + 1), QString::number((*values)[i], 'g', 4)));
    }
  }
  m_clickedStart->setText(tr("<b>Running from a clicked start</b>: %1 (not the panel's; edit any value to go back)")
                              .arg(parts.join(QStringLiteral(", "))));
  m_clickedStart->show();
}

void ParameterPanel::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() != QEvent::FontChange) return;
  for (QLabel* label : {m_message, m_refusal, m_clickedStart, m_notes}) {
    QFont font = this->font();
    font.setBold(label == m_message);
    label->setFont(font);
  }
}

void ParameterPanel::setNotes(const QStringList& notes) {
  m_notes->setText(tr("Note: %1.").arg(notes.join(QStringLiteral("; "))));
  m_notes->setVisible(!notes.isEmpty());
}

QString ParameterPanel::notes() const { return m_notes->isVisible() ? m_notes->text() : QString(); }

QString ParameterPanel::clickedStartText() const {
  return m_clickedStart->isVisible() ? m_clickedStart->text() : QString();
}

QString ParameterPanel::refusal() const { return m_refusal->isVisible() ? m_refusal->text() : QString(); }

void ParameterPanel::clearRefusal() { m_refusal->hide(); }

void ParameterPanel::changed() {
  m_refusal->hide();  // a value taken answers the last refusal
  updateFeasibility();
  emit paramsChanged(m_params);
}

void ParameterPanel::updateFeasibility() {
  const bool design = m_params.resonantDesign;
  m_branch->setEnabled(design);
  if (SliderSpin* k2 = m_controls.value(ParamKey::K2)) {
    k2->setVisible(!design && m_sceneKeys.contains(ParamKey::K2));
  }
  const double ratio = m_params.m2 / m_params.m1;
  const bool feasible = ratio <= core::kMaxResonantMassRatio;
  m_feasibility->setText(
      design ? tr("Feasible: m₂/m₁ ≤ 9/16 = 0.5625 — now %1 %2")
                   .arg(ratio, 0, 'g', 4)
                   .arg(feasible ? tr("✓") : tr("✗ (no 1:2 chain)"))
             : tr("Detuned chain: k₂ as typed, no resonance imposed."));
  m_feasibility->setStyleSheet(feasible || !design ? QString()
                                                   : QStringLiteral("QLabel { color: #a01010; }"));
}

}  // namespace grazelab::ui
