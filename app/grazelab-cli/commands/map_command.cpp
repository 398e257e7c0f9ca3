// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/map_command.h"

#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>

#include <atomic>
#include <optional>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "commands/parameter_map.h"
#include "io/chain_map_input.h"
#include "io/cli_input.h"
#include "io/map_files.h"
#include "io/map_picture.h"
#include "io/output_files.h"
#include "parallel/tbb_parallel_for.h"
#include "exit_codes.h"

namespace grazelab::cli {
namespace {

using Clock = std::chrono::steady_clock;

// "NAME:from:to:count"
std::optional<core::MapAxis> parseAxis(const QString& option, const QString& text,
                                         QString& error) {
  const QStringList parts = text.split(':');
  if (parts.size() != 4) {
    error = QStringLiteral("--%1: '%2' is not NAME:from:to:count").arg(option, text);
    return std::nullopt;
  }
  const auto variable = core::parseMapVariable(parts[0].toStdString());
  if (!variable) {
    error = QStringLiteral("--%1: '%2' is not a variable; use one of %3")
                .arg(option, parts[0], QString::fromStdString(core::mapVariableNames()));
    return std::nullopt;
  }
  bool okFrom = false, okTo = false, okCount = false;
  core::MapAxis axis;
  axis.variable = *variable;
  axis.from = parts[1].toDouble(&okFrom);
  axis.to = parts[2].toDouble(&okTo);
  axis.count = parts[3].toLongLong(&okCount);
  if (!okFrom || !okTo) {
    error = QStringLiteral("--%1: '%2' and '%3' must be numbers").arg(option, parts[1], parts[2]);
    return std::nullopt;
  }
  if (!okCount || axis.count < 1) {
    error = QStringLiteral("--%1: '%2' is not a count (a whole number >= 1)").arg(option, parts[3]);
    return std::nullopt;
  }
  return axis;
}

struct Shard {
  std::int64_t k = 1;
  std::int64_t n = 1;
};

std::optional<Shard> parseShard(const QString& text, QString& error) {
  const QStringList parts = text.split('/');
  bool okK = false, okN = false;
  Shard shard;
  if (parts.size() == 2) {
    shard.k = parts[0].toLongLong(&okK);
    shard.n = parts[1].toLongLong(&okN);
  }
  constexpr std::int64_t kMaxStripes = std::int64_t(1) << 31;
  if (!okK || !okN || shard.n < 1 || shard.n > kMaxStripes || shard.k < 1 || shard.k > shard.n) {
    error = QStringLiteral("--shard: '%1' is not K/N with 1 <= K <= N (stripes count from 1)").arg(text);
    return std::nullopt;
  }
  return shard;
}

// The axes of a map of the note's chain written with --masses that the two-mass map shares:
// u1, u2, v1, v2, from --state (not the GLO weights w<j> nor --glo-weights; --glo and --onepp
// are the two-mass options', refused for a chain given by --masses)
bool onStateAxes(const OptionValues& options) {
  const auto onState = [&](const char* axis) {
    const QString name = options.value(axis).section(':', 0, 0).trimmed();
    return QStringList{"u1", "u2", "v1", "v2"}.contains(name);
  };
  return onState("x") && onState("y") && !options.isSet("glo-weights") && !options.isSet("glo") && !options.isSet("onepp");
}

std::optional<core::MapSpec> parseSpec(const OptionValues& options, QString& error) {
  core::MapSpec spec;
  for (const char* name : {"x", "y"}) {
    if (!options.isSet(name)) {
      error = QStringLiteral("--%1 NAME:from:to:count is required").arg(name);
      return std::nullopt;
    }
  }
  const auto x = parseAxis("x", options.value("x"), error);
  if (!x) return std::nullopt;
  const auto y = parseAxis("y", options.value("y"), error);
  if (!y) return std::nullopt;
  spec.x = *x;
  spec.y = *y;
  const Parsed<ModelInput<double>> model = parseModel<double>(options);
  if (!model.value) {
    error = model.error;
    return std::nullopt;
  }
  spec.model = model.value->model;
  if (options.isSet("glo") || options.isSet("onepp") || options.isSet("state") || options.isSet("perturb")) {
    Parsed<core::StartSpec<double>> start = parseStartSpec<double>(options, spec.model);
    if (!start.value) {
      error = start.error;
      return std::nullopt;
    }
    spec.perturbation = start.value->perturbation;
    start.value->perturbation.reset();
    // --perturb alone: on the grazing-start plane
    if (options.isSet("glo") || options.isSet("onepp") || options.isSet("state")) spec.start = start.value;
  }
  if (options.isSet("contacts")) {
    bool ok = false;
    spec.contacts = options.value("contacts").toLongLong(&ok);
    if (!ok || spec.contacts < 1) {
      error = QStringLiteral("--contacts: '%1' is not a count >= 1").arg(options.value("contacts"));
      return std::nullopt;
    }
  }
  if (options.isSet("trust")) {
    const QString trust = options.value("trust");
    if (trust != "off" && trust != "auto") {
      error = QStringLiteral("--trust: '%1' is not off or auto (a map estimates each point's "
                             "horizon with auto)").arg(trust);
      return std::nullopt;
    }
    spec.estimateHorizon = trust == "auto";
  }
  const std::string problem = core::checkMap(spec);
  if (!problem.empty()) {
    error = QString::fromStdString(problem);
    return std::nullopt;
  }
  // a base start that cannot be made (an inadmissible --onepp T) would give a map of NaN: said
  // here, when no axis changes the chain it is made on
  const auto changesChain = [](core::MapVariable v) {
    return v == core::MapVariable::MassRatio || v == core::MapVariable::Gap ||
           v == core::MapVariable::Detuning;
  };
  if (spec.start && !changesChain(spec.x.variable) && !changesChain(spec.y.variable)) {
    const core::StartOrProblem<double> start = core::makeStart(model.value->chain, *spec.start);
    if (!start.start) {
      const bool onepp = spec.start->kind == core::StartSpec<double>::Kind::OnePeriodic;
      error = (onepp ? QStringLiteral("--onepp: ") : QString()) + QString::fromStdString(start.problem);
      return std::nullopt;
    }
  }
  return spec;
}

// a line on the messages at most every two seconds while a long map computes, and each step
// to the caller's progress
class ProgressLine {
 public:
  explicit ProgressLine(const Io& io) : m_io(io) {}
  void operator()(std::int64_t done, std::int64_t total) {
    if (m_io.progress) {
      m_io.progress(double(done) / double(total), std::to_string(done) + " of " + std::to_string(total) + " points");
    }
    const std::int64_t now = Clock::now().time_since_epoch().count();
    std::int64_t last = m_last.load();
    const std::int64_t every = std::chrono::duration_cast<Clock::duration>(std::chrono::seconds(2)).count();
    if (now - last < every || !m_last.compare_exchange_strong(last, now)) return;
    std::fprintf(m_io.messages, "grazelab-cli: map: %lld of %lld points (%.0f %%)\n", (long long)done,
                 (long long)total, 100.0 * double(done) / double(total));
  }

