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
#include <string_view>
#include <tuple>

namespace grazelab::ui {
namespace {

constexpr std::array kAllKeys = {ParamKey::Lambda, ParamKey::M1,           ParamKey::M2,
                                 ParamKey::Gap,    ParamKey::K1,           ParamKey::K2,
                                 ParamKey::Perturbation, ParamKey::Horizon, ParamKey::Period,
                                 ParamKey::FrequencyRatio, ParamKey::ChainPeriod, ParamKey::ModeFamily,
                                 ParamKey::ModeEnergy};
constexpr std::array kAllDirections = {PerturbDirection::V2, PerturbDirection::U2,
                                       PerturbDirection::U1, PerturbDirection::V1};

QJsonArray numbersArray(const auto& values) {
  QJsonArray array;
  for (const auto value : values) array.append(double(value));
  return array;
}

QJsonObject toJson(const MassChainParams& chain) {
  return QJsonObject{{QStringLiteral("masses"), numbersArray(chain.masses)},
                     {QStringLiteral("springs"), numbersArray(chain.springs)},
                     {QStringLiteral("rightSpring"), chain.rightSpring},
                     {QStringLiteral("harmonics"), numbersArray(chain.harmonics)},
                     {QStringLiteral("designBranch"), chain.designBranch},
                     {QStringLiteral("stopMass"), chain.stopMass},
                     {QStringLiteral("shownMass"), chain.shownMass},
                     {QStringLiteral("sectionX"), chain.sectionX},
                     {QStringLiteral("sectionY"), chain.sectionY},
                     {QStringLiteral("weights"), numbersArray(chain.weights)}};
}

// numbers, each finite and within [low, high]; nothing when any is not
std::optional<std::vector<double>> numbersOf(const QJsonValue& value, double low, double high) {
  if (!value.isArray()) return std::nullopt;
  std::vector<double> numbers;
  for (const QJsonValue& item : value.toArray()) {
    if (!item.isDouble() || !std::isfinite(item.toDouble()) || item.toDouble() < low || item.toDouble() > high) {
      return std::nullopt;
    }
    numbers.push_back(item.toDouble());
  }
  return numbers;
}

std::optional<MassChainParams> massChainFromJson(const QJsonObject& object, const MassChainParams& base,
                                                 QString& error) {
  MassChainParams chain = base;
  const QStringList known{QStringLiteral("masses"), QStringLiteral("springs"), QStringLiteral("rightSpring"),
                          QStringLiteral("harmonics"),
                          QStringLiteral("designBranch"), QStringLiteral("stopMass"), QStringLiteral("shownMass"),
                          QStringLiteral("sectionX"), QStringLiteral("sectionY"),
                          QStringLiteral("weights")};
  for (const QString& name : object.keys()) {
    if (!known.contains(name)) {
      error = QStringLiteral("unknown field \"massChain.%1\" (known: %2)").arg(name, known.join(QStringLiteral(", ")));
      return std::nullopt;
    }
  }
  if (object.contains(QStringLiteral("masses"))) {
    const auto masses = numbersOf(object.value(QStringLiteral("masses")), 1e-6, 1e6);
    if (!masses || masses->empty() || int(masses->size()) > MassChainParams::kMaxMasses || masses->front() <= 0) {
      error = QStringLiteral("\"massChain.masses\" must be 1 to %1 masses in [1e-6, 1e6]").arg(MassChainParams::kMaxMasses);
      return std::nullopt;
    }
    chain = chain.resized(int(masses->size()));
    chain.masses = *masses;
  }
  const std::size_t n = chain.masses.size();
  if (object.contains(QStringLiteral("springs"))) {
    const auto springs = numbersOf(object.value(QStringLiteral("springs")), 1e-6, 1e6);
    if (!springs || springs->size() != n) {
      error = QStringLiteral("\"massChain.springs\" must be %1 springs in [1e-6, 1e6] (one per mass)").arg(n);
      return std::nullopt;
    }
    chain.springs = *springs;
  }
  if (object.contains(QStringLiteral("rightSpring"))) {
    const QJsonValue value = object.value(QStringLiteral("rightSpring"));
    const double k = value.toDouble(-1);
    if (!value.isDouble() || !(k == 0 || (k >= 1e-6 && k <= 1e6))) {
      error = QStringLiteral("\"massChain.rightSpring\" must be 0 (no right wall) or a spring in [1e-6, 1e6]");
      return std::nullopt;
    }
    chain.rightSpring = k;
  }
  if (object.contains(QStringLiteral("harmonics"))) {
    const auto harmonics = numbersOf(object.value(QStringLiteral("harmonics")), 1, 64);
    bool whole = harmonics && (harmonics->empty() || harmonics->size() == n);
    for (std::size_t j = 0; whole && harmonics && j < harmonics->size(); ++j) {
      whole = (*harmonics)[j] == std::floor((*harmonics)[j]) && (j == 0 || (*harmonics)[j] < (*harmonics)[j - 1]);
    }
    if (!whole) {
      error = QStringLiteral("\"massChain.harmonics\" must be empty or %1 whole numbers, fastest first").arg(n);
      return std::nullopt;
    }
    chain.harmonics.assign(harmonics->begin(), harmonics->end());
  }
  for (const auto& [name, field, high] : {std::tuple{"designBranch", &chain.designBranch, 40320},
                                          std::tuple{"stopMass", &chain.stopMass, int(n)},
                                          std::tuple{"shownMass", &chain.shownMass, int(n)},
                                          std::tuple{"sectionX", &chain.sectionX, int(2 * n)},
                                          std::tuple{"sectionY", &chain.sectionY, int(2 * n)}}) {
    const QJsonValue value = object.value(QString::fromLatin1(name));
    if (value.isUndefined()) continue;
    const double number = value.toDouble(-1);
    const int low = std::string_view(name) == "designBranch" ? 1 : 0;
    if (!value.isDouble() || number != std::floor(number) || number < low || number > high) {
      error = QStringLiteral("\"massChain.%1\" must be a whole number from %2 to %3").arg(QString::fromLatin1(name)).arg(low).arg(high);
      return std::nullopt;
    }
    *field = int(number);
  }
  if (chain.stopMass > int(n)) chain.stopMass = 0;
  if (chain.shownMass > int(n)) chain.shownMass = 0;
  if (object.contains(QStringLiteral("weights"))) {
    const auto weights = numbersOf(object.value(QStringLiteral("weights")), -1e3, 1e3);
    double sum = 0;
    if (weights) for (double w : *weights) sum += w;
    if (!weights || weights->size() != n || !(std::abs(sum - 1) <= 1e-9)) {
      error = QStringLiteral("\"massChain.weights\" must be %1 numbers summing to 1").arg(n);
      return std::nullopt;
    }
    chain.weights = *weights;
  }
  if (chain.springs.size() != n || chain.weights.size() != n || (!chain.harmonics.empty() && chain.harmonics.size() != n)) {
    error = QStringLiteral("\"massChain\": give springs, harmonics and weights for %1 masses").arg(n);
    return std::nullopt;
  }
  return chain;
}

}  // namespace

MassChainParams MassChainParams::resized(int count) const {
  MassChainParams chain = *this;
  count = std::clamp(count, 1, kMaxMasses);
  const auto n = std::size_t(count);
  chain.masses.resize(n, masses.empty() ? 1.0 : masses.back());
  chain.springs.resize(n, 1.0);
  // even weights to three decimals (a box shows 0.333, not 0.33333333), the first balancing (as
  // in the editor, where lambda_1 = 1 - the others)
  const double even = std::round(1000.0 / count) / 1000;
  chain.weights.assign(n, even);
  chain.weights.front() = 1 - even * (count - 1);
  if (chain.harmonics.size() != n) chain.harmonics.clear();
  if (chain.stopMass > count) chain.stopMass = 0;
  if (chain.shownMass > count) chain.shownMass = 0;
  // a coordinate's number moves with the count (v1 is N + 1): back to the default pair
  if (n != masses.size()) chain.sectionX = chain.sectionY = 0;
  if (n != masses.size()) chain.designBranch = 1;
  return chain;
}

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
    case ParamKey::ChainPeriod: return chainPeriodFraction;
    case ParamKey::ModeFamily: return modeFamily;
    case ParamKey::ModeEnergy: return modeEnergy;
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
    case ParamKey::ChainPeriod: chainPeriodFraction = value; break;
    case ParamKey::ModeFamily: modeFamily = value; break;
    case ParamKey::ModeEnergy: modeEnergy = value; break;
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
    case ParamKey::ChainPeriod: return QStringLiteral("chainPeriodOverT");
    case ParamKey::ModeFamily: return QStringLiteral("modeFamily");
    case ParamKey::ModeEnergy: return QStringLiteral("modeEnergy");
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
  object.insert(QStringLiteral("massChain"), toJson(params.massChain));
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
                    QStringLiteral("mapRegion"), QStringLiteral("massChain")};
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
  if (const QJsonValue value = object.value(QStringLiteral("massChain")); !value.isUndefined()) {
    if (!value.isObject()) return fail(QStringLiteral("\"massChain\" must be an object"));
    QString problem;
    const auto chain = massChainFromJson(value.toObject(), params.massChain, problem);
    if (!chain) return fail(problem);
    params.massChain = *chain;
  }
  return params;
}

}  // namespace grazelab::ui
