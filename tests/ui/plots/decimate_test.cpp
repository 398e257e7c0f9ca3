// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for ui/plots/decimate.cpp.
#include <QTest>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include "ui/plots/decimate.h"
#include "ui/plots/run_points.h"

using grazelab::ui::decimatePath;
using grazelab::ui::decimateScatter;
using grazelab::ui::decimateScatterSets;
using grazelab::ui::decimateTrace;
using grazelab::ui::PixelFrame;

class DecimateTest : public QObject {
  Q_OBJECT

 private slots:
  void traceKeepsExtremesAndEnds() {
    std::vector<QPointF> points;
    const int count = 1'000'000;
    for (int i = 0; i < count; ++i) {
      const double t = 100.0 * i / (count - 1);
      points.emplace_back(t, std::sin(7 * t) + 0.001 * std::cos(300 * t));
    }
    points[123457].setY(5.0);   // a spike must survive
    points[654321].setY(-5.0);  // and a dip
    const PixelFrame frame{0, 100, -6, 6, 800, 300};
    const QList<QPointF> out = decimateTrace(points, frame);
    QVERIFY(out.size() <= 4 * 800 + 2);
    QVERIFY(out.size() > 800);
    QCOMPARE(out.first(), points.front());
    QCOMPARE(out.last(), points.back());
    bool spike = false;
    bool dip = false;
    for (qsizetype i = 0; i < out.size(); ++i) {
      if (i > 0) QVERIFY(out[i].x() >= out[i - 1].x());  // order kept
      spike = spike || out[i].y() == 5.0;
      dip = dip || out[i].y() == -5.0;
    }
    QVERIFY(spike);
    QVERIFY(dip);
  }

