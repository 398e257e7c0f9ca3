// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/shown_run.h"

#include <QCoreApplication>

#include <algorithm>
#include <numbers>

#include "core/model/linear_modes.h"

namespace grazelab::ui {

namespace {
QString tr(const char* text) { return QCoreApplication::translate("grazelab::ui::ShownRun", text); }
}  // namespace

QString ShownRun::unitName() const {
  switch (unit) {
    case Unit::SlowPeriodT2: return tr("T₂");
    case Unit::CommonPeriod: return tr("T");
    case Unit::Scenes: return scenes.name;
    case Unit::SlowestPeriod: break;
  }
  return tr("slowest period");
}

QString ShownRun::unitInWords() const {
  switch (unit) {
    case Unit::SlowPeriodT2: return tr("the slow period T₂");
    case Unit::CommonPeriod: return tr("the chain's common period T");
    case Unit::Scenes: return scenes.inWords;
    case Unit::SlowestPeriod: break;
  }
  return tr("its slowest period (it has no common one)");
}

std::size_t ShownRun::eventCount() const {
  return twoMassEvents ? twoMassEvents->size() : chainEvents ? chainEvents->size() : 0;
}

double ShownRun::eventTime(std::size_t k) const {
  return twoMassEvents ? (*twoMassEvents)[k].t : (*chainEvents)[k].t;
}

core::EventType ShownRun::eventType(std::size_t k) const {
  return twoMassEvents ? (*twoMassEvents)[k].type : (*chainEvents)[k].type;
}

std::optional<ShownRun> shownRun(const SimUpdate& update) {
  ShownRun run;
  run.id = update.id;
  run.attempt = update.attempt;
  if (!update.chains.empty()) {
    const std::shared_ptr<const core::experiments::ChainSeries>& series = update.chains.front();
    run.owner = series;
    run.samples = StateSpan(series->grid);
    run.masses = series->chain.size();
    run.stopped = series->chain.stopped() - 1;
    run.chosen = std::clamp(update.request->params.massChain.shown(), 1, run.masses) - 1;
    run.gap = series->chain.gap;
    const bool resonant = series->period > 0;
    run.unit = resonant ? ShownRun::Unit::CommonPeriod : ShownRun::Unit::SlowestPeriod;
    run.period = resonant ? series->period : 2 * std::numbers::pi / series->modes.omega.minCoeff();
    run.tFinal = series->run.tFinal;
    run.chainEvents = &series->run.events;
  } else if (update.result) {
    const core::Model& model = update.request->job.spec.model;
    run.owner = update.result;
    run.samples = StateSpan(update.result->samples);
    run.masses = 2;
    run.stopped = 1;
    run.chosen = 1;
    run.gap = model.gap;
    run.unit = ShownRun::Unit::SlowPeriodT2;
    run.period = core::computeModes(model).T2;
    run.tFinal = update.result->tFinal;
    run.twoMassEvents = &update.result->events;
  } else {
    return std::nullopt;
  }
  if (const std::optional<TimeUnit>& given = update.request->job.timeUnit; given && given->length > 0) {
    run.unit = ShownRun::Unit::Scenes;
    run.scenes = *given;
    run.period = given->length;
  }
  return run;
}

}  // namespace grazelab::ui
