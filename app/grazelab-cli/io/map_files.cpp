// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/map_files.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <cmath>

#include "io/npy.h"
#include "io/output_files.h"

namespace grazelab::cli::map {
namespace {

using core::PointSummary;
using core::Quantity;

QJsonArray stateArray(const core::State& s) { return {s.u1, s.u2, s.v1, s.v2}; }

QJsonObject axisJson(const core::MapAxis& axis) {
  return {{"variable", QString::fromUtf8(core::toString(axis.variable))},
          {"from", axis.from},
          {"to", axis.to},
          {"count", qint64(axis.count)},
          {"values", "numpy.linspace(from, to, count)"}};
}

QJsonObject startJson(const core::MapSpec& spec) {
  using Kind = core::StartSpec<double>::Kind;
  QJsonObject start;
  if (!spec.start) {
    start = {{"kind", "grazing-start plane"}, {"u2", "gap"}, {"v2", 0},
             {"note", "u1 and v1 are 0 where no axis sets them"}};
  } else {
    switch (spec.start->kind) {
      case Kind::Glo: start = {{"kind", "glo"}, {"lambda", spec.start->lambda}}; break;
      case Kind::Glom: start = {{"kind", "glom"}, {"mode", int(spec.start->mode)}}; break;
      case Kind::OnePeriodic: start = {{"kind", "onepp"}, {"T", spec.start->period}}; break;
      case Kind::Explicit: start = {{"kind", "state"}, {"state", stateArray(spec.start->state)}}; break;
    }
  }
  const bool epsilonAxis = spec.x.variable == core::MapVariable::Epsilon ||
                           spec.y.variable == core::MapVariable::Epsilon;
  if (spec.perturbation && !epsilonAxis) start["perturbation"] = stateArray(*spec.perturbation);
  if (epsilonAxis) {
    start["epsilon_direction"] = stateArray(spec.perturbation.value_or(core::State{0, 0, 0, -1}));
  }
  return start;
}

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
  const QJsonObject& spec = map.description.spec;
  QByteArray text = "column,row," + spec["x"].toObject()["variable"].toString().toUtf8() + "," +
                    spec["y"].toObject()["variable"].toString().toUtf8();
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

core::MapAxis axisOf(const QJsonObject& spec, const char* which) {
  const QJsonObject axis = spec[which].toObject();
  core::MapAxis result;
  result.variable = core::parseMapVariable(axis["variable"].toString().toStdString())
                        .value_or(core::MapVariable::U1);
  result.from = axis["from"].toDouble();
  result.to = axis["to"].toDouble();
  result.count = axis["count"].toInteger();
  return result;
}

QJsonObject specJson(const core::MapSpec& spec, double period, const QString& pictureQuantity) {
  const core::Model& m = spec.model;
  QJsonObject model{{"m1", m.m1}, {"m2", m.m2}, {"k1", m.k1}, {"gap", m.gap}, {"T2", period}};
  if (m.design) {
    model["branch"] = QString::fromUtf8(core::toString(*m.design));
    model["k2"] = "1:2 design of the branch (follows m2/m1)";
  } else {
    model["k2"] = m.k2;
  }
  QJsonObject quantities;
  for (const core::QuantityInfo& info : core::quantities()) {
    quantities[QString::fromUtf8(info.name)] =
        QJsonObject{{"unit", QString::fromUtf8(info.unit)},
                    {"dtype", info.integer ? "int64" : "float64"},
                    {"meaning", QString::fromUtf8(info.meaning)}};
  }
  return {{"format", "grazelab-map"},
          {"generator", "grazelab-cli " + QCoreApplication::applicationVersion()},
          {"layout", "PREFIX-QUANTITY.npy: row index = y index, column index = x index"},
          {"x", axisJson(spec.x)},
          {"y", axisJson(spec.y)},
          {"model", model},
          {"start", startJson(spec)},
          {"contacts", qint64(spec.contacts)},
          {"contacts_note", "each run makes this many contacts, and more (at most 3) if its first "
                            "flight from the stop has not ended by then"},
          {"horizon", spec.estimateHorizon ? "estimated per point (--trust auto)"
                                           : "not estimated (--trust off): NaN; give --trust auto"},
          {"missing_values", "NaN: not defined at that point (no such flight or impact in the "
                             "run, or the model or start is unusable there); inf: the run proved "
                             "it never comes (a resonant flight that never returns); the counts "
                             "are -1 where the model or start is unusable (no run)"},
          {"picture", pictureQuantity},
          {"quantities", quantities}};
}

bool writeMapFiles(const QString& prefix, const StoredMap& map, QString& error) {
  const std::int64_t rows = map.rows.rowEnd - map.rows.rowBegin;
  // a map written over another: its description goes first and comes back last, so that a
  // write that fails half-way leaves no JSON describing a mixture of old and new arrays
  for (const QString& stale : {prefix + ".json", prefix + ".csv"}) {
    if (QFile::exists(stale) && !QFile::remove(stale)) {
      error = QStringLiteral("cannot replace %1").arg(stale);
      return false;
    }
  }
  QJsonObject files;
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
    if (!saveAtomically(path, encodeNpy(array), error)) return false;
    files[QString::fromUtf8(info.name)] = quantityFile(baseName(prefix), info.name);
  }
  if (rows * map.columns <= kCsvMaxPoints) {
    if (!saveAtomically(prefix + ".csv", csvText(map), error)) return false;
    files["csv"] = baseName(prefix) + ".csv";
  }
  return saveAtomically(prefix + ".json", QJsonDocument(mapDocument(map, files)).toJson(), error);
}

QJsonObject mapDocument(const StoredMap& map, const QJsonObject& files) {
  QJsonObject run = map.description.run;
  run["rows"] = QJsonArray{qint64(map.rows.rowBegin), qint64(map.rows.rowEnd)};
  run["total_rows"] = qint64(map.totalRows);
  run["shape"] = QJsonArray{qint64(map.rows.rowEnd - map.rows.rowBegin), qint64(map.columns)};
  if (!files.isEmpty()) run["files"] = files;
  return {{"spec", map.description.spec}, {"run", run}};
}

std::optional<StoredMap> readMapFiles(const QString& prefix, QString& error) {
  QFile jsonFile(prefix + ".json");
  if (!jsonFile.open(QIODevice::ReadOnly)) {
    error = QStringLiteral("cannot read %1.json: %2").arg(prefix, jsonFile.errorString());
    return std::nullopt;
  }
  const QJsonObject document = QJsonDocument::fromJson(jsonFile.readAll()).object();
  StoredMap map;
  map.description.spec = document["spec"].toObject();
  map.description.run = document["run"].toObject();
  if (map.description.spec["format"].toString() != "grazelab-map") {
    error = prefix + ".json is not a grazelab map";
    return std::nullopt;
  }
  const QJsonArray rows = map.description.run["rows"].toArray();
  map.rows = {rows[0].toInteger(), rows[1].toInteger()};
  map.totalRows = map.description.run["total_rows"].toInteger();
  map.columns = map.description.spec["x"].toObject()["count"].toInteger();
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
    seconds += part.description.run["seconds"].toDouble();
    next = part.rows.rowEnd;
  }
  if (next != whole.totalRows) {
    error = QStringLiteral("rows %1 to %2 are in no part: a stripe is missing").arg(next).arg(whole.totalRows - 1);
    return std::nullopt;
  }
  whole.description.run = {{"merged_from", qint64(parts.size())},
                           {"seconds", seconds},
                           {"complete", true}};
  return whole;
}

}  // namespace grazelab::cli::map
