// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/window/session.h"

#include "ui/widgets/number_box.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace grazelab::ui {
namespace {

const QString kFormat = QStringLiteral("grazelab-session");

}  // namespace

QByteArray sessionToJson(const Session& session) {
  QJsonObject object;
  object.insert(QStringLiteral("format"), kFormat);
  object.insert(QStringLiteral("version"), 1);
  object.insert(QStringLiteral("scene"), session.scene);
  object.insert(QStringLiteral("params"), toJson(session.params));
  if (session.start) {
    QJsonObject start;
    for (Eigen::Index i = 0; i < session.start->u.size(); ++i) {
      start.insert(QStringLiteral("u%1").arg(i + 1), session.start->u[i]);
      start.insert(QStringLiteral("v%1").arg(i + 1), session.start->v[i]);
    }
    object.insert(QStringLiteral("start"), start);
  }
  return QJsonDocument(object).toJson(QJsonDocument::Indented);
}

std::optional<Session> sessionFromJson(const QByteArray& json, const Params& defaults,
                                       QString* error) {
  QJsonParseError parseError;
  const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
  auto fail = [&](const QString& text) {
    if (error) *error = text;
    return std::nullopt;
  };
  if (document.isNull()) return fail(QStringLiteral("not JSON: %1").arg(parseError.errorString()));
  const QJsonObject object = document.object();
  if (object.value(QStringLiteral("format")).toString() != kFormat) {
    return fail(QStringLiteral("not a GrazeLab session (\"format\" is not \"%1\")").arg(kFormat));
  }
  Session session;
  session.scene = object.value(QStringLiteral("scene")).toString();
  QString paramsError;
  const auto params =
      paramsFromJson(object.value(QStringLiteral("params")).toObject(), defaults, &paramsError);
  if (!params) return fail(paramsError);
  session.params = *params;
  if (object.contains(QStringLiteral("start"))) {
    // u1 ... uN and v1 ... vN: N from the positions given (two masses: u1, u2, v1, v2)
    const QJsonObject start = object.value(QStringLiteral("start")).toObject();
    int n = 0;
    while (start.contains(QStringLiteral("u%1").arg(n + 1))) ++n;
    if (n < 2) return fail(QStringLiteral("\"start\" needs the numbers u1, u2, ..., v1, v2, ... of every mass"));
    core::ChainState state{core::ChainVector<double>(n), core::ChainVector<double>(n)};
    for (int i = 0; i < 2 * n; ++i) {
      const QString name = QStringLiteral("%1%2").arg(i < n ? QLatin1Char('u') : QLatin1Char('v')).arg(i % n + 1);
      const QJsonValue value = start.value(name);
      if (!value.isDouble() || !std::isfinite(value.toDouble())) {
        return fail(QStringLiteral("\"start\" needs a finite number \"%1\"").arg(name));
      }
      (i < n ? state.u[i] : state.v[i - n]) = value.toDouble();
    }
    session.start = state;
  }
  return session;
}

QString sessionPathFor(const QString& snapshotPath) {
  // the whole name: a PNG, an SVG and a CSV saved under one base name each keep their own
  const QFileInfo info(snapshotPath);
  return info.dir().filePath(info.fileName() + QStringLiteral(".session.json"));
}

QString sessionTitle(const Session& session, bool massChain) {
  const Params& p = session.params;
  const auto n = [](double value) { return shortestText(value); };
  if (massChain) {
    // a chain of N masses: its own numbers (the two-mass ones are not this run's)
    const MassChainParams& c = p.massChain;
    const auto joined = [&n](const auto& values) {
      QStringList parts;
      for (const auto value : values) parts.append(n(double(value)));
      return parts.join(QStringLiteral(", "));
    };
    QStringList ratio;
    for (auto it = c.harmonics.rbegin(); it != c.harmonics.rend(); ++it) ratio.append(QString::number(*it));
    QString springs = c.harmonics.empty()
                          ? QStringLiteral("k = (%1)").arg(joined(c.springs))
                          : QStringLiteral("k₁ = %1 and the springs of %2 (design %3)")
                                .arg(n(c.springs.front()), ratio.join(QLatin1Char(':')))
                                .arg(c.designBranch);
    if (c.rightSpring > 0) springs += QStringLiteral(", a right wall's k = %1").arg(n(c.rightSpring));
    if (session.start) {
      // the weights and the push do not describe a clicked start: the start itself does
      const core::ChainState& x = *session.start;
      return QStringLiteral("GrazeLab: %1 (masses (%2), %3, stop on mass %4, d = %5, from the clicked start u = (%6), v = (%7), %8 contacts)")
          .arg(session.scene, joined(c.masses), springs)
          .arg(c.stopMass > 0 ? c.stopMass : c.size())
          .arg(n(p.gap), joined(std::vector<double>(x.u.begin(), x.u.end())),
               joined(std::vector<double>(x.v.begin(), x.v.end())), n(p.horizon));
    }
    return QStringLiteral("GrazeLab: %1 (masses (%2), %3, stop on mass %4, d = %5, weights (%6), δ = %7, %8 contacts)")
        .arg(session.scene, joined(c.masses), springs)
        .arg(c.stopMass > 0 ? c.stopMass : c.size())
        .arg(n(p.gap), joined(c.weights), n(p.perturbation), n(p.horizon));
  }
  const QString chain = QStringLiteral("m₁ = %1, m₂ = %2, k₁ = %3, k₂ = %4, d = %5")
                            .arg(n(p.m1), n(p.m2), n(p.k1), n(p.k2), n(p.gap));
  if (session.start && session.start->u.size() == 2) {
    // the scene's λ and push do not describe a clicked start: the start itself does
    const core::State x = core::twoMassStateOf(*session.start);
    return QStringLiteral("GrazeLab: %1 (%2, from the clicked start u₁ = %3, u₂ = %4, v₁ = %5, v₂ = %6, %7 contacts)")
        .arg(session.scene, chain, n(x.u1), n(x.u2), n(x.v1), n(x.v2))
        .arg(n(p.horizon));
  }
  return QStringLiteral("GrazeLab: %1 (λ = %2, δ = %3, %4, %5 contacts)")
      .arg(session.scene, n(p.lambda), n(p.perturbation), chain)
      .arg(n(p.horizon));
}

std::optional<Session> readSessionFile(const QString& path, const Params& defaults,
                                       QString* error) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) {
    if (error) *error = QStringLiteral("cannot read %1: %2").arg(path, file.errorString());
    return std::nullopt;
  }
  QString parseError;
  auto loaded = sessionFromJson(file.readAll(), defaults, &parseError);
  if (!loaded && error) *error = QStringLiteral("%1: %2").arg(path, parseError);
  return loaded;
}

}  // namespace grazelab::ui
