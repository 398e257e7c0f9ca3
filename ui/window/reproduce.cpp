// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/window/reproduce.h"

#include <cmath>

#include "ui/widgets/number_box.h"

namespace grazelab::ui {

QString simulateCommand(const core::experiments::Spec& spec) {
  const core::Model& m = spec.model;
  const core::State& x = spec.run.initial;
  QString line = QStringLiteral("grazelab-cli simulate --m1 %1 --m2 %2 --k1 %3 --gap %4")
                     .arg(shortestText(m.m1), shortestText(m.m2), shortestText(m.k1), shortestText(m.gap));
  if (m.design) {
    line += QStringLiteral(" --branch %1").arg(*m.design == core::Branch::Upper ? QStringLiteral("upper")
                                                                                  : QStringLiteral("lower"));
  } else {
    line += QStringLiteral(" --k2 %1").arg(shortestText(m.k2));
  }
  line += QStringLiteral(" --state %1,%2,%3,%4")
              .arg(shortestText(x.u1), shortestText(x.u2), shortestText(x.v1), shortestText(x.v2));
  line += QStringLiteral(" --contacts %1").arg(spec.run.maxContacts);
  if (std::isfinite(spec.run.tEnd)) line += QStringLiteral(" --t-end %1").arg(shortestText(spec.run.tEnd));
  if (spec.run.flightSearchSteps != core::defaultSearchSteps<double>()) {
    line += QStringLiteral(" --search-steps %1").arg(spec.run.flightSearchSteps);
  }
  return line;
}

}  // namespace grazelab::ui
