// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/scenes/one_ipp_scene.h"

#include <QCoreApplication>

#include "core/orbits.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::OneIppScene", text);
}

}  // namespace

QString OneIppScene::name() const { return QStringLiteral("1IPP orbits approaching GLO_lambda*"); }
QString OneIppScene::alias() const { return QStringLiteral("1ipp"); }
QString OneIppScene::title() const { return tr("1IPP orbits approaching GLO_λ*"); }

QString OneIppScene::description() const {
  return tr("One impact per period T. Slide T towards T₂ from below: the impact data (u₁, v₁) "
            "moves to the GLO_λ* data and the impact velocity goes to zero (Theorem 2.1).");
}

Params OneIppScene::defaults() const {
  Params params;
  params.periodFraction = 0.9;
  params.perturbation = 0;
  params.direction = PerturbDirection::V2;
  params.horizon = 20;
  return params;
}

QList<ParamKey> OneIppScene::parameters() const {
  // k2 too: it is what the "1:2 design" box hands over to the user when unticked
  return {ParamKey::Period, ParamKey::M1, ParamKey::M2,           ParamKey::Gap,
          ParamKey::K1,     ParamKey::K2, ParamKey::Perturbation, ParamKey::Horizon};
}

QList<PlotKind> OneIppScene::plots() const {
  return {PlotKind::TraceU2, PlotKind::FreeFlight, PlotKind::PhaseU2V2, PlotKind::PhaseU1V1,
          PlotKind::Poincare};
}

SceneJob OneIppScene::build(const Params& params, const DerivedModel& derived) const {
  SceneJob job;
  job.model = derived.model;
  const double period = params.periodFraction * derived.modes.T2;
  const core::OnePeriodicOrbit orbit =
      core::onePeriodicOrbit(derived.model, derived.modes, period);
  if (!orbit.admissible) {
    job.message = tr("No one-impact-per-period orbit for T = %1 (T/T₂ = %2): %3")
                      .arg(period, 0, 'g', 6)
                      .arg(params.periodFraction, 0, 'g', 6)
                      .arg(QString::fromStdString(orbit.reason));
    return job;
  }
  job.request.initial = perturbed(orbit.postImpact, params);
  job.request.maxContacts = std::int64_t(params.horizon);
  job.request.needs = needsFor(plots(), derived.modes, 400 * derived.modes.T2);
  job.reference = core::gloData(derived.model, derived.modes, derived.lambdaStar);
  job.referenceLabel = tr("GLO_λ* data");
  job.ok = true;
  return job;
}

}  // namespace grazelab::ui
