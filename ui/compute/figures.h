// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QPointF>
#include <QString>

#include <map>
#include <vector>

namespace grazelab::ui {

/// The kinds of view a scene can show.
enum class PlotKind {
  Trace,            ///< the stopped mass's u/d against t/T, the stop and the contacts, any chain
  Phase,            ///< the phase portrait of the mass 'phase of' names (mass 2 of the note's chain)
  PhaseU1V1,        ///< the phase portrait of mass 1
  Poincare,         ///< the state at each contact (on H) on two coordinates ((u1, v1); N: chosen), by contact index
  FreeFlight,       ///< each flight from the stop over the period against contact index, the bound 1
  WorkPrecision,    ///< every method's error against its run time, with an overlay picker
  OnePeriodicData,  ///< the 1IPP impact data u1(T) against T/T2, with the GLO_lambda* value
  ImpactSpeed,      ///< the 1IPP impact speed |V(T)| against T/T2, going to 0 at T2
  FrequencyEnergy,  ///< the 1IPP family's frequency 2 pi / T against its energy (log), to GLO(lambda*)
  GrazingMaximum,   ///< Lemma 2.1: max u2/d of GLO(lambda) against lambda, = 1 on [0, 4/3]
  SpreadAgainstSize,  ///< Theorem 2.2: the spread of FFT/T2 against the push size (log-log)
  FlightHistogram,  ///< Theorem 2.3: histogram of FFT/T2 over random starts, bound at 1
  Chain,            ///< the chain moving, any number of masses (ChainView), the time cursor of the other views
  Landscape,        ///< a map over the grazing-start plane, the run's section over it
  ModesAtlas,       ///< the periodic impacting families: 2 pi / T against log E, click an orbit
  Multipliers,      ///< the chosen orbit's multipliers against the unit circle
  GrazingSet,       ///< N masses: the grazing set of two modes (top against lambda) or three (a region)
  ContrastFlights,  ///< the experiment's second run (the start on the chain detuned), its flights
                    ///< over the first run's period T, those past 3 T on the top edge
};

/// A curve a scene computes itself (no run needed), drawn by a CurvePlot: the curve, the
/// current parameter's point on it, and a reference (a line or a point) it is compared with.
struct CurveFigure {
  QString title;
  QString xTitle;
  QString yTitle;
  QString toolTip;
  QString curveName;
  std::vector<QPointF> curve;
  /// the curve's points are values at separate events (a flight per contact): drawn as dots,
  /// not joined by a line (joined spikes merge into a block on a projector)
  bool dots = false;
  QString markerName;
  std::vector<QPointF> markers;
  QString referenceName;
  std::vector<QPointF> reference;  ///< two points: a dashed line; one: a ringed point
  /// fixed axes [xMin, xMax] x [yMin, yMax], so that the marker's motion is seen (empty: fit)
  double xMin = 0, xMax = 0, yMin = 0, yMax = 0;
  /// the one-point reference (or else the one marker) is the panel's GLO weights on these modes
  /// (0-based, fastest first: x is the second's weight, y the third's, the first balancing):
  /// dragging it, or clicking, moves them (empty: nothing to drag)
  std::vector<int> draggedModes;
  /// said in place of the plot when it has no curve and no markers (a run with no contact has no
  /// flight to draw: bare -1..1 axes said nothing)
  QString whyEmpty;
};

using Figures = std::map<PlotKind, CurveFigure>;

}  // namespace grazelab::ui
