// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/model/chain_design.cpp: springs designed for requested frequency ratios,
// against the note's closed-form 1:2 design, against the designed chains' own spectra, and
// against brute force (every design a dense scan of the springs finds).
#include "core/model/chain_design.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <random>
#include <stop_token>

#include "core/model/mass_chain.h"
#include "core/model/model.h"
#include "core/numbers/scalar.h"

namespace grazelab::core {
namespace {

// the designed chain's frequencies are n_j w0, by its own binary128 spectrum
void expectInRatio(const std::vector<double>& masses, const ChainDesign& design, const std::vector<int>& harmonics,
                   double rightSpring = 0) {
  const ChainModes modes = chainModes(MassChain{masses, design.springs, rightSpring, 0, 1});
  for (std::size_t j = 0; j < masses.size(); ++j) {
    EXPECT_NEAR(modes.omega[Eigen::Index(j)] / (harmonics[j] * design.omega0), 1.0, 1e-14) << "mode " << j + 1;
  }
  for (double k : design.springs) EXPECT_GT(k, 0);
}

TEST(ChainDesign, TwoMassesOneToTwoAreTheNotesBranches) {
  // the note's closed-form design: two branches up to m2/m1 = 9/16, none beyond
  for (double ratio : {0.05, 0.2, 0.5, 0.56, 0.5624}) {
    const std::vector<double> masses{2.0, 2.0 * ratio};
    const ChainDesigns designs = designSprings(masses, 3.0, {2, 1});
    ASSERT_EQ(designs.outcome, DesignOutcome::Designed) << ratio;
    ASSERT_EQ(designs.designs.size(), 2u) << ratio;
    EXPECT_EQ(designs.paths, 2);
    int index = 0;
    for (Branch branch : {Branch::Upper, Branch::Lower}) {
      const auto model = designedModel<double>(2.0, 2.0 * ratio, 3.0, 1.0, branch);
      ASSERT_TRUE(model);
      const ChainDesign& design = designs.designs[std::size_t(index++)];
      EXPECT_NEAR(design.springs[1] / model->k2, 1.0, 1e-14) << ratio;
      EXPECT_EQ(design.springs[0], 3.0);
      expectInRatio(masses, design, {2, 1});
    }
  }
  // at m2/m1 = 9/16 exactly the two branches are one double root (two paths end there): one
  // design, the note's k2 = 0.36 k1 ... and none a hair beyond
  const ChainDesigns edge = designSprings({1.0, 0.5625}, 1.0, {2, 1});
  ASSERT_EQ(edge.outcome, DesignOutcome::Designed);
  ASSERT_EQ(edge.designs.size(), 1u);
  EXPECT_NEAR(edge.designs[0].springs[1], designedModel<double>(1.0, 0.5625, 1.0, 1.0, Branch::Upper)->k2, 1e-12);
  EXPECT_EQ(designSprings({1.0, 0.5625 * (1 + 1e-10)}, 1.0, {2, 1}).outcome, DesignOutcome::NoPositiveDesign);
  for (double ratio : {0.5626, 0.7, 2.0}) {
    const ChainDesigns designs = designSprings({1.0, ratio}, 1.0, {2, 1});
    EXPECT_EQ(designs.outcome, DesignOutcome::NoPositiveDesign) << ratio;
    EXPECT_TRUE(designs.designs.empty());
    EXPECT_EQ(designs.complexEnds + designs.infiniteEnds, 2) << ratio;  // two distinct roots
  }
}

TEST(ChainDesign, DesignsAreExactAndScaleWithTheMassesAndK1) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> logMass(-1, 1);
  const std::vector<std::vector<int>> requests{{3, 1}, {3, 2}, {5, 2}, {3, 2, 1}, {4, 3, 1}, {5, 3, 1}, {4, 3, 2, 1}};
  int designed = 0;
  for (const std::vector<int>& harmonics : requests) {
    for (int trial = 0; trial < 4; ++trial) {
      std::vector<double> masses;
      for (std::size_t i = 0; i < harmonics.size(); ++i) masses.push_back(std::pow(10.0, logMass(random)));
      const ChainDesigns designs = designSprings(masses, 1.0, harmonics);
      ASSERT_NE(designs.outcome, DesignOutcome::Incomplete);
      ASSERT_NE(designs.outcome, DesignOutcome::BadRequest);
      for (const ChainDesign& design : designs.designs) expectInRatio(masses, design, harmonics);
      designed += int(designs.designs.size());
      // the same request on a chain 1000 times heavier with k1 = 10: the same springs over k1,
      // w0 scaled by sqrt(10 / 1000)
      std::vector<double> heavy;
      for (double m : masses) heavy.push_back(1000 * m);
      const ChainDesigns scaled = designSprings(heavy, 10.0, harmonics);
      ASSERT_EQ(scaled.designs.size(), designs.designs.size());
      for (std::size_t d = 0; d < designs.designs.size(); ++d) {
        for (std::size_t i = 0; i < masses.size(); ++i) {
          EXPECT_NEAR(scaled.designs[d].springs[i] / (10 * designs.designs[d].springs[i]), 1.0, 1e-13);
        }
        EXPECT_NEAR(scaled.designs[d].omega0 / (designs.designs[d].omega0 * std::sqrt(0.01)), 1.0, 1e-13);
      }
    }
  }
  EXPECT_GT(designed, 10);  // the requests are not all impossible
}

// Brute force, independent of the homotopy: the mismatch of a three-mass chain's ratios from
// the request over a dense grid of (log k2, log k3), k1 = 1 (and a right wall as given); each
// grid minimum is refined by a pattern search, and those that reach zero are the designs in the
// grid's range: the homotopy must have found each of them (every design found) and no other
// (none made up).
TEST(ChainDesign, EveryDesignOfThreeMassesIsFound) {
  struct Request {
    std::vector<double> masses;
    std::vector<int> harmonics;
    double rightSpring;
  };
  for (const auto& [masses, harmonics, rightSpring] : std::vector<Request>{
           {{1.0, 0.2, 0.05}, {3, 2, 1}, 0.0}, {{1.0, 1.0, 0.2}, {4, 3, 1}, 0.0}, {{1.0, 0.4, 0.2}, {5, 3, 1}, 0.0},
           {{1.0, 0.1, 0.3}, {4, 3, 1}, 0.0}, {{1.0, 0.5, 2.0}, {3, 2, 1}, 0.0},
           // a right wall: its spring kept, the equations quadratic in 1/k1 (twice the paths)
           {{1.0, 0.2, 0.05}, {3, 2, 1}, 0.01}, {{1.0, 1.0, 1.0}, {3, 2, 1}, 0.5}, {{1.0, 0.4, 0.2}, {5, 3, 1}, 2.0},
           {{0.3, 1.0, 0.5}, {4, 3, 1}, 0.2}}) {
    const ChainDesigns designs = designSprings(masses, 1.0, rightSpring, harmonics);
    ASSERT_NE(designs.outcome, DesignOutcome::Incomplete);
    EXPECT_EQ(designs.paths, rightSpring > 0 ? 12 : 6);
    // the chain's frequencies by Eigen's dense solver in double, apart from chainModes
    const auto mismatch = [&](double logK2, double logK3) {
      const double k[4] = {1.0, std::exp(logK2), std::exp(logK3), rightSpring};
      Eigen::Matrix3d scaled;  // M^-1/2 K M^-1/2
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          const double entry = i == j ? k[i] + k[i + 1] : (std::abs(i - j) == 1 ? -k[std::max(i, j)] : 0.0);
          scaled(i, j) = entry / std::sqrt(masses[std::size_t(i)] * masses[std::size_t(j)]);
        }
      }
      const Eigen::Vector3d w2 = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scaled).eigenvalues();  // ascending
      const double a = std::sqrt(w2[2] / w2[0]) - double(harmonics[0]) / harmonics[2];
      const double b = std::sqrt(w2[1] / w2[0]) - double(harmonics[1]) / harmonics[2];
      return std::hypot(a, b);
    };
    // fine enough to part the close pairs designs come in (k2 = 0.775 and 0.738, k3 = 0.189
    // and 0.196 for masses 1, 0.2, 0.05 and 3:2:1)
    constexpr int kGrid = 400;
    constexpr double kLow = -3 * 2.302585092994046, kHigh = 3 * 2.302585092994046;  // 1e-3 ... 1e3
    const auto at = [](int i) { return kLow + (kHigh - kLow) * i / (kGrid - 1); };
    std::vector<double> value(std::size_t(kGrid * kGrid));
    for (int i = 0; i < kGrid; ++i) {
      for (int j = 0; j < kGrid; ++j) value[std::size_t(i * kGrid + j)] = mismatch(at(i), at(j));
    }
    std::vector<std::pair<double, double>> solutions;  // log k2, log k3
    for (int i = 1; i + 1 < kGrid; ++i) {
      for (int j = 1; j + 1 < kGrid; ++j) {
        const double here = value[std::size_t(i * kGrid + j)];
        bool lowest = true;
        for (int di = -1; di <= 1; ++di) {
          for (int dj = -1; dj <= 1; ++dj) lowest = lowest && here <= value[std::size_t((i + di) * kGrid + j + dj)];
        }
        if (!lowest) continue;
        double a = at(i), b = at(j), step = (kHigh - kLow) / kGrid;
        double f = here;
        while (step > 1e-13) {
          bool moved = false;
          for (const auto& [da, db] : {std::pair{step, 0.0}, {-step, 0.0}, {0.0, step}, {0.0, -step},
                                        {step, step}, {-step, -step}, {step, -step}, {-step, step}}) {
            const double g = mismatch(a + da, b + db);
            if (g < f) {
              a += da;
              b += db;
              f = g;
              moved = true;
              break;
            }
          }
          if (!moved) step /= 2;
        }
        const bool known = std::any_of(solutions.begin(), solutions.end(), [&](const auto& s) {
          return std::abs(s.first - a) < 1e-6 && std::abs(s.second - b) < 1e-6;
        });
        if (f < 1e-8 && !known) solutions.emplace_back(a, b);
      }
    }
    int inRange = 0;
    for (const ChainDesign& design : designs.designs) {
      expectInRatio(masses, design, harmonics, rightSpring);
      const double a = std::log(design.springs[1]), b = std::log(design.springs[2]);
      if (a < kLow || a > kHigh || b < kLow || b > kHigh) continue;
      ++inRange;
      EXPECT_TRUE(std::any_of(solutions.begin(), solutions.end(), [&](const auto& s) {
        return std::abs(s.first - a) < 1e-5 && std::abs(s.second - b) < 1e-5;
      })) << "a design no brute force confirms: k2 = " << design.springs[1] << ", k3 = " << design.springs[2];
    }
    EXPECT_EQ(int(solutions.size()), inRange) << "masses " << masses[0] << ", " << masses[1] << ", " << masses[2]
                                              << ", right wall " << rightSpring;
  }
}

