// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>

#include "ui/plots/plot_view.h"
#include "ui/plots/shown_run.h"

namespace grazelab::ui {

/// The section H of any chain's run: the state at each contact of the stopped mass on two
/// coordinates (mass 1's (u₁, v₁) for the note's chain; the scene's 'section on' pair of N
/// masses), in the views' units, coloured by contact index; a click starts a run there.
class PoincarePlot final : public PlotView {
  Q_OBJECT

 public:
  explicit PoincarePlot(QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;
  /// The section's points, in its units (every bin, in contact order).
  std::vector<QPointF> points() const;

 private:
  /// The titles and tooltip of the section of this run.
  void nameFor(const ShownRun& run);

  static constexpr int kBins = 5;
  int m_bins[kBins] = {};
  int m_reference = 0;
  std::optional<ShownRun> m_run;  ///< the run shown
  std::int64_t m_perBin = 0;  ///< contacts per colour bin, fixed for the run's updates
};

}  // namespace grazelab::ui
