// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <memory>

#include "ui/compute/atlas_figure.h"
#include "ui/plots/plot_view.h"

namespace grazelab::ui {

/// The frequency-energy picture of the chain's periodic impacting families (the atlas the
/// scene computed, of two masses or of N): each orbit a dot at (log10 E, 2 pi / T), filled where
/// it is stable and a ring where it is not, coloured by its impacts per period; flips, Krein
/// collisions and ends marked; the orbit the run follows ringed. A click on a family chooses its
/// nearest orbit.
class ModesPlot final : public PlotView {
  Q_OBJECT

 public:
  explicit ModesPlot(QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;
  bool drawsSceneDataOnly() const override { return true; }
  /// The atlas itself, orbit by orbit and point by point: x = E, y = 2π/T, value = T/T₂
  /// (the picture's x is log₁₀ E).
  void appendCsv(CsvTable& table) const override;
  /// How near a click must fall to a family's orbit to choose it [pixels].
  static constexpr double kChoiceRadius = 24;

 signals:
  /// An orbit of the atlas was clicked: its family (the index in the atlas's families), its
  /// index in that family, and its state just after an impact.
  void orbitChosen(int family, int orbit, const grazelab::core::ChainState& start);
  /// A click fell on no family.
  void missed();

 private:
  void choose(QPointF value);

  std::shared_ptr<const AtlasFigure> m_atlas;
  int m_dots[4][2] = {};  ///< per class of impacts (1, 2, 4, more) and stable / unstable
  int m_unstableKey = 0;  ///< a legend entry only: what a ring means
  int m_flips = 0;
  int m_orphanFlips = 0;
  int m_krein = 0;
  int m_ends = 0;
  int m_chosen = 0;
};

}  // namespace grazelab::ui
