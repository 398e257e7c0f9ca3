// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>

#include "ui/plots/plot_view.h"
#include "ui/plots/shown_run.h"

namespace grazelab::ui {

/// Every free flight of any chain's run that starts on the stop, over the chain's period (T₂ of
/// the note's chain, T of a resonant one, the slowest of one with none), against the index of
/// the contact that ends it, with the bound 1 where the theorem gives it (Theorem 2.3).
class FreeFlightPlot final : public PlotView {
  Q_OBJECT

 public:
  explicit FreeFlightPlot(QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;
  void setPresentation(bool on, int textPixels) override;
  /// The flights drawn, in its units.
  PointSpan flights() const { return entries()[std::size_t(m_flights)].points(); }

 private:
  void applyMarkers();
  /// The titles and tooltip of the flights of this run.
  void nameFor(const ShownRun& run);

  bool m_dense = false;  ///< more flights than pixel columns
  int m_flights = 0;
  int m_period = 0;
  std::optional<ShownRun> m_run;  ///< the run shown
  std::size_t m_taken = 0;        ///< flights already drawn
};

}  // namespace grazelab::ui
