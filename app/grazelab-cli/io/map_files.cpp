// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/map_files.h"

#include <QFile>

#include <algorithm>
#include <cmath>

#include "io/json_read.h"
#include "io/npy.h"
#include "io/output_files.h"

namespace grazelab::cli::map {
namespace {

using core::PointSummary;
using core::Quantity;

using V = JsonValue;

QString quantityFile(const QString& prefix, std::string_view name) {
  return prefix + "-" + QString::fromUtf8(name) + ".npy";
}

// the file names relative to the JSON file's folder, so that a moved folder still reads
QString baseName(const QString& prefix) { return prefix.section('/', -1); }

void setValue(PointSummary& point, Quantity quantity, double real, std::int64_t integer) {
  switch (quantity) {
    case Quantity::FftFirst: point.fftFirst = real; break;
    case Quantity::FftMin: point.fftMin = real; break;
    case Quantity::FftMax: point.fftMax = real; break;
    case Quantity::FftMean: point.fftMean = real; break;
    case Quantity::Impacts: point.impacts = integer; break;
    case Quantity::Grazings: point.grazings = integer; break;
    case Quantity::Sticks: point.sticks = integer; break;
    case Quantity::FirstImpactTime: point.firstImpactTime = real; break;
    case Quantity::Horizon: point.horizon = real; break;
  }
}

std::int64_t integerOf(const PointSummary& point, Quantity quantity) {
  switch (quantity) {
    case Quantity::Impacts: return point.impacts;
    case Quantity::Grazings: return point.grazings;
    case Quantity::Sticks: return point.sticks;
    default: return 0;
  }
}

QByteArray csvNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return QByteArray::number(value, 'g', 17);
}

QByteArray csvText(const StoredMap& map) {
  const core::MapAxis x = axisOf(map.description.spec, "x");
  const core::MapAxis y = axisOf(map.description.spec, "y");
  // the axes' names as the spec gives them (a chain of N masses has u3, v2, ...)
  const V& spec = map.description.spec;
  QByteArray text = "column,row," + QByteArray::fromStdString(axisVariable(spec, "x")) + "," +
                    QByteArray::fromStdString(axisVariable(spec, "y"));
  for (const core::QuantityInfo& info : core::quantities()) text += "," + QByteArray(info.name.data());
  text += "\n";
  for (std::int64_t r = map.rows.rowBegin; r < map.rows.rowEnd; ++r) {
    for (std::int64_t c = 0; c < map.columns; ++c) {
      const PointSummary& point = map.points[std::size_t((r - map.rows.rowBegin) * map.columns + c)];
      text += QByteArray::number(c) + "," + QByteArray::number(r) + "," + csvNumber(x.at(c)) +
              "," + csvNumber(y.at(r));
      for (const core::QuantityInfo& info : core::quantities()) {
        text += "," + (info.integer ? QByteArray::number(qint64(integerOf(point, info.quantity)))
                                    : csvNumber(core::valueOf(point, info.quantity)));
      }
      text += "\n";
    }
  }
  return text;
}

}  // namespace

std::optional<V> writeMapFiles(const QString& prefix, const StoredMap& map, QString& error) {
  const std::int64_t rows = map.rows.rowEnd - map.rows.rowBegin;
  // a map written over another: its description goes first and comes back last, so that a
  // write that fails half-way leaves no JSON describing a mixture of old and new arrays
  for (const QString& stale : {prefix + ".json", prefix + ".csv"}) {
    if (QFile::exists(stale) && !QFile::remove(stale)) {
      error = QStringLiteral("cannot replace %1").arg(stale);
      return std::nullopt;
    }
  }
  std::vector<V::Field> files;
  for (const core::QuantityInfo& info : core::quantities()) {
    NpyArray array;
    array.integer = info.integer;
    array.rows = rows;
    array.columns = map.columns;
    if (info.integer) {
      array.integers.reserve(map.points.size());
    } else {
      array.reals.reserve(map.points.size());
    }
    for (const PointSummary& point : map.points) {
      if (info.integer) {
        array.integers.push_back(integerOf(point, info.quantity));
      } else {
        array.reals.push_back(core::valueOf(point, info.quantity));
      }
    }
    const QString path = quantityFile(prefix, info.name);
    if (!saveAtomically(path, encodeNpy(array), error)) return std::nullopt;
    files.emplace_back(JsonKey::owned(std::string(info.name)), V::of(quantityFile(baseName(prefix), info.name).toStdString()));
  }
  if (rows * map.columns <= kCsvMaxPoints) {
    if (!saveAtomically(prefix + ".csv", csvText(map), error)) return std::nullopt;
    files.emplace_back("csv", V::of((baseName(prefix) + ".csv").toStdString()));
  }
  V names = V::object(std::move(files));
  const std::string document = indented(mapDocument(map, names));
  if (!saveAtomically(prefix + ".json", QByteArray::fromStdString(document), error)) return std::nullopt;
  return names;
}

