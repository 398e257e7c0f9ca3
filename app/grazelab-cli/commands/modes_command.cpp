// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli modes`: its options read into a request (commands/modes_atlas_command.h), its
// outcome written as PREFIX.json, a CSV and .npy per family and a picture.
#include "commands/modes_command.h"

#include <QCommandLineParser>
#include <QFileInfo>

#include <cmath>
#include <functional>
#include <type_traits>

#include "commands/orbit_command.h"
#include "commands/simulate_command.h"
#include "core/orbits/periodic_orbit.h"
#include "exit_codes.h"
#include "io/npy.h"
#include "io/output_files.h"
#include "io/table_csv.h"
#include "io/prepared_chain.h"

#include <QPainter>

#include "ui/pictures/modes_picture.h"

namespace grazelab::cli {
namespace {

// The picture's curves (log10 E, 2 pi / T) and marks: the bifurcations and the ends
template <typename S>
void pictureOf(const AtlasIn<S>& in, std::vector<pictures::ModesPictureFamily>& curves,
               std::vector<pictures::ModesPictureMark>& marks) {
  for (const core::ModeFamily<S>& family : in.atlas.families) {
    pictures::ModesPictureFamily curve;
    curve.impacts = family.impacts;
    for (const core::FamilyOrbit<S>& o : family.orbits) {
      curve.points.emplace_back(std::log10(double(o.energy)), 2 * M_PI / double(o.period));
      curve.stable.push_back(o.stability == core::Stability::Elliptic);
    }
    for (const core::FamilyBifurcation<S>& b : family.bifurcations) {
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
  }
}

// the same for a chain of N masses: stable where every multiplier is on the circle; marks at the
// changes of stability and at the ends that are the family's own (not a range or a budget)
template <typename S>
void pictureOf(const ChainAtlasIn<S>& in, std::vector<pictures::ModesPictureFamily>& curves,
               std::vector<pictures::ModesPictureMark>& marks) {
  const auto at = [](const S& energy, const S& period) {
    return QPointF(std::log10(double(energy)), 2 * M_PI / double(period));
  };
  for (const core::ChainAtlasFamily<S>& family : in.atlas.families) {
    const std::vector<core::BasicChainPeriodicOrbit<S>>& orbits = family.path.orbits;
    pictures::ModesPictureFamily curve;
    curve.impacts = family.path.impacts;
    for (const core::BasicChainPeriodicOrbit<S>& o : orbits) {
      curve.points.push_back(at(o.energy, o.period));
      curve.stable.push_back(o.monodromy.stability == core::ChainStability::Elliptic);
    }
    for (std::size_t i = 0; i < family.path.changes.size(); ++i) {
      const core::ChainFamilyChange<S>& change = family.path.changes[i];
      QString label = change.kind == core::ChainBifurcationKind::PeriodDoubling
                          ? QStringLiteral("flip")
                          : QString::fromUtf8(core::toString(change.kind).data());
      for (const core::ChainAtlasBranch& branch : family.branches) {
        if (branch.change == i && branch.outcome == core::ChainBranchOutcome::NotFound) {
          label = QStringLiteral("flip, no family found");
        }
      }
      marks.push_back({at(change.energy, change.period), label});
    }
    if (orbits.empty()) continue;
    const std::pair<const core::ChainAtlasEnd*, const core::BasicChainPeriodicOrbit<S>*> ends[] = {
        {family.firstEnd ? &*family.firstEnd : nullptr, &orbits.front()}, {&family.lastEnd, &orbits.back()}};
    for (const auto& [end, orbit] : ends) {
      if (!end) continue;
      const core::ChainFamilyEnd kind = end->kind;
      if (kind == core::ChainFamilyEnd::EnergyLimit || kind == core::ChainFamilyEnd::StepLimit ||
          kind == core::ChainFamilyEnd::MeetsDoubling || kind == core::ChainFamilyEnd::Stopped) {
        continue;  // not an end of the family itself (a doubling is marked as a flip)
      }
      marks.push_back({at(orbit->energy, orbit->period), QString::fromUtf8(core::toString(kind).data())});
    }
    curves.push_back(std::move(curve));
  }
}

// What the files are of: `modes`'s atlas, or `family --impacts`'s one family from an orbit.
enum class Written { Atlas, OneFamily };

// PREFIX.json, PREFIX-family-N.csv and .npy, and where pictures are drawn PREFIX.png and .svg
int writeModes(const ModesOutcome& outcome, const QString& prefix, Written written, const Io& io, QString& error) {
  const JsonValue json = modesDocument(outcome, QFileInfo(prefix).fileName().toStdString());
  std::vector<std::pair<QString, QByteArray>> files;
  const std::size_t count = modesFamilyCount(outcome);
  const std::vector<std::string> columns = modesColumns(outcome);
  for (std::size_t i = 0; i < count; ++i) {
    const std::vector<double> table = modesTable(outcome, i);
    const std::int64_t id = json.find("families")->items[i].find("id")->integer;
    NpyArray array;
    array.rows = std::int64_t(table.size() / columns.size());
    array.columns = std::int64_t(columns.size());
    array.reals = table;
    files.emplace_back(prefix + QStringLiteral("-family-%1.csv").arg(id), tableCsv(columns, table));
    files.emplace_back(prefix + QStringLiteral("-family-%1.npy").arg(id), encodeNpy(array));
  }
  files.emplace_back(prefix + ".json", QByteArray::fromStdString(fieldPerLine(json, "  ", "") + "\n"));
  for (const auto& [path, bytes] : files) {
    if (!saveAtomically(path, bytes, error)) return 1;
  }
  if (picturesAvailable()) {
    std::vector<pictures::ModesPictureFamily> curves;
    std::vector<pictures::ModesPictureMark> marks;
    std::visit(
        [&](const auto& in) {
          if constexpr (!std::is_same_v<std::decay_t<decltype(in)>, std::monostate>) pictureOf(in, curves, marks);
        },
        outcome.atlas);
    const JsonValue* model = json.find("model");
    const bool oneFamily = written == Written::OneFamily;
    const QString title =
        oneFamily ? QStringLiteral("A family of %1-impact orbits of %2 masses: frequency against energy")
                        .arg(outcome.maxImpacts)
                        .arg(json.find("chain")->find("masses")->items.size())
        : model ? QStringLiteral("Nonlinear modes: frequency against energy (m2/m1 = %1, up to %2 impacts)")
                    .arg(model->find("m2")->toDouble() / model->find("m1")->toDouble(), 0, 'g', 4)
                    .arg(outcome.maxImpacts)
              : QStringLiteral("Nonlinear modes of %1 masses: frequency against energy (up to %2 impacts)")
                    .arg(json.find("chain")->find("masses")->items.size())
                    .arg(outcome.maxImpacts);
    const QSize size(1100, 760);
    const bool drawn = savePngAndSvg(
        prefix, size, title, "GrazeLabModes", QByteArray::fromStdString(oneLine(json)),
        [&](QPainter& painter) { pictures::paintModes(painter, QRectF(QPointF(0, 0), size), curves, marks, title); },
        error);
    if (!drawn) return 1;
  }
  if (written == Written::OneFamily) {
    std::fprintf(io.messages, "grazelab-cli: family: %lld orbits: %s.json\n",
                 (long long)json.find("families")->items.front().find("rows")->integer, qPrintable(prefix));
  } else {
    std::fprintf(io.messages, "grazelab-cli: modes: %lld families: %s.json\n", (long long)count, qPrintable(prefix));
  }
  // (said, not only written: an atlas with parts undecided is not the whole atlas)
  if (const JsonValue* undecided = json.find("undecided_periods"); undecided && undecided->integer > 0) {
    std::fprintf(io.messages,
                 "grazelab-cli: modes: %lld periods of the 1IPP family undecided in %s: parts may be missing "
                 "(a wider --precision decides more)\n",
                 (long long)undecided->integer, core::toString(outcome.precision).data());
  }
  return kExitOk;
}

}  // namespace

void addModesOptions(QCommandLineParser& parser) {
  parser.addOptions({
      {"max-impacts", "modes: the most impacts per period of the families followed (default 4).", "K"},
      {"energy-range", "modes, family --impacts: follow families with energies in [A, B] (default: 1/100 to "
                       "10000 times the grazing end's energy; family: 1e-4 to 1e4 times the orbit's).", "A:B"},
  });
}

std::optional<ModesRequest> readModesRequest(const OptionValues& options, QString& error) {
  ModesRequest request;
  if (options.isSet("max-impacts")) {
    bool ok = false;
    request.maxImpacts = options.value("max-impacts").toInt(&ok);
    if (!ok || request.maxImpacts < 1 || request.maxImpacts > 64) {
      error = QStringLiteral("--max-impacts: '%1' is not a number from 1 to 64").arg(options.value("max-impacts"));
      return std::nullopt;
    }
  }
  const std::optional<PrecisionChoice> precision = readPrecisionChoice(options, error);
  if (!precision) return std::nullopt;
  request.precision = *precision;
  if (options.isSet("energy-range")) request.energyRange = options.value("energy-range").toStdString();
  return request;
}

namespace {

// The part `modes` and `family --impacts` share once their request is read: where the files go
// (refused before anything is computed), the chain, the outcome of `compute` on it, the files.
ModesRun computedWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                           bool filesRequired, Written written,
                           const std::function<ModesOutcome(const PreparedMassChain&)>& compute) {
  ModesRun run;
  run.code = kExitInvalidInput;
  std::optional<QString> prefix;
  if (filesRequired || options.isSet("out")) {
    const bool atlas = written == Written::Atlas;
    prefix = parseOutputPrefix(options, atlas ? "PREFIX.json, PREFIX-family-N.csv, ..." : "PREFIX.json, PREFIX-family-0.csv, ...",
                               atlas ? "modes" : "family", error);
    if (!prefix) return run;
  }
  const auto chain = recentChain(options, stop);
  if (!chain.value) {
    error = chain.error;
    if (chain.error.isEmpty()) run.code = kExitInterrupted;  // (the design was interrupted)
    return run;
  }
  run.outcome = compute(**chain.value);
  if (run.outcome.status == ModesStatus::Interrupted || stop.stop_requested()) {
    run.code = kExitInterrupted;
    return run;
  }
  if (run.outcome.status != ModesStatus::Computed) {
    error = QString::fromStdString(run.outcome.problem);
    return run;
  }
  run.code = prefix ? writeModes(run.outcome, *prefix, written, io, error) : kExitOk;
  return run;
}

}  // namespace

ModesRun modesWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                        bool filesRequired) {
  const std::optional<ModesRequest> request = readModesRequest(options, error);
  if (!request) return {kExitInvalidInput, {}};
  return computedWithFiles(options, io, stop, error, filesRequired, Written::Atlas,
                           [&](const PreparedMassChain& chain) { return modesAtlas(chain, *request, io.progress, stop); });
}

