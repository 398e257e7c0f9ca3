// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli family --onepp`: its options read into a request (commands/onepp_family.h), its
// outcome written as PREFIX.csv, .npy, .json and a picture.
#include "commands/family_command.h"

#include <QFileInfo>
#include <QPainter>

#include <string>
#include <vector>

#include "commands/simulate_command.h"
#include "exit_codes.h"
#include "io/cli_output.h"
#include "io/npy.h"
#include "io/output_files.h"
#include "io/table_csv.h"
#include "io/prepared_chain.h"
#include "ui/pictures/family_picture.h"

namespace grazelab::cli {
namespace {

// PREFIX.csv, .npy, .json and, where pictures are drawn, .png and .svg
int writeFamily(const FamilyOutcome& outcome, const QString& prefix, const Io& io, QString& error) {
  NpyArray array;
  array.rows = std::int64_t(outcome.rows());
  array.columns = std::int64_t(outcome.columns.size());
  array.reals = outcome.table;
  const JsonValue document = familyDocument(outcome, QFileInfo(prefix).fileName().toStdString());
  const QByteArray json = QByteArray::fromStdString(fieldPerLine(document, "  ", "") + "\n");
  if (!saveAtomically(prefix + ".csv", tableCsv(outcome.columns, outcome.table), error) || !saveAtomically(prefix + ".npy", encodeNpy(array), error) ||
      !saveAtomically(prefix + ".json", json, error)) {
    return 1;
  }
  const bool chain = std::holds_alternative<ChainFamily>(outcome.of);
  // (a chain of N masses with no admissible orbit has no curve to draw)
  if (picturesAvailable() && (!chain || outcome.admissible > 0)) {
    const QString title = QString::fromStdString(outcome.title);
    std::vector<pictures::FrequencyEnergyPoint> points;
    points.reserve(outcome.points.size());
    for (const FamilyPoint& p : outcome.points) points.push_back({p.energy, p.omega, p.admissible});
    const pictures::FrequencyEnergyPoint end{outcome.end.energy, outcome.end.omega, outcome.end.admissible};
    const QSize size(1100, 760);
    const bool drawn = savePngAndSvg(
        prefix, size, title, "GrazeLabFamily", QByteArray::fromStdString(chain ? json.toStdString() : oneLine(document)),
        [&](QPainter& painter) {
          if (chain) {
            pictures::paintFrequencyEnergy(painter, QRectF(QPointF(0, 0), size), points, end, title,
                                           QStringLiteral("grazing end: T → T_max, V → 0"));
          } else {
            pictures::paintFrequencyEnergy(painter, QRectF(QPointF(0, 0), size), points, end, title);
          }
        },
        error);
    if (!drawn) return 1;
  }
  std::fprintf(io.messages, "grazelab-cli: family: %lld orbits (%lld admissible): %s.csv\n",
               (long long)outcome.rows(), (long long)outcome.admissible, qPrintable(prefix));
  return kExitOk;
}

}  // namespace

std::optional<FamilyRequest> readFamilyRequest(const OptionValues& options, QString& error) {
  // the note's chain, however written, is the note's family; its limits are not N masses'
  const bool notes = !options.isSet("masses") || writesTheNotesChain(options);
  FamilyRequest request;
  const QString precisionText = options.value("precision");
  if (!notes && precisionText != "double" && precisionText != "auto") {
    error = kFamilyOfNMassesInDouble;
    return std::nullopt;
  }
  const std::optional<PrecisionChoice> precision = readPrecisionChoice(options, error);
  if (!precision) return std::nullopt;
  request.precision = *precision;
  if (options.isSet("count")) {
    bool ok = false;
    request.count = options.value("count").toLongLong(&ok);
    if (!ok || request.count < 1 || request.count > familyMaxCount(notes)) {
      error = QStringLiteral("--count: '%1' is not a count from 1 to %2").arg(options.value("count")).arg(familyMaxCount(notes));
      return std::nullopt;
    }
  }
  return request;
}

FamilyRun familyWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                          bool filesRequired) {
  FamilyRun run;
  run.code = kExitInvalidInput;
  if (!options.isSet("onepp")) {
    error = "family: name the family: --onepp (one impact per period), or --impacts K from an orbit";
    return run;
  }
  for (const char* other : {"energy", "period", "guess", "energy-range"}) {
    if (options.isSet(other)) {
      error = QStringLiteral("family --onepp: --%1 belongs to family --impacts K (the family of an orbit found "
                             "from a guess)").arg(QLatin1String(other));
      return run;
    }
  }
  const std::optional<FamilyRequest> request = readFamilyRequest(options, error);
  if (!request) return run;
  const auto chain = recentChain(options, stop);
  if (!chain.value) {
    error = chain.error;
    if (chain.error.isEmpty()) run.code = kExitInterrupted;  // (the design was interrupted)
    return run;
  }
  if (const std::optional<std::string> refusal = familyRefusal(**chain.value, *request)) {
    error = QString::fromStdString(*refusal);
    return run;
  }
  // where the files go, refused before any of the family is computed
  std::optional<QString> prefix;
  if (filesRequired || options.isSet("out")) {
    prefix = parseOutputPrefix(options, "PREFIX.csv, PREFIX.npy, PREFIX.json, ...", "family", error);
    if (!prefix) return run;
  }
  run.outcome = onePeriodicFamily(**chain.value, *request, io.progress, stop);
  if (run.outcome.status == FamilyStatus::Interrupted || stop.stop_requested()) {
    run.code = kExitInterrupted;
    return run;
  }
  if (run.outcome.status != FamilyStatus::Computed) {
    error = QString::fromStdString(run.outcome.problem);
    return run;
  }
  run.code = prefix ? writeFamily(run.outcome, *prefix, io, error) : kExitOk;
  return run;
}

int runFamily(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  return familyWithFiles(options, io, stop, error, true).code;
}

}  // namespace grazelab::cli
