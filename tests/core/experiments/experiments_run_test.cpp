// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The one function that computes an experiment (core/experiments/run.h), as the explorer's
// worker calls it: its pieces add up to the run computed whole, a contact double cannot decide
// is decided again in a higher precision, a stop ends it with a final report, and its map is
// the map computed in one go (and is remembered).
#include <gtest/gtest.h>

#include <bit>
#include <optional>

#include "core/model/two_mass_form.h"
#include "core/experiments/run.h"
#include "core/orbits/special_orbits.h"
#include "core/orbits/starts.h"
#include "core/solver/simulate.h"
#include "parallel/tbb_parallel_for.h"
#include "support/point_bits.h"

namespace grazelab::core::experiments {
namespace {

Model resonantChain() { return *designedModel(1.0, 0.5, 1.0, 1.0, Branch::Upper); }

Spec gloRun(double lambda, double push, std::int64_t contacts) {
  Spec spec;
  spec.model = resonantChain();
  StartSpec<double> start;
  start.lambda = lambda;
  start.perturbation = State{0, 0, 0, push};
  spec.run.initial = makeStart(*makeTwoMassForm(spec.model).chain, start).start->state;
  spec.run.maxContacts = contacts;
  spec.run.needs.events = true;
  spec.run.needs.poincare = true;
  spec.run.needs.freeFlights = true;
  return spec;
}

TEST(ExperimentRunTest, itsPiecesAreTheRunComputedWhole) {
  // many small pieces: a report at least every 1e-4 s of work, or four times what its copy took
  // (on a loaded machine under the sanitizers a copy can take milliseconds: 20 000 contacts
  // still make several reports there, where 5 000 once made only two)
  Spec spec = gloRun(0.5, -0.05, 20000);
  spec.run.needs.samples.spacing = 0.05;
  spec.run.needs.samples.tEnd = 200;
  Options options;
  options.chunkSeconds = 1e-4;
  Result assembled;
  int pieces = 0;
  int finals = 0;
  double progress = 0;
  const Update last = run(spec, {}, options, [&](const Update& update) {
    EXPECT_GE(update.progress, progress);
    progress = update.progress;
    if (update.final && !update.trustPending) ++finals;  // the estimate's report comes last
    if (!update.chunk) return;
    ++pieces;
    const Result& chunk = *update.chunk;
    assembled.events.insert(assembled.events.end(), chunk.events.begin(), chunk.events.end());
    assembled.poincare.insert(assembled.poincare.end(), chunk.poincare.begin(), chunk.poincare.end());
    assembled.freeFlights.insert(assembled.freeFlights.end(), chunk.freeFlights.begin(),
                                 chunk.freeFlights.end());
    assembled.samples.insert(assembled.samples.end(), chunk.samples.begin(), chunk.samples.end());
  });
  EXPECT_GE(pieces, 2);  // a piece appended to another: the seam is checked below
  EXPECT_EQ(finals, 1);
  ASSERT_TRUE(last.final && last.runDone && last.result);
  ASSERT_TRUE(last.trust);
  const Result whole = simulate(spec.model, spec.run);
  EXPECT_EQ(last.result->events, whole.events);
  EXPECT_EQ(last.result->final, whole.final);
  // the pieces are a prefix of the whole (the last stretch comes with the final report)
  ASSERT_LE(assembled.events.size(), whole.events.size());
  for (std::size_t i = 0; i < assembled.events.size(); ++i) ASSERT_EQ(assembled.events[i], whole.events[i]);
  ASSERT_LE(assembled.samples.size(), whole.samples.size());
  for (std::size_t i = 0; i < assembled.samples.size(); ++i) {
    ASSERT_EQ(assembled.samples[i].t, whole.samples[i].t);
    ASSERT_EQ(assembled.samples[i].state, whole.samples[i].state);
  }
  EXPECT_GT(assembled.events.size(), whole.events.size() / 2);
}

// GLOM1 pushed by 3e-9: the crossing at T1 rises ~1e-17 above the stop, which double cannot
// tell from a graze; the run is made again in long double or binary128, as --precision auto.
TEST(ExperimentRunTest, aContactDoubleCannotDecideIsDecidedInAHigherPrecision) {
  Spec spec;
  spec.model = resonantChain();
  spec.run.initial = gloData(*makeTwoMassForm(spec.model).chain, 0.0);
  spec.run.initial.v2 -= 3e-9;
  spec.run.maxContacts = 20;
  spec.run.needs.events = true;
  const Update last = run(spec, {}, Options{}, [](const Update&) {});
  ASSERT_TRUE(last.final && last.result);
  EXPECT_GT(last.attempt, 0);
  EXPECT_EQ(last.result->cost.impacts, 20);
  EXPECT_TRUE(last.trust);
  EXPECT_NE(last.precisionNote.find("contact 1"), std::string::npos) << last.precisionNote;
}

TEST(ExperimentRunTest, aStopEndsItWithAFinalReport) {
  Spec spec = gloRun(0.5, -0.05, 50'000'000);
  Options options;
  options.chunkSeconds = 1e-4;
  std::stop_source stopper;
  int reports = 0;
  const Update last = run(spec, stopper.get_token(), options, [&](const Update& update) {
    if (++reports == 3) stopper.request_stop();
    EXPECT_TRUE(!update.final || update.result);
  });
  ASSERT_TRUE(last.final && last.result);
  EXPECT_EQ(last.result->stop, StopReason::Cancelled);
  EXPECT_LT(last.result->cost.impacts, 50'000'000);
}

using testing::sameBits;

TEST(ExperimentRunTest, anExperimentOfChainsRunsThemInTurnTheShownOneFirstAndMakesNoTwoMassRun) {
  // three masses, stopped on mass 2 (inside), against a right wall; beside it the same start on
  // the chain with its second spring 3 % stiffer
  MassChain chain;
  chain.masses = {0.7, 1.0, 0.4};
  chain.springs = {1.0, 0.6, 1.5};
  chain.rightSpring = 0.8;
  chain.stopMass = 2;
  chain.gap = 0.4;
  ChainState start{Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(3)};
  start.v << 0.3, 0.9, -0.2;
  MassChain other = chain;
  other.springs[1] *= 1.03;
  Spec spec;
  spec.chains = {{chain, start, 250, 30.0, 400, TrustMode::Auto}, {other, start, 250, 0, 0, TrustMode::Off}};
  Options options;
  options.chunkSeconds = 1e-12;  // a report after every piece
  std::vector<Update> reports;
  const Update last = run(spec, {}, options, [&](const Update& update) { reports.push_back(update); });
  ASSERT_TRUE(last.final && last.runDone);
  EXPECT_FALSE(last.result);  // no two-mass run
  ASSERT_EQ(last.chains.size(), 2u);
  // each run is the series computed alone, to the bit
  for (std::size_t i = 0; i < 2; ++i) {
    const ChainSeries alone = chainSeries(spec.chains[i]);
    const ChainSeries& shown = *last.chains[i];
    ASSERT_EQ(shown.run.events.size(), alone.run.events.size());
    for (std::size_t e = 0; e < alone.run.events.size(); ++e) {
      ASSERT_EQ(shown.run.events[e].t, alone.run.events[e].t);
      ASSERT_EQ(shown.run.events[e].u, alone.run.events[e].u);
    }
    EXPECT_EQ(shown.trust.stateError, alone.trust.stateError);
    EXPECT_EQ(shown.grid.size(), alone.grid.size());
  }
  // partial reports of the first run carry it alone; then it whole (runDone) before its error
  // estimate (trust pending), then with it, then the second one's; the progress never goes back
  ASSERT_GE(reports.size(), 4u);
  std::size_t firstWhole = reports.size();
  double progress = 0;
  for (std::size_t r = 0; r < reports.size(); ++r) {
    const Update& update = reports[r];
    EXPECT_FALSE(update.result);
    EXPECT_GE(update.progress, progress);
    progress = update.progress;
    if (update.runDone && firstWhole == reports.size()) firstWhole = r;
  }
  ASSERT_LT(firstWhole + 2, reports.size());
  const Update& beforeEstimate = reports[firstWhole];
  EXPECT_TRUE(beforeEstimate.trustPending && !beforeEstimate.final);
  ASSERT_EQ(beforeEstimate.chains.size(), 1u);
  EXPECT_EQ(beforeEstimate.chains.front()->run.contacts, 250);
  EXPECT_EQ(beforeEstimate.chains.front()->run.events.size(), last.chains.front()->run.events.size());
  EXPECT_EQ(beforeEstimate.chains.front()->trust.verdict, Verdict::Unchecked);
  const Update& estimated = reports[firstWhole + 1];
  EXPECT_TRUE(estimated.runDone && !estimated.trustPending);
  ASSERT_EQ(estimated.chains.size(), 1u);
  EXPECT_NE(estimated.chains.front()->trust.verdict, Verdict::Unchecked);
  EXPECT_EQ(estimated.chains.front()->trust.stateError, last.chains.front()->trust.stateError);
  EXPECT_EQ(reports[firstWhole + 2].chains.size(), 2u);
  for (std::size_t r = 0; r < firstWhole; ++r) {
    EXPECT_EQ(reports[r].chains.size(), 1u);
    EXPECT_LE(reports[r].chains.front()->run.contacts, 250);
    EXPECT_FALSE(reports[r].trustPending);
  }
  // the second run (its estimate off) has no report before an estimate
  for (std::size_t r = firstWhole + 1; r < reports.size(); ++r) EXPECT_FALSE(reports[r].trustPending);
}

TEST(ExperimentRunTest, itsMapIsTheMapComputedWholeAndIsRemembered) {
  Spec spec = gloRun(0.5, -0.05, 10);
  MapSpec map;
  map.model = spec.model;
  map.x = {MapVariable::U1, -1.0, 2.0, 1500};  // bands of 5 rows: several reports
  map.y = {MapVariable::V1, -1.5, 1.5, 12};
  map.contacts = 3;
  spec.map = map;
  Options options;
  options.parallelFor = parallel::tbbParallelFor(2);
  options.mapCache = std::make_shared<MapCache>();
  std::int64_t rowsSeen = 0;
  int mapReports = 0;
  const Update last = run(spec, {}, options, [&](const Update& update) {
    if (!update.map) return;
    ++mapReports;
    EXPECT_GE(update.map->rowsDone, rowsSeen);  // rows only ever added
    rowsSeen = update.map->rowsDone;
  });
  ASSERT_TRUE(last.final && last.map && last.map->complete);
  EXPECT_GE(mapReports, 3);
  const MapRows whole = computeMap(map, {0, map.y.count}, serialFor());
  ASSERT_EQ(last.map->points->size(), whole.points.size());
  for (std::size_t i = 0; i < whole.points.size(); ++i) {
    ASSERT_TRUE(sameBits((*last.map->points)[i], whole.points[i])) << "point " << i;
  }
  // asked again: the same grid at once, from the cache
  const Update again = run(spec, {}, options, [](const Update&) {});
  ASSERT_TRUE(again.map);
  EXPECT_EQ(again.map->points, last.map->points);
}

}  // namespace
}  // namespace grazelab::core::experiments