 private:
  const Io& m_io;
  std::atomic<std::int64_t> m_last = Clock::now().time_since_epoch().count();
};

// Where a map's files go: under --out PREFIX, or nowhere when the caller takes the map in
// memory (the Python module) and gave no --out. False, with `error`, for an unusable --out.
bool filesPrefix(const OptionValues& options, bool filesRequired, std::optional<QString>& prefix, QString& error) {
  if (!filesRequired && !options.isSet("out")) return true;
  prefix = parseOutputPrefix(options, "PREFIX.json, PREFIX-QUANTITY.npy, ...", "map", error);
  return prefix.has_value();
}

}  // namespace

void addMapOptions(QCommandLineParser& parser) {
  parser.addOptions({
      {"x", QStringLiteral("map: the columns, NAME:from:to:count; NAME is one of %1 (with --masses: u<i>, "
                           "v<i> of the start, or w<j>, a GLO weight)")
                .arg(QString::fromStdString(core::mapVariableNames())), "NAME:from:to:count"},
      {"y", "map: the rows, NAME:from:to:count.", "NAME:from:to:count"},
      {"threads", "map: threads (default: all cores).", "T"},
      {"shard", "map: compute stripe K of N of the rows only (K from 1 to N); join the "
                "stripes with merge.", "K/N"},
      {"picture", "map: the quantity drawn in PREFIX.png/.svg (default fft_first).", "QUANTITY"},
      {"count", "family --onepp: periods T in (0, T2) (default 2000); family --impacts: the most orbits "
                "followed each way (default 2000).", "N"},
  });
}

std::optional<MapRequest> readMapRequest(const OptionValues& options, std::stop_token stop, QString& error,
                                         bool& stopped) {
  stopped = false;
  if (options.value("precision") != "auto" && options.value("precision") != "double") {
    error = "--precision: a map runs in auto precision (double, each point raised to long double "
            "or binary128 where a contact needs it); use simulate for one run in long or quad";
    return std::nullopt;
  }
  // a chain of N masses (--masses) or the two-mass chain; the note's chain written with --masses
  // over the axes u<i>, v<i> (from a --state, else the grazing-start plane, as for every chain)
  // is the note's map (its engine: the two-mass options' bits)
  const bool notes = writesTheNotesChain(options) && onStateAxes(options);
  const bool masses = options.isSet("masses") && !notes;
  MapRequest request;
  if (masses) {
    std::optional<core::ChainMapSpec> spec = parseChainMapSpec(options, stop, error, stopped);
    if (!spec) return std::nullopt;
    request.spec = std::move(*spec);
  } else {
    if (!notes) {
      for (const char* name : {"springs", "right-spring", "stop-mass", "frequencies", "design-branch", "glo-weights"}) {
        if (options.isSet(name)) {
          error = "--springs, --right-spring, --stop-mass, --frequencies and --glo-weights describe a chain given by --masses";
          return std::nullopt;
        }
      }
    }
    std::optional<core::MapSpec> spec = parseSpec(options, error);
    if (!spec) return std::nullopt;
    request.spec = std::move(*spec);
  }
  if (options.isSet("shard")) {
    const auto shard = parseShard(options.value("shard"), error);
    if (!shard) return std::nullopt;
    request.stripe = shard->k;
    request.stripes = shard->n;
  }
  request.threads = parallel::defaultThreadCount();
  if (options.isSet("threads")) {
    bool ok = false;
    request.threads = options.value("threads").toInt(&ok);
    if (!ok || request.threads < 1) {
      error = QStringLiteral("--threads: '%1' is not a count >= 1").arg(options.value("threads"));
      return std::nullopt;
    }
  }
  if (options.isSet("picture")) request.picture = options.value("picture").toStdString();
  if (!core::parseQuantity(request.picture)) {
    QStringList names;
    for (const auto& info : core::quantities()) names << QString::fromUtf8(info.name);
    error = QStringLiteral("--picture: '%1' is not a quantity; use one of %2")
                .arg(QString::fromStdString(request.picture), names.join(", "));
    return std::nullopt;
  }
  const core::RowRange rows = request.rows();
  const std::int64_t points = (rows.rowEnd - rows.rowBegin) * request.columns();
  // a summary is 80 bytes: beyond 2^27 points (10.7 GB) a process should take a stripe
  constexpr std::int64_t kMaxPointsInMemory = std::int64_t(1) << 27;
  if (points > kMaxPointsInMemory) {
    error = QStringLiteral("%1 points (%2 GB in memory) in one process: split the rows with "
                           "--shard K/N and join the stripes with merge")
                .arg(points).arg(double(points) * 80 / 1e9, 0, 'f', 1);
    return std::nullopt;
  }
  return request;
}

MapRun mapWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                    bool filesRequired) {
  MapRun run;
  bool stopped = false;
  const std::optional<MapRequest> request = readMapRequest(options, stop, error, stopped);
  if (!request) {
    run.code = stopped ? kExitInterrupted : kExitInvalidInput;
    return run;
  }
  std::optional<QString> prefix;
  if (!filesPrefix(options, filesRequired, prefix, error)) {
    run.code = kExitInvalidInput;
    return run;
  }
  const core::RowRange rows = request->rows();
  const bool whole = rows.rowBegin == 0 && rows.rowEnd == request->totalRows();
  const bool drawsPicture = prefix && whole && picturesAvailable();
  // the fonts load while the points are computed (the picture needs them afterwards)
  std::thread fontThread;
  if (drawsPicture) fontThread = std::thread(map::prepareFonts);
  ProgressLine progress(io);
  run.outcome = parameterMap(*request, stop, std::ref(progress));
  if (fontThread.joinable()) fontThread.join();
  if (run.outcome.status == MapStatus::Interrupted) {
    run.code = kExitInterrupted;
    return run;
  }
  if (!prefix) return run;
  const map::StoredMap& stored = run.outcome.map;
  // the picture (fonts, painting, PNG and SVG encoding: more than the arrays) is drawn on a
  // thread of its own while the arrays are written, so that on two cores the files add no wall
  // time (QPainter draws on images in any thread; the two write different files)
  bool pictureWritten = true;
  QString pictureError;
  std::thread pictureThread;
  if (drawsPicture) {
    pictureThread = std::thread([&] { pictureWritten = map::writeMapPicture(*prefix, stored, pictureError); });
  }
  run.files = map::writeMapFiles(*prefix, stored, error);
  if (pictureThread.joinable()) pictureThread.join();
  if (!run.files || !pictureWritten) {
    if (run.files) error = pictureError;
    run.code = 1;
    return run;
  }
  const std::int64_t points = std::int64_t(stored.points.size());
  const double seconds = run.outcome.seconds;
  std::fprintf(io.messages, "grazelab-cli: map: %lld points in %.3f s on %d thread%s (%.0f runs/s): %s.json\n",
               (long long)points, seconds, request->threads, request->threads == 1 ? "" : "s",
               seconds > 0 ? double(points) / seconds : 0.0, qPrintable(*prefix));
  return run;
}