// A right wall scales with the chain (masses x1000, k1 and k_(N+1) x10: the springs x10, w0 x
// sqrt(10 / 1000)); a wall weak against k1 is a perturbation: its designs tend to the wall-less
// ones (each within the wall's relative stiffness).
TEST(ChainDesign, RightWallDesignsScaleAndVanishWithTheWall) {
  const std::vector<double> masses{1.0, 0.2, 0.05};
  const std::vector<int> harmonics{3, 2, 1};
  const ChainDesigns walled = designSprings(masses, 1.0, 0.3, harmonics);
  ASSERT_EQ(walled.outcome, DesignOutcome::Designed);
  const ChainDesigns heavy = designSprings({1000.0, 200.0, 50.0}, 10.0, 3.0, harmonics);
  ASSERT_EQ(heavy.designs.size(), walled.designs.size());
  for (std::size_t d = 0; d < walled.designs.size(); ++d) {
    expectInRatio(masses, walled.designs[d], harmonics, 0.3);
    for (std::size_t i = 0; i < masses.size(); ++i) {
      EXPECT_NEAR(heavy.designs[d].springs[i] / (10 * walled.designs[d].springs[i]), 1.0, 1e-13);
    }
    EXPECT_NEAR(heavy.designs[d].omega0 / (walled.designs[d].omega0 * 0.1), 1.0, 1e-13);
  }
  const ChainDesigns free = designSprings(masses, 1.0, harmonics);
  const ChainDesigns faint = designSprings(masses, 1.0, 1e-9, harmonics);
  ASSERT_EQ(free.outcome, DesignOutcome::Designed);
  ASSERT_EQ(faint.designs.size(), free.designs.size());
  for (std::size_t d = 0; d < free.designs.size(); ++d) {
    expectInRatio(masses, faint.designs[d], harmonics, 1e-9);
    for (std::size_t i = 0; i < masses.size(); ++i) {
      EXPECT_NEAR(faint.designs[d].springs[i] / free.designs[d].springs[i], 1.0, 1e-6);
    }
  }
  // a wall as stiff as it gets is refused as input, never a silent design
  EXPECT_EQ(designSprings(masses, 1.0, -1.0, harmonics).outcome, DesignOutcome::BadRequest);
  EXPECT_EQ(designSprings(masses, 1.0, std::nan(""), harmonics).outcome, DesignOutcome::BadRequest);
}

