// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/window/reproduce.h"

#include <QStringList>

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

QString chainSimulateCommand(const core::experiments::ChainSeries& series) {
  const core::MassChain& chain = series.chain;
  const auto joined = [](const auto& values) {
    QStringList parts;
    for (const double value : values) parts.append(shortestText(value));
    return parts.join(QLatin1Char(','));
  };
  std::vector<double> state(series.start.u.data(), series.start.u.data() + series.start.u.size());
  state.insert(state.end(), series.start.v.data(), series.start.v.data() + series.start.v.size());
  QString line = QStringLiteral("grazelab-cli simulate --masses %1 --springs %2")
                     .arg(joined(chain.masses), joined(chain.springs));
  if (chain.rightSpring > 0) line += QStringLiteral(" --right-spring %1").arg(shortestText(chain.rightSpring));
  // a GLO start as its weights: its modes of weight 0 still, as the explorer ran it
  const QString start = series.gloWeights.empty() ? QStringLiteral("--state %1").arg(joined(state))
                                                  : QStringLiteral("--glo-weights %1").arg(joined(series.gloWeights));
  line += QStringLiteral(" --stop-mass %1 --gap %2 %3 --contacts %4 --precision double")
              .arg(chain.stopped())
              .arg(shortestText(chain.gap), start)
              .arg(series.contactsAsked);
  return line;
}

}  // namespace grazelab::ui
