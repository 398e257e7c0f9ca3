// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/experiments/chain_series.h"
#include "core/model/mass_chain.h"
#include "core/solver/chain_run.h"
#include "core/solver/events.h"
#include "ui/compute/sim_types.h"
#include "ui/plots/run_points.h"

namespace grazelab::ui {

/// The run an update shows, as the run views read it, whatever the chain: the note's chain's
/// run (its samples and events) or the first series of an experiment of N masses (its grid and
/// events), both read where they are. Drawn in the chain's own units: time over its period,
/// displacements over the gap, velocities over the gap times the fastest frequency.
struct ShownRun {
  std::shared_ptr<const void> owner;  ///< keeps what `samples` and the events read alive
  StateSpan samples;
  int stopped = 0;  ///< 0-based
  /// 0-based: the mass the scene's 'phase of' names (SceneJob::chosenMass; else the stopped one)
  int chosen = 0;
  double gap = 1;
  /// the time unit: the common period (T₂ of the note's chain, T of a resonant one), the slowest
  /// period of a chain with none, or the scene's own (SceneJob::timeUnit)
  TimeUnit unit;
  double speed = 1;        ///< the velocities' unit: d times the fastest frequency
  core::ChainState start;  ///< where it started
  double tFinal = 0;       ///< where the run is (so far)
  /// the run is whole (its last report, or a later run of the same experiment is coming in)
  bool whole = false;
  /// the run as computed: a raised run (attempt) or another request starts the views over
  std::uint64_t id = 0;
  int attempt = 0;
  /// the note's chain's run (its own words in places: mass 1 keeps the energy on a click)
  bool twoMass = false;
  std::int64_t contactsAsked = 0;  ///< the contacts the run was asked for (0: no limit)
  /// the coordinates its section H is drawn on, 0-based in the state (u1..uN, v1..vN): the
  /// scene's choice (SceneJob::sectionOn), by default mass 1's (u, v) (mass 2's when mass 1 is
  /// the stopped one); the note's chain's always (u1, v1)
  int sectionX = 0, sectionY = 0;

  int masses() const { return samples.masses(); }
  /// The points of the section H (the state at each contact, velocities before it) on
  /// (sectionX, sectionY), in the views' units, read where the run keeps them.
  PointSpan sectionPoints() const;
  /// A free flight from the stop: the contact that ends it (0-based), its length [time], and
  /// the chain's period (T₂, T or the slowest) less that length, exact near the period.
  struct Flight {
    std::int64_t contact = 0;
    double duration = 0;
    double shortfall = 0;
  };
  /// The run's flights so far (flightAt: none for one that does not start on the stop).
  std::size_t flightCount() const;
  std::optional<Flight> flightAt(std::size_t k) const;
  /// Its flights from the stop are bounded by its period (the note's chain, a resonant one).
  bool flightsBounded = false;
  /// `unit` is the chain's period, which the flights' shortfalls are measured from (not a
  /// scene's own unit)
  bool unitIsPeriod = true;
  /// A coordinate's name ("u₃", "v₁") and its axis ("u₃ / d", "v₁ / (d ω₁)").
  QString coordinateName(int c) const;
  QString coordinateAxis(int c) const;
  /// The time the views draw to: the samples' end, or the run's when they end within a step of
  /// it (a grid has no sample at the last contact).
  double drawnUntil() const;
  std::size_t eventCount() const;
  double eventTime(std::size_t k) const;
  core::EventType eventType(std::size_t k) const;
  /// Mass i's displacement at event k and its velocity just before it (0-based i).
  double eventU(std::size_t k, int i) const;
  double eventVBefore(std::size_t k, int i) const;
  /// The views word this run as `other` (titles, names, tooltips): a new run of the same chain
  /// keeps them, and a view that set them again would lay its chart out at every edit.
  bool wordedAlike(const ShownRun& other) const {
    return twoMass == other.twoMass && masses() == other.masses() && stopped == other.stopped &&
           chosen == other.chosen && sectionX == other.sectionX && sectionY == other.sectionY &&
           flightsBounded == other.flightsBounded && unit.name == other.unit.name && unit.inWords == other.unit.inWords;
  }
  /// the same run as `before`, grown (not another one, nor a raised one from its start)
  bool continues(const ShownRun& before) const {
    return owner && before.owner && id == before.id && attempt == before.attempt &&
           samples.size() >= before.samples.size() && eventCount() >= before.eventCount() &&
           flightCount() >= before.flightCount();
  }

  /// The chain moving (its masses, springs, stop and gap) and its slowest period [time].
  core::MassChain chain;
  double slowestPeriod = 0;

  /// where the run is kept (one of the two, owned by `owner`): its events, section and flights
  /// are read there
  const core::Result* twoMassRun = nullptr;
  const core::experiments::ChainSeries* series = nullptr;
};

/// The run of `update`: its first series of N masses, or its run of the note's chain; none when
/// it has neither (a scene's own computation so far).
std::optional<ShownRun> shownRun(const SimUpdate& update);

}  // namespace grazelab::ui