  void traceColumnHasItsMinAndMax() {
    // every column's extremes are present, so the drawn envelope is exact
    std::vector<QPointF> points;
    for (int i = 0; i < 10'000; ++i) points.emplace_back(i * 0.01, std::sin(i * 0.37));
    const PixelFrame frame{0, 100, -1, 1, 50, 50};
    const QList<QPointF> out = decimateTrace(points, frame);
    for (int column = 0; column < 50; ++column) {
      double low = 1e9, high = -1e9, outLow = 1e9, outHigh = -1e9;
      for (const QPointF& p : points) {
        if (int(std::floor(p.x() / 2.0)) != column) continue;
        low = std::min(low, p.y());
        high = std::max(high, p.y());
      }
      for (const QPointF& p : out) {
        if (int(std::floor(p.x() / 2.0)) != column) continue;
        outLow = std::min(outLow, p.y());
        outHigh = std::max(outHigh, p.y());
      }
      QCOMPARE(outLow, low);
      QCOMPARE(outHigh, high);
    }
  }

  void traceDropsPointsOutsideButOneEachSide() {
    std::vector<QPointF> points;
    for (int i = 0; i <= 1000; ++i) points.emplace_back(i, i % 7);
    const PixelFrame frame{400, 500, 0, 7, 1000, 100};
    const QList<QPointF> out = decimateTrace(points, frame);
    QCOMPARE(out.first().x(), 399.0);
    QCOMPARE(out.last().x(), 501.0);
    QCOMPARE(out.size(), qsizetype(103));  // fewer points than pixels: all kept
  }

  // A run's samples read where they are (the views hold no copy) reduce exactly as the same
  // points copied out of them, for a trace (t, u2) and a path (u2, v2).
  void pointsReadInPlaceReduceAsTheirCopy() {
    std::vector<grazelab::core::Sample> samples;
    for (int i = 0; i < 50'000; ++i) {
      const double t = 0.01 * i;
      samples.push_back({t, {std::cos(t), std::sin(2 * t), -std::sin(t), 2 * std::cos(2 * t)}});
    }
    grazelab::core::Result run;
    run.samples = samples;
    std::vector<QPointF> trace;
    std::vector<QPointF> path;
    for (const auto& sample : samples) {
      trace.emplace_back(sample.t, sample.state.u2);
      path.emplace_back(sample.state.u2, sample.state.v2);
    }
    const PixelFrame frame{0, 500, -1.1, 1.1, 640, 240};
    const grazelab::ui::StateSpan states(run.samples);
    const grazelab::ui::PointSpan inPlace = states.points(states.timeField(), states.displacementField(1));
    QCOMPARE(inPlace.size(), trace.size());
    QCOMPARE(inPlace[777], trace[777]);
    QCOMPARE(decimateTrace(inPlace, frame), decimateTrace(trace, frame));
    const PixelFrame phase{-1.1, 1.1, -2.2, 2.2, 300, 300};
    QCOMPARE(decimatePath(states.points(states.displacementField(1), states.velocityField(1)), phase),
             decimatePath(path, phase));
    // a stretch of them, as the phase portrait's window takes it
    QCOMPARE(inPlace.subspan(1000, 300).toVector(),
             std::vector<QPointF>(trace.begin() + 1000, trace.begin() + 1300));
  }

  void traceOfNothingIsNothing() {
    QVERIFY(decimateTrace({}, PixelFrame{}).isEmpty());
    QVERIFY(decimateScatter({}, PixelFrame{}).isEmpty());
    QVERIFY(decimatePath({}, PixelFrame{}).isEmpty());
  }

  void scatterKeepsOnePointPerCell() {
    std::vector<QPointF> points;
    for (int i = 0; i < 100'000; ++i) {
      points.emplace_back((i % 1000) / 1000.0, (i / 1000) / 100.0);
    }
    const PixelFrame frame{0, 1, 0, 1, 10, 10};
    const QList<QPointF> out = decimateScatter(points, frame);
    QCOMPARE(out.size(), qsizetype(100));
    // one per cell
    std::vector<int> seen(100, 0);
    for (const QPointF& p : out) {
      const int cell = std::min(9, int(p.y() * 10)) * 10 + std::min(9, int(p.x() * 10));
      QCOMPARE(++seen[std::size_t(cell)], 1);
    }
  }

  void scatterDropsOutsideAndNonFinite() {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<QPointF> points = {{0.5, 0.5}, {2, 0.5}, {0.5, -1}, {nan, 0.5}, {1, 1}};
    const QList<QPointF> out = decimateScatter(points, PixelFrame{0, 1, 0, 1, 100, 100});
    QCOMPARE(out.size(), qsizetype(2));
    QCOMPARE(out[0], QPointF(0.5, 0.5));
    QCOMPARE(out[1], QPointF(1, 1));  // the closed upper edge belongs to the last cell
  }

  // Five colour classes filling the same cells (a near-grazing Poincaré cloud): drawn one
  // after the other, the last covered the rest. Decimated jointly, each cell keeps one point of
  // a class drawn at random, so every class keeps about its share, and each cell has one.
  void scatterSetsShareTheCellsFairly() {
    const int sets = 5;
    std::vector<std::vector<QPointF>> data(sets);
    for (int set = 0; set < sets; ++set) {
      for (int i = 0; i < 4000; ++i) {
        const double angle = 0.001 * (i * sets + set) * 2 * std::numbers::pi;  // the same ring
        data[std::size_t(set)].emplace_back(std::cos(angle), std::sin(angle));
      }
    }
    std::vector<grazelab::ui::PointSpan> spans(data.begin(), data.end());
    const PixelFrame frame{-1.1, 1.1, -1.1, 1.1, 100, 100};
    const auto reduced = decimateScatterSets(spans, frame);
    QCOMPARE(int(reduced.size()), sets);
    qsizetype total = 0;
    for (const auto& kept : reduced) total += kept.size();
    // as many as the cells the ring covers, one point each
    std::vector<QPointF> all;
    for (const auto& set : data) all.insert(all.end(), set.begin(), set.end());
    QCOMPARE(total, decimateScatter(all, frame).size());
    for (const auto& kept : reduced) {
      QVERIFY2(kept.size() > total / sets / 2, qPrintable(QString::number(kept.size())));
    }
  }

  void pathDropsRepeatsInTheSameCell() {
    // a circle traced 100 times, densely: only cell changes survive
    std::vector<QPointF> points;
    for (int i = 0; i < 200'000; ++i) {
      const double angle = 2 * std::numbers::pi * i / 2000.0;
      points.emplace_back(std::cos(angle), std::sin(angle));
    }
    const PixelFrame frame{-1.1, 1.1, -1.1, 1.1, 200, 200};
    const QList<QPointF> out = decimatePath(points, frame);
    QVERIFY(out.size() < 100 * 800);
    QVERIFY(out.size() > 100 * 300);
    QCOMPARE(out.first(), points.front());
    QCOMPARE(out.last(), points.back());
    for (qsizetype i = 1; i + 1 < out.size(); ++i) {
      const bool sameCell = int(std::floor((out[i].x() + 1.1) / 2.2 * 200)) ==
                                int(std::floor((out[i - 1].x() + 1.1) / 2.2 * 200)) &&
                            int(std::floor((out[i].y() + 1.1) / 2.2 * 200)) ==
                                int(std::floor((out[i - 1].y() + 1.1) / 2.2 * 200));
      QVERIFY(!sameCell);
    }
  }

  // A run's points arrive in chunks: each kind, fed only the new points, must give exactly
  // what the one-shot reduction of everything so far gives, without starting over.
  void appendedPointsReduceAsTheWholeData() {
    using grazelab::ui::IncrementalDecimation;
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<QPointF> trace;   // x rising from left of the frame to right of it
    std::vector<QPointF> cloud;   // a scatter and a path, anywhere (some outside)
    const PixelFrame frame{10, 90, -1, 1, 300, 120};
    IncrementalDecimation traceCut(IncrementalDecimation::Kind::Trace);
    IncrementalDecimation scatterCut(IncrementalDecimation::Kind::Scatter);
    IncrementalDecimation pathCut(IncrementalDecimation::Kind::Path);
    int restartsInside = 0;
    for (int chunk = 0; chunk < 120; ++chunk) {
      const bool allLeft = !trace.empty() && trace.back().x() < frame.xMin;
      const int count = 1 + int(unit(random) * 900);
      for (int i = 0; i < count; ++i) {
        trace.emplace_back(100.0 * double(trace.size()) / 45'000.0, std::sin(double(trace.size())) * unit(random));
        cloud.emplace_back(100 * unit(random), 2.4 * unit(random) - 1.2);
      }
      QCOMPARE(traceCut.update(trace, frame, chunk == 0), decimateTrace(trace, frame));
      QCOMPARE(scatterCut.update(cloud, frame, chunk == 0), decimateScatter(cloud, frame));
      QCOMPARE(pathCut.update(cloud, frame, chunk == 0), decimatePath(cloud, frame));
      if (chunk > 0) {
        QVERIFY(!scatterCut.startedOver());
        QVERIFY(!pathCut.startedOver());
        restartsInside += traceCut.startedOver() && !allLeft ? 1 : 0;
      }
    }
    // the trace starts over only while all its points lie left of the frame (its visible
    // slice's first point moves); once inside, never
    QCOMPARE(restartsInside, 0);
    QVERIFY(trace.back().x() > frame.xMax);
    // a new frame (a zoom) or replaced data start over
    const PixelFrame zoomed{20, 40, -1, 1, 300, 120};
    QCOMPARE(traceCut.update(trace, zoomed, false), decimateTrace(trace, zoomed));
    QVERIFY(traceCut.startedOver());
  }

  void appendedSetsReduceAsTheWholeSets() {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<std::vector<QPointF>> sets(5);
    const PixelFrame frame{0, 1, 0, 1, 80, 60};
    grazelab::ui::IncrementalScatterSets cut;
    for (int chunk = 0; chunk < 60; ++chunk) {
      // the bins fill one after the other, as a run's colour bins do
      auto& set = sets[std::size_t(std::min(4, chunk / 12))];
      for (int i = 0; i < 500; ++i) set.emplace_back(unit(random), unit(random));
      std::vector<grazelab::ui::PointSpan> spans(sets.begin(), sets.end());
      QCOMPARE(cut.update(spans, frame, chunk == 0), decimateScatterSets(spans, frame));
      if (chunk > 0) QVERIFY(!cut.startedOver());
    }
  }
};

QTEST_APPLESS_MAIN(DecimateTest)
#include "decimate_test.moc"