// A chain given in binary128 (masses 0.2, 0.05 read from their decimal text there, which double
// rounds 1e-17 away): each double design refined for it is in the ratio to binary128's rounding.
// Two masses in 1:2 against the closed form (w1^2 = 4 w2^2 makes the characteristic polynomial's
// (sum of roots)^2 / product = 25/4, a quadratic in k2 whose two roots are the note's branches);
// three, with and without a wall, by the characteristic polynomial of K - lambda M, whose roots
// are 9x, 4x, x when its coefficients' ratios are 14, 49, 36. The double design itself is off by
// double's rounding there (the refinement is what makes a binary128 run's chain resonant).
TEST(ChainDesign, RefinedDesignsAreExactInBinary128) {
  const Quad m2 = parseScalar<Quad>("0.2").value.value(), m3 = parseScalar<Quad>("0.05").value.value();
  const Quad k1 = parseScalar<Quad>("1.3").value.value();
  {
    const std::vector<Quad> masses{Quad(1), m2};
    const ChainDesigns designs = designSprings({1.0, 0.2}, 1.3, {2, 1});
    ASSERT_EQ(designs.designs.size(), 2u);
    // (a k2 + b)^2 = 25/4 m1 m2 k1 k2 with a = m1 + m2, b = m2 k1
    const Quad a = masses[0] + masses[1], b = masses[1] * k1, c = Quad(25) / 4 * masses[0] * masses[1] * k1;
    const Quad p = 2 * a * b - c, root = sqrt(p * p - 4 * a * a * b * b);
    const Quad branches[2] = {(-p + root) / (2 * a * a), (-p - root) / (2 * a * a)};  // upper first
    for (std::size_t d = 0; d < 2; ++d) {
      const auto springs = refinedSprings(masses, k1, Quad(0), {2, 1}, designs.designs[d]);
      ASSERT_TRUE(springs.has_value()) << d;
      EXPECT_EQ((*springs)[0], k1);
      EXPECT_LT(double(fabs((*springs)[1] / branches[d] - 1)), 1e-31) << d;
      EXPECT_GT(double(fabs(Quad(designs.designs[d].springs[1]) / branches[d] - 1)), 1e-20) << d;
    }
  }
  // masses just past the edge where the two 1:2 designs meet (m2/m1 = 9/16 plus 1e-19): double
  // rounds them onto the edge, where a design exists; binary128 has none to refine it to
  {
    const std::vector<Quad> past{Quad(1), parseScalar<Quad>("0.5625000000000000001").value.value()};
    const ChainDesigns edge = designSprings({1.0, 0.5625}, 1.0, {2, 1});
    ASSERT_EQ(edge.outcome, DesignOutcome::Designed);
    for (const ChainDesign& design : edge.designs) EXPECT_FALSE(refinedSprings(past, Quad(1), Quad(0), {2, 1}, design));
  }
  for (const Quad& wall : {Quad(0), parseScalar<Quad>("0.3").value.value()}) {
    const std::vector<Quad> masses{Quad(1), m2, m3};
    const ChainDesigns designs = designSprings({1.0, 0.2, 0.05}, 1.3, double(wall), {3, 2, 1});
    ASSERT_EQ(designs.outcome, DesignOutcome::Designed);
    // the coefficients' ratios' worst error for springs k (K tridiagonal, its last diagonal k3 + wall)
    const auto ratioError = [&](const std::vector<Quad>& k) {
      const Quad a0 = k[0] + k[1], a1 = k[1] + k[2], a2 = k[2] + wall;
      const Quad p3 = masses[0] * masses[1] * masses[2];
      const Quad p2 = a0 * masses[1] * masses[2] + a1 * masses[0] * masses[2] + a2 * masses[0] * masses[1];
      const Quad p1 = a0 * a1 * masses[2] + a0 * a2 * masses[1] + a1 * a2 * masses[0] - k[1] * k[1] * masses[2] -
                      k[2] * k[2] * masses[0];
      const Quad p0 = a0 * a1 * a2 - a0 * k[2] * k[2] - a2 * k[1] * k[1];
      const Quad x = p2 / p3 / 14;
      return double(std::max(fabs(p1 / p3 / (49 * x * x) - 1), fabs(p0 / p3 / (36 * x * x * x) - 1)));
    };
    for (const ChainDesign& design : designs.designs) {
      const auto springs = refinedSprings(masses, k1, wall, {3, 2, 1}, design);
      ASSERT_TRUE(springs.has_value());
      EXPECT_LT(ratioError(*springs), 1e-30) << double(wall);
      std::vector<Quad> unrefined{k1};
      for (std::size_t i = 1; i < 3; ++i) unrefined.push_back(Quad(design.springs[i]));
      EXPECT_GT(ratioError(unrefined), 1e-20) << double(wall);
    }
  }
}

