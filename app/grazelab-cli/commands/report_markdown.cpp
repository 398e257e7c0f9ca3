// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// report.md: the problem, the horizon, who reaches which accuracy at what cost, the slopes, the
// penalty method against k_c, the speed ratios.
#include <algorithm>
#include <cmath>

#include "io/output_files.h"
#include "commands/report_internal.h"
#include "commands/report_support.h"

namespace grazelab::cli::report {
namespace {

using core::methods::ErrorMeasure;

QString cell(const WorkPrecisionPoint* p) {
  if (p == nullptr) return "—";
  return parameterText(p->setting) + ", " + humanSeconds(p->secondsMin);
}

}  // namespace

QByteArray reportMarkdown(const ReportInput& input, const core::methods::ComparisonEnd& end,
                          const std::vector<MethodKind>& methods,
                          const std::map<MethodKind, std::vector<WorkPrecisionPoint>>& byMethod,
                          const core::methods::TimingPolicy& timing, bool quick) {
  QString md;
  md += "# GrazeLab work-precision report\n\n";
  md += QStringLiteral("Written by %1%2. Every error is measured against the exact solver in "
                       "binary128 (docs/model.md section 8).\n\n")
            .arg(versionString(), quick ? " with --quick (fewer settings and runs)" : "");
  md += "## Problem\n\n";
  md += QStringLiteral("- Chain: %1; T2 = %2.\n").arg(input.chainLine).arg(input.period, 0, 'g', 10);
  md += QStringLiteral("- Start: %1: %2.\n").arg(input.startDescription, input.startLine);
  md += QStringLiteral("- Horizon: %1 (%2 T2), %3 contacts in the reference.\n")
            .arg(input.horizonNote)
            .arg(input.tEnd / input.period, 0, 'g', 4)
            .arg(input.referenceContacts);
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
            .arg(humanSeconds(input.referenceSeconds));
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
  md += "## Contacts missed and invented\n\n";
  md += QStringLiteral("The reference makes %1 contacts up to t_end. A method's contact is matched to the "
                       "reference's within a quarter of T2 (and half the distance to the neighbouring "
                       "contacts); a reference contact left without one is missed, a method's contact "
                       "left without one is extra.\n\n")
            .arg(input.referenceContacts);
  md += "| method | settings that miss a contact | most missed (setting) | settings with an extra contact | "
        "most extra (setting) | missed at the finest setting |\n|---|---|---|---|---|---|\n";
  for (MethodKind kind : methods) {
    const auto& points = byMethod.at(kind);
    int missing = 0, inventing = 0;
    const WorkPrecisionPoint* mostMissed = nullptr;
    const WorkPrecisionPoint* mostExtra = nullptr;
    for (const WorkPrecisionPoint& p : points) {
      if (p.errors.missed > 0) ++missing;
      if (p.errors.extra > 0) ++inventing;
      if (p.errors.missed > 0 && (mostMissed == nullptr || p.errors.missed > mostMissed->errors.missed)) mostMissed = &p;
      if (p.errors.extra > 0 && (mostExtra == nullptr || p.errors.extra > mostExtra->errors.extra)) mostExtra = &p;
    }
    auto worst = [](const WorkPrecisionPoint* p, std::int64_t count) {
      return p == nullptr ? QStringLiteral("0") : QStringLiteral("%1 (%2)").arg(count).arg(parameterText(p->setting));
    };
    md += QStringLiteral("| %1 | %2 of %3 | %4 | %5 of %3 | %6 | %7 |\n")
              .arg(name(kind))
              .arg(missing)
              .arg(points.size())
              .arg(worst(mostMissed, mostMissed ? mostMissed->errors.missed : 0))
              .arg(inventing)
              .arg(worst(mostExtra, mostExtra ? mostExtra->errors.extra : 0))
              .arg(points.empty() ? QStringLiteral("—") : QString::number(points.back().errors.missed));
  }
  md += "\nA run that stopped early is judged up to where it stopped.\n\n";
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
        "amplifies each step's error by a factor that depends on its direction (docs/model.md "
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
  md += "\n## Files\n\n- results.csv: one row per run (setting).\n";
  if (picturesAvailable()) {
    md += "- work_precision.svg/.png: state error against run time.\n"
          "- convergence.svg/.png: contact-time error against the knob (h / T2, rtol, eps, k1 / k_c).\n";
  } else {
    md += "- no pictures: the Python module draws none (grazelab-cli report draws "
          "work_precision and convergence).\n";
  }
  return md.toUtf8();
}


}  // namespace grazelab::cli::report
