// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "ui/scene.h"

class QWidget;

namespace grazelab::ui {

class PlotView;

/// Creates the plot widget for one kind of plot (nothing for WorkPrecision, an AccuracyView).
PlotView* makePlot(PlotKind kind, QWidget* parent = nullptr);

}  // namespace grazelab::ui
