// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "ui/plots/plot_view.h"

namespace grazelab::ui {

class PoincarePlot final : public PlotView {
  Q_OBJECT

 public:
  explicit PoincarePlot(QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;

 private:
  static constexpr int kBins = 5;
  int m_bins[kBins] = {};
  int m_reference = 0;
  RunProgress m_taken;      ///< points already binned
  std::int64_t m_perBin = 0;  ///< contacts per colour bin, fixed for the run's updates
};

}  // namespace grazelab::ui
