// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/scenes/near_grazing_scene.h"

#include <QCoreApplication>

#include "core/orbits.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::NearGrazingScene", text);
}

}  // namespace

QString NearGrazingScene::name() const { return QStringLiteral("Near grazing: Poincaré points on H"); }
QString NearGrazingScene::alias() const { return QStringLiteral("near-grazing"); }
QString NearGrazingScene::title() const { return tr("Near grazing: Poincaré points on H"); }

QString NearGrazingScene::description() const {
  return tr("Many contacts from a start just off a grazing orbit: the points (u₁, v₁) on the "
            "contact plane H and the free-flight times, which stay at or below T₂ (Theorem 2.3).");
}

Params NearGrazingScene::defaults() const {
  Params params;
  params.lambda = 0.5;
  params.perturbation = -0.01;
  params.direction = PerturbDirection::V2;
  params.horizon = 20000;
  return params;
}

QList<ParamKey> NearGrazingScene::parameters() const {
  return {ParamKey::Lambda, ParamKey::M1,           ParamKey::M2,     ParamKey::Gap,
          ParamKey::K1,     ParamKey::K2,           ParamKey::Perturbation, ParamKey::Horizon};
}

QList<PlotKind> NearGrazingScene::plots() const {
  return {PlotKind::Poincare, PlotKind::FreeFlight, PlotKind::TraceU2};
}

SceneJob NearGrazingScene::build(const Params& params, const DerivedModel& derived) const {
  SceneJob job;
  job.model = derived.model;
  const core::State start = core::gloData(derived.model, derived.modes, params.lambda);
  job.request.initial = perturbed(start, params);
  job.request.maxContacts = std::int64_t(params.horizon);
  // the trace is a glance at the first periods only; the section is the point of the scene
  job.request.needs = needsFor(plots(), derived.modes, 30 * derived.modes.T2);
  job.reference = start;
  job.referenceLabel = tr("GLO(λ) data");
  job.ok = true;
  return job;
}

}  // namespace grazelab::ui
