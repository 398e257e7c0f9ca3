// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/scenes/grazing_family_scene.h"

#include <QCoreApplication>

#include <algorithm>

#include "core/orbits.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::GrazingFamilyScene", text);
}

}  // namespace

QString GrazingFamilyScene::name() const { return QStringLiteral("Grazing family GLO_lambda"); }
QString GrazingFamilyScene::alias() const { return QStringLiteral("grazing"); }
QString GrazingFamilyScene::title() const { return tr("Grazing family GLO(λ)"); }

QString GrazingFamilyScene::description() const {
  return tr("Starts on the grazing linear orbit GLO(λ), pushed off the grazing-start plane so "
            "that it impacts. Drag λ, the masses or the gap and watch every plot follow.");
}

Params GrazingFamilyScene::defaults() const {
  Params params;
  params.lambda = 0.5;
  params.perturbation = -0.05;
  params.direction = PerturbDirection::V2;
  params.horizon = 60;
  return params;
}

QList<ParamKey> GrazingFamilyScene::parameters() const {
  return {ParamKey::Lambda, ParamKey::M1,           ParamKey::M2,     ParamKey::Gap,
          ParamKey::K1,     ParamKey::K2,           ParamKey::Perturbation, ParamKey::Horizon};
}

QList<PlotKind> GrazingFamilyScene::plots() const {
  return {PlotKind::TraceU2, PlotKind::FreeFlight, PlotKind::PhaseU2V2, PlotKind::PhaseU1V1,
          PlotKind::Poincare};
}

SceneJob GrazingFamilyScene::build(const Params& params, const DerivedModel& derived) const {
  SceneJob job;
  job.model = derived.model;
  job.request.initial = perturbed(core::gloData(derived.model, derived.modes, params.lambda), params);
  job.request.maxContacts = std::int64_t(params.horizon);
  // dense output over the whole run for short runs, over the first 400 T2 for long ones
  job.request.needs = needsFor(plots(), derived.modes, 400 * derived.modes.T2);
  job.reference = core::gloData(derived.model, derived.modes, params.lambda);
  job.referenceLabel = tr("GLO(λ) data");
  job.ok = true;
  return job;
}

}  // namespace grazelab::ui
