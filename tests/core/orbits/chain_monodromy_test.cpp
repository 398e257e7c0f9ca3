// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/orbits/chain_monodromy.cpp: the 2N x 2N monodromy of periodic impacting orbits
// of N masses (docs/model.md section 12). Two masses are the note's exact multipliers (section
// 10's 2 x 2 trace, and the reference values of section 12); the flight's matrix is the exact
// flight's derivative and the monodromy the exact run's (central differences); every orbit's
// monodromy is symplectic with the multipliers in reciprocal and conjugate pairs; double agrees
// with binary128 within its error bars; complex quadruplets and Krein signatures are reported.
// (The independent 50-digit check on random chains is tools/reference/chain_orbit_check.py.)
#include "core/orbits/chain_monodromy.h"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "core/model/model.h"
#include "core/model/two_mass_form.h"
#include "core/orbits/chain_onepp.h"
#include "support/random_chains.h"

namespace grazelab::core {
namespace {

using test_chains::randomChain;

std::complex<double> valueOf(const ChainMultiplier<double>& m) { return {m.re, m.im}; }

// the admissible 1IPP orbits of `chain` over `count` periods across its slowest period
std::vector<ChainOnePeriodicStability<double>> orbitsOf(const MassChain& chain, int count) {
  const ReadyChain ready = readyChain(chain);
  std::vector<ChainOnePeriodicStability<double>> orbits;
  const double end = chainOnePeriodicEnd(chain);
  for (int k = 1; k < count; ++k) {
    ChainOnePeriodicStability<double> found = chainOnePeriodicStability(ready, end * k / count);
    if (found.onePeriodic == OnePeriodicRefusal::None && found.orbit.admissible()) orbits.push_back(std::move(found));
  }
  return orbits;
}

TEST(ChainMonodromy, TheNotesChainAtSixIsSectionTwelvesReference) {
  const MassChain note{{1.0, 0.5}, {1.0, 0.5}, 0, 0, 1.0};
  // binary128 to 1e-25 (the reference's 19 digits: to their last), double within its bars; two
  // multipliers of one angle by modulus
  const auto quad = chainOnePeriodicStability<Quad>(readyChain(chainCast<Quad>(note)), Quad(6));
  ASSERT_TRUE(quad.orbit.admissible());
  ASSERT_EQ(quad.orbit.monodromy.multipliers.size(), 2u);
  EXPECT_EQ(quad.orbit.monodromy.stability, ChainStability::FlipHyperbolic);
  const Quad expected[2] = {Quad("-0.8497181158871879342"), Quad("-1.176860868684555745")};
  for (int i = 0; i < 2; ++i) {
    const ChainMultiplier<Quad>& m = quad.orbit.monodromy.multipliers[std::size_t(i)];
    EXPECT_LT(double(abs(m.re - expected[i])), 1e-18) << i;
    EXPECT_EQ(double(m.im), 0.0);
    EXPECT_LT(double(m.error), 1e-25);
  }
  const auto twice = chainOnePeriodicStability<double>(readyChain(note), 6.0);
  for (int i = 0; i < 2; ++i) {
    const ChainMultiplier<double>& m = twice.orbit.monodromy.multipliers[std::size_t(i)];
    const ChainMultiplier<Quad>& q = quad.orbit.monodromy.multipliers[std::size_t(i)];
    EXPECT_LE(std::abs(m.re - double(q.re)), m.error) << i;
    EXPECT_LT(m.error, 1e-12);
  }
}

// N = 2 is section 10: the pair's sum is the trace of the 2 x 2 Jacobian of the two-mass code,
// and the classes are the same, over both design branches, mass ratios and periods.
TEST(ChainMonodromy, TwoMassesAreTheNotesExactMultipliers) {
  int compared = 0;
  for (const Branch branch : {Branch::Upper, Branch::Lower}) {
    for (const double m2 : {0.12, 0.3, 0.5}) {
      const auto model = designedModel<double>(1.0, m2, 1.0, 1.0, branch);
      ASSERT_TRUE(model);
      const TwoMassForm<double> form = *makeTwoMassForm(*model).chain;
      const MassChain chain = massChainOf(*model);
      const ReadyChain ready = readyChain(chain, Kernel::Modal);  // the N-mass kernel, not the note's
      const double T2 = twoPi<double>() / form.omegaSlow;
      for (int k = 1; k < 60; ++k) {
        const double T = T2 * k / 60.0;
        const OrbitSearch<double> two = onePeriodicOrbitStability(form, T);
        const ChainOnePeriodicStability<double> n = chainOnePeriodicStability(ready, T);
        const bool admissible = n.onePeriodic == OnePeriodicRefusal::None && n.orbit.admissible();
        if (!two.orbit || !admissible) {
          EXPECT_FALSE(two.orbit.has_value() && two.dataError < 1e-12 && !admissible) << "T = " << T << " m2 " << m2;
          continue;
        }
        const PeriodicOrbit<double>& orbit = *two.orbit;
        const auto& mu = n.orbit.monodromy.multipliers;
        ASSERT_EQ(mu.size(), 2u);
        const double sum = mu[0].re + mu[1].re;
        EXPECT_NEAR(sum, orbit.trace, 1e-12 * std::max(1.0, std::abs(orbit.trace)) + orbit.traceError)
            << "T = " << T << " m2 " << m2;
        const Stability decided = decidedStability(orbit);
        const ChainStability mine = n.orbit.monodromy.stability;
        if (decided == Stability::Elliptic) {
          EXPECT_EQ(mine, ChainStability::Elliptic) << T;
        } else if (decided == Stability::Hyperbolic) {
          EXPECT_EQ(mine, ChainStability::Hyperbolic) << T;
        } else if (decided == Stability::FlipHyperbolic) {
          EXPECT_EQ(mine, ChainStability::FlipHyperbolic) << T;
        }
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 150);
}

// The flight's matrix is the derivative of the exact flight: central differences of stateAt.
TEST(ChainMonodromy, FlowMatrixIsTheExactFlightsDerivative) {
  std::mt19937 rng(11);
  for (int n = 2; n <= 6; ++n) {
    const MassChain chain = randomChain(rng, n);
    const ChainDynamics dynamics = chainDynamics(chain);
    const double tau = 0.37 * n + 0.9;
    const ChainMatrix<double> phi = chainFlowMatrix(dynamics, tau);
    const double h = 1e-5;
    for (int column = 0; column < 2 * n; ++column) {
      ChainState plus{ChainVector<double>::Zero(n), ChainVector<double>::Zero(n)};
      ChainState minus = plus;
      (column < n ? plus.u[column] : plus.v[column - n]) += h;
      (column < n ? minus.u[column] : minus.v[column - n]) -= h;
      const ChainState a = stateAt(dynamics, flightFrom(dynamics, plus), tau);
      const ChainState b = stateAt(dynamics, flightFrom(dynamics, minus), tau);
      for (int row = 0; row < 2 * n; ++row) {
        const double difference = ((row < n ? a.u[row] : a.v[row - n]) - (row < n ? b.u[row] : b.v[row - n])) / (2 * h);
        EXPECT_NEAR(phi(row, column), difference, 1e-9) << n << " masses, (" << row << ", " << column << ")";
      }
    }
  }
}

// The monodromy is the exact run's derivative: started mid-flight on the orbit (the map from
// there one period on is Phi(T/2) M Phi(T/2)^-1), central differences of runs of one impact.
TEST(ChainMonodromy, MonodromyIsTheExactRunsDerivative) {
  std::mt19937 rng(5);
  int checked = 0;
  for (int c = 0; c < 6; ++c) {
    const MassChain chain = randomChain(rng, 3 + c % 3);
    const ReadyChain ready = readyChain(chain);
    for (const ChainOnePeriodicStability<double>& found : orbitsOf(chain, 7)) {
      const ChainPeriodicOrbit& orbit = found.orbit;
      const int n = chain.size();
      const double T = orbit.period;
      const ChainMatrix<double> half = chainFlowMatrix(ready.dynamics, T / 2);
      const ChainMatrix<double> expected = half * orbit.monodromy.matrix * half.inverse();
      ChainVector<double> x0(2 * n);
      x0 << orbit.state.u, orbit.state.v;
      const ChainVector<double> middle = half * x0;
      const double h = 1e-6 * chain.gap;
      for (int column = 0; column < 2 * n; ++column) {
        ChainVector<double> ends[2];
        for (int side = 0; side < 2; ++side) {
          ChainVector<double> x = middle;
          x[column] += side == 0 ? h : -h;
          const ChainRun run = runChain(ready, ChainStart(ChainState{x.head(n), x.tail(n)}), 5, T);
          ASSERT_EQ(run.impacts, 1) << "one impact in one period";
          ends[side] = ChainVector<double>(2 * n);
          ends[side] << run.final.u, run.final.v;
        }
        const ChainVector<double> difference = (ends[0] - ends[1]) / (2 * h);
        for (int row = 0; row < 2 * n; ++row) {
          EXPECT_NEAR(difference[row], expected(row, column), 1e-5 * (1 + expected.col(column).norm()))
              << n << " masses, T " << T << " (" << row << ", " << column << ")";
        }
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 5);
}

// Every orbit's monodromy is symplectic, its trivial pair fixed, its 2N - 2 multipliers closed
// under lambda -> 1 / conj(lambda) and conj; conjugates on the circle have opposite Krein
// signatures; double agrees with binary128 within its bars, class for class.
TEST(ChainMonodromy, SymplecticPairedAndWithinItsBarsOfBinary128) {
  std::mt19937 rng(2026);
  int checked = 0;
  int quadruplets = 0;
  for (int c = 0; c < 16; ++c) {
    const int n = 3 + c % 4;
    const MassChain chain = randomChain(rng, n);
    const BasicReadyChain<Quad> quadChain = readyChain(chainCast<Quad>(chain));
    for (const ChainOnePeriodicStability<double>& found : orbitsOf(chain, 9)) {
      const ChainMonodromy<double>& m = found.orbit.monodromy;
      EXPECT_LT(m.symplecticDefect, 1e-12);
      EXPECT_LT(m.trivialPairDefect, 1e-10);
      EXPECT_LT(m.detDefect, 1e-9);
      ASSERT_EQ(m.multipliers.size(), std::size_t(2 * n - 2));
      for (const ChainMultiplier<double>& mu : m.multipliers) {
        const std::complex<double> z = valueOf(mu);
        const std::complex<double> partners[2] = {std::conj(z), 1.0 / std::conj(z)};
        for (const std::complex<double>& partner : partners) {
          double nearest = INFINITY;
          for (const ChainMultiplier<double>& other : m.multipliers) nearest = std::min(nearest, std::abs(valueOf(other) - partner));
          EXPECT_LT(nearest, 1e-8 * std::max(1.0, std::abs(z)));
        }
        if (mu.krein != 0) {
          for (const ChainMultiplier<double>& other : m.multipliers) {
            if (std::abs(valueOf(other) - std::conj(z)) < 1e-9 && other.krein != 0) {
              EXPECT_EQ(other.krein, -mu.krein);
            }
          }
        }
      }
      const auto quad = chainOnePeriodicStability<Quad>(quadChain, Quad(found.orbit.period));
      ASSERT_TRUE(quad.orbit.admissible());
      const auto& exact = quad.orbit.monodromy.multipliers;
      ASSERT_EQ(exact.size(), m.multipliers.size());
      for (std::size_t i = 0; i < exact.size(); ++i) {
        const std::complex<double> z(double(exact[i].re), double(exact[i].im));
        const ChainMultiplier<double>* nearest = &m.multipliers[0];
        for (const ChainMultiplier<double>& mu : m.multipliers) {
          if (std::abs(valueOf(mu) - z) < std::abs(valueOf(*nearest) - z)) nearest = &mu;
        }
        const double error = std::abs(valueOf(*nearest) - z);
        EXPECT_LE(error, nearest->error) << "T " << found.orbit.period;
        EXPECT_LT(error, 1e-10 * std::max(1.0, std::abs(z))) << "T " << found.orbit.period;
      }
      if (m.stability != ChainStability::Undecided) {
        EXPECT_EQ(m.stability, quad.orbit.monodromy.stability);
      }
      quadruplets += m.stability == ChainStability::ComplexQuadruplet;
      ++checked;
    }
  }
  EXPECT_GT(checked, 40);
  EXPECT_GT(quadruplets, 0) << "chains of three masses and more leave the circle as quadruplets too";
}

// Two algorithms that must agree: the monodromy built from the run's own path (legsOf: sigma
// from each impact's state) and from the closed form's sigma, each within the other's bars,
// away from multiples of a mode's period (where the path's sigma loses its digits).
TEST(ChainMonodromy, ThePathsMonodromyIsTheClosedFormsWithinItsBars) {
  std::mt19937 rng(31);
  int compared = 0;
  for (int c = 0; c < 8; ++c) {
    const MassChain chain = randomChain(rng, 2 + c % 5);
    const ReadyChain ready = readyChain(chain);
    for (const ChainOnePeriodicStability<double>& found : orbitsOf(chain, 9)) {
      const ChainPeriodicOrbit path = evaluateChainOrbit(ready, found.orbit.state, 1, 1e-9);
      ASSERT_TRUE(path.admissible());
      const auto& closed = found.orbit.monodromy.multipliers;
      const auto& walked = path.monodromy.multipliers;
      ASSERT_EQ(walked.size(), closed.size());
      for (const ChainMultiplier<double>& m : closed) {
        double nearest = INFINITY;
        double bars = 0;
        for (const ChainMultiplier<double>& w : walked) {
          if (std::abs(valueOf(w) - valueOf(m)) < nearest) {
            nearest = std::abs(valueOf(w) - valueOf(m));
            bars = w.error + m.error;
          }
        }
        EXPECT_LE(nearest, bars) << "T " << found.orbit.period;
      }
      EXPECT_LT(path.periodicityResidual, 1e-12);
      ++compared;
    }
  }
  EXPECT_GT(compared, 15);
}

// Scale invariance (docs/model.md section 7): masses and springs times 1e6 (the same
// frequencies) and the gap times 1e-6 leave the multipliers, their class and signatures as they are.
TEST(ChainMonodromy, ScaledChainsHaveTheSameMultipliers) {
  std::mt19937 rng(77);
  int compared = 0;
  for (int c = 0; c < 6; ++c) {
    const MassChain chain = randomChain(rng, 3 + c % 3);
    MassChain scaled = chain;
    for (double& m : scaled.masses) m *= 1e6;
    for (double& k : scaled.springs) k *= 1e6;
    scaled.rightSpring *= 1e6;
    scaled.gap *= 1e-6;
    const ReadyChain ready = readyChain(scaled);
    for (const ChainOnePeriodicStability<double>& found : orbitsOf(chain, 9)) {
      const auto other = chainOnePeriodicStability(ready, found.orbit.period);
      ASSERT_TRUE(other.orbit.admissible()) << "T " << found.orbit.period;
      const auto& a = found.orbit.monodromy;
      const auto& b = other.orbit.monodromy;
      ASSERT_EQ(a.multipliers.size(), b.multipliers.size());
      EXPECT_EQ(a.stability, b.stability);
      for (std::size_t i = 0; i < a.multipliers.size(); ++i) {
        EXPECT_NEAR(std::abs(valueOf(a.multipliers[i]) - valueOf(b.multipliers[i])), 0.0,
                    a.multipliers[i].error + b.multipliers[i].error)
            << "T " << found.orbit.period << ": " << a.multipliers[i].re << " " << a.multipliers[i].im << " against "
            << b.multipliers[i].re << " " << b.multipliers[i].im;
        EXPECT_EQ(a.multipliers[i].krein, b.multipliers[i].krein);
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, 10);
}

// A complex quadruplet (impossible for two masses): lambda, conj(lambda), 1/lambda and
// 1/conj(lambda), all off the circle and off the real axis, and the class says so.
TEST(ChainMonodromy, AQuadrupletIsReportedAsSuch) {
  const MassChain chain{{0.6865, 1.9630, 0.8236}, {0.8423, 1.0745, 0.7486}, 0, 2, 1.0};
  const auto found = chainOnePeriodicStability<double>(readyChain(chain), 10.836024);
  ASSERT_TRUE(found.orbit.admissible());
  const ChainMonodromy<double>& m = found.orbit.monodromy;
  EXPECT_EQ(m.stability, ChainStability::ComplexQuadruplet);
  for (const ChainMultiplier<double>& mu : m.multipliers) {
    EXPECT_FALSE(mu.onCircle);
    EXPECT_GT(std::abs(mu.im), 100 * mu.error);
    EXPECT_EQ(mu.krein, 0);
  }
}

TEST(ChainMonodromy, OneMassHasOnlyItsTrivialPair) {
  const MassChain chain{{1.0}, {2.0}, 0, 0, 1.0};
  // (its 1IPP orbits have T between half its period pi / w and its period 2 pi / w, w = sqrt(2))
  const auto found = chainOnePeriodicStability<double>(readyChain(chain), 3.0);
  ASSERT_EQ(found.onePeriodic, OnePeriodicRefusal::None);
  ASSERT_TRUE(found.orbit.admissible());
  EXPECT_TRUE(found.orbit.monodromy.multipliers.empty());
  EXPECT_EQ(found.orbit.monodromy.stability, ChainStability::Elliptic);
  EXPECT_LT(found.orbit.monodromy.trivialPairDefect, 1e-13);
}

}  // namespace
}  // namespace grazelab::core
