// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Periodic impacting orbits and their exact stability (docs/model.md section 10): the flow
// matrix is the solver's flight, the identities det DP = 1, M's trivial pair at 1 and
// tr M = 2 + tr DP hold on every orbit, the exact Jacobian is the map's finite differences,
// Newton finds the 1IPP orbit of the closed form, double agrees with binary128, and the
// symmetry of type A is recognised.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <type_traits>

#include "core/model/two_mass_form.h"
#include "core/orbits/special_orbits.h"
#include "core/orbits/periodic_orbit.h"
#include "core/orbits/starts.h"
#include "core/solver/simulate.h"

namespace grazelab::core {
namespace {

template <typename S = double>
TwoMassForm<S> resonantChain(double m2 = 0.5, Branch branch = Branch::Upper) {
  return *makeTwoMassForm(*designedModel<S>(S(1), S(m2), S(1), S(1), branch)).chain;
}

template <typename S>
S slowPeriod(const TwoMassForm<S>& chain) {
  return twoPi<S>() / chain.omegaSlow;
}

TEST(PeriodicOrbitTest, theFlowMatrixCarriesAStateAsTheSolverDoes) {
  const TwoMassForm<double> chain = resonantChain();
  const State start{0.1, -0.2, 0.05, 0.1};  // small: a free flight that stays below the stop
  for (double tau : {0.1, 1.7, 5.3, 8.8}) {
    Request request;
    request.initial = start;
    request.tEnd = tau;
    request.maxContacts = 10;
    const Result run = simulate(chain.model, request);
    ASSERT_TRUE(run.events.empty()) << tau;
    const Matrix4<double> phi = flowMatrix(chain, tau);
    const double x[4] = {start.u1, start.u2, start.v1, start.v2};
    const double expected[4] = {run.final.u1, run.final.u2, run.final.v1, run.final.v2};
    for (int i = 0; i < 4; ++i) {
      double y = 0;
      for (int k = 0; k < 4; ++k) y += phi(i, k) * x[k];
      EXPECT_NEAR(y, expected[i], 1e-13) << "tau " << tau << " row " << i;
    }
  }
}

TEST(PeriodicOrbitTest, everyOnePeriodicOrbitSatisfiesTheIdentities) {
  for (Branch branch : {Branch::Upper, Branch::Lower}) {
    const TwoMassForm<double> chain = resonantChain(0.5, branch);
    const double T2 = slowPeriod(chain);
    int checked = 0;
    for (double fraction = 0.52; fraction < 0.999; fraction += 0.013) {
      const OrbitSearch<double> found = onePeriodicOrbitStability(chain, fraction * T2);
      if (!found.orbit) continue;
      const PeriodicOrbit<double>& orbit = *found.orbit;
      ++checked;
      EXPECT_NEAR(orbit.period, fraction * T2, 1e-12 * T2);
      EXPECT_LT(std::abs(orbit.checks.detMinus1), 1e-12) << fraction;
      // a double eigenvalue moves by the square root of the rounding
      EXPECT_LT(orbit.checks.trivialPair, 1e-6) << fraction;
      EXPECT_LT(orbit.checks.periodicityResidual, 1e-13) << fraction;
      double traceM = 0;
      for (int i = 0; i < 4; ++i) traceM += orbit.monodromy(i, i);
      EXPECT_NEAR(traceM - 2, orbit.trace, 1e-10 * std::max(1.0, std::abs(orbit.trace))) << fraction;
      // the multipliers' product is det = 1 and their sum the trace
      const auto& mu = orbit.multipliers;
      EXPECT_NEAR(mu[0][0] + mu[1][0], orbit.trace, 1e-12 * std::max(1.0, std::abs(orbit.trace)));
      EXPECT_NEAR(mu[0][0] * mu[1][0] - mu[0][1] * mu[1][1], 1.0, 1e-10);
      EXPECT_EQ(orbitSymmetry(orbit, 1e-12), "A");  // v1 = 0 at the impact
    }
    EXPECT_GT(checked, 10);
  }
}

// The Jacobian from flow and saltation matrices against central differences of the return map
// at fixed energy (which keep only about half of double's digits). Periods on both admissible
// parts of the family (below T1 and above).
TEST(PeriodicOrbitTest, theExactJacobianIsTheMapsFiniteDifference) {
  const TwoMassForm<double> chain = resonantChain();
  const double T2 = slowPeriod(chain);
  for (double fraction : {0.45, 0.8, 0.93}) {
    const OrbitSearch<double> found = onePeriodicOrbitStability(chain, fraction * T2);
    ASSERT_TRUE(found.orbit) << found.problem;
    const PeriodicOrbit<double>& orbit = *found.orbit;
    const auto map = [&](double u1, double v1) {
      const std::optional<State> start = sectionState(chain, orbit.energy, u1, v1);
      EXPECT_TRUE(start);
      if (!start) return std::array<double, 2>{};
      const PeriodicOrbit<double> image = evaluateOrbit(chain, *start, 1, 1.0);
      EXPECT_EQ(image.events.size(), 1u) << image.reason;
      return std::array<double, 2>{image.events.back().after.u1, image.events.back().after.v1};
    };
    const double h = 1e-6;
    const auto plusU = map(orbit.state.u1 + h, orbit.state.v1);
    const auto minusU = map(orbit.state.u1 - h, orbit.state.v1);
    const auto plusV = map(orbit.state.u1, orbit.state.v1 + h);
    const auto minusV = map(orbit.state.u1, orbit.state.v1 - h);
    for (int i = 0; i < 2; ++i) {
      const double byU = (plusU[std::size_t(i)] - minusU[std::size_t(i)]) / (2 * h);
      const double byV = (plusV[std::size_t(i)] - minusV[std::size_t(i)]) / (2 * h);
      EXPECT_NEAR(orbit.reduced(i, 0), byU, 1e-6 * std::max(1.0, std::abs(byU))) << fraction;
      EXPECT_NEAR(orbit.reduced(i, 1), byV, 1e-6 * std::max(1.0, std::abs(byV))) << fraction;
    }
    // and the energy derivative, at fixed (u1, v1)
    const auto atEnergy = [&](double energy) {
      const std::optional<State> start = sectionState(chain, energy, orbit.state.u1, orbit.state.v1);
      EXPECT_TRUE(start);
      if (!start) return std::array<double, 2>{};
      const PeriodicOrbit<double> image = evaluateOrbit(chain, *start, 1, 1.0);
      return std::array<double, 2>{image.events.back().after.u1, image.events.back().after.v1};
    };
    const double e = 1e-6 * orbit.energy;
    const auto up = atEnergy(orbit.energy + e);
    const auto down = atEnergy(orbit.energy - e);
    for (int i = 0; i < 2; ++i) {
      const double byE = (up[std::size_t(i)] - down[std::size_t(i)]) / (2 * e);
      EXPECT_NEAR(orbit.energyDerivative[std::size_t(i)], byE, 1e-5 * std::max(1.0, std::abs(byE))) << fraction;
    }
  }
}

TEST(PeriodicOrbitTest, newtonFindsTheOnePeriodicOrbitOfTheClosedForm) {
  const TwoMassForm<double> chain = resonantChain();
  const double T2 = slowPeriod(chain);
  for (double fraction : {0.45, 0.8, 0.95}) {
    const OrbitSearch<double> closedForm = onePeriodicOrbitStability(chain, fraction * T2);
    ASSERT_TRUE(closedForm.orbit) << closedForm.problem;
    const PeriodicOrbit<double>& exact = *closedForm.orbit;
    const OrbitSearch<double> found =
        findOrbit(chain, exact.energy, exact.state.u1 + 1e-3, exact.state.v1 - 2e-3, 1);
    ASSERT_TRUE(found.orbit) << found.problem;
    EXPECT_NEAR(found.orbit->state.u1, exact.state.u1, 1e-12);
    EXPECT_NEAR(found.orbit->state.v1, 0.0, 1e-12);
    EXPECT_NEAR(found.orbit->period, fraction * T2, 1e-11 * T2);
    EXPECT_NEAR(found.orbit->trace, exact.trace, 1e-9);
    EXPECT_LT(found.iterations, 10);  // quadratic convergence
  }
}

TEST(PeriodicOrbitTest, binary128AgreesWithDoubleAndMeetsTheIdentitiesTo1e28) {
  const TwoMassForm<double> chain = resonantChain();
  const TwoMassForm<Quad> exact = resonantChain<Quad>();
  const double T2 = slowPeriod(chain);
  for (double fraction : {0.45, 0.72, 0.9}) {
    const OrbitSearch<double> inDouble = onePeriodicOrbitStability(chain, fraction * T2);
    ASSERT_TRUE(inDouble.orbit) << inDouble.problem;
    const PeriodicOrbit<double>& orbit = *inDouble.orbit;
    const OrbitSearch<Quad> found = onePeriodicOrbitStability(exact, Quad(fraction) * slowPeriod(exact));
    ASSERT_TRUE(found.orbit) << found.problem;
    const PeriodicOrbit<Quad>& quad = *found.orbit;
    EXPECT_NEAR(orbit.trace, double(quad.trace), 1e-10 * std::max(1.0, std::abs(orbit.trace)));
    EXPECT_LT(abs(quad.checks.detMinus1), Quad(1e-28));
    EXPECT_LT(quad.checks.periodicityResidual, Quad(1e-30));
    EXPECT_LT(quad.checks.trivialPair, Quad(1e-14));
  }
}

TEST(PeriodicOrbitTest, aPathThatIsNotTheOrbitIsRefusedWithItsReason) {
  const TwoMassForm<double> chain = resonantChain();
  const double T2 = slowPeriod(chain);
  const OrbitSearch<double> found = onePeriodicOrbitStability(chain, 0.8 * T2);
  ASSERT_TRUE(found.orbit) << found.problem;
  const PeriodicOrbit<double>& orbit = *found.orbit;
  // the same orbit, asked to close after 2 impacts: a 1-impact orbit repeated
  const PeriodicOrbit<double> twice = evaluateOrbit(chain, orbit.state, 2, defaultCloseTolerance<double>());
  EXPECT_FALSE(twice.admissible);
  EXPECT_NE(twice.reason.find("1-impact orbit repeated"), std::string::npos) << twice.reason;
  // a nearby start does not close
  State off = orbit.state;
  off.u1 += 1e-3;
  const std::optional<State> offStart = sectionState(chain, orbit.energy, off.u1, off.v1);
  ASSERT_TRUE(offStart);
  const PeriodicOrbit<double> open = evaluateOrbit(chain, *offStart, 1, defaultCloseTolerance<double>());
  EXPECT_FALSE(open.admissible);
  EXPECT_NE(open.reason.find("does not close"), std::string::npos) << open.reason;
  // no state of that energy there
  EXPECT_FALSE(findOrbit(chain, orbit.energy, 50.0, 0.0, 1).orbit);
}

TEST(PeriodicOrbitTest, nearT1APathThatMissesClosingByTheAmplifiedRoundingIsUndecidedNotOpen) {
  // the lower part of the 1IPP family ends at T1 = T2 / 2 on GLOM1's data: the impact speed V
  // falls like T1 - T, and the return map amplifies the rounding like 2 a2 / V (2e10 at the
  // note's period 4.44288293802508, 1.3e-10 below T1, where binary128's path misses closing by
  // 9e-25): undecided there, never "does not close"; a 50-digit evaluation closes it to 1e-52
  const TwoMassForm<Quad> exact = resonantChain<Quad>();
  const OrbitSearch<Quad> near = onePeriodicOrbitStability(exact, parseScalar<Quad>("4.44288293802508").value.value());
  EXPECT_FALSE(near.orbit);
  EXPECT_EQ(near.refusal, OrbitRefusal::Undecided) << near.problem;
  EXPECT_EQ(near.problem.find("does not close"), std::string::npos) << near.problem;
  EXPECT_NE(near.problem.find("cannot be decided in quad"), std::string::npos) << near.problem;
  // 1e-9 and 1e-7 below T1 in each precision: found, or undecided; never refused as open
  const auto foundOrUndecided = [](const auto& chain, const auto& below) {
    using Scalar = std::decay_t<decltype(below)>;
    const Scalar T1 = twoPi<Scalar>() / (chain.ratio * chain.omegaSlow);
    const auto search = onePeriodicOrbitStability(chain, Scalar(T1 - below));
    if (!search.orbit) EXPECT_EQ(search.refusal, OrbitRefusal::Undecided) << search.problem;
    else EXPECT_LT(search.orbit->checks.periodicityResidual, Scalar(1e-6));
  };
  for (double below : {1e-9, 1e-7}) {
    foundOrUndecided(resonantChain<double>(), below);
    foundOrUndecided(resonantChain<long double>(), (long double)below);
    foundOrUndecided(exact, Quad(below));
  }
  // above T1, V > 0: refused, and decided so in every precision
  const Quad T1 = twoPi<Quad>() / (exact.ratio * exact.omegaSlow);
  const OrbitSearch<Quad> above = onePeriodicOrbitStability(exact, Quad(T1 + Quad(1e-9)));
  EXPECT_FALSE(above.orbit);
  EXPECT_NE(above.refusal, OrbitRefusal::Undecided);
  EXPECT_NE(above.problem.find(">= 0"), std::string::npos) << above.problem;
  // (a start really off an orbit still does not close: aPathThatIsNotTheOrbitIsRefusedWithItsReason)
}

TEST(PeriodicOrbitTest, nearT1AClassIsTheTracesWhereItsErrorDecidesAndUndecidedWhereNotBinary128Confirms) {
  // below T1 the impact speed V ~ T1 - T falls and the return map amplifies the rounding like
  // 1 / V: long double's trace of the orbit 1e-8 below T1 of m2 = 0.3 is -2.2417 with an error
  // of 0.41, which cannot tell flip-hyperbolic from elliptic. Every precision's trace is within
  // its error of binary128's; its class, where that error decides it, is binary128's, and
  // Undecided where it does not, never a side taken. Both branches, a scaled chain.
  struct Chain {
    double m1, m2, k1, gap;
    Branch branch;
  };
  int decided = 0;
  int undecided = 0;
  for (const Chain& c : {Chain{1, 0.3, 1, 1, Branch::Upper}, Chain{1, 0.3, 1, 1, Branch::Lower},
                         Chain{1, 0.5, 1, 1, Branch::Upper}, Chain{4, 0.8, 9, 0.05, Branch::Upper}}) {
    const auto form = [&c](auto unit) {
      using S = decltype(unit);
      return *makeTwoMassForm(*designedModel<S>(S(c.m1), S(c.m2), S(c.k1), S(c.gap), c.branch)).chain;
    };
    const TwoMassForm<Quad> exact = form(Quad(0));
    const Quad exactT1 = twoPi<Quad>() / (exact.ratio * exact.omegaSlow);
    for (double below : {1e-4, 1e-6, 1e-8, 1e-10}) {
      const double fraction = below / toDouble(exactT1);  // `below` T1 (in time), relative
      const OrbitSearch<Quad> reference = onePeriodicOrbitStability(exact, Quad(exactT1 * (1 - Quad(fraction))));
      if (!reference.orbit) continue;
      ASSERT_NE(decidedStability(*reference.orbit), Stability::Undecided) << c.m2 << " " << below;
      const auto check = [&](auto unit) {
        using S = decltype(unit);
        const TwoMassForm<S> chain = form(unit);
        const S T1 = twoPi<S>() / (chain.ratio * chain.omegaSlow);
        const OrbitSearch<S> search = onePeriodicOrbitStability(chain, S(T1 * (1 - S(fraction))));
        if (!search.orbit) {  // its path's closing cannot be decided here: said, not a class
          EXPECT_EQ(search.refusal, OrbitRefusal::Undecided) << search.problem;
          return;
        }
        const PeriodicOrbit<S>& orbit = *search.orbit;
        EXPECT_LE(std::abs(toDouble(orbit.trace) - toDouble(reference.orbit->trace)), toDouble(orbit.traceError))
            << c.m2 << " " << below;
        const Stability stability = decidedStability(orbit);
        if (stability == Stability::Undecided) {
          ++undecided;
        } else {
          ++decided;
          EXPECT_EQ(stability, reference.orbit->stability) << c.m2 << " " << below << " " << toDouble(orbit.trace);
        }
      };
      check(double(0));
      check((long double)0);
    }
  }
  // both verdicts met: the sweep reaches where double and long double decide and where they cannot
  EXPECT_GT(decided, 0);
  EXPECT_GT(undecided, 0);
  // the case found: m2 = 0.3, 1e-8 below T1: long double gives the orbit, its class undecided
  const TwoMassForm<long double> light = resonantChain<long double>(0.3);
  const long double T1 = twoPi<long double>() / (light.ratio * light.omegaSlow);
  const OrbitSearch<long double> near = onePeriodicOrbitStability(light, T1 - 1e-8L);
  ASSERT_TRUE(near.orbit) << near.problem;
  EXPECT_EQ(decidedStability(*near.orbit), Stability::Undecided) << toDouble(near.orbit->trace);
}

}  // namespace
}  // namespace grazelab::core
