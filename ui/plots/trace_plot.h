// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "ui/plots/plot_view.h"

namespace grazelab::ui {

class TracePlot final : public PlotView {
  Q_OBJECT

 public:
  explicit TracePlot(QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;

 private:
  int m_trace = 0;
  int m_stop = 0;
  int m_impacts = 0;
  int m_grazings = 0;
};

}  // namespace grazelab::ui
