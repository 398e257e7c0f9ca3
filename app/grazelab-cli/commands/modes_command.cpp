// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli modes`: the atlas of the chain's nonlinear normal modes (issue 22).
#include "commands/modes_command.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>

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

using V = JsonValue;

template <typename S>
V endValue(const core::FamilyEnd<S>& end) {
  std::vector<V::Field> fields;
  fields.emplace_back("kind", V::of(std::string(core::toString(end.kind))));
  fields.emplace_back("energy", V::number(end.energy));
  fields.emplace_back("period", V::number(end.period));
  fields.emplace_back("state", orbitStateValue(end.state));
  if (core::isFinite(end.gloLambda)) fields.emplace_back("glo_lambda", V::number(end.gloLambda));
  if (end.kind == core::PointKind::GrazingOrbit || end.kind == core::PointKind::PeriodDoubling) {
    fields.emplace_back("exact", V::of(end.exact));
    fields.emplace_back("last_energy", V::number(end.lastEnergy));
  }
  if (end.family >= 0) fields.emplace_back("family", V::of(std::int64_t(end.family)));
  return V::object(std::move(fields));
}

const char* const kColumns = "energy,period,omega,trace,stability,u1,v1,min_impact_speed,min_clearance";

template <typename S>
int modesIn(const OptionValues& options, const FileOutput& output, const QString& precision, int maxImpacts,
            const Io& io, std::stop_token stop, QString& error) {
  const Parsed<ModelInput<S>> model = parseModel<S>(options);
  if (!model.value) {
    error = model.error;
    return kExitInvalidInput;
  }
  const core::TwoMassForm<S>& chain = model.value->chain;
  if (!chain.resonant) {
    error = "modes: the atlas starts from the 1IPP family of the 1:2 resonant chain (give no --k2)";
    return kExitInvalidInput;
  }
  const S T2 = core::twoPi<S>() / chain.omegaSlow;
  const core::AtlasEnergyRange<S> range = core::defaultAtlasEnergyRange(chain);
  S low = range.low;
  S high = range.high;
  if (options.isSet("energy-range")) {
    const QStringList parts = options.value("energy-range").split(':');
    const auto a = parts.size() == 2 ? core::parseScalar<S>(parts[0].toStdString()) : core::ParsedScalar<S>{};
    const auto b = parts.size() == 2 ? core::parseScalar<S>(parts[1].toStdString()) : core::ParsedScalar<S>{};
    if (!a.value || !b.value || !(*a.value > 0) || !(*b.value > *a.value)) {
      error = QStringLiteral("--energy-range: '%1' is not A:B with 0 < A < B").arg(options.value("energy-range"));
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
  std::vector<V> families;
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
    std::vector<V> bifurcations;
    for (const core::FamilyBifurcation<S>& b : family.bifurcations) {
      std::vector<V::Field> point = bifurcationFields(b, T2, true);
      if (b.kind == core::PointKind::PeriodDoubling) {
        if (b.born >= 0) point.emplace_back("born_family", V::of(std::int64_t(b.born)));
        else if (!b.birthProblem.empty()) point.emplace_back("born_family", V::null());
        if (!b.birthProblem.empty()) point.emplace_back("birth_problem", V::of(b.birthProblem));
      }
      bifurcations.push_back(V::object(std::move(point)));
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
    V born = V::object({{"kind", V::of(std::string(core::toString(family.birth)))},
                        {"family", family.parent < 0 ? V::null() : V::of(std::int64_t(family.parent))},
                        {"energy", V::number(family.bornEnergy)},
                        {"T", V::number(family.bornPeriod)}});
    families.push_back(V::object(
        {{"id", V::of(std::int64_t(family.id))},
         {"impacts", V::of(std::int64_t(family.impacts))},
         {"symmetry", family.symmetry.empty() ? V::null() : V::of(family.symmetry)},
         {"born_at", std::move(born)},
         {"side", family.birth == core::Birth::OnePeriodic ? V::null() : V::of(std::string(core::toString(family.side)))},
         {"start", endValue(family.startEnd)},
         {"end", endValue(family.end)},
         {"bifurcations", V::array(std::move(bifurcations))},
         {"rows", V::of(std::int64_t(family.orbits.size()))},
         {"file", V::of((name + ".csv").toStdString())}}));
  }
  const core::BasicModel<S>& m = chain.model;
  const V json = V::object({
      {"format", V::of("grazelab-modes")},
      {"precision", V::of(precision.toStdString())},
      {"model", V::object({{"m1", V::number(m.m1)}, {"m2", V::number(m.m2)}, {"k1", V::number(m.k1)},
                           {"k2", V::number(S(chain.kappa * m.k1))}, {"gap", V::number(m.gap)},
                           {"T2", V::number(T2)}})},
      {"max_impacts", V::of(std::int64_t(maxImpacts))},
      {"energy_range", V::array({V::number(low), V::number(high)})},
      {"families", V::array(std::move(families))},
      // what the fields of each family mean, apart from the families themselves
      {"about", V::object({
        {"columns", V::of(kColumns)},
        {"stability", V::of("elliptic (|tr| < 2, stable), hyperbolic (tr > 2), flip-hyperbolic (tr < -2), "
                      "parabolic (|tr| = 2 within rounding); in the .npy 0, 1, 2, 3")},
        {"start", V::of("a 1IPP part: its low-energy end; a family born at a flip: the flip (at twice its period)")},
        {"end", V::of("grazing-orbit (every impact speed, or one with a clearance, tends to 0: a grazing linear "
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
                "glo_lambda: the GLO_lambda a grazing-orbit end tends to")},
        {"born_at", V::of("one-periodic: a part of the 1IPP family from its closed form (energy and period T "
                    "of its orbit nearest the middle of the range); period-doubling: born at a flip of "
                    "`family`")},
        {"bifurcations", V::of("kind period-doubling (tr = -2), fold (tr = +2, the energy turns back) or "
                         "branch-point (tr = +2, it goes on); checked: the trace is within sqrt(eps) of "
                         "the level (false: not solved in this precision, where the search stopped); "
                         "energy_error: an estimate of how far the energy may be from the exact point "
                         "(the trace's error over its slope in the energy; null when it cannot be "
                         "estimated); born_family: the family born at a flip, or null with birth_problem saying why "
                         "none was found (absent beyond --max-impacts)")},
        {"min_clearance", V::of("the smallest distance below the stop of an interior maximum of u2 over "
                          "the gap (empty / NaN: no flight turns back below the stop)")}})},
      {"generator", V::of(std::string("grazelab-cli ").append(QCoreApplication::applicationVersion().toStdString()))}});
  files.emplace_back(prefix + ".json", QByteArray::fromStdString(fieldPerLine(json, "  ", "") + "\n"));
  for (const auto& [path, bytes] : files) {
    if (!output.save(path, bytes, error)) return 1;
  }
  if (picturesAvailable() && !output.inMemory()) {
    const QString title = QStringLiteral("Nonlinear modes: frequency against energy (m2/m1 = %1, up to %2 impacts)")
                              .arg(double(m.m2 / m.m1), 0, 'g', 4)
                              .arg(maxImpacts);
    const QSize size(1100, 760);
    const bool drawn = savePngAndSvg(
        prefix, size, title, "GrazeLabModes", QByteArray::fromStdString(oneLine(json)),
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

int runModes(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  int maxImpacts = core::kDefaultAtlasMaxImpacts;
  if (options.isSet("max-impacts")) {
    bool ok = false;
    maxImpacts = options.value("max-impacts").toInt(&ok);
    if (!ok || maxImpacts < 1 || maxImpacts > 64) {
      error = QStringLiteral("--max-impacts: '%1' is not a number from 1 to 64").arg(options.value("max-impacts"));
      return kExitInvalidInput;
    }
  }
  const QString precision = options.value("precision");
  if (!QStringList{"auto", "double", "long", "quad"}.contains(precision)) {
    error = QStringLiteral("--precision: '%1' is not auto, double, long or quad").arg(precision);
    return kExitInvalidInput;
  }
  const auto output = openFileOutput(options, io, "PREFIX.json, PREFIX-family-N.csv, ...", "modes", error);
  if (!output) return kExitInvalidInput;
  if (precision == "long") return modesIn<long double>(options, *output, precision, maxImpacts, io, stop, error);
  if (precision == "quad") return modesIn<core::Quad>(options, *output, precision, maxImpacts, io, stop, error);
  return modesIn<double>(options, *output, "double", maxImpacts, io, stop, error);
}

}  // namespace grazelab::cli