ModesRun impactsFamilyWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                                bool filesRequired) {
  if (options.isSet("onepp") || options.isSet("energy") == options.isSet("period") || !options.isSet("guess")) {
    error = "family --impacts K: give --guess U,V and one of --energy E or --period T (the orbit the family is "
            "followed from), and no --onepp";
    return {kExitInvalidInput, {}};
  }
  const std::optional<OrbitRequest> start = readOrbitRequest(options, error);
  if (!start) return {kExitInvalidInput, {}};
  ImpactsFamilyRequest request;
  request.start = *start;
  if (options.isSet("energy-range")) request.energyRange = options.value("energy-range").toStdString();
  if (options.isSet("count")) {
    bool ok = false;
    request.maxOrbits = options.value("count").toInt(&ok);
    if (!ok || request.maxOrbits < 2 || request.maxOrbits > 1000000) {
      error = QStringLiteral("--count: '%1' is not a count of orbits from 2 to 1000000").arg(options.value("count"));
      return {kExitInvalidInput, {}};
    }
  }
  return computedWithFiles(options, io, stop, error, filesRequired, Written::OneFamily,
                           [&](const PreparedMassChain& chain) { return impactsFamily(chain, request, stop); });
}

int runModes(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  return modesWithFiles(options, io, stop, error, true).code;
}

}  // namespace grazelab::cli
