// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// A map's picture, drawn by the explorer's heat-map painter (built with the explorer only).
#include "io/map_picture.h"

#include <QImage>
#include <QPainter>

#include "io/output_files.h"
#include "ui/pictures/heat_map.h"

namespace grazelab::cli::map {

namespace {

constexpr int kWidth = 1000;
constexpr int kHeight = 820;

QString axisTitle(const JsonValue& spec, const char* which) {
  const QString name = QString::fromStdString(axisVariable(spec, which));
  // u<i> and v<i>: the two-mass map's u1, v1, v2 and a chain of N masses' coordinates
  if (name == "gap" || (name.size() > 1 && name[0] == 'u' && name[1].isDigit())) return name + " [length]";
  if (name.size() > 1 && name[0] == 'v' && name[1].isDigit()) return name + " [length/time]";
  if (name == "mass-ratio") return "m2 / m1";
  if (name == "detuning") return "detuning w1/w2 - 2";
  if (name == "epsilon") return "epsilon (size of the push)";
  // w<j>: a chain of N masses' GLO weight lambda_j
  if (name.size() > 1 && name[0] == 'w' && name[1].isDigit()) return "λ" + name.mid(1) + " (GLO weight of mode " + name.mid(1) + ")";
  return name;
}

pictures::HeatMapData heatMapOf(const StoredMap& map) {
  const JsonValue& spec = map.description.spec;
  // a field's text, or empty
  const auto text = [](const JsonValue* value) { return value ? QString::fromStdString(value->text) : QString(); };
  const QString quantity = text(spec.find("picture"));
  const auto which = core::parseQuantity(quantity.toStdString()).value_or(core::Quantity::FftFirst);
  const JsonValue* quantities = spec.find("quantities");
  const JsonValue* info = quantities ? quantities->find(quantity.toStdString()) : nullptr;
  pictures::HeatMapData data;
  data.columns = map.columns;
  data.rows = map.rows.rowEnd - map.rows.rowBegin;
  for (const core::PointSummary& point : map.points) data.values.push_back(core::valueOf(point, which));
  const core::MapAxis x = axisOf(spec, "x");
  const core::MapAxis y = axisOf(spec, "y");
  data.xFrom = x.from;
  data.xTo = x.to;
  data.yFrom = y.at(map.rows.rowBegin);
  data.yTo = y.at(map.rows.rowEnd - 1);
  const JsonValue* contactsValue = spec.find("contacts");
  const qint64 contacts = contactsValue ? qint64(contactsValue->toDouble()) : 0;
  QString meaning = text(info ? info->find("meaning") : nullptr);
  if (!meaning.isEmpty()) meaning[0] = meaning[0].toUpper();
  data.title = QStringLiteral("%1 (%2 contact%3 per run)").arg(meaning).arg(contacts).arg(contacts == 1 ? "" : "s");
  data.xTitle = axisTitle(spec, "x");
  data.yTitle = axisTitle(spec, "y");
  const QString unit = text(info ? info->find("unit") : nullptr);
  data.valueTitle = unit == "count" ? quantity : QStringLiteral("%1 [%2]").arg(quantity, unit);
  return data;
}

}  // namespace

void prepareFonts() {
  QImage image(64, 16, QImage::Format_ARGB32_Premultiplied);
  QPainter painter(&image);
  painter.drawText(QPointF(0, 12), QStringLiteral("0.5 T2"));
}

bool writeMapPicture(const QString& prefix, const StoredMap& map, QString& error) {
  const pictures::HeatMapData data = heatMapOf(map);
  const QByteArray description = QByteArray::fromStdString(oneLine(map.description.spec));
  return savePngAndSvg(
      prefix, QSize(kWidth, kHeight), data.title, "GrazeLabMap", description,
      [&](QPainter& painter) { pictures::paintHeatMap(painter, QRectF(0, 0, kWidth, kHeight), data); }, error);
}


}  // namespace grazelab::cli::map
