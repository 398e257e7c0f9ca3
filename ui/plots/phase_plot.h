// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "ui/plots/plot_view.h"

namespace grazelab::ui {

/// A phase portrait of one mass: (u2, v2) with the stop line, or (u1, v1).
class PhasePlot final : public PlotView {
  Q_OBJECT

 public:
  enum class Mass { One, Two };
  explicit PhasePlot(Mass mass, QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;

 private:
  Mass m_mass;
  int m_path = 0;
  int m_stop = -1;
  int m_start = 0;
};

}  // namespace grazelab::ui