int runMap(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  return mapWithFiles(options, io, std::move(stop), error, true).code;
}

MapRun mergeWithFiles(const OptionValues& options, const QStringList& parts, const Io& io, std::stop_token stop,
                      QString& error, bool filesRequired) {
  MapRun run;
  run.code = kExitInvalidInput;
  if (parts.isEmpty()) {
    error = "merge: give the parts' prefixes after --out PREFIX";
    return run;
  }
  std::optional<QString> prefix;
  if (!filesPrefix(options, filesRequired, prefix, error)) return run;
  std::vector<map::StoredMap> stored;
  for (const QString& part : parts) {
    if (stop.stop_requested()) {
      run.code = kExitInterrupted;
      return run;
    }
    QString reason;
    auto read = map::readMapFiles(part, reason);
    if (!read) {
      error = "merge: " + reason;
      return run;
    }
    stored.push_back(std::move(*read));
  }
  auto whole = map::mergeStripes(std::move(stored), error);
  if (!whole) {
    error = "merge: " + error;
    return run;
  }
  if (stop.stop_requested()) {
    run.code = kExitInterrupted;
    return run;
  }
  run.code = kExitOk;
  run.outcome.status = MapStatus::Computed;
  run.outcome.map = std::move(*whole);
  if (!prefix) return run;
  const map::StoredMap& merged = run.outcome.map;
  run.files = map::writeMapFiles(*prefix, merged, error);
  if (!run.files || (picturesAvailable() && !map::writeMapPicture(*prefix, merged, error))) {
    run.code = 1;
    return run;
  }
  std::fprintf(io.messages, "grazelab-cli: merge: %lld parts, %lld x %lld points: %s.json\n",
               (long long)parts.size(), (long long)merged.totalRows, (long long)merged.columns,
               qPrintable(*prefix));
  return run;
}

int runMerge(const OptionValues& options, const QStringList& parts, const Io& io, std::stop_token stop,
             QString& error) {
  return mergeWithFiles(options, parts, io, std::move(stop), error, true).code;
}

}  // namespace grazelab::cli
