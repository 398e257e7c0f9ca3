// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/shown_run.h"

#include <QCoreApplication>

#include <algorithm>
#include <numbers>

#include "core/model/linear_modes.h"
#include "ui/widgets/param_specs.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("grazelab::ui::ShownRun", text); }

}  // namespace

double ShownRun::drawnUntil() const {
  if (samples.empty()) return tFinal;
  const double last = samples.t(samples.size() - 1);
  const double step = samples.size() > 1 ? samples.t(1) - samples.t(0) : 0.0;
  return tFinal <= last + step ? std::max(last, tFinal) : last;
}

PointSpan ShownRun::sectionPoints() const {
  const double x = sectionX < masses() ? 1 / gap : 1 / speed,
               y = sectionY < masses() ? 1 / gap : 1 / speed;
  if (twoMassRun) return grazelab::ui::sectionPoints(twoMassRun->poincare).scaled(x, y);  // (u1, v1)
  const StateSpan section(series->section);
  const auto field = [&section, this](int c) {
    return c < masses() ? section.displacementField(c) : section.velocityField(c - masses());
  };
  return section.points(field(sectionX), field(sectionY)).scaled(x, y);
}

QString ShownRun::coordinateName(int c) const {
  return c < masses() ? tr("u%1").arg(subscriptDigits(c + 1))
                      : tr("v%1").arg(subscriptDigits(c - masses() + 1));
}

QString ShownRun::coordinateAxis(int c) const {
  return c < masses() ? tr("%1 / d").arg(coordinateName(c))
                      : tr("%1 / (d ω₁)").arg(coordinateName(c));
}

std::size_t ShownRun::flightCount() const {
  return twoMassRun ? twoMassRun->freeFlights.size() : series ? series->flights.size() : 0;
}

std::optional<ShownRun::Flight> ShownRun::flightAt(std::size_t k) const {
  if (twoMassRun) {
    const core::FreeFlight& flight = twoMassRun->freeFlights[k];
    return Flight{flight.contactIndex, flight.duration, flight.shortfall};
  }
  const core::experiments::ChainFlight& flight = series->flights[k];
  if (!flight.fromStop) return std::nullopt;
  return Flight{flight.contact - 1, flight.duration, flight.shortfall};
}

std::size_t ShownRun::eventCount() const {
  return twoMassRun ? twoMassRun->events.size() : series ? series->run.events.size() : 0;
}

double ShownRun::eventTime(std::size_t k) const {
  return twoMassRun ? twoMassRun->events[k].t : series->run.events[k].t;
}

core::EventType ShownRun::eventType(std::size_t k) const {
  return twoMassRun ? twoMassRun->events[k].type : series->run.events[k].type;
}

double ShownRun::eventU(std::size_t k, int i) const {
  if (twoMassRun) return i == 0 ? twoMassRun->events[k].before.u1 : twoMassRun->events[k].before.u2;
  return series->run.events[k].u[i];
}

double ShownRun::eventVBefore(std::size_t k, int i) const {
  if (twoMassRun) return i == 0 ? twoMassRun->events[k].before.v1 : twoMassRun->events[k].before.v2;
  return series->run.events[k].vBefore[i];
}

std::optional<ShownRun> shownRun(const SimUpdate& update) {
  const SceneJob& job = update.request->job;
  ShownRun run;
  run.id = update.id;
  run.attempt = update.attempt;
  run.whole = update.final || update.runDone || update.chains.size() > 1;
  if (!update.chains.empty()) {
    const std::shared_ptr<const core::experiments::ChainSeries>& series = update.chains.front();
    run.owner = series;
    run.samples = StateSpan(series->grid);
    run.stopped = series->chain.stopped() - 1;
    run.gap = series->chain.gap;
    run.slowestPeriod = 2 * std::numbers::pi / core::slowestFrequency(series->modes.omega);
    run.unit = series->period > 0 ? TimeUnit{series->period, tr("T"), tr("the chain's common period T")}
                                  : TimeUnit{run.slowestPeriod, tr("slowest period"),
                                             tr("its slowest period (it has no common one)")};
    run.speed = run.gap * series->modes.omega.maxCoeff();
    run.start = series->start;
    run.tFinal = series->run.tFinal;
    run.contactsAsked = series->contactsAsked;
    run.series = series.get();
    run.chain = series->chain;
    run.flightsBounded = series->period > 0;
    // the scene's pair, or mass 1's (u, v) (mass 2's when mass 1 is the stopped one)
    const int n = series->chain.size(), fallback = run.stopped == 0 && n > 1 ? 1 : 0;
    const auto inState = [n](int c) { return c >= 1 && c <= 2 * n; };
    run.sectionX = inState(job.sectionOn.first) ? job.sectionOn.first - 1 : fallback;
    run.sectionY = inState(job.sectionOn.second) ? job.sectionOn.second - 1 : n + fallback;
  } else if (update.result) {
    const core::Model& model = job.spec.model;
    const core::Modes modes = core::computeModes(model);
    run.owner = update.result;
    run.samples = StateSpan(update.result->samples);
    run.stopped = 1;
    run.gap = model.gap;
    run.unit = TimeUnit{modes.T2, tr("T₂"), tr("the slow period T₂")};
    run.speed = run.gap * modes.omegaFast;
    run.start = core::chainStateOf(job.spec.run.initial);
    run.tFinal = update.result->tFinal;
    run.twoMass = true;
    run.contactsAsked = job.spec.run.maxContacts;
    run.twoMassRun = update.result.get();
    run.chain = core::massChainOf(model);
    run.slowestPeriod = modes.T2;
    run.flightsBounded = true;
    run.sectionX = 0;
    run.sectionY = 2;
  } else {
    return std::nullopt;
  }
  run.chosen =
      job.chosenMass >= 1 && job.chosenMass <= run.masses() ? job.chosenMass - 1 : run.stopped;
  if (job.timeUnit && job.timeUnit->length > 0) {
    run.unit = *job.timeUnit;
    run.unitIsPeriod = false;
    run.flightsBounded = false;
  }
  return run;
}

}  // namespace grazelab::ui
