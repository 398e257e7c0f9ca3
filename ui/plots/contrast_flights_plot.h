// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "ui/plots/plot_view.h"

namespace grazelab::ui {

/// The detuned contrast of an experiment of any chain: its second run (the same start on the
/// chain detuned, Spec::chains[1]), each flight from the stop over the first run's common period
/// T, against the index of the contact that ends it, with the resonant chain's bound 1. Its
/// flights past T last 10 to 200 T: the axis stops at 3 T and they are drawn on its top edge as
/// their own dots, named in the title and counted in the tooltip (1 % off hid its two such flights above the axis, and a
/// class saw every flight below T). The scene names the contrast (SceneJob::viewWords: its
/// title's head, its tooltip, and why there is none when it has none).
class ContrastFlightsPlot final : public PlotView {
  Q_OBJECT

 public:
  explicit ContrastFlightsPlot(QWidget* parent = nullptr);
  void show(const SimUpdate& update) override;
  /// What it draws, in its units: the flights up to 3 T and those past it (on the top edge).
  PointSpan below() const { return entries()[std::size_t(m_flights)].points(); }
  PointSpan past() const { return entries()[std::size_t(m_past)].points(); }

 private:
  /// its flights drawn faded: the run they came from is being replaced (no layout: a title or
  /// note that changed would lay the chart out again)
  void setFaded(bool faded);

  int m_flights = 0;
  int m_past = 0;
  int m_bound = 0;
};

}  // namespace grazelab::ui
