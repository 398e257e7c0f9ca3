// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QMetaType>
#include <QString>

#include <cstdint>
#include <memory>
#include <optional>

#include "core/simulate.h"
#include "core/trust.h"
#include "ui/params.h"

namespace grazelab::ui {

/// One computation asked of the worker, as a value. The controller stamps the id.
struct SimRequest {
  std::uint64_t id = 0;
  core::Model model;
  core::Request request;
  Params params;       ///< the parameters that produced it (for the display and snapshots)
  QString sceneName;
  std::optional<core::State> reference;
  QString referenceLabel;
};

/// A partial or final result coming back from the worker, as a value. The result is shared
/// read-only between the worker's copy and the display, never written after it is sent.
struct SimUpdate {
  std::uint64_t id = 0;
  std::shared_ptr<const core::Result> result;
  double progress = 0;  ///< fraction of the requested work done, [0, 1]
  bool final = false;   ///< the run is over (complete, cancelled or invalid)
  std::shared_ptr<const SimRequest> request;  ///< what was asked
  std::optional<core::Trust> trust;  ///< the error estimate, on the final update
};

}  // namespace grazelab::ui

Q_DECLARE_METATYPE(grazelab::ui::SimUpdate)