std::optional<StoredMap> readMapFiles(const QString& prefix, QString& error) {
  QFile jsonFile(prefix + ".json");
  if (!jsonFile.open(QIODevice::ReadOnly)) {
    error = QStringLiteral("cannot read %1.json: %2").arg(prefix, jsonFile.errorString());
    return std::nullopt;
  }
  const std::optional<V> document = readJson(jsonFile.readAll());
  const V* spec = document ? document->find("spec") : nullptr;
  const V* run = document ? document->find("run") : nullptr;
  const V* format = spec ? spec->find("format") : nullptr;
  const V* rows = run ? run->find("rows") : nullptr;
  const V* totalRows = run ? run->find("total_rows") : nullptr;
  if (!format || format->text != "grazelab-map" || !rows || rows->items.size() != 2 || !totalRows) {
    error = prefix + ".json is not a grazelab map";
    return std::nullopt;
  }
  StoredMap map;
  map.description.spec = *spec;
  map.description.run = *run;
  map.rows = {std::int64_t(rows->items[0].toDouble()), std::int64_t(rows->items[1].toDouble())};
  map.totalRows = std::int64_t(totalRows->toDouble());
  map.columns = axisOf(map.description.spec, "x").count;
  const std::int64_t count = (map.rows.rowEnd - map.rows.rowBegin) * map.columns;
  if (count < 0 || map.rows.rowBegin < 0 || map.rows.rowEnd > map.totalRows) {
    error = prefix + ".json: rows out of range";
    return std::nullopt;
  }
  map.points.assign(std::size_t(count), PointSummary{});
  for (const core::QuantityInfo& info : core::quantities()) {
    const QString path = quantityFile(prefix, info.name);
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
      error = QStringLiteral("cannot read %1: %2").arg(path, file.errorString());
      return std::nullopt;
    }
    QString reason;
    const std::optional<NpyArray> array = decodeNpy(file.readAll(), reason);
    if (!array) {
      error = path + ": " + reason;
      return std::nullopt;
    }
    if (array->integer != info.integer || array->rows * array->columns != count ||
        array->columns != map.columns) {
      error = path + ": its shape or type is not the one " + prefix + ".json describes";
      return std::nullopt;
    }
    for (std::size_t i = 0; i < std::size_t(count); ++i) {
      setValue(map.points[i], info.quantity, info.integer ? 0.0 : array->reals[i],
               info.integer ? array->integers[i] : 0);
    }
  }
  for (PointSummary& point : map.points) point.valid = point.impacts >= 0;  // -1: no run there
  return map;
}

std::optional<StoredMap> mergeStripes(std::vector<StoredMap> parts, QString& error) {
  if (parts.empty()) {
    error = "nothing to merge";
    return std::nullopt;
  }
  // empty stripes (more stripes than rows) hold nothing to place
  std::erase_if(parts, [](const StoredMap& part) { return part.rows.rowEnd == part.rows.rowBegin; });
  if (parts.empty()) {
    error = "every part is an empty stripe";
    return std::nullopt;
  }
  std::sort(parts.begin(), parts.end(), [](const StoredMap& a, const StoredMap& b) {
    return std::pair(a.rows.rowBegin, a.rows.rowEnd) < std::pair(b.rows.rowBegin, b.rows.rowEnd);
  });
  StoredMap whole;
  whole.description.spec = parts.front().description.spec;
  whole.columns = parts.front().columns;
  whole.totalRows = parts.front().totalRows;
  whole.rows = {0, whole.totalRows};
  double seconds = 0;
  std::int64_t next = 0;
  for (const StoredMap& part : parts) {
    if (part.description.spec != whole.description.spec) {
      error = "the parts are stripes of different maps (their axes, model, start, contacts or "
              "versions differ)";
      return std::nullopt;
    }
    if (part.rows.rowBegin != next) {
      error = part.rows.rowBegin > next
                  ? QStringLiteral("rows %1 to %2 are in no part: a stripe is missing").arg(next).arg(part.rows.rowBegin - 1)
                  : QStringLiteral("row %1 is in two parts: a stripe is given twice or the parts overlap").arg(part.rows.rowBegin);
      return std::nullopt;
    }
    whole.points.insert(whole.points.end(), part.points.begin(), part.points.end());
    if (const V* partSeconds = part.description.run.find("seconds")) seconds += partSeconds->toDouble();
    next = part.rows.rowEnd;
  }
  if (next != whole.totalRows) {
    error = QStringLiteral("rows %1 to %2 are in no part: a stripe is missing").arg(next).arg(whole.totalRows - 1);
    return std::nullopt;
  }
  whole.description.run = V::object({{"merged_from", V::of(std::int64_t(parts.size()))},
                                     {"seconds", V::number(seconds)},
                                     {"complete", V::of(true)}});
  return whole;
}

}  // namespace grazelab::cli::map
