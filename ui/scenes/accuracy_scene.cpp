// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/scenes/accuracy_scene.h"

#include <QCoreApplication>

#include "core/methods/work_precision.h"
#include "core/orbits.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::AccuracyScene", text);
}

}  // namespace

QString AccuracyScene::name() const { return QStringLiteral("Accuracy: methods against the exact solver"); }
QString AccuracyScene::alias() const { return QStringLiteral("accuracy"); }
QString AccuracyScene::title() const { return tr("Accuracy: methods against the exact solver"); }

QString AccuracyScene::description() const {
  return tr("The standard methods of nonsmooth mechanics (Moreau–Jean, Schatzman–Paoli, "
            "event-driven Runge–Kutta, CVODE, a penalty spring) on the same start, each at "
            "several step sizes or tolerances: their error against their run time. Pick one to "
            "draw its u₂(t) over the exact motion.");
}

Params AccuracyScene::defaults() const {
  Params params;
  params.lambda = 0.5;
  params.perturbation = -0.05;
  params.direction = PerturbDirection::V2;
  params.horizon = 50;
  return params;
}

QList<ParamKey> AccuracyScene::parameters() const {
  return {ParamKey::Lambda, ParamKey::M1, ParamKey::M2,           ParamKey::Gap,
          ParamKey::K1,     ParamKey::K2, ParamKey::Perturbation, ParamKey::Horizon};
}

QList<PlotKind> AccuracyScene::plots() const {
  return {PlotKind::TraceU2, PlotKind::WorkPrecision};
}

SceneJob AccuracyScene::build(const Params& params, const DerivedModel& derived) const {
  SceneJob job;
  job.model = derived.model;
  job.request.initial = perturbed(core::gloData(derived.model, derived.modes, params.lambda), params);
  job.request.maxContacts = std::int64_t(params.horizon);
  // the trace shows the whole comparison: it is what the overlay is drawn on
  job.request.needs = needsFor(plots(), derived.modes, (params.horizon + 1) * derived.modes.T2);
  AccuracyJob accuracy;
  for (core::methods::MethodKind kind : core::methods::kAllMethods) {
    for (const auto& setting : core::methods::reportSettings(kind, derived.modes.T2, derived.model.k1, true)) {
      accuracy.settings.push_back(setting);
    }
  }
  job.accuracy = std::move(accuracy);
  job.ok = true;
  return job;
}

}  // namespace grazelab::ui
