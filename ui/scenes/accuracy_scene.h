// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include "ui/scene.h"

namespace grazelab::ui {

/// Error against run time: every method of nonsmooth mechanics on the current chain and start,
/// measured against the exact solver, with one method's trajectory drawn over the exact one.
class AccuracyScene final : public Scene {
 public:
  QString name() const override;
  QString alias() const override;
  QString title() const override;
  QString description() const override;
  Params defaults() const override;
  QList<ParamKey> parameters() const override;
  QList<PlotKind> plots() const override;
  SceneJob build(const Params& params, const DerivedModel& derived) const override;
};

}  // namespace grazelab::ui
