// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
//
// Chains held by no wall (k1 = 0, no right wall; docs/model.md section 11): one mode is the rigid
// body's, w = 0, its flight linear in time, and the contact search carries the drift as a slope.
// Checked by closed forms (two equal masses, a held mass's release), by the laws a free chain
// keeps (momentum changes only at the impacts, energy always), by brute force in long double, by
// the chain with a very weak wall, and by the same run in binary128.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "core/solver/chain_run.h"
#include "core/solver/chain_stick.h"

namespace grazelab::core {
namespace {

MassChain floatingChain(const std::vector<double>& masses, const std::vector<double>& inner, int stop, double gap) {
  MassChain chain;
  chain.masses = masses;
  chain.springs.push_back(0.0);
  chain.springs.insert(chain.springs.end(), inner.begin(), inner.end());
  chain.stopMass = stop;
  chain.gap = gap;
  return chain;
}

double momentum(const MassChain& chain, const Eigen::VectorXd& v) {
  double p = 0;
  for (int i = 0; i < chain.size(); ++i) p += chain.masses[std::size_t(i)] * v[i];
  return p;
}

// a random floating chain of n masses, stop on the first, last or an interior mass
MassChain randomFloatingChain(int n, int trial, std::mt19937& random) {
  std::uniform_real_distribution<double> value(0.2, 5.0);
  std::vector<double> masses, inner;
  for (int i = 0; i < n; ++i) masses.push_back(value(random));
  for (int i = 1; i < n; ++i) inner.push_back(value(random));
  const int stop = trial % 3 == 0 ? n : trial % 3 == 1 ? 1 : 1 + (n - 1) / 2;
  return floatingChain(masses, inner, stop, value(random));
}

// a start below the stop, vibrating, the whole chain moving onto the stop
ChainState randomPush(const MassChain& chain, std::mt19937& random) {
  std::uniform_real_distribution<double> value(-0.3, 0.3);
  const Eigen::Index n = chain.size();
  ChainState start{Eigen::VectorXd(n), Eigen::VectorXd(n)};
  // toward the stop: the stop acts on u_s = d > 0, so a positive drift
  for (Eigen::Index i = 0; i < n; ++i) {
    start.u[i] = chain.gap * value(random);
    start.v[i] = 1.0 + value(random);
  }
  return start;
}

// u_s(t) - d along a flight, in long double, from the modes (the rigid one as q + qdot t)
long double stopDistance(const ChainDynamics& dynamics, const ChainFlight& flight, long double t) {
  long double f = -dynamics.gap;
  for (Eigen::Index j = 0; j < flight.q.size(); ++j) {
    const long double w = dynamics.omega[j];
    const long double q = w == 0 ? flight.q[j] + flight.qdot[j] * t
                                 : flight.q[j] * std::cos(w * t) + flight.qdot[j] / w * std::sin(w * t);
    f += dynamics.P(dynamics.stop, j) * q;
  }
  return f;
}

TEST(FloatingChain, ItsRigidModeIsExactAndItsOthersAreTheWeakWallsLimit) {
  std::mt19937 random(41);
  for (int n = 1; n <= 8; ++n) {
    const MassChain chain = randomFloatingChain(n, n, random);
    ASSERT_TRUE(validate(chain).empty());
    ASSERT_TRUE(chain.floats());
    const ChainModes modes = chainModes(chain);
    double total = 0;
    for (double m : chain.masses) total += m;
    EXPECT_EQ(modes.omega[n - 1], 0.0);
    for (int i = 0; i < n; ++i) EXPECT_NEAR(modes.P(i, n - 1), 1 / std::sqrt(total), 1e-16);
    EXPECT_EQ(slowestFrequency(modes.omega), n > 1 ? modes.omega[n - 2] : 0.0);
    // M-orthonormal, and K diagonal in them
    const Eigen::MatrixXd M = massMatrix(chain), K = stiffnessMatrix(chain);
    const Eigen::MatrixXd identity = modes.P.transpose() * M * modes.P;
    EXPECT_LT((identity - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(), 1e-14) << "n = " << n;
    const Eigen::MatrixXd diagonal = modes.P.transpose() * K * modes.P;
    const double scale = modes.omega[0] * modes.omega[0];
    for (int j = 0; j < n; ++j) {
      EXPECT_NEAR(diagonal(j, j), modes.omega[j] * modes.omega[j], 1e-14 * scale);
    }
    // the same chain held by a wall 1e-12 of its springs: its frequencies but the slowest move
    // by that much, the slowest goes to 0 as its square root
    MassChain weak = chain;
    weak.springs[0] = 1e-24;
    const ChainModes held = chainModes(weak);
    for (int j = 0; j + 1 < n; ++j) EXPECT_NEAR(held.omega[j], modes.omega[j], 1e-12 * modes.omega[0]);
    EXPECT_LT(held.omega[n - 1], 1e-11);
  }
}

TEST(FloatingChain, ABarsModesAreTheClosedFormsEigenvectors) {
  // equal masses and springs, floating: the modes come from the closed form (the discrete cosine
  // transform's), not the solver; they must still be M-orthonormal, diagonalise K, go fastest
  // first, and have their nodes exactly where j (2s + 1) = N mod 2N (a stop in the middle of an
  // odd chain: every odd mode)
  for (const int n : {2, 3, 7, 12, 41}) {
    for (const int stop : {n, 1, (n + 1) / 2}) {
      const MassChain chain = floatingChain(std::vector<double>(std::size_t(n), 0.3), std::vector<double>(std::size_t(n - 1), 7.0), stop, 1.0);
      const ChainModes modes = chainModes(chain);
      const Eigen::MatrixXd M = massMatrix(chain), K = stiffnessMatrix(chain);
      EXPECT_LT((modes.P.transpose() * M * modes.P - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(), 1e-13);
      const Eigen::MatrixXd diagonal = modes.P.transpose() * K * modes.P;
      const double scale = modes.omega[0] * modes.omega[0];
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          EXPECT_NEAR(diagonal(i, j), i == j ? modes.omega[j] * modes.omega[j] : 0.0, 1e-13 * scale) << n << " " << i << " " << j;
        }
        if (j > 0) {
          EXPECT_LT(modes.omega[j], modes.omega[j - 1]);
        }
        const int harmonic = n - 1 - j;
        const bool node = harmonic * (2 * (stop - 1) + 1) % (2 * n) == n;
        EXPECT_EQ(modes.nodeAtStop[std::size_t(j)], node) << n << " stop " << stop << " mode " << j;
        if (!node) {
          EXPECT_GT(modes.P(stop - 1, j), 0);
        }
      }
      EXPECT_EQ(modes.omega[n - 1], 0.0);
      // the solver's frequencies, on the same chain with one mass a part in 1e15 heavier
      MassChain nudged = chain;
      nudged.masses[0] *= 1 + 1e-15;
      const ChainModes solved = chainModes(nudged);
      for (int j = 0; j < n; ++j) EXPECT_NEAR(solved.omega[j], modes.omega[j], 1e-13 * modes.omega[0]);
    }
  }
}

TEST(FloatingChain, TwoEqualMassesReboundAsOneAfterHalfTheirSpringsPeriod) {
  // m -- k -- m thrown at the wall at v0, the right mass touching it: after its impact the centre
  // of mass is at rest and the right mass at d - (v0 / w) sin wt (w = sqrt(2k / m)) returns to the
  // stop at t = pi / w moving in at v0; that second impact leaves both at -v0, the spring slack
  for (const double m : {0.3, 1.0, 7.0}) {
    for (const double k : {0.5, 40.0}) {
      for (const double v0 : {1e-3, 2.0}) {
        const MassChain chain = floatingChain({m, m}, {k}, 2, 0.25);
        const ChainState start{Eigen::Vector2d(0.25, 0.25), Eigen::Vector2d(v0, v0)};
        const ChainRun run = runChain(chain, start, 100, 0);
        ASSERT_EQ(run.stop, StopReason::NoFurtherContact) << m << " " << k << " " << v0;
        ASSERT_EQ(run.impacts, 2);
        const double w = std::sqrt(2 * k / m);
        EXPECT_EQ(run.events[0].t, 0);
        // (to the rounding of u_s, eps (d + v0 / w), over the speed v0 it meets the stop at)
        const double rounding = 8 * 2.2e-16 * (0.25 + v0 / w) / v0;
        EXPECT_NEAR(run.events[1].t, std::numbers::pi / w, 1e-14 * std::numbers::pi / w + rounding);
        EXPECT_NEAR(run.events[1].vBefore[1], v0, 1e-13 * v0);
        EXPECT_NEAR(run.final.v[0], -v0, 1e-13 * v0);
        EXPECT_NEAR(run.final.v[1], -v0, 1e-13 * v0);
        EXPECT_NEAR(run.energyFinal, run.energyInitial, 1e-14 * run.energyInitial);
      }
    }
  }
}

TEST(FloatingChain, MomentumChangesOnlyAtTheImpactsAndNoContactIsMissed) {
  // random chains of 2 to 8 masses, stops on the first, last or an interior mass: between
  // impacts no force acts on a floating chain, so its momentum after the run is its start's plus
  // m_s (vAfter - vBefore) at each impact; its energy is kept; and u_s, sampled 2000 times per
  // fastest period in long double before each contact found, stays below the stop
  std::mt19937 random(43);
  int impacts = 0, drifting = 0;
  for (int trial = 0; trial < 21; ++trial) {
    const int n = 2 + trial % 7;
    const MassChain chain = randomFloatingChain(n, trial, random);
    const ChainState start = randomPush(chain, random);
    const ChainRun run = runChain(chain, start, 60, 0);
    ASSERT_TRUE(run.stop == StopReason::NoFurtherContact || run.stop == StopReason::ContactLimit)
        << "trial " << trial << ": " << int(run.stop);
    drifting += run.stop == StopReason::NoFurtherContact;
    const int s = chain.stopped() - 1;
    double p = momentum(chain, start.v);
    const ChainDynamics dynamics = chainDynamics(chain);
    const double step = 2 * std::numbers::pi / dynamics.omega.maxCoeff() / 2000;
    ChainState state = start;
    double t = 0;
    for (const ChainEvent& event : run.events) {
      ASSERT_EQ(event.type, EventType::Impact);
      ++impacts;
      p += chain.masses[std::size_t(s)] * (event.vAfter - event.vBefore[s]);
      const ChainFlight flight = flightFrom(dynamics, state);
      const double length = event.t - t;
      for (double at = step; at < length - 1e-9 * (1 + length); at += step) {
        ASSERT_LT(stopDistance(dynamics, flight, at), 1e-12L)
            << "trial " << trial << ": a contact at t = " << t + at << " before the one found at " << event.t;
      }
      EXPECT_NEAR(double(stopDistance(dynamics, flight, length)), 0.0, 1e-10 * chain.gap);
      state.u = event.u;
      state.v = event.vBefore;
      state.v[s] = event.vAfter;
      t = event.t;
    }
    EXPECT_NEAR(momentum(chain, run.final.v), p, 1e-12 * (1 + std::abs(p))) << "trial " << trial;
    EXPECT_LT(run.maxEnergyDrift, 1e-12) << "trial " << trial;
    if (run.stop == StopReason::NoFurtherContact) {
      // it leaves for good: the drift away from the stop
      EXPECT_LT(momentum(chain, run.final.v), 0) << "trial " << trial;
    }
  }
  EXPECT_GT(impacts, 80);
  EXPECT_GT(drifting, 5);
}

TEST(FloatingChain, ItsRunIsTheWeakWallsAndItsBinary128Runs) {
  // the same chain held by a left wall 1e-8 of its springs (every mode a sinusoid, the slowest
  // of period ~1e4, its amplitude at the stop ~1e4 times the drift's) makes the same contacts to
  // 1e-5 over a few periods (a force of 1e-8 moves the chain by about that much, the weak mode's
  // rounding 1e-11 of it); in binary128 to 1e-10 (the double run's own rounding)
  std::mt19937 random(47);
  for (int trial = 0; trial < 9; ++trial) {
    const int n = 2 + trial % 5;
    const MassChain chain = randomFloatingChain(n, trial, random);
    const ChainState start = randomPush(chain, random);
    const ChainRun run = runChain(chain, start, 12, 0);
    MassChain weak = chain;
    weak.springs[0] = 1e-8;
    const ChainRun held = runChain(weak, start, 12, run.tFinal * 1.01 + 0.01);
    ASSERT_GE(held.events.size(), run.events.size()) << "trial " << trial;
    for (std::size_t k = 0; k < run.events.size(); ++k) {
      EXPECT_NEAR(held.events[k].t, run.events[k].t, 1e-5 * (1 + run.events[k].t)) << "trial " << trial << " event " << k;
    }
    const BasicMassChain<Quad> wide = chainCast<Quad>(chain);
    const BasicChainState<Quad> wideStart{start.u.cast<Quad>(), start.v.cast<Quad>()};
    const BasicChainRun<Quad> exact = runChain<Quad>(wide, wideStart, 12, Quad(0));
    ASSERT_EQ(exact.events.size(), run.events.size()) << "trial " << trial;
    EXPECT_EQ(exact.stop, run.stop);
    for (std::size_t k = 0; k < run.events.size(); ++k) {
      EXPECT_NEAR(double(exact.events[k].t), run.events[k].t, 1e-10 * (1 + run.events[k].t))
          << "trial " << trial << " event " << k;
    }
  }
}

TEST(FloatingChain, OneDriftingAwayEndsAtOnceAndRunsToTheEndTimeWhenGiven) {
  std::mt19937 random(53);
  for (int trial = 0; trial < 6; ++trial) {
    const MassChain chain = randomFloatingChain(2 + trial, trial, random);
    ChainState start = randomPush(chain, random);
    start.v = -start.v;  // away from the stop, vibrating
    // its vibration reaches well short of the stop's gap: the drift only takes it further
    const ChainRun run = runChain(chain, start, 10, 0);
    EXPECT_EQ(run.stop, StopReason::NoFurtherContact) << "trial " << trial;
    EXPECT_TRUE(run.events.empty());
    const ChainRun timed = runChain(chain, start, 10, 5.0);
    EXPECT_EQ(timed.stop, StopReason::TimeLimit);
    EXPECT_EQ(timed.tFinal, 5.0);
    EXPECT_NEAR(momentum(chain, timed.final.v), momentum(chain, start.v), 1e-13 * std::abs(momentum(chain, start.v)));
  }
  // one mass alone: it meets the stop at (d - u) / v, once
  const MassChain one = floatingChain({2.0}, {}, 1, 1.5);
  const ChainRun run = runChain(one, ChainState{Eigen::VectorXd::Constant(1, 0.5), Eigen::VectorXd::Constant(1, 4.0)}, 5, 0);
  ASSERT_EQ(run.impacts, 1);
  EXPECT_DOUBLE_EQ(run.events[0].t, 0.25);
  EXPECT_EQ(run.stop, StopReason::NoFurtherContact);
  EXPECT_DOUBLE_EQ(run.final.v[0], -4.0);
}

TEST(FloatingChain, AFreeLeftEndFollowsAHeldMassAndItsReleaseIsTheClosedForms) {
  // m1 (free on the left) -- k -- m2 (on the stop) -- k -- m3 -- k -- wall: held, m1 rests at d
  // with the clamp and m3 at d / 2 (two equal springs in series); from u3 = d/2 + A, u1 = d, at
  // rest, the force on m2 is k (u3 - d) = k (A cos(sqrt(2k/m) t) - d/2): released when
  // cos(sqrt(2k/m) t) = d / (2A)
  for (const double m : {0.5, 3.0}) {
    for (const double A : {0.8, 5.0}) {
      const double d = 1.0, k = 2.0;
      MassChain chain = floatingChain({m, m, m}, {k, k}, 2, d);
      chain.rightSpring = k;
      ASSERT_FALSE(chain.floats());
      const ChainState start{Eigen::Vector3d(d, d, d / 2 + A), Eigen::Vector3d::Zero()};
      const ChainRun run = runChain(chain, start, 3, 0);
      ASSERT_GE(run.events.size(), 2u);
      EXPECT_EQ(run.events[0].type, EventType::Stick);
      ASSERT_EQ(run.events[1].type, EventType::Release);
      const double release = std::acos(d / (2 * A)) / std::sqrt(2 * k / m);
      EXPECT_NEAR(run.events[1].t, release, 1e-13 * release) << m << " " << A;
      EXPECT_NEAR(run.events[1].u[0], d, 1e-15);  // m1 stayed with the clamp
      EXPECT_NEAR(run.events[1].vBefore[0], 0.0, 1e-15);
      const ChainStuckPhase phase = stuckPhase(chain, start);
      EXPECT_EQ(phase.restForce, -k * d / 2);
    }
  }
}

}  // namespace
}  // namespace grazelab::core
