// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/json_read.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include <cmath>

namespace grazelab::cli {
namespace {

JsonValue fromQt(const QJsonValue& value) {
  switch (value.type()) {
    case QJsonValue::Bool: return JsonValue::of(value.toBool());
    case QJsonValue::Double: {
      const double number = value.toDouble();
      // a whole number is a count as the writer wrote it
      if (number == std::trunc(number) && std::fabs(number) < 0x1p53) return JsonValue::of(std::int64_t(number));
      return JsonValue::number(number);
    }
    case QJsonValue::String: return JsonValue::of(value.toString().toStdString());
    case QJsonValue::Array: {
      std::vector<JsonValue> items;
      for (const QJsonValue& item : value.toArray()) items.push_back(fromQt(item));
      return JsonValue::array(std::move(items));
    }
    case QJsonValue::Object: {
      const QJsonObject object = value.toObject();
      std::vector<JsonValue::Field> fields;
      for (auto it = object.begin(); it != object.end(); ++it) {
        fields.emplace_back(JsonKey::owned(it.key().toStdString()), fromQt(it.value()));
      }
      return JsonValue::object(std::move(fields));
    }
    case QJsonValue::Null:
    case QJsonValue::Undefined: break;
  }
  return JsonValue::null();
}

}  // namespace

std::optional<JsonValue> readJson(const QByteArray& text) {
  QJsonParseError error{};
  const QJsonDocument document = QJsonDocument::fromJson(text, &error);
  if (error.error != QJsonParseError::NoError) return std::nullopt;
  return document.isObject() ? fromQt(document.object()) : fromQt(document.array());
}

}  // namespace grazelab::cli
