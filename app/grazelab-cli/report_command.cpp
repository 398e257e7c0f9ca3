// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli report`: every method on one problem, timed and measured against the binary128
// exact run, written as a CSV, two pictures and a Markdown report (issue 8).
#include "report_command.h"

#include <QCommandLineParser>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <map>

#include "cli_input.h"
#include "core/methods/work_precision.h"
#include "report_support.h"
#if GRAZELAB_CLI_PICTURES
#include "ui/export.h"
#include "ui/plots/log_log_chart.h"
#endif

namespace grazelab::cli {
namespace {

using core::methods::ErrorMeasure;
using core::methods::MethodKind;
using core::methods::WorkPrecisionPoint;

constexpr double kDefaultPeriods = 200;
const core::State kDefaultPush{0, 0, 0.05, -0.05};

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
[[maybe_unused]] double fineness(const core::methods::MethodSetting& setting, double period, double k1) {
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

struct ReportInput {
  core::methods::Task task;
  QString startDescription;
  QString horizonNote;
  double period = 0;
};

/// The task of the report from the command line: the default problem unless told otherwise.
std::optional<ReportInput> parseReportInput(const QCommandLineParser& parser, QString& error) {
  for (const char* option : {"format", "trust", "precision"}) {
    if (parser.isSet(option)) {
      error = QStringLiteral("--%1 does not apply here (the report runs every method and every "
                             "precision of the exact solver itself)").arg(option);
      return std::nullopt;
    }
  }
  if (parser.isSet("t-end") && parser.isSet("contacts")) {
    error = "give --t-end or --contacts, not both";
    return std::nullopt;
  }
  Parsed<RunInput<double>> run = parseRun<double>(parser);
  if (!run.value) {
    error = run.error;
    return std::nullopt;
  }
  ReportInput input;
  core::methods::Task& task = input.task;
  task.model = run.value->model.model;
  task.start = run.value->request.initial;
  input.startDescription = run.value->initialDescription;
  const bool startGiven = parser.isSet("glo") || parser.isSet("onepp") || parser.isSet("state") ||
                          parser.isSet("perturb");
  if (!startGiven) {
    task.start = task.start + kDefaultPush;
    input.startDescription += ", pushed by (0, 0, 0.05, -0.05) (the default problem)";
  }
  const core::Chain<double>& chain = run.value->model.chain;
  input.period = core::twoPi<double>() / chain.omegaSlow;
  task.needs.events = true;
  if (parser.isSet("t-end")) {
    task.tEnd = run.value->request.tEnd;
    if (!(task.tEnd > 0) || !std::isfinite(task.tEnd)) {
      error = "--t-end must be a positive time for a report";
      return std::nullopt;
    }
    input.horizonNote = QStringLiteral("t_end = %1 (given)").arg(task.tEnd);
  } else if (parser.isSet("contacts")) {
    // the horizon ends halfway between the N-th and the next contact of the exact run, so
    // that no method is judged at a contact instant
    const std::int64_t contacts = run.value->request.maxContacts;
    if (contacts < 1) {
      error = "--contacts must be at least 1 for a report";
      return std::nullopt;
    }
    core::Request request;
    request.initial = task.start;
    request.maxContacts = contacts + 1;
    request.needs.events = false;
    std::vector<double> times;
    request.onEvent = [&times](const core::Event& e) {
      if (core::isContact(e.type)) times.push_back(e.t);
    };
    core::simulate(task.model, request);
    if (std::int64_t(times.size()) < contacts) {
      error = QStringLiteral("--contacts: this start makes only %1 contacts").arg(times.size());
      return std::nullopt;
    }
    const double nth = times[std::size_t(contacts - 1)];
    task.tEnd = times.size() > std::size_t(contacts) ? 0.5 * (nth + times[std::size_t(contacts)])
                                                     : nth + 0.5 * input.period;
    input.horizonNote = QStringLiteral("t_end = %1, halfway between contact %2 and the next")
                            .arg(task.tEnd, 0, 'g', 10)
                            .arg(contacts);
  } else {
    task.tEnd = kDefaultPeriods * input.period;
    input.horizonNote = QStringLiteral("t_end = %1 (the default, 200 T2)").arg(task.tEnd, 0, 'g', 10);
  }
  return input;
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

[[maybe_unused]] QJsonObject metadata(const ReportInput& input) {
  const core::Model& m = input.task.model;
  QJsonObject model{{"m1", m.m1}, {"m2", m.m2}, {"k1", m.k1}, {"k2", m.k2}, {"gap", m.gap}};
  if (m.design) model["branch"] = QString::fromUtf8(core::toString(*m.design).data());
  const core::State& s = input.task.start;
  return QJsonObject{{"generator", versionString()},
                     {"model", model},
                     {"start", QJsonArray{s.u1, s.u2, s.v1, s.v2}},
                     {"t_end", input.task.tEnd}};
}

#if GRAZELAB_CLI_PICTURES
bool savePictures(ui::LogLogChart& chart, const QString& stem, const QByteArray& json,
                  QString& error) {
  chart.resize(1200, 760);
  for (const char* suffix : {".svg", ".png"}) {
    QString reason;
    if (!ui::saveSnapshot(&chart, stem + suffix, json, &reason)) {
      error = reason;
      return false;
    }
  }
  return true;
}

/// One curve per method, and a second one for the penalty method's tolerance sweep.
std::vector<std::pair<MethodKind, bool>> curveKeys(
    const std::vector<MethodKind>& methods,
    const std::map<MethodKind, std::vector<WorkPrecisionPoint>>& byMethod) {
  std::vector<std::pair<MethodKind, bool>> keys;
  for (MethodKind kind : methods) {
    keys.push_back({kind, false});
    const auto& points = byMethod.at(kind);
    if (std::any_of(points.begin(), points.end(),
                    [](const auto& p) { return p.setting.penaltyToleranceSweep; })) {
      keys.push_back({kind, true});
    }
  }
  return keys;
}

/// The two pictures: the same chart class as the explorer's Accuracy scene.
bool writePictures(const QString& dir, const ReportInput& input,
                   const std::vector<MethodKind>& methods,
                   const std::map<MethodKind, std::vector<WorkPrecisionPoint>>& byMethod,
                   QString& error) {
  using core::methods::RunStatus;
  const QByteArray json = QJsonDocument(metadata(input)).toJson(QJsonDocument::Compact);
  ui::LogLogChart work("Error against run time", "run time [s] (minimum of repeated runs)",
                       "state error at t_end");
  ui::LogLogChart convergence("Convergence", "h / T2, rtol, eps or k1 / k_c (finer to the left)",
                              "contact-time error / T2");
  for (const auto& [kind, toleranceSweep] : curveKeys(methods, byMethod)) {
    std::vector<WorkPrecisionPoint> points = byMethod.at(kind);
    std::sort(points.begin(), points.end(),
              [](const auto& a, const auto& b) { return a.secondsMin < b.secondsMin; });
    const QString label = toleranceSweep ? name(kind) + " (rtol, k_c = 1e12 k1)" : name(kind);
    ui::LogLogCurve curve{label, {}};
    ui::LogLogCurve order{label, {}};
    for (const WorkPrecisionPoint& p : points) {
      if (p.status != RunStatus::Completed || p.setting.penaltyToleranceSweep != toleranceSweep) continue;
      curve.points.push_back({p.secondsMin, p.errors.state});
      // an error of 0 (binary128 against binary128, seen in double) tells nothing about order
      if (p.errors.contactTime > 0) {
        order.points.push_back({fineness(p.setting, input.period, input.task.model.k1), p.errors.contactTime});
      }
    }
    std::sort(order.points.begin(), order.points.end(),
              [](const QPointF& a, const QPointF& b) { return a.x() < b.x(); });
    const auto slope = core::methods::fittedSlope(byMethod.at(kind), ErrorMeasure::ContactTime);
    if (slope && !toleranceSweep) order.name += QStringLiteral(" (slope %1)").arg(slope->value, 0, 'f', 2);
    const int index = work.addCurve(curve.name);
    for (const QPointF& p : curve.points) work.addPoint(index, p);
    const int orderIndex = convergence.addCurve(order.name);
    for (const QPointF& p : order.points) convergence.addPoint(orderIndex, p);
  }
  return savePictures(work, dir + "/work_precision", json, error) &&
         savePictures(convergence, dir + "/convergence", json, error);
}
#endif

QString cell(const WorkPrecisionPoint* p) {
  if (p == nullptr) return "—";
  return parameterText(p->setting) + ", " + humanSeconds(p->secondsMin);
}

QByteArray reportMarkdown(const ReportInput& input, const core::methods::ComparisonEnd& end,
                          const core::methods::Reference& reference,
                          const std::vector<MethodKind>& methods,
                          const std::map<MethodKind, std::vector<WorkPrecisionPoint>>& byMethod,
                          const core::methods::TimingPolicy& timing, bool quick) {
  const core::Model& m = input.task.model;
  const core::State& s = input.task.start;
  QString md;
  md += "# GrazeLab work-precision report\n\n";
  md += QStringLiteral("Written by %1%2. Every error is measured against the exact solver in "
                       "binary128 (MODEL.md section 8).\n\n")
            .arg(versionString(), quick ? " with --quick (fewer settings and runs)" : "");
  md += "## Problem\n\n";
  md += QStringLiteral("- Chain: m1 = %1, m2 = %2, k1 = %3, k2 = %4%5, gap d = %6; T2 = %7.\n")
            .arg(m.m1).arg(m.m2).arg(m.k1).arg(m.k2, 0, 'g', 17)
            .arg(m.design ? QStringLiteral(" (1:2 design, %1 branch)").arg(core::toString(*m.design).data())
                          : QStringLiteral(" (as given)"))
            .arg(m.gap).arg(input.period, 0, 'g', 10);
  md += QStringLiteral("- Start: %1: (u1, u2, v1, v2) = (%2, %3, %4, %5).\n")
            .arg(input.startDescription)
            .arg(s.u1, 0, 'g', 17).arg(s.u2, 0, 'g', 17).arg(s.v1, 0, 'g', 17).arg(s.v2, 0, 'g', 17);
  md += QStringLiteral("- Horizon: %1 (%2 T2), %3 contacts in the reference.\n")
            .arg(input.horizonNote)
            .arg(input.task.tEnd / input.period, 0, 'g', 4)
            .arg(reference.run.result.cost.contacts);
  md += QStringLiteral("- Predictability horizon of the start (trust of the exact double run, %1): "
                       "t = %2 (%3 T2); verdict %4, estimated state error %5 at t_end. %6\n")
            .arg(QString::fromStdString(end.trust.horizonMethod))
            .arg(end.horizon, 0, 'g', 4)
            .arg(end.horizon / input.period, 0, 'g', 4)
            .arg(core::toString(end.trust.verdict).data())
            .arg(scientific(end.trust.stateError, 2))
            .arg(end.shortened
                     ? QStringLiteral("The horizon asked for goes past it: the end was moved before it.")
                     : QStringLiteral("The comparison stays inside it."));
  md += QStringLiteral("- Reference: the exact solver in binary128 on the chain scaled 3x in length, "
                       "5x in mass and 1/sqrt(3) in time (other roundings, same physics), %1.\n")
            .arg(humanSeconds(reference.seconds));
  md += QStringLiteral("- Errors: state at t_end, max of |du| / d and |dv| / (w1 d); contact "
                       "times / T2 over contacts matched one to one; missed and extra contacts "
                       "counted. Timing: minimum and median of %1 runs per setting (fewer once "
                       "%2 s are spent; a short run repeated until %3 s are spent), one core of "
                       "this machine.\n\n")
            .arg(timing.runs).arg(timing.capSeconds).arg(timing.minSeconds);

  md += "## Settings\n\n";
  md += "| method | settings | completed | run time, fastest to slowest | decades spanned |\n|---|---|---|---|---|\n";
  for (MethodKind kind : methods) {
    const auto& points = byMethod.at(kind);
    double fastest = 0, slowest = 0;
    int completed = 0;
    for (const WorkPrecisionPoint& p : points) {
      if (p.status != core::methods::RunStatus::Completed) continue;
      fastest = completed == 0 ? p.secondsMin : std::min(fastest, p.secondsMin);
      slowest = std::max(slowest, p.secondsMin);
      ++completed;
    }
    md += QStringLiteral("| %1 | %2 | %3 | %4 | %5 |\n")
              .arg(name(kind))
              .arg(points.size())
              .arg(completed)
              .arg(completed > 0 ? humanSeconds(fastest) + " … " + humanSeconds(slowest) : "—")
              .arg(completed > 1 ? QString::number(std::log10(slowest / fastest), 'f', 1) : "—");
  }
  md += "\nThe exact solver's only knob is its precision (three settings). CVODE's and the "
        "penalty method's loose settings cannot be much cheaper than their tight ones here: "
        "every impact restarts the integrator at order 1 with a small first step.\n\n";
  md += "## Which method reaches which state error, and at what cost\n\n";
  md += "The cheapest setting whose state error at t_end is at most the target, with its run time (minimum).\n\n";
  md += "| method | 1e-3 | 1e-6 | 1e-9 | 1e-12 |\n|---|---|---|---|---|\n";
  for (MethodKind kind : methods) {
    const auto& points = byMethod.at(kind);
    md += "| " + name(kind);
    for (double target : {1e-3, 1e-6, 1e-9, 1e-12}) {
      md += " | " + cell(core::methods::cheapestReaching(points, target));
    }
    md += " |\n";
  }

  md += "\n## Convergence\n\n";
  md += "Least-squares slopes of log(error) against log(h), log(rtol), log(eps) or log(1/k_c), over the "
        "settings that completed with every contact matched and an error between 1e-13 and 1e-2. "
        "The contact-time error is the order measure: the end state of this sensitive motion "
        "amplifies each step's error by a factor that depends on its direction (MODEL.md "
        "section 6), so its slope scatters (it is given beside it).\n\n";
  md += "| method | knob | slope (contact times) | slope (end state) | settings in the fit |\n|---|---|---|---|---|\n";
  for (MethodKind kind : methods) {
    const auto& points = byMethod.at(kind);
    const auto time = core::methods::fittedSlope(points, ErrorMeasure::ContactTime);
    const auto state = core::methods::fittedSlope(points, ErrorMeasure::State);
    const std::string_view knob = core::methods::parameterName(kind);
    md += QStringLiteral("| %1 | %2 | %3 | %4 | %5 |\n")
              .arg(name(kind), kind == MethodKind::Penalty ? "1/k_c" : QString::fromUtf8(knob.data()))
              .arg(time ? QString::number(time->value, 'f', 2)
                   : kind == MethodKind::Exact ? "— (its errors are at the resolution of double)"
                                               : "— (fewer than 3 settings qualify)")
              .arg(state ? QString::number(state->value, 'f', 2) : "—")
              .arg(time ? time->points : 0);
  }

  if (byMethod.count(MethodKind::Penalty)) {
    md += QStringLiteral("\n## The penalty method against its stiffness (CVODE BDF, rtol %1)\n\n")
              .arg(core::methods::kPenaltyReportRtol);
    md += "| k_c | run time | steps | state error | contact-time error / T2 | status |\n|---|---|---|---|---|---|\n";
    for (const WorkPrecisionPoint& p : byMethod.at(MethodKind::Penalty)) {
      if (p.setting.penaltyToleranceSweep) continue;
      md += QStringLiteral("| %1 | %2 | %3 | %4 | %5 | %6 |\n")
                .arg(p.setting.value, 0, 'g', 3)
                .arg(humanSeconds(p.secondsMin))
                .arg(p.steps)
                .arg(scientific(p.errors.state), scientific(p.errors.contactTime))
                .arg(core::methods::toString(p.status).data());
    }
    md += "\nThe contact lasts about pi sqrt(m2 / k_c); CVODE BDF restarts at each switch of the "
          "force, so its step count hardly grows with k_c, while the modelling error "
          "(the contact's length) falls like k_c^(-1/2) until the tolerance takes over. Its "
          "cost is set by the tolerance instead (the rows with parameter rtol, at k_c = 1e12 k1).\n";
  }

  if (byMethod.count(MethodKind::Exact)) {
    const WorkPrecisionPoint* exact = nullptr;
    for (const WorkPrecisionPoint& p : byMethod.at(MethodKind::Exact)) {
      if (p.setting.precision == core::Precision::Double) exact = &p;
    }
    if (exact != nullptr && exact->status == core::methods::RunStatus::Completed) {
      md += "\n## Speed of the exact solver at equal accuracy\n\n";
      md += QStringLiteral("The exact solver in double: %1, state error %2. Each method's time "
                           "to reach a state error (log-log interpolation between its settings), "
                           "and how many times longer it takes than the exact solver.\n\n")
                .arg(humanSeconds(exact->secondsMin), scientific(exact->errors.state, 2));
      md += "| method | time to 1e-6 | ratio | time to 1e-8 | ratio |\n|---|---|---|---|---|\n";
      double best8 = 0, best6 = 0;
      QString best8Name, best6Name;
      for (MethodKind kind : methods) {
        if (kind == MethodKind::Exact) continue;
        const auto& points = byMethod.at(kind);
        const auto t6 = core::methods::secondsToReach(points, 1e-6);
        const auto t8 = core::methods::secondsToReach(points, 1e-8);
        md += QStringLiteral("| %1 | %2 | %3 | %4 | %5 |\n")
                  .arg(name(kind))
                  .arg(t6 ? humanSeconds(*t6) : "not reached")
                  .arg(t6 ? QString::number(*t6 / exact->secondsMin, 'f', 0) + "x" : "—")
                  .arg(t8 ? humanSeconds(*t8) : "not reached")
                  .arg(t8 ? QString::number(*t8 / exact->secondsMin, 'f', 0) + "x" : "—");
        if (t8 && (best8Name.isEmpty() || *t8 < best8)) {
          best8 = *t8;
          best8Name = name(kind);
        }
        if (t6 && (best6Name.isEmpty() || *t6 < best6)) {
          best6 = *t6;
          best6Name = name(kind);
        }
      }
      md += "\n";
      if (!best8Name.isEmpty()) {
        md += QStringLiteral("**At a state error of 1e-8 the exact solver is %1x faster than the "
                             "best other method (%2, %3).**\n")
                  .arg(best8 / exact->secondsMin, 0, 'f', 0)
                  .arg(best8Name, humanSeconds(best8));
      } else if (!best6Name.isEmpty()) {
        md += QStringLiteral("**No other method reaches a state error of 1e-8 within its settings "
                             "and budget. At 1e-6 the exact solver is %1x faster than the best "
                             "other method (%2, %3).**\n")
                  .arg(best6 / exact->secondsMin, 0, 'f', 0)
                  .arg(best6Name, humanSeconds(best6));
      } else {
        md += "**No other method reaches a state error of 1e-6 within its settings and budget.**\n";
      }
    }
  }

  md += "\n## What the methods do at a tangency\n\n"
        "- moreau-jean, moreau-jean-theta1, schatzman-paoli: the contact is active when the "
        "predicted gap closes; a graze that stays within a step's reach of the stop may get an "
        "impulse (an invented impact) or none (a missed contact), as the step falls.\n"
        "- dopri5-events: only a sign change of u2 - d at the end of an accepted step is seen; "
        "a touch inside one step is missed, a crossing located with v2 <= 0 is recorded as a "
        "grazing and the flight goes on.\n"
        "- cvode-adams, cvode-bdf: CVODE's root finding sees sign changes only, the same as "
        "above; a root function that is zero at a restart is inactive until it moves away, so "
        "a start pressed onto the stop slides through it (the run stops and says so).\n"
        "- penalty: a touch is a short, shallow contact with the spring.\n"
        "- exact: grazing is a double root of the contact polynomial, decided within rounding.\n";
  md += "\n## Files\n\n- results.csv: one row per run (setting).\n"
        "- work_precision.svg/.png: state error against run time.\n"
        "- convergence.svg/.png: contact-time error against the knob (h / T2, rtol, eps, k1 / k_c).\n";
  return md.toUtf8();
}

}  // namespace

void addReportOptions(QCommandLineParser& parser) {
  parser.addOptions({
      {"out", "report, stability: the directory to write into (created if missing).", "DIR"},
      {"methods", "report, stability: the methods to run, comma-separated (default: all): exact, "
                  "moreau-jean, moreau-jean-theta1, schatzman-paoli, dopri5-events, cvode-adams, "
                  "cvode-bdf, penalty.", "list"},
      {"quick", "report, stability: fewer settings and runs (seconds instead of minutes)."},
  });
}

QStringList reportOnlyOptionsSet(const QCommandLineParser& parser) {
  QStringList set;
  for (const char* option : {"out", "methods", "quick"}) {
    if (parser.isSet(option)) set << QStringLiteral("--%1").arg(option);
  }
  return set;
}

int runReport(const QCommandLineParser& parser, std::stop_token stop, QString& error) {
  using namespace core::methods;
  const auto methods = parseMethodsOption(parser, error);
  if (!methods) return kExitInvalidInput;
  auto input = parseReportInput(parser, error);
  if (!input) return kExitInvalidInput;
  const auto directory = prepareOutputDirectory(parser, error);
  if (!directory) return kExitInvalidInput;
  const bool quick = parser.isSet("quick");
  const TimingPolicy timing = quick ? TimingPolicy{2, 0.5, 0.05, 1000} : TimingPolicy{5, 3.0, 0.2, 1000};
  WorkBudget budget;
  budget.maxSteps = 1'000'000'000;
  budget.maxSeconds = quick ? 5 : 60;
  Task& task = input->task;

  progress("report", QStringLiteral("estimating the predictability horizon of the start"));
  const ComparisonEnd end = comparisonEnd(task, stop);
  if (end.shortened) {
    input->horizonNote += QStringLiteral("; moved to t = %1, an eighth of T2 before the "
                                         "predictability horizon of the start (%2)")
                              .arg(end.tEnd, 0, 'g', 10)
                              .arg(end.horizon, 0, 'g', 6);
    task.tEnd = end.tEnd;
  }
  progress("report", QStringLiteral("binary128 reference to t = %1 (%2 T2)")
                         .arg(task.tEnd, 0, 'g', 6).arg(task.tEnd / input->period, 0, 'g', 4));
  const Reference reference = makeReference(task, budget, stop);
  if (stop.stop_requested()) return kExitInterrupted;
  if (reference.run.status != RunStatus::Completed) {
    error = "no trustworthy reference for this problem: " + QString::fromStdString(reference.run.reason);
    return kExitInvalidInput;
  }

  std::vector<std::pair<MethodKind, MethodSetting>> plan;
  for (MethodKind kind : *methods) {
    for (const MethodSetting& setting : reportSettings(kind, input->period, task.model.k1, quick)) {
      plan.push_back({kind, setting});
    }
  }
  std::map<MethodKind, std::vector<WorkPrecisionPoint>> byMethod;
  std::vector<WorkPrecisionPoint> all;
  int done = 0;
  for (const auto& [kind, setting] : plan) {
    WorkPrecisionPoint point = measurePoint(task, reference, setting, budget, timing, stop);
    if (stop.stop_requested()) return kExitInterrupted;
    ++done;
    progress("report", QStringLiteral("[%1/%2] %3 %4: %5, state error %6%7")
                           .arg(done).arg(plan.size())
                           .arg(name(kind), parameterText(setting), humanSeconds(point.secondsMin))
                           .arg(scientific(point.errors.state, 2).isEmpty() ? "—" : scientific(point.errors.state, 2))
                           .arg(point.status == RunStatus::Completed ? QString()
                                                                     : " (" + QString::fromStdString(point.reason) + ")"));
    byMethod[kind].push_back(point);
    all.push_back(point);
  }

  const QByteArray csv = resultsCsv(all);
  const QByteArray md =
      reportMarkdown(*input, end, reference, *methods, byMethod, timing, quick);
  const QString dir = *directory;
  if (!writeAtomically(dir + "/results.csv", csv, error)) return 1;
#if GRAZELAB_CLI_PICTURES
  if (!writePictures(dir, *input, *methods, byMethod, error)) return 1;
  const QString pictures = "work_precision.svg/.png, convergence.svg/.png, ";
#else
  const QString pictures;
  progress("report", "this build has no explorer (GRAZELAB_BUILD_UI=OFF): no pictures");
#endif
  if (!writeAtomically(dir + "/report.md", md, error)) return 1;
  progress("report", QStringLiteral("wrote %1/{results.csv, %2report.md}").arg(dir, pictures));
  return kExitOk;
}

}  // namespace grazelab::cli
