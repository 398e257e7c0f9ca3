// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/session.h"

#include "ui/number_box.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>

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
  return session;
}

QString sessionPathFor(const QString& snapshotPath) {
  // the whole name: a PNG, an SVG and a CSV saved under one base name each keep their own
  const QFileInfo info(snapshotPath);
  return info.dir().filePath(info.fileName() + QStringLiteral(".session.json"));
}

QString sessionTitle(const Session& session) {
  const Params& p = session.params;
  const auto n = [](double value) { return shortestText(value); };
  return QStringLiteral("GrazeLab: %1 (λ = %2, δ = %3, m₁ = %4, m₂ = %5, k₁ = %6, k₂ = %7, d = %8, %9 contacts)")
      .arg(session.scene, n(p.lambda), n(p.perturbation), n(p.m1), n(p.m2), n(p.k1), n(p.k2), n(p.gap))
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