TEST(ChainDesign, RefusesBadRequests) {
  EXPECT_EQ(designSprings({}, 1.0, {}).outcome, DesignOutcome::BadRequest);
  EXPECT_EQ(designSprings({1.0, 1.0}, 1.0, {2}).outcome, DesignOutcome::BadRequest);         // one ratio short
  EXPECT_EQ(designSprings({1.0, 1.0}, 1.0, {1, 2}).outcome, DesignOutcome::BadRequest);      // slowest first
  EXPECT_EQ(designSprings({1.0, 1.0}, 1.0, {2, 2}).outcome, DesignOutcome::BadRequest);      // equal
  EXPECT_EQ(designSprings({1.0, -1.0}, 1.0, {2, 1}).outcome, DesignOutcome::BadRequest);
  EXPECT_EQ(designSprings({1.0, 1.0}, std::nan(""), {2, 1}).outcome, DesignOutcome::BadRequest);
  EXPECT_EQ(designSprings(std::vector<double>(8, 1.0), 1.0, {8, 7, 6, 5, 4, 3, 2, 1}).outcome,
            DesignOutcome::BadRequest);
  // a common factor is the same request: 4:2 is 2:1
  const ChainDesigns doubled = designSprings({1.0, 0.5}, 1.0, {4, 2});
  const ChainDesigns plain = designSprings({1.0, 0.5}, 1.0, {2, 1});
  ASSERT_EQ(doubled.designs.size(), plain.designs.size());
  EXPECT_EQ(doubled.designs[0].omega0, plain.designs[0].omega0);
}

