// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The command line's arguments parsed and its command run, in process: the same for
// grazelab-cli and for the Python module (docs/design.md "Command line").
#include "cli_run.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>

#include "cli_input.h"
#include "cli_output.h"
#include "core/trust.h"
#include "family_command.h"
#include "map_command.h"
#include "modes_command.h"
#include "orbit_command.h"
#include "exit_codes.h"
#include "report_command.h"
#include "simulate_command.h"

namespace grazelab::cli {
namespace {

int fail(const Io& io, const QString& message) {
  std::fprintf(io.messages, "grazelab-cli: %s\n", qPrintable(message.simplified()));
  return kExitInvalidInput;
}

// The end of a command that writes files: one line for invalid input (exit 2), a note for an
// interrupt (130: nothing written), the reason of a failed write.
int ended(const Io& io, int code, const QString& error) {
  if (code == kExitInvalidInput) return fail(io, error);
  if (code == kExitInterrupted) {
    std::fprintf(io.messages, "grazelab-cli: interrupted: nothing written\n");
  } else if (code != 0) {
    std::fprintf(io.messages, "grazelab-cli: %s\n", qPrintable(error));
  }
  return code;
}

void write(const Io& io, const QByteArray& bytes) {
  std::fwrite(bytes.constData(), 1, bytes.size(), io.out);
}

template <typename S>
int info(const QCommandLineParser& parser, const Io& io) {
  const auto model = parseModel<S>(parser);
  if (!model.value) return fail(io, model.error);
  write(io, QByteArray::fromStdString(infoJson(*model.value)));
  return 0;
}

}  // namespace

int runCommandLine(const QStringList& commandLine, const Io& io, std::stop_token stop) {
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Exact event-driven simulation of a 2-dof chain against a rigid stop in 1:2 internal "
      "resonance.\nCommands: info (the model and its derived quantities), simulate (a run), "
      "report (every method against the exact solver: error against run time, --out DIR), "
      "stability (every method on stiff and extreme cases, --out DIR), map (a 2-D grid of runs "
      "reduced to summaries: --x, --y, --out PREFIX), merge (join a map's stripes: --out PREFIX "
      "PART1 ... PARTN), family --onepp (the 1IPP family: --out PREFIX), orbit (one periodic impacting orbit with its "
      "exact multipliers: --onepp --period T, or --impacts K --energy E --guess U1,V1), modes (the "
      "atlas of the chain's periodic impacting families up to --max-impacts K: --out PREFIX).");
  parser.addPositionalArgument("command", "info | simulate | report | stability | map | merge | family | orbit | modes");
  const QCommandLineOption help = parser.addHelpOption();
  const QCommandLineOption version = parser.addVersionOption();
  addOptions(parser);
  addReportOptions(parser);
  addMapOptions(parser);
  addOrbitOptions(parser);
  addModesOptions(parser);

  // `family --onepp` and `orbit --onepp` name the family: the option takes no period there
  QStringList arguments = commandLine;
  for (const QString& command : {QStringLiteral("family"), QStringLiteral("orbit")}) {
    if (!arguments.contains(command)) continue;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
      const bool bare = arguments[i] == "--onepp" &&
                        (i + 1 == arguments.size() || arguments[i + 1].startsWith("--") ||
                         arguments[i + 1] == command);
      if (bare) arguments[i] = "--onepp=" + command;
    }
  }
  if (!parser.parse(arguments)) return fail(io, parser.errorText());
  if (parser.isSet(help)) {
    write(io, parser.helpText().toUtf8());
    return 0;
  }
  if (parser.isSet(version)) {
    write(io, "grazelab-cli " + QCoreApplication::applicationVersion().toUtf8() + "\n");
    return 0;
  }
  const QStringList repeated = repeatedOptions(parser);
  if (!repeated.isEmpty()) {
    return fail(io, repeated.join(", ") + " given more than once: give each option once");
  }
  const QStringList positional = parser.positionalArguments();
  if (!positional.isEmpty() && positional.first() == "merge") {
    QString error;
    return ended(io, runMerge(parser, positional.mid(1), io, stop, error), error);
  }
  if (positional.size() != 1) {
    return fail(io, "expected one command: info, simulate, report, stability, map, merge, family, orbit or modes (see --help)");
  }
  const QString command = positional.first();
  if (command == "modes") {
    QString error;
    return ended(io, runModes(parser, io, stop, error), error);
  }
  if (command == "orbit") {
    QString error;
    const int code = runOrbit(parser, io, stop, error);
    if (code == kExitInvalidInput) return fail(io, error);
    return code;
  }
  const QStringList orbitOnly = orbitOnlyOptionsSet(parser);
  if (!orbitOnly.isEmpty()) return fail(io, orbitOnly.join(", ") + " only apply to 'orbit'");
  if (command == "map") {
    QString error;
    return ended(io, runMap(parser, io, stop, error), error);
  }
  if (command == "family") {
    QString error;
    return ended(io, runFamily(parser, io, stop, error), error);
  }
  const QStringList mapOnly = mapOnlyOptionsSet(parser);
  if (!mapOnly.isEmpty()) return fail(io, mapOnly.join(", ") + " only apply to 'map' (--count to 'family')");
  if (command == "report" || command == "stability") {
    QString error;
    const int code = command == "report" ? runReport(parser, io, stop, error)
                                         : runStability(parser, io, stop, error);
    if (code == kExitInvalidInput) return fail(io, error);
    if (code == kExitInterrupted) {
      std::fprintf(io.messages, "grazelab-cli: interrupted: nothing written\n");
    }
    if (code != 0 && !error.isEmpty()) std::fprintf(io.messages, "grazelab-cli: %s\n", qPrintable(error));
    return stop.stop_requested() ? kExitInterrupted : code;
  }
  const QStringList reportOnly = reportOnlyOptionsSet(parser);
  if (!reportOnly.isEmpty()) {
    return fail(io, reportOnly.join(", ") + " only apply to 'report' and 'stability'");
  }
  QString error;
  const auto precision = parsePrecisionOption(parser, error);
  if (!precision) return fail(io, error);
  const auto trust = parseTrustOption(parser, error);
  if (!trust) return fail(io, error);

  using grazelab::core::Precision;
  if (command == "info") {
    const QStringList extra = simulateOnlyOptionsSet(parser);
    if (!extra.isEmpty()) return fail(io, extra.join(", ") + " only apply to 'simulate'");
    switch (precision->fixed.value_or(Precision::Double)) {
      case Precision::Double:
        return info<double>(parser, io);
      case Precision::Long:
        return info<long double>(parser, io);
      case Precision::Quad:
        return info<grazelab::core::Quad>(parser, io);
    }
  }
  if (command == "simulate") {
    QString error;
    const int code = runSimulate(parser, *precision, *trust, io, stop, error);
    return code == kExitInvalidInput ? fail(io, error) : code;
  }
  return fail(io, QStringLiteral("unknown command '%1': use info, simulate, report, stability, map, merge, family, orbit or modes").arg(command));
}

}  // namespace grazelab::cli
