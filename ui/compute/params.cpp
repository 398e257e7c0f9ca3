// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/compute/params.h"

#include "ui/widgets/number_box.h"
#include "ui/widgets/param_specs.h"

#include <QJsonArray>
#include <QJsonValue>

#include <algorithm>
#include <array>
#include <cmath>

namespace grazelab::ui {
namespace {

constexpr std::array kAllKeys = {ParamKey::Lambda, ParamKey::M1,           ParamKey::M2,
                                 ParamKey::Gap,    ParamKey::K1,           ParamKey::K2,
                                 ParamKey::Perturbation, ParamKey::Horizon, ParamKey::Period,
                                 ParamKey::FrequencyRatio};
constexpr std::array kAllDirections = {PerturbDirection::V2, PerturbDirection::U2,
                                       PerturbDirection::U1, PerturbDirection::V1};

}  // namespace

double Params::value(ParamKey key) const {
  switch (key) {
    case ParamKey::Lambda: return lambda;
    case ParamKey::M1: return m1;
    case ParamKey::M2: return m2;
    case ParamKey::Gap: return gap;
    case ParamKey::K1: return k1;
    case ParamKey::K2: return k2;
    case ParamKey::Perturbation: return perturbation;
    case ParamKey::Horizon: return horizon;
    case ParamKey::Period: return periodFraction;
    case ParamKey::FrequencyRatio: return frequencyRatio;
  }
  return 0;
}

void Params::setValue(ParamKey key, double value) {
  switch (key) {
    case ParamKey::Lambda: lambda = value; break;
    case ParamKey::M1: m1 = value; break;
    case ParamKey::M2: m2 = value; break;
    case ParamKey::Gap: gap = value; break;
    case ParamKey::K1: k1 = value; break;
    case ParamKey::K2: k2 = value; break;
    case ParamKey::Perturbation: perturbation = value; break;
    case ParamKey::Horizon: horizon = value; break;
    case ParamKey::Period: periodFraction = value; break;
    case ParamKey::FrequencyRatio: frequencyRatio = value; break;
  }
}

QString jsonKey(ParamKey key) {
  switch (key) {
    case ParamKey::Lambda: return QStringLiteral("lambda");
    case ParamKey::M1: return QStringLiteral("m1");
    case ParamKey::M2: return QStringLiteral("m2");
    case ParamKey::Gap: return QStringLiteral("gap");
    case ParamKey::K1: return QStringLiteral("k1");
    case ParamKey::K2: return QStringLiteral("k2");
    case ParamKey::Perturbation: return QStringLiteral("perturbation");
    case ParamKey::Horizon: return QStringLiteral("contacts");
    case ParamKey::Period: return QStringLiteral("periodOverT2");
    case ParamKey::FrequencyRatio: return QStringLiteral("frequencyRatio");
  }
  return {};
}

QString jsonKey(PerturbDirection direction) {
  switch (direction) {
    case PerturbDirection::V2: return QStringLiteral("v2");
    case PerturbDirection::U2: return QStringLiteral("u2");
    case PerturbDirection::U1: return QStringLiteral("u1");
    case PerturbDirection::V1: return QStringLiteral("v1");
  }
  return {};
}

QJsonObject toJson(const Params& params) {
  QJsonObject object;
  for (ParamKey key : kAllKeys) object.insert(jsonKey(key), params.value(key));
  object.insert(QStringLiteral("direction"), jsonKey(params.direction));
  object.insert(QStringLiteral("resonantDesign"), params.resonantDesign);
  object.insert(QStringLiteral("branch"),
                QString::fromUtf8(core::toString(params.branch).data()));
  const Params::MapRegion& r = params.mapRegion;
  object.insert(QStringLiteral("mapRegion"), QJsonArray{r.u1From, r.u1To, r.v1From, r.v1To});
  return object;
}

std::optional<Params> paramsFromJson(const QJsonObject& object, const Params& base, QString* error) {
  Params params = base;
  auto fail = [&](const QString& text) {
    if (error) *error = text;
    return std::nullopt;
  };
  // a misspelt name would otherwise be dropped and its run replaced by another ("horizon"
  // for "contacts" ran 200 contacts where a million were asked)
  QStringList known{QStringLiteral("direction"), QStringLiteral("resonantDesign"), QStringLiteral("branch"),
                    QStringLiteral("mapRegion")};
  for (ParamKey key : kAllKeys) known.append(jsonKey(key));
  for (const QString& name : object.keys()) {
    if (!known.contains(name)) {
      return fail(QStringLiteral("unknown parameter \"%1\" (known: %2)").arg(name, known.join(QStringLiteral(", "))));
    }
  }
  for (ParamKey key : kAllKeys) {
    const QJsonValue value = object.value(jsonKey(key));
    if (value.isUndefined()) continue;
    if (!value.isDouble()) return fail(QStringLiteral("\"%1\" must be a number").arg(jsonKey(key)));
    // the same limits as the spin boxes: a value the panel cannot show is not run either
    const ParamSpec spec = paramSpec(key);
    const double number = value.toDouble();
    if (!std::isfinite(number) || number < spec.spinMin || number > spec.spinMax) {
      return fail(QStringLiteral("\"%1\" = %2 is outside [%3, %4]")
                      .arg(jsonKey(key))
                      .arg(shortestText(number), shortestText(spec.spinMin), shortestText(spec.spinMax)));
    }
    if (key == ParamKey::Horizon && number != std::floor(number)) {
      return fail(QStringLiteral("\"%1\" must be a whole number").arg(jsonKey(key)));
    }
    params.setValue(key, number);
  }
  if (const QJsonValue value = object.value(QStringLiteral("direction")); !value.isUndefined()) {
    bool found = false;
    for (PerturbDirection direction : kAllDirections) {
      if (value.toString() == jsonKey(direction)) {
        params.direction = direction;
        found = true;
      }
    }
    if (!found) return fail(QStringLiteral("\"direction\" must be one of v2, u2, u1, v1"));
  }
  if (const QJsonValue value = object.value(QStringLiteral("resonantDesign"));
      !value.isUndefined()) {
    if (!value.isBool()) return fail(QStringLiteral("\"resonantDesign\" must be true or false"));
    params.resonantDesign = value.toBool();
  }
  if (const QJsonValue value = object.value(QStringLiteral("branch")); !value.isUndefined()) {
    const auto branch = core::parseBranch(value.toString().toStdString());
    if (!branch) return fail(QStringLiteral("\"branch\" must be \"upper\" or \"lower\""));
    params.branch = *branch;
  }
  if (const QJsonValue value = object.value(QStringLiteral("mapRegion")); !value.isUndefined()) {
    const QJsonArray r = value.toArray();
    const bool numbers = r.size() == 4 && std::all_of(r.begin(), r.end(), [](const QJsonValue& v) {
      return v.isDouble() && std::isfinite(v.toDouble()) && std::abs(v.toDouble()) <= 1e6;
    });
    if (!numbers || !(r[0].toDouble() < r[1].toDouble()) || !(r[2].toDouble() < r[3].toDouble())) {
      return fail(QStringLiteral("\"mapRegion\" must be [u1From, u1To, v1From, v1To] with From < To"));
    }
    params.mapRegion = {r[0].toDouble(), r[1].toDouble(), r[2].toDouble(), r[3].toDouble()};
  }
  return params;
}

}  // namespace grazelab::ui
