// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/budget.h"

#include <algorithm>
#include <cmath>

namespace grazelab::core {

std::int64_t nextChunkContacts(std::int64_t lastContacts, double secondsTaken,
                               double targetSeconds) {
  const double measured = std::isfinite(secondsTaken) ? std::max(secondsTaken, 1e-6) : 1e-6;
  const double target = std::isfinite(targetSeconds) && targetSeconds > 0 ? targetSeconds : 0.03;
  const double scale = std::clamp(target / measured, 0.25, 8.0);
  const double next = std::max<double>(double(lastContacts), 1.0) * scale;
  return std::clamp<std::int64_t>(std::int64_t(std::min(next, double(kMaxChunkContacts))),
                                  kMinChunkContacts, kMaxChunkContacts);
}

}  // namespace grazelab::core
