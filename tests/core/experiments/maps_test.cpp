// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Maps (issue 10): the grazing family's FFT is T2 exactly, no first flight lasts longer, the
// result does not depend on threads or stripes, and bad specs are refused.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <thread>

#include "core/model/two_mass_form.h"
#include "core/orbits/special_orbits.h"
#include "core/experiments/maps.h"
#include "parallel/tbb_parallel_for.h"
#include "support/point_bits.h"

namespace grazelab::core {
namespace {

MapSpec grazingPlane(std::int64_t columns, std::int64_t rows, std::int64_t contacts) {
  MapSpec spec;
  spec.model.design = Branch::Upper;
  spec.x = {MapVariable::U1, -1.0, 2.0, columns};
  spec.y = {MapVariable::V1, -1.5, 1.5, rows};
  spec.contacts = contacts;
  return spec;
}

using testing::sameBits;

double periodOf(const Model& model) {
  Model designed = model;
  designed.k2 = designKappa(model.m2 / model.m1, *model.design) * model.k1;
  return twoPi<double>() / makeTwoMassForm(designed).chain->omegaSlow;
}

TEST(MapsTest, theGrazingFamilyFliesExactlyT2OverMassRatiosAndLambdas) {
  MapSpec spec;
  spec.model.design = Branch::Upper;
  spec.x = {MapVariable::Lambda, 0.0, 4.0 / 3.0, 9};
  spec.y = {MapVariable::MassRatio, 0.05, 0.55, 6};
  spec.contacts = 12;
  ASSERT_EQ(checkMap(spec), "");
  const MapRows map = computeMap(spec, {0, spec.y.count}, serialFor());
  ASSERT_TRUE(map.complete);
  for (std::int64_t r = 0; r < spec.y.count; ++r) {
    Model model = spec.model;
    model.m2 = spec.y.at(r) * model.m1;
    const double period = periodOf(model);
    for (std::int64_t c = 0; c < spec.x.count; ++c) {
      const PointSummary& p = map.points[std::size_t(r * spec.x.count + c)];
      SCOPED_TRACE("lambda " + std::to_string(spec.x.at(c)) + ", m2/m1 " + std::to_string(spec.y.at(r)));
      ASSERT_TRUE(p.valid);
      if (c == 0) {
        // lambda = 0 is GLOM1, the fast mode alone: it touches every T1 = T2 / 2, a touch no
        // precision decides (the map raises it to binary128): T1 to the rounding of T1
        EXPECT_DOUBLE_EQ(p.fftFirst, period / 2);
        continue;
      }
      EXPECT_EQ(p.fftFirst, period);
      EXPECT_EQ(p.fftMin, 1.0);
      EXPECT_EQ(p.fftMax, 1.0);
      EXPECT_EQ(p.fftMean, 1.0);
      EXPECT_EQ(p.impacts, 0);
      EXPECT_EQ(p.grazings, spec.contacts);
      EXPECT_TRUE(std::isnan(p.firstImpactTime));
    }
  }
}

TEST(MapsTest, noFirstFlightOnTheGrazingStartPlaneLastsLongerThanT2) {
  const MapSpec spec = grazingPlane(41, 37, 1);
  const MapRows map = computeMap(spec, {0, spec.y.count}, serialFor());
  int atT2 = 0, below = 0;
  for (std::size_t i = 0; i < map.points.size(); ++i) {
    const PointSummary& p = map.points[i];
    const double u1 = spec.x.at(std::int64_t(i) % spec.x.count), v1 = spec.y.at(std::int64_t(i) / spec.x.count);
    if (u1 == -1.0 && v1 == 0.0) {
      // GLOM_1 data (u1 = -d at rest): its top comes back within rounding of the stop at T1, a
      // touch no precision decides: no run, said so (NaN, counts -1), as simulate says undecided
      EXPECT_FALSE(p.valid);
      EXPECT_EQ(p.impacts, -1);
      continue;
    }
    ASSERT_TRUE(p.valid);
    ASSERT_TRUE(std::isfinite(p.fftFirst));  // every start on H leaves and comes back
    EXPECT_LE(p.fftFirst, map.period);
    EXPECT_LE(p.fftMax, 1.0);
    (p.fftFirst == map.period ? atT2 : below) += 1;
    // starts with u1 > gap are pressed on the stop: they stick first, then fly
    EXPECT_EQ(p.impacts + p.grazings + p.sticks >= 1, true);
  }
  // both kinds are there: the grazing set (a disc around the origin) and the rest
  EXPECT_GT(atT2, 100);
  EXPECT_GT(below, 100);
}

TEST(MapsTest, aStartPressedOnTheStopFliesAfterItsStuckPhase) {
  MapSpec spec = grazingPlane(1, 1, 1);
  spec.x = {MapVariable::U1, 1.5, 1.5, 1};
  spec.y = {MapVariable::V1, 0.3, 0.3, 1};
  const PointSummary p = mapPoint(spec, 0, 0);
  EXPECT_EQ(p.sticks, 1);
  EXPECT_TRUE(std::isfinite(p.fftFirst));
  EXPECT_LT(p.fftFirst, periodOf(spec.model));
}

TEST(MapsTest, onAllCoresTheMapIsTheSerialOneBitForBit) {
  MapSpec spec = grazingPlane(48, 40, 30);
  const MapRows serial = computeMap(spec, {0, spec.y.count}, serialFor());
  const MapRows parallel = computeMap(spec, {0, spec.y.count}, parallel::tbbParallelFor(2));
  // and with the pieces run backwards on two plain threads
  const ParallelFor backwards = [](std::int64_t count, const std::function<void(std::int64_t, std::int64_t)>& body) {
    std::thread other([&] {
      for (std::int64_t i = count - 1; i >= count / 2; --i) body(i, i + 1);
    });
    for (std::int64_t i = count / 2 - 1; i >= 0; --i) body(i, i + 1);
    other.join();
  };
  const MapRows shuffled = computeMap(spec, {0, spec.y.count}, backwards);
  ASSERT_EQ(serial.points.size(), parallel.points.size());
  for (std::size_t i = 0; i < serial.points.size(); ++i) {
    ASSERT_TRUE(sameBits(serial.points[i], parallel.points[i])) << "point " << i;
    ASSERT_TRUE(sameBits(serial.points[i], shuffled.points[i])) << "point " << i;
  }
}

TEST(MapsTest, stripesCoverEveryRowOnceAndJoinToTheWholeMap) {
  for (std::int64_t rows : {1, 5, 37, 512}) {
    for (std::int64_t n : {1, 2, 3, 4, 7}) {
      std::int64_t next = 0;
      for (std::int64_t k = 1; k <= n; ++k) {
        const RowRange r = stripe(rows, k, n);
        EXPECT_EQ(r.rowBegin, next);
        EXPECT_GE(r.rowEnd, r.rowBegin);
        next = r.rowEnd;
      }
      EXPECT_EQ(next, rows);
    }
  }
  MapSpec spec = grazingPlane(16, 11, 8);
  const MapRows whole = computeMap(spec, {0, 11}, serialFor());
  std::vector<PointSummary> joined;
  for (std::int64_t k = 1; k <= 4; ++k) {
    const MapRows part = computeMap(spec, stripe(11, k, 4), serialFor());
    joined.insert(joined.end(), part.points.begin(), part.points.end());
  }
  ASSERT_EQ(joined.size(), whole.points.size());
  for (std::size_t i = 0; i < joined.size(); ++i) ASSERT_TRUE(sameBits(joined[i], whole.points[i]));
}

TEST(MapsTest, axesAreNumpyLinspace) {
  const MapAxis axis{MapVariable::MassRatio, 0.1, 0.7, 4};
  EXPECT_EQ(axis.at(0), 0.1);
  EXPECT_EQ(axis.at(3), 0.7);
  const double step = (0.7 - 0.1) / 3;
  EXPECT_EQ(axis.at(1), 1 * step + 0.1);
  EXPECT_EQ(axis.at(2), 2 * step + 0.1);
  EXPECT_EQ((MapAxis{MapVariable::Gap, 2.0, 5.0, 1}).at(0), 2.0);
}

TEST(MapsTest, pointsWithoutAChainOrAStartAreNaNNotNumbers) {
  MapSpec spec;
  spec.model.design = Branch::Upper;
  spec.x = {MapVariable::MassRatio, 0.5, 0.7, 2};  // 0.7 > 9/16: no 1:2 chain
  spec.y = {MapVariable::Gap, 1.0, 1.0, 1};
  const MapRows map = computeMap(spec, {0, 1}, serialFor());
  EXPECT_TRUE(map.points[0].valid);
  EXPECT_FALSE(map.points[1].valid);
  EXPECT_TRUE(std::isnan(map.points[1].fftFirst));
  // no run there: no count either (a 0 would read as "a run without impacts")
  EXPECT_EQ(map.points[1].impacts, -1);
  for (const QuantityInfo& info : quantities()) EXPECT_TRUE(std::isnan(valueOf(map.points[1], info.quantity)));
  // a start beyond the stop
  MapSpec past = grazingPlane(1, 1, 1);
  past.start = StartSpec<double>{};
  past.start->kind = StartSpec<double>::Kind::Explicit;
  past.start->state = State{0, 1.5, 0, 0};
  EXPECT_FALSE(mapPoint(past, 0, 0).valid);
}

TEST(MapsTest, detuningZeroIsTheResonantDesignWhateverK2WasGiven) {
  MapSpec spec;
  spec.model = Model{1.0, 0.5, 1.0, 0.3, 1.0, std::nullopt};  // a chain given by its k2
  spec.x = {MapVariable::Detuning, -0.1, 0.1, 3};
  spec.y = {MapVariable::Lambda, 0.5, 0.5, 1};
  spec.contacts = 5;
  const MapRows map = computeMap(spec, {0, 1}, serialFor());
  // the middle column: the 1:2 chain, where GLO_0.5 grazes every T2
  MapSpec designed = spec;
  designed.model.design = Branch::Upper;
  designed.x = {MapVariable::Gap, 1.0, 1.0, 1};
  EXPECT_TRUE(sameBits(map.points[1], mapPoint(designed, 0, 0)));
  EXPECT_EQ(map.points[1].grazings, 5);
  EXPECT_EQ(map.points[1].fftFirst, periodOf(designed.model));
}

TEST(MapsTest, aStopEndsTheMapIncomplete) {
  std::stop_source source;
  source.request_stop();
  const MapSpec spec = grazingPlane(8, 8, 1);
  const MapRows map = computeMap(spec, {0, 8}, serialFor(), source.get_token());
  EXPECT_FALSE(map.complete);
  EXPECT_EQ(map.computed, 0);
}

TEST(MapsTest, progressCountsEveryPointOnce) {
  const MapSpec spec = grazingPlane(30, 10, 1);
  std::atomic<std::int64_t> last = 0;
  computeMap(spec, {0, 10}, parallel::tbbParallelFor(2), {},
        [&last](std::int64_t done) { last = std::max<std::int64_t>(last, done); });
  EXPECT_EQ(last.load(), 300);
}

TEST(MapsTest, specsThatMakeNoSenseAreRefusedWithAReason) {
  MapSpec spec = grazingPlane(4, 4, 1);
  spec.y.variable = MapVariable::U1;
  EXPECT_NE(checkMap(spec).find("both u1"), std::string::npos);
  spec = grazingPlane(4, 4, 1);
  spec.x.variable = MapVariable::Lambda;
  EXPECT_NE(checkMap(spec).find("lambda sets the whole start"), std::string::npos);
  spec = grazingPlane(0, 4, 1);
  EXPECT_NE(checkMap(spec).find("count"), std::string::npos);
  spec = grazingPlane(4, 4, 0);
  EXPECT_NE(checkMap(spec).find("contacts"), std::string::npos);
  spec = grazingPlane(4, 4, 1);
  spec.x.to = INFINITY;
  EXPECT_NE(checkMap(spec).find("finite"), std::string::npos);
}

}  // namespace
}  // namespace grazelab::core
