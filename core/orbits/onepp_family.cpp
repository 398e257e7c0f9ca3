// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/orbits/onepp_family.h"

#include <algorithm>

#include "core/orbits/special_orbits.h"

namespace grazelab::core {

namespace {

// A member computed in binary128, rounded once.
OnePeriodicOrbit<double> rounded(const OnePeriodicOrbit<Quad>& orbit) {
  OnePeriodicOrbit<double> out;
  out.T = toDouble(orbit.T);
  out.admissible = orbit.admissible;
  out.refusal = orbit.refusal;
  out.reason = orbit.reason;
  out.postImpact = {toDouble(orbit.postImpact.u1), toDouble(orbit.postImpact.u2),
                    toDouble(orbit.postImpact.v1), toDouble(orbit.postImpact.v2)};
  out.V = toDouble(orbit.V);
  out.energy = toDouble(orbit.energy);
  return out;
}

}  // namespace

std::vector<OnePeriodicOrbit<double>> onePeriodicFamily(const TwoMassForm<double>& chain, std::int64_t count,
                                                        std::stop_token stop) {
  const double T2 = twoPi<double>() / chain.omegaSlow;
  // each member in binary128 from its (double) period, rounded once: near T2, V ~ (T2 - T) is
  // conditioned like T2 / (T2 - T) in T, and a double evaluation lost up to 1e-4 of it there
  // (an independent 40-digit check at the printed periods); this way every row is right to
  // double precision for the period it prints
  const TwoMassFormOrProblem<Quad> quad = makeTwoMassForm(convertModel<Quad>(chain.model));
  if (!quad.chain) return {};
  std::vector<double> periods;
  for (std::int64_t k = 1; k <= count; ++k) periods.push_back(T2 * double(k) / double(count + 1));
  // towards the grazing end: V and the distance to GLO_lambda* fall like T2 - T
  for (int k = 8; k <= 40; ++k) periods.push_back(T2 * (1 - std::ldexp(1.0, -k)));
  std::sort(periods.begin(), periods.end());
  std::vector<OnePeriodicOrbit<double>> family;
  family.reserve(periods.size());
  for (double T : periods) {
    if (stop.stop_requested()) break;
    const OnePeriodicOrbit<Quad> orbit = onePeriodicOrbit(*quad.chain, Quad(T));
    if (!orbit.hasData()) continue;  // a multiple of T1 or T2: no data at all
    family.push_back(rounded(orbit));
  }
  return family;
}

OnePeriodicOrbit<double> grazingEnd(const TwoMassForm<double>& chain) {
  OnePeriodicOrbit<double> end;
  end.T = twoPi<double>() / chain.omegaSlow;
  end.postImpact = gloData(chain, lambdaStar(chain));
  end.V = 0;
  end.energy = physicalEnergy(chain, end.postImpact);
  end.admissible = true;
  return end;
}

}  // namespace grazelab::core