// chooseDesign keeps the designs it made: asked again it gives the same bits as a fresh search;
// a search that was stopped is not kept (asked again, the chain is designed)
TEST(ChainDesign, ChosenDesignsAreKeptButAStoppedSearchIsNot) {
  const std::vector<double> masses{1.0, 0.31, 0.07};  // (masses no other test asks for)
  std::stop_source stopped;
  stopped.request_stop();
  EXPECT_EQ(chooseDesign(masses, 1.0, 0.0, {3, 2, 1}, 1, stopped.get_token()).problem, DesignChoiceProblem::Stopped);
  const DesignChoice first = chooseDesign(masses, 1.0, 0.0, {3, 2, 1}, 1);
  ASSERT_EQ(first.problem, DesignChoiceProblem::None);
  const ChainDesigns fresh = designSprings(masses, 1.0, 0.0, {3, 2, 1});
  const DesignChoice again = chooseDesign(masses, 1.0, 0.0, {3, 2, 1}, 2);
  ASSERT_EQ(fresh.designs.size(), first.designs.designs.size());
  ASSERT_EQ(again.designs.designs.size(), first.designs.designs.size());
  for (std::size_t i = 0; i < fresh.designs.size(); ++i) {
    EXPECT_EQ(again.designs.designs[i].springs, fresh.designs[i].springs) << "design " << i + 1;
    EXPECT_EQ(first.designs.designs[i].springs, fresh.designs[i].springs) << "design " << i + 1;
  }
  EXPECT_EQ(again.number, 2);
  // another k1 is another chain: its springs scale with it
  const DesignChoice stiffer = chooseDesign(masses, 2.0, 0.0, {3, 2, 1}, 1);
  ASSERT_EQ(stiffer.problem, DesignChoiceProblem::None);
  EXPECT_NEAR(stiffer.chosen().springs[1], 2 * first.chosen().springs[1], 1e-13 * first.chosen().springs[1]);
}

}  // namespace
}  // namespace grazelab::core
