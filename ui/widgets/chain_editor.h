// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QList>
#include <QWidget>

#include "ui/compute/params.h"

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QLayout;
class QSpinBox;
class QVBoxLayout;

namespace grazelab::ui {

class SliderSpin;

/// The chain of N masses of the N-mass scenes: how many masses (1 to 8), each mass on a slider
/// with its number box, the resonance asked for (its springs designed, one of its designs) or the
/// springs as given, the stop's mass, and the weights of the grazing linear orbit the run starts
/// on. It only edits a MassChainParams; what the chain is (its designed springs, frequencies, or
/// why no chain has the resonance) comes back from the worker and is shown with setSummary().
class ChainEditor : public QWidget {
  Q_OBJECT

 public:
  explicit ChainEditor(QWidget* parent = nullptr);

  /// Shows these values without emitting chainChanged.
  void setChain(const MassChainParams& chain);
  const MassChainParams& chain() const { return m_chain; }
  /// What the chain is, in words (designed springs, frequencies and their ratio, the period),
  /// how many designs the resonance has for these masses, or why it has none (`refused`).
  void setSummary(const QString& text, int designs, bool refused);
  QString summary() const;
  /// Shows the weights of the grazing linear orbit (a scene that starts elsewhere hides them).
  void setWeightsShown(bool shown);
  /// Offers the choice of the mass whose phase portrait is drawn (a scene that draws one).
  void setShownMassOffered(bool offered);
  /// Offers the choice of the two coordinates the Poincaré points on H are drawn on.
  void setSectionOffered(bool offered);

  /// The resonances offered for `masses` masses, as their harmonics fastest first ("1:2:3" is
  /// 3, 2, 1); the first entry, empty, is "as given".
  static QList<std::vector<int>> resonancesFor(int masses);

 signals:
  void chainChanged(const grazelab::ui::MassChainParams& chain);
  /// A typed value was refused and the previous one kept.
  void inputRefused(const QString& reason);

 private:
  void rebuildRows();
  void fillResonances();
  void fillSection();
  void changed();
  /// the label of λ1, the weight that balances the others
  void showFirstWeight();

  MassChainParams m_chain;
  QSpinBox* m_count = nullptr;
  QSpinBox* m_stop = nullptr;
  QSpinBox* m_shown = nullptr;
  QLayout* m_shownRow = nullptr;
  QComboBox* m_sectionX = nullptr;
  QComboBox* m_sectionY = nullptr;
  QLayout* m_sectionRow = nullptr;
  QFormLayout* m_form = nullptr;
  QComboBox* m_resonance = nullptr;
  QComboBox* m_design = nullptr;
  QLabel* m_designLabel = nullptr;
  QVBoxLayout* m_rows = nullptr;
  QList<SliderSpin*> m_masses;
  QList<SliderSpin*> m_springs;
  QList<SliderSpin*> m_weights;
  QCheckBox* m_wall = nullptr;
  SliderSpin* m_wallSpring = nullptr;
  double m_lastWall = 1;  ///< the wall's spring restored when the wall comes back
  QLabel* m_firstWeight = nullptr;  ///< λ1 = 1 - the others, shown (not edited)
  QLabel* m_summary = nullptr;
  bool m_weightsShown = true;
};

/// A resonance's name as the menu shows it, slowest first ("1:2:3" for harmonics 3, 2, 1).
QString resonanceName(const std::vector<int>& harmonics);

}  // namespace grazelab::ui
