// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli modes`: the atlas of the chain's nonlinear normal modes (issue 22).
#include "commands/modes_command.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <type_traits>

#include "commands/orbit_json.h"
#include "io/cli_input.h"
#include "core/orbits/modes_atlas.h"
#include "core/orbits/special_orbits.h"
#include "io/npy.h"
#include "io/output_files.h"
#include "exit_codes.h"

#include <QPainter>

#include "ui/pictures/modes_picture.h"

namespace grazelab::cli {
namespace {

QByteArray cell(double value) { return std::isfinite(value) ? QByteArray::number(value, 'g', 17) : QByteArray(); }

template <typename S>
QJsonObject endJson(const core::FamilyEnd<S>& end) {
  QJsonObject json{{"kind", QString::fromUtf8(core::toString(end.kind).data())}, {"energy", scalarJson(end.energy)},
                   {"period", scalarJson(end.period)}, {"state", stateJson(end.state)}};
  if (core::isFinite(end.gloLambda)) json["glo_lambda"] = scalarJson(end.gloLambda);
  if (end.kind == core::PointKind::GrazingOrbit || end.kind == core::PointKind::PeriodDoubling) {
    json["exact"] = end.exact;
    json["last_energy"] = scalarJson(end.lastEnergy);
  }
  if (end.family >= 0) json["family"] = end.family;
  return json;
}

const char* const kColumns = "energy,period,omega,trace,stability,u1,v1,min_impact_speed,min_clearance";

template <typename S>
int modesIn(const QCommandLineParser& parser, const FileOutput& output, const QString& precision, int maxImpacts,
            const Io& io, std::stop_token stop, QString& error) {
  const Parsed<ModelInput<S>> model = parseModel<S>(parser);
  if (!model.value) {
    error = model.error;
    return kExitInvalidInput;
  }
  const core::Chain<S>& chain = model.value->chain;
  if (!chain.resonant) {
    error = "modes: the atlas starts from the 1IPP family of the 1:2 resonant chain (give no --k2)";
    return kExitInvalidInput;
  }
  const S T2 = core::twoPi<S>() / chain.omegaSlow;
  const core::AtlasEnergyRange<S> range = core::defaultAtlasEnergyRange(chain);
  S low = range.low;
  S high = range.high;
  if (parser.isSet("energy-range")) {
    const QStringList parts = parser.value("energy-range").split(':');
    const auto a = parts.size() == 2 ? core::parseScalar<S>(parts[0].toStdString()) : core::ParsedScalar<S>{};
    const auto b = parts.size() == 2 ? core::parseScalar<S>(parts[1].toStdString()) : core::ParsedScalar<S>{};
    if (!a.value || !b.value || !(*a.value > 0) || !(*b.value > *a.value)) {
      error = QStringLiteral("--energy-range: '%1' is not A:B with 0 < A < B").arg(parser.value("energy-range"));
      return kExitInvalidInput;
    }
    low = *a.value;
    high = *b.value;
  }
  int familiesDone = 0;
  const core::ModesAtlas<S> atlas = core::computeModesAtlas<S>(
      chain, maxImpacts, low, high, stop, [&](const core::ModeFamily<S>& family) {
        io.reportProgress(-1, "family " + std::to_string(++familiesDone) + " followed (" +
                                  std::to_string(family.impacts) + " impacts per period)");
      });
  if (stop.stop_requested() || !atlas.complete) return kExitInterrupted;

  const QString& prefix = output.prefix;
  const QString base = QFileInfo(prefix).fileName();
  QJsonArray families;
  std::vector<std::pair<QString, QByteArray>> files;
  // the picture's curves and marks (drawn when picturesAvailable())
  std::vector<pictures::ModesPictureFamily> curves;
  std::vector<pictures::ModesPictureMark> marks;
  for (const core::ModeFamily<S>& family : atlas.families) {
    QByteArray csv = QByteArray(kColumns) + "\n";
    NpyArray array;
    array.rows = std::int64_t(family.orbits.size());
    array.columns = 9;
    pictures::ModesPictureFamily curve;
    curve.impacts = family.impacts;
    for (const core::FamilyOrbit<S>& o : family.orbits) {
      const double energy = double(o.energy), period = double(o.period);
      const double omega = 2 * M_PI / period;
      const double row[9] = {energy, period, omega, double(o.trace), double(int(o.stability)),
                             double(o.state.u1), double(o.state.v1), double(o.minImpactSpeed),
                             // no interior maximum (the core's infinity): NaN, as the CSV's empty cell
                             core::isFinite(o.minClearance) ? double(o.minClearance) : std::nan("")};
      csv += cell(row[0]) + "," + cell(row[1]) + "," + cell(row[2]) + "," + cell(row[3]) + "," +
             QByteArray(core::toString(o.stability).data()) + "," + cell(row[5]) + "," + cell(row[6]) + "," +
             cell(row[7]) + "," + cell(row[8]) + "\n";
      array.reals.insert(array.reals.end(), row, row + 9);
      curve.points.emplace_back(std::log10(energy), omega);
      curve.stable.push_back(o.stability == core::Stability::Elliptic);
    }
    const QString name = QStringLiteral("%1-family-%2").arg(base).arg(family.id);
    files.emplace_back(prefix + QStringLiteral("-family-%1.csv").arg(family.id), csv);
    files.emplace_back(prefix + QStringLiteral("-family-%1.npy").arg(family.id), encodeNpy(array));
    QJsonArray bifurcations;
    for (const core::FamilyBifurcation<S>& b : family.bifurcations) {
      QJsonObject point = bifurcationJson(b, T2);
      if (b.kind == core::PointKind::PeriodDoubling) {
        if (b.born >= 0) point["born_family"] = b.born;
        else if (!b.birthProblem.empty()) point["born_family"] = QJsonValue();
        if (!b.birthProblem.empty()) point["birth_problem"] = QString::fromStdString(b.birthProblem);
      }
      bifurcations.append(point);
      QString label = b.kind == core::PointKind::PeriodDoubling ? QStringLiteral("flip")
                                                                 : QString::fromUtf8(core::toString(b.kind).data());
      // a flip whose family could not be found says so on the picture too
      if (b.kind == core::PointKind::PeriodDoubling && b.born < 0 && !b.birthProblem.empty()) {
        label = QStringLiteral("flip, no family found");
      }
      marks.push_back({QPointF(std::log10(double(b.energy)), 2 * M_PI / double(b.T)), label});
    }
    for (const core::FamilyEnd<S>* end : {&family.end, &family.startEnd}) {
      if (end->kind == core::PointKind::PeriodDoubling || !(end->period > 0)) continue;
      QString label = QString::fromUtf8(core::toString(end->kind).data());
      // a grazing end named by the grazing linear orbit it tends to
      if (end->exact) {
        label = end->gloLambda == 0 ? QStringLiteral("GLOM₁") : QStringLiteral("GLO(λ*)");
      } else if (core::isFinite(end->gloLambda)) {
        // to the three decimals a picture shows (no "-0.000" for a lambda of -2e-7)
        const double lambda = std::round(double(end->gloLambda) * 1000) / 1000 + 0.0;
        label = QStringLiteral("GLO(λ ≈ %1)").arg(lambda, 0, 'f', 3);
      }
      if (end->kind == core::PointKind::EnergyLimit || end->kind == core::PointKind::StepLimit) continue;  // not an end of the family
      marks.push_back({QPointF(std::log10(double(end->energy)), 2 * M_PI / double(end->period)), label});
    }
    curves.push_back(std::move(curve));
    QJsonObject born{{"kind", QString::fromUtf8(core::toString(family.birth).data())},
                     {"family", family.parent < 0 ? QJsonValue() : QJsonValue(family.parent)},
                     {"energy", scalarJson(family.bornEnergy)},
                     {"T", scalarJson(family.bornPeriod)}};
    families.append(QJsonObject{
        {"id", family.id},
        {"impacts", family.impacts},
        {"symmetry", family.symmetry.empty() ? QJsonValue() : QJsonValue(QString::fromStdString(family.symmetry))},
        {"born_at", born},
        {"side", family.birth == core::Birth::OnePeriodic ? QJsonValue()
                                                          : QJsonValue(QString::fromUtf8(core::toString(family.side).data()))},
        {"start", endJson(family.startEnd)},
        {"end", endJson(family.end)},
        {"bifurcations", bifurcations},
        {"rows", qint64(family.orbits.size())},
        {"file", name + ".csv"}});
  }
  const core::BasicModel<S>& m = chain.model;
  const QJsonObject json{
      {"format", "grazelab-modes"},
      {"precision", precision},
      {"model", QJsonObject{{"m1", scalarJson(m.m1)}, {"m2", scalarJson(m.m2)}, {"k1", scalarJson(m.k1)},
                            {"k2", scalarJson(S(chain.kappa * m.k1))}, {"gap", scalarJson(m.gap)},
                            {"T2", scalarJson(T2)}}},
      {"max_impacts", maxImpacts},
      {"energy_range", QJsonArray{scalarJson(low), scalarJson(high)}},
      {"families", families},
      // what the fields of each family mean, apart from the families themselves
      {"about", QJsonObject{
        {"columns", QString(kColumns)},
        {"stability", "elliptic (|tr| < 2, stable), hyperbolic (tr > 2), flip-hyperbolic (tr < -2), "
                      "parabolic (|tr| = 2 within rounding); in the .npy 0, 1, 2, 3"},
        {"start", "a 1IPP part: its low-energy end; a family born at a flip: the flip (at twice its period)"},
        {"end", "grazing-orbit (every impact speed, or one with a clearance, tends to 0: a grazing linear "
                "orbit), interior-grazing (a flight touches the stop), impact-speed-zero (one impact fades), "
                "period-doubling (the family comes back to a flip of `family`: its orbit becomes that "
                "flip's run twice), energy-limit (the --energy-range, or the 1IPP part's energy growing "
                "without bound), step-limit, undecided (the continuation, or the precision, cannot go "
                "on with no event in sight), classified from the last orbit within 5 % of w2 d or of the "
                "gap. A 1IPP part's ends are its closed form's, located by bisection in T. Where impact "
                "speeds tend to 0 the end is located by bisection in the energy when Newton at fixed "
                "energy can follow. energy, period and state are the last orbit's, except where exact "
                "is true: then they are the limit orbit's, known exactly (a period tending to an odd "
                "number of T1 belongs to GLOM1 alone; the 1IPP family ends on GLO_lambda*; a "
                "period-doubling end is the flip's orbit), last_energy being the last orbit computed. "
                "glo_lambda: the GLO_lambda a grazing-orbit end tends to"},
        {"born_at", "one-periodic: a part of the 1IPP family from its closed form (energy and period T "
                    "of its orbit nearest the middle of the range); period-doubling: born at a flip of "
                    "`family`"},
        {"bifurcations", "kind period-doubling (tr = -2), fold (tr = +2, the energy turns back) or "
                         "branch-point (tr = +2, it goes on); checked: the trace is within sqrt(eps) of "
                         "the level (false: not solved in this precision, where the search stopped); "
                         "energy_error: an estimate of how far the energy may be from the exact point "
                         "(the trace's error over its slope in the energy; null when it cannot be "
                         "estimated); born_family: the family born at a flip, or null with birth_problem saying why "
                         "none was found (absent beyond --max-impacts)"},
        {"min_clearance", "the smallest distance below the stop of an interior maximum of u2 over "
                          "the gap (empty / NaN: no flight turns back below the stop)"}}},
      {"generator", "grazelab-cli " + QCoreApplication::applicationVersion()}};
  files.emplace_back(prefix + ".json", QJsonDocument(json).toJson());
  for (const auto& [path, bytes] : files) {
    if (!output.save(path, bytes, error)) return 1;
  }
  if (picturesAvailable() && !output.inMemory()) {
    const QString title = QStringLiteral("Nonlinear modes: frequency against energy (m2/m1 = %1, up to %2 impacts)")
                              .arg(double(m.m2 / m.m1), 0, 'g', 4)
                              .arg(maxImpacts);
    const QSize size(1100, 760);
    const bool drawn = savePngAndSvg(
        prefix, size, title, "GrazeLabModes", QJsonDocument(json).toJson(QJsonDocument::Compact),
        [&](QPainter& painter) { pictures::paintModes(painter, QRectF(QPointF(0, 0), size), curves, marks, title); },
        error);
    if (!drawn) return 1;
  }
  std::fprintf(io.messages, "grazelab-cli: modes: %lld families: %s.json\n", (long long)atlas.families.size(),
               qPrintable(prefix));
  return kExitOk;
}

}  // namespace

void addModesOptions(QCommandLineParser& parser) {
  parser.addOptions({
      {"max-impacts", "modes: the most impacts per period of the families followed (default 4).", "K"},
      {"energy-range", "modes: follow families with energies in [A, B] (default: 1/100 to 10000 "
                       "times the grazing end's energy).", "A:B"},
  });
}

int runModes(const QCommandLineParser& parser, const Io& io, std::stop_token stop, QString& error) {
  int maxImpacts = core::kDefaultAtlasMaxImpacts;
  if (parser.isSet("max-impacts")) {
    bool ok = false;
    maxImpacts = parser.value("max-impacts").toInt(&ok);
    if (!ok || maxImpacts < 1 || maxImpacts > 64) {
      error = QStringLiteral("--max-impacts: '%1' is not a number from 1 to 64").arg(parser.value("max-impacts"));
      return kExitInvalidInput;
    }
  }
  const QString precision = parser.value("precision");
  if (!QStringList{"auto", "double", "long", "quad"}.contains(precision)) {
    error = QStringLiteral("--precision: '%1' is not auto, double, long or quad").arg(precision);
    return kExitInvalidInput;
  }
  const auto output = openFileOutput(parser, io, "PREFIX.json, PREFIX-family-N.csv, ...", "modes", error);
  if (!output) return kExitInvalidInput;
  if (precision == "long") return modesIn<long double>(parser, *output, precision, maxImpacts, io, stop, error);
  if (precision == "quad") return modesIn<core::Quad>(parser, *output, precision, maxImpacts, io, stop, error);
  return modesIn<double>(parser, *output, "double", maxImpacts, io, stop, error);
}

}  // namespace grazelab::cli
