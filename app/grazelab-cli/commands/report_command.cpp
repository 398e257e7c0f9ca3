// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli report`: every method on one problem, timed and measured against the binary128
// exact run, written as a CSV, two pictures and a Markdown report (issue 8).
#include "io/output_files.h"
#include "commands/report_command.h"

#include <QCommandLineParser>

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>
#include <vector>

#include "core/solver/chain_run.h"
#include "core/solver/two_mass_run.h"
#include "io/chain_start.h"
#include "io/cli_input.h"
#include "io/option_values.h"
#include "commands/report_internal.h"
#include "commands/report_support.h"

namespace grazelab::cli {
namespace report {

QString name(MethodKind kind) {
  const std::string_view text = core::methods::methodName(kind);
  return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

QString parameterText(const core::methods::MethodSetting& setting) {
  if (setting.kind == MethodKind::Exact) {
    const std::string_view p = core::toString(setting.precision);
    return QString::fromUtf8(p.data(), qsizetype(p.size()));
  }
  return QString::fromStdString(setting.label()).section(' ', 1);
}

/// Smaller is finer, dimensionless: h / T2, rtol, k1 / k_c, or the unit roundoff.
double fineness(const core::methods::MethodSetting& setting, double period, double k1) {
  switch (setting.kind) {
    case MethodKind::MoreauJean:
    case MethodKind::MoreauJeanTheta1:
    case MethodKind::SchatzmanPaoli:
      return setting.value / period;
    case MethodKind::Penalty:
      return setting.penaltyToleranceSweep ? setting.penaltyRtol : k1 / setting.value;
    default:
      return setting.parameterValue();
  }
}


JsonValue metadata(const ReportInput& input) {
  using V = JsonValue;
  return V::object({{"generator", V::of(versionString().toStdString())},
                    {"model", input.chain},
                    {"start", input.start},
                    {"t_end", V::number(input.tEnd)}});
}


}  // namespace report

namespace {

using namespace report;
using core::methods::ErrorMeasure;

constexpr double kDefaultPeriods = 200;
const core::State kDefaultPush{0, 0, 0.05, -0.05};

/// The problem of a report: its task (the note's chain, or any chain of N masses) and the words
/// that describe it.
struct ReportProblem {
  ReportInput words;
  std::variant<core::methods::Task, core::methods::ChainTask> task;
};

/// The horizon of a report (--t-end, --contacts N, or 200 T2) given the times of the exact
/// run's first contacts (`contactTimes(count)`, at least `count` of them when it makes them);
/// nothing with `error` set.
template <typename ContactTimes>
std::optional<double> reportHorizon(const OptionValues& options, ReportInput& input, const ContactTimes& contactTimes,
                                    QString& error) {
  if (options.isSet("t-end")) {
    const auto tEnd = core::parseScalar<double>(options.value("t-end").trimmed().toStdString()).value;
    if (!tEnd || !(*tEnd > 0) || !std::isfinite(*tEnd)) {
      error = "--t-end must be a positive time for a report";
      return std::nullopt;
    }
    input.horizonNote = QStringLiteral("t_end = %1 (given)").arg(*tEnd);
    return *tEnd;
  }
  if (options.isSet("contacts")) {
    // the horizon ends halfway between the N-th and the next contact of the exact run, so
    // that no method is judged at a contact instant
    bool ok = false;
    const qlonglong contacts = options.value("contacts").trimmed().toLongLong(&ok);
    if (!ok || contacts < 1) {
      error = "--contacts must be at least 1 for a report";
      return std::nullopt;
    }
    const std::vector<double> times = contactTimes(std::int64_t(contacts) + 1);
    if (std::int64_t(times.size()) < contacts) {
      error = QStringLiteral("--contacts: this start makes only %1 contacts").arg(times.size());
      return std::nullopt;
    }
    const double nth = times[std::size_t(contacts - 1)];
    const double tEnd = times.size() > std::size_t(contacts) ? 0.5 * (nth + times[std::size_t(contacts)])
                                                             : nth + 0.5 * input.period;
    input.horizonNote = QStringLiteral("t_end = %1, halfway between contact %2 and the next")
                            .arg(tEnd, 0, 'g', 10)
                            .arg(contacts);
    return tEnd;
  }
  const double tEnd = kDefaultPeriods * input.period;
  input.horizonNote = QStringLiteral("t_end = %1 (the default)").arg(tEnd, 0, 'g', 10);
  return tEnd;
}

QString numberText(double value) { return QString::number(value, 'g', 17); }

QString listText(const Eigen::VectorXd& values) {
  QStringList parts;
  for (const double value : values) parts << numberText(value);
  return parts.join(", ");
}

JsonValue numbersValue(const Eigen::VectorXd& values) {
  std::vector<JsonValue> numbers;
  for (const double value : values) numbers.push_back(JsonValue::number(value));
  return JsonValue::array(std::move(numbers));
}

// The note's chain (the two-mass options, or --masses m1,m2 of its shape): the default problem
// unless told otherwise
std::optional<ReportProblem> twoMassProblem(const OptionValues& options, QString& error) {
  if (options.isSet("glo-weights")) {
    error = "--glo-weights describes a chain given by --masses (the two-mass chain starts with --glo)";
    return std::nullopt;
  }
  Parsed<RunInput<double>> run = parseRun<double>(options);
  if (!run.value) {
    error = run.error;
    return std::nullopt;
  }
  ReportProblem problem;
  ReportInput& input = problem.words;
  core::methods::Task task;
  task.model = run.value->model.model;
  task.start = run.value->request.initial;
  input.startDescription = QString::fromStdString(run.value->initialDescription);
  const bool startGiven = options.isSet("glo") || options.isSet("onepp") || options.isSet("state") ||
                          options.isSet("perturb");
  if (!startGiven) {
    task.start = task.start + kDefaultPush;
    input.startDescription += ", pushed by (0, 0, 0.05, -0.05) (the default problem)";
  }
  const core::TwoMassForm<double>& chain = run.value->model.chain;
  input.period = core::twoPi<double>() / chain.omegaSlow;
  task.needs.events = true;
  const auto tEnd = reportHorizon(options, input, [&task](std::int64_t count) {
    core::Request request;
    request.initial = task.start;
    request.maxContacts = count;
    request.needs.events = false;
    std::vector<double> times;
    request.onEvent = [&times](const core::Event& e) {
      if (core::isContact(e.type)) times.push_back(e.t);
    };
    core::TwoMassRun<double>(task.model, request).advance(std::numeric_limits<std::int64_t>::max());
    return times;
  }, error);
  if (!tEnd) return std::nullopt;
  task.tEnd = *tEnd;
  const core::Model& m = task.model;
  input.chainLine = QStringLiteral("m1 = %1, m2 = %2, k1 = %3, k2 = %4%5, gap d = %6")
                        .arg(m.m1).arg(m.m2).arg(m.k1).arg(m.k2, 0, 'g', 17)
                        .arg(m.design ? QStringLiteral(" (1:2 design, %1 branch)").arg(core::toString(*m.design).data())
                                      : QStringLiteral(" (as given)"))
                        .arg(m.gap);
  const core::State& s = task.start;
  input.startLine = QStringLiteral("(u1, u2, v1, v2) = (%1, %2, %3, %4)")
                        .arg(numberText(s.u1), numberText(s.u2), numberText(s.v1), numberText(s.v2));
  using V = JsonValue;
  input.chain = V::object({{"m1", V::number(m.m1)}, {"m2", V::number(m.m2)}, {"k1", V::number(m.k1)},
                           {"k2", V::number(m.k2)}, {"gap", V::number(m.gap)}});
  if (m.design) input.chain.set("branch", V::of(std::string(core::toString(*m.design))));
  input.start = V::array({V::number(s.u1), V::number(s.u2), V::number(s.v1), V::number(s.v2)});
  input.k1 = m.k1;
  input.tEnd = task.tEnd;
  problem.task = core::methods::prepared(std::move(task));  // no timed run pays for the modes
  return problem;
}

// A chain of N masses (--masses of any other shape): its start must be given (--state,
// --glo-weights or --onepp, and --perturb)
std::optional<ReportProblem> chainProblem(const OptionValues& options, QString& error) {
  if (!noTwoMassStart(options, error)) return std::nullopt;
  const Parsed<MassChainInput> parsed = parseMassChain(options);
  if (!parsed.value) {
    error = parsed.error;
    return std::nullopt;
  }
  ReportProblem problem;
  ReportInput& input = problem.words;
  core::methods::ChainTask task;
  task.chain = parsed.value->chain;
  std::string description;
  const auto start = chainStart<double>(options, task.chain, error, &description);
  if (!start) return std::nullopt;
  task.start = start->state;
  task.stillModes = start->stillModes;
  input.startDescription = QString::fromStdString(description);
  const core::ChainModes modes = core::chainModes(task.chain);
  input.period = core::twoPi<double>() / core::slowestFrequency(modes.omega);
  const auto tEnd = reportHorizon(options, input, [&task](std::int64_t count) {
    const core::ChainRun run = core::runChain(task.chain, {task.start, task.stillModes}, long(count));
    std::vector<double> times;
    for (const core::ChainEvent& e : run.events) {
      if (core::isContact(e.type)) times.push_back(e.t);
    }
    return times;
  }, error);
  if (!tEnd) return std::nullopt;
  task.tEnd = *tEnd;
  const core::MassChain& c = task.chain;
  const Eigen::Map<const Eigen::VectorXd> masses(c.masses.data(), c.size());
  const Eigen::Map<const Eigen::VectorXd> springs(c.springs.data(), c.size());
  input.chainLine = QStringLiteral("%1 masses (%2), springs (%3)%4, stopped mass %5, gap d = %6; "
                                   "w1 = %7 (its fastest mode), T2 its slowest period")
                        .arg(c.size())
                        .arg(listText(masses), listText(springs))
                        .arg(c.rightSpring > 0 ? QStringLiteral(", right wall spring %1").arg(numberText(c.rightSpring))
                                               : QString())
                        .arg(c.stopped())
                        .arg(numberText(c.gap))
                        .arg(modes.omega.maxCoeff(), 0, 'g', 10);
  input.startLine = QStringLiteral("u = (%1), v = (%2)").arg(listText(task.start.u), listText(task.start.v));
  using V = JsonValue;
  input.chain = V::object({{"masses", numbersValue(masses)},
                           {"springs", numbersValue(springs)},
                           {"right_spring", V::number(c.rightSpring)},
                           {"stop_mass", V::of(std::int64_t(c.stopped()))},
                           {"gap", V::number(c.gap)}});
  input.start = V::object({{"u", numbersValue(task.start.u)}, {"v", numbersValue(task.start.v)}});
  input.k1 = c.springs.front();
  input.tEnd = task.tEnd;
  problem.task = core::methods::prepared(std::move(task));  // no timed run pays for the modes
  return problem;
}

std::optional<ReportProblem> parseReportProblem(const OptionValues& options, QString& error) {
  if (options.isSet("t-end") && options.isSet("contacts")) {
    error = "give --t-end or --contacts, not both";
    return std::nullopt;
  }
  if (options.isSet("masses") && !hasTheNotesShape(OptionValues(options))) return chainProblem(options, error);
  return twoMassProblem(options, error);
}

// The errors are differences of runs handed back in double: below about one rounding of double
// (the state, relative to its scales) or of t_end (contact times, in T2) the comparison cannot see
// them, and an error of exactly 0 would claim more than it knows. Such an error is written as
// that bound, and the row's reason says so.
struct Resolution {
  double state = 0;
  double contactTime = 0;
};

Resolution comparisonResolution(double tEnd, double period) {
  const double eps = std::numeric_limits<double>::epsilon();
  return {eps, period > 0 ? eps * std::max(1.0, tEnd / period) : eps};
}

// The points with every error below `resolution` raised to it, the row's reason saying so: what
// the table, the pictures and report.md all show (none claims an accuracy the comparison cannot see)
std::vector<WorkPrecisionPoint> resolved(std::vector<WorkPrecisionPoint> points, const Resolution& resolution) {
  for (WorkPrecisionPoint& p : points) {
    core::methods::Errors& e = p.errors;
    const bool below = (e.state < resolution.state) || (e.contactTime < resolution.contactTime) ||
                       (e.impactSpeed < resolution.state);
    if (!below) continue;
    e.state = std::max(e.state, resolution.state);
    e.contactTime = std::max(e.contactTime, resolution.contactTime);
    e.impactSpeed = std::max(e.impactSpeed, resolution.state);
    const std::string note = "errors below the comparison's resolution (double: " +
                             scientific(resolution.state, 2).toStdString() + " in state, " +
                             scientific(resolution.contactTime, 2).toStdString() +
                             " T2 in contact times) are written as that bound";
    p.reason = p.reason.empty() ? note : p.reason + "; " + note;
  }
  return points;
}

QByteArray resultsCsv(const std::vector<WorkPrecisionPoint>& points) {
  QByteArray csv =
      "method,parameter,value,seconds_min,seconds_median,runs,state_error,contact_time_error,"
      "impact_speed_error,missed_contacts,extra_contacts,energy_drift,status,reason\n";
  for (const WorkPrecisionPoint& p : points) {
    const std::string_view parameter = p.setting.parameter();
    QString reason = QString::fromStdString(p.reason);
    reason.replace('"', "'");
    const std::string_view status = core::methods::toString(p.status);
    csv += QStringLiteral("%1,%2,%3,%4,%5,%6,%7,%8,%9,%10,%11,%12,%13,\"%14\"\n")
               .arg(name(p.setting.kind), QString::fromUtf8(parameter.data(), qsizetype(parameter.size())),
                    QString::number(p.setting.parameterValue(), 'g', 17),
                    scientific(p.secondsMin, 4), scientific(p.secondsMedian, 4))
               .arg(p.runs)
               .arg(scientific(p.errors.state), scientific(p.errors.contactTime),
                    scientific(p.errors.impactSpeed))
               .arg(p.errors.missed)
               .arg(p.errors.extra)
               .arg(scientific(p.errors.energyDrift),
                    QString::fromUtf8(status.data(), qsizetype(status.size())), reason)
               .toUtf8();
  }
  return csv;
}


}  // namespace

void addReportOptions(QCommandLineParser& parser) {
  parser.addOptions({
      {"out", "report, stability: the directory to write into (created if missing); map, merge, family, "
              "modes: the PREFIX of the files written; glo-set: PREFIX.png and PREFIX.svg, the set drawn.",
       "DIR|PREFIX"},
      {"methods", "report, stability: the methods to run, comma-separated (default: all): exact, "
                  "moreau-jean, moreau-jean-theta1, schatzman-paoli, dopri5-events, cvode-adams, "
                  "cvode-bdf, penalty.", "list"},
      {"quick", "report, stability: fewer settings and runs (seconds instead of minutes)."},
  });
}

ReportRun reportWithFiles(const OptionValues& options, const Io& io, std::stop_token stop, QString& error,
                          bool filesRequired) {
  ReportRun run;
  run.code = kExitInvalidInput;
  const auto methods = parseMethodsOption(options, error);
  if (!methods) return run;
  auto problem = parseReportProblem(options, error);
  if (!problem) return run;
  std::optional<QString> directory;
  if (filesRequired || options.isSet("out")) {
    directory = prepareOutputDirectory(options, error);
    if (!directory) return run;
  }
  ReportInput& input = problem->words;
  ReportRequest request;
  request.task = std::move(problem->task);
  request.methods = *methods;
  request.quick = options.isSet("quick");
  request.period = input.period;
  request.k1 = input.k1;
  ReportProgress heard;
  heard.horizon = [&io] { progress(io, "report", QStringLiteral("estimating the predictability horizon of the start")); };
  heard.reference = [&io, &input](double tEnd) {
    progress(io, "report", QStringLiteral("binary128 reference to t = %1 (%2 T2)")
                               .arg(tEnd, 0, 'g', 6).arg(tEnd / input.period, 0, 'g', 4));
  };
  heard.point = [&io](std::size_t done, std::size_t total, const WorkPrecisionPoint& point) {
    const QString stateError = scientific(point.errors.state, 2);
    progress(io, "report", QStringLiteral("[%1/%2] %3 %4: %5, state error %6%7")
                               .arg(done).arg(total)
                               .arg(name(point.setting.kind), parameterText(point.setting), humanSeconds(point.secondsMin))
                               .arg(stateError.isEmpty() ? "—" : stateError)
                               .arg(point.status == core::methods::RunStatus::Completed
                                        ? QString()
                                        : " (" + QString::fromStdString(point.reason) + ")"),
             double(done) / double(total));
  };
  run.outcome = workPrecisionReport(request, stop, heard);
  const ReportOutcome& outcome = run.outcome;
  if (outcome.status == ReportStatus::Interrupted) {
    run.code = kExitInterrupted;
    return run;
  }
  if (outcome.status == ReportStatus::NoReference) {
    error = QString::fromStdString(outcome.problem);
    return run;
  }
  if (outcome.end.shortened) {
    input.horizonNote += QStringLiteral("; moved to t = %1, an eighth of T2 before the "
                                        "predictability horizon of the start (%2)")
                             .arg(outcome.end.tEnd, 0, 'g', 10)
                             .arg(outcome.end.horizon, 0, 'g', 6);
  }
  input.tEnd = outcome.tEnd;
  input.referenceContacts = outcome.referenceContacts;
  input.referenceSeconds = outcome.referenceSeconds;
  const std::vector<WorkPrecisionPoint> points =
      resolved(outcome.points, comparisonResolution(outcome.tEnd, outcome.referencePeriod));
  PointsByMethod byMethod;
  for (const WorkPrecisionPoint& point : points) byMethod[point.setting.kind].push_back(point);
  run.csv = resultsCsv(points);
  run.markdown = reportMarkdown(input, outcome.end, *methods, byMethod, request.timing(), request.quick);
  run.code = kExitOk;
  if (!picturesAvailable()) progress(io, "report", "no pictures: the Python module draws none");
  if (!directory) return run;
  const QString& dir = *directory;
  run.code = 1;
  if (!writeAtomically(dir + "/results.csv", run.csv, error)) return run;
  QString pictures;
  if (picturesAvailable()) {
    if (!writePictures(dir, input, *methods, byMethod, error)) return run;
    pictures = "work_precision.svg/.png, convergence.svg/.png, ";
  }
  if (!writeAtomically(dir + "/report.md", run.markdown, error)) return run;
  progress(io, "report", QStringLiteral("wrote %1/{results.csv, %2report.md}").arg(dir, pictures));
  run.code = kExitOk;
  return run;
}

int runReport(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  return reportWithFiles(options, io, std::move(stop), error, true).code;
}

}  // namespace grazelab::cli
