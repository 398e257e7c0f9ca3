// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/onepp_family.h"

#include <algorithm>

#include "core/orbits/special_orbits.h"

namespace grazelab::core {

std::vector<FamilyPoint> onePeriodicFamily(const Chain<double>& chain, std::int64_t count,
                                           std::stop_token stop) {
  const double T2 = twoPi<double>() / chain.omegaSlow;
  // each member in binary128 from its (double) period, rounded once: near T2, V ~ (T2 - T) is
  // conditioned like T2 / (T2 - T) in T, and a double evaluation lost up to 1e-4 of it there
  // (an independent 40-digit check at the printed periods); this way every row is right to
  // double precision for the period it prints
  const ChainOrProblem<Quad> quad = makeChain(convertModel<Quad>(chain.model));
  if (!quad.chain) return {};
  std::vector<double> periods;
  for (std::int64_t k = 1; k <= count; ++k) periods.push_back(T2 * double(k) / double(count + 1));
  // towards the grazing end: V and the distance to GLO_lambda* fall like T2 - T
  for (int k = 8; k <= 40; ++k) periods.push_back(T2 * (1 - std::ldexp(1.0, -k)));
  std::sort(periods.begin(), periods.end());
  std::vector<FamilyPoint> family;
  family.reserve(periods.size());
  for (double T : periods) {
    if (stop.stop_requested()) break;
    const OnePeriodicOrbit<Quad> orbit = onePeriodicOrbit(*quad.chain, Quad(T));
    if (orbit.V == 0 && !orbit.admissible) continue;  // a multiple of T1 or T2: no data at all
    FamilyPoint point;
    point.T = T;
    point.omega = twoPi<double>() / T;
    point.V = toDouble(orbit.V);
    point.u1 = toDouble(orbit.postImpact.u1);
    point.energy = toDouble(physicalEnergy(*quad.chain, orbit.postImpact));
    point.admissible = orbit.admissible;
    family.push_back(point);
  }
  return family;
}

FamilyPoint grazingEnd(const Chain<double>& chain) {
  const State data = gloData(chain, lambdaStar(chain));
  FamilyPoint end;
  end.T = twoPi<double>() / chain.omegaSlow;
  end.omega = chain.omegaSlow;
  end.V = 0;
  end.u1 = data.u1;
  end.energy = physicalEnergy(chain, data);
  end.admissible = true;
  return end;
}

}  // namespace grazelab::core
