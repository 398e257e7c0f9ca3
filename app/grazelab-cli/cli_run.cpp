// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The command line's arguments parsed and its command run, in process: the same for
// grazelab-cli and for the Python module (docs/design.md "Command line").
#include "cli_run.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <vector>

#include "commands/bar_command.h"
#include "commands/chain_info.h"
#include "commands/family_command.h"
#include "commands/glo_set_command.h"
#include "commands/map_command.h"
#include "commands/modes_command.h"
#include "commands/orbit_command.h"
#include "commands/report_command.h"
#include "commands/stability_command.h"
#include "commands/simulate_command.h"
#include "core/solver/trust.h"
#include "exit_codes.h"
#include "io/cli_input.h"
#include "io/cli_output.h"
#include "io/json_value.h"

namespace grazelab::cli {
namespace {

int fail(const Io& io, const QString& message) {
  std::fprintf(io.messages, "grazelab-cli: %s\n", qPrintable(message.simplified()));
  return kExitInvalidInput;
}

// A command that failed otherwise (a file not written): its line
void failed(const Io& io, const QString& message) {
  std::fprintf(io.messages, "grazelab-cli: %s\n", qPrintable(message));
}

// The end of a command that writes files: one line for invalid input (exit 2), a note for an
// interrupt (130: nothing written), the reason of a failed write.
int ended(const Io& io, int code, const QString& error) {
  if (code == kExitInvalidInput) return fail(io, error);
  if (code == kExitInterrupted) {
    std::fprintf(io.messages, "grazelab-cli: interrupted: nothing written\n");
  } else if (code != 0) {
    failed(io, error);
  }
  return code;
}

void write(const Io& io, const QByteArray& bytes) {
  std::fwrite(bytes.constData(), 1, bytes.size(), io.out);
}

// `info`: the typed command (commands/chain_info.h), its document or its line
int info(const OptionValues& options, const Io& io, std::stop_token stop) {
  QString error;
  const std::optional<InfoRequest> request = readInfoRequest(options, error);
  if (!request) return fail(io, error);
  const InfoOutcome outcome = describeChain(options, *request, stop);
  if (outcome.status == InfoStatus::Interrupted) {
    std::fprintf(io.messages, "grazelab-cli: interrupted: nothing written\n");
    return kExitInterrupted;
  }
  if (outcome.status == InfoStatus::Refused) return fail(io, QString::fromStdString(outcome.problem));
  write(io, QByteArray::fromStdString(infoText(outcome)));
  return 0;
}

// What a command runs: its options, its operands (merge's parts), where it writes.
using Runner = std::function<int(const OptionValues&, const QStringList&, const Io&, std::stop_token)>;

// One command: its name, every option it takes (any other is refused before it runs), and how
// it runs.
struct Command {
  QString name;
  QStringList options;
  bool takesOperands = false;  ///< merge: the stripes to join
  Runner run;
  QString whyNot;  ///< said after a refused option: why the command takes none of the others
};

const QStringList kChain = {"m1", "m2", "k1", "gap", "k2", "branch"};
const QStringList kStart = {"glo", "onepp", "state", "perturb"};
const QStringList kMassChain = {"masses", "springs", "right-spring", "stop-mass", "frequencies", "design-branch"};

// a command that writes files: invalid input, interrupt and failed writes as `ended` says
Runner writesFiles(int (*command)(const OptionValues&, const Io&, std::stop_token, QString&)) {
  return [command](const OptionValues& options, const QStringList&, const Io& io, std::stop_token stop) {
    QString error;
    return ended(io, command(options, io, stop, error), error);
  };
}

int runReportOrStability(bool report, const OptionValues& options, const Io& io, std::stop_token stop) {
  QString error;
  const int code = report ? runReport(options, io, stop, error) : runStability(options, io, stop, error);
  if (code == kExitInvalidInput) return fail(io, error);
  if (code == kExitInterrupted) std::fprintf(io.messages, "grazelab-cli: interrupted: nothing written\n");
  if (code != 0 && !error.isEmpty()) failed(io, error);
  return stop.stop_requested() ? kExitInterrupted : code;
}

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"info", kChain + kMassChain + QStringList{"precision"}, false,
       [](const OptionValues& options, const QStringList&, const Io& io, std::stop_token stop) {
         return info(options, io, stop);
       },
       {}},
      {"simulate", kChain + kStart + kMassChain + QStringList{"glo-weights", "precision", "contacts", "t-end", "search-steps", "format", "trust", "sample-step", "sample-times"}, false,
       [](const OptionValues& options, const QStringList&, const Io& io, std::stop_token stop) {
         QString error;
         if (!options.isSet("masses") &&
             (options.isSet("glo-weights") ||
              std::any_of(kMassChain.begin(), kMassChain.end(), [&](const QString& name) { return options.isSet(name); }))) {
           return fail(io, "--springs, --right-spring, --stop-mass, --frequencies and --glo-weights describe a chain given by --masses");
         }
         const int code = runSimulate(options, io, stop, error);
         // a streamed run says what it wrote before the interrupt
         if (code == kExitInterrupted) {
           std::fprintf(io.messages, "grazelab-cli: interrupted: %s\n", error.isEmpty() ? "nothing written" : qPrintable(error));
         }
         return code == kExitInvalidInput ? fail(io, error) : code;
       },
       {}},
      {"report",
       kChain + kStart + kMassChain + QStringList{"glo-weights", "contacts", "t-end", "out", "methods", "quick"},
       false,
       [](const OptionValues& options, const QStringList&, const Io& io, std::stop_token stop) {
         return runReportOrStability(true, options, io, stop);
       },
       "the report runs every method, and every precision of the exact solver, itself"},
      {"stability", kMassChain + QStringList{"gap", "state", "onepp", "perturb", "glo-weights", "out", "methods", "quick"}, false,
       [](const OptionValues& options, const QStringList&, const Io& io, std::stop_token stop) {
         return runReportOrStability(false, options, io, stop);
       },
       "it runs its own list of cases (see matrix.md), or the cases of a chain given by --masses"},
      {"map", kChain + kStart + kMassChain + QStringList{"glo-weights", "precision", "contacts", "trust", "out", "x", "y", "threads", "shard", "picture"}, false,
       writesFiles(runMap), {}},
      {"merge", {"out"}, true,
       [](const OptionValues& options, const QStringList& parts, const Io& io, std::stop_token stop) {
         QString error;
         return ended(io, runMerge(options, parts, io, stop, error), error);
       },
       "the parts say what the map is"},
      {"family", kChain + kMassChain + QStringList{"precision", "onepp", "out", "count", "impacts", "energy", "period",
                                                   "guess", "energy-range"}, false,
       [](const OptionValues& options, const QStringList&, const Io& io, std::stop_token stop) {
         QString error;
         if (std::any_of(kMassChain.begin(), kMassChain.end(), [&](const QString& name) { return options.isSet(name); }) &&
             !options.isSet("masses")) {
           return fail(io, "--springs, --right-spring, --stop-mass and --frequencies describe a chain given by --masses");
         }
         // a kIPP family from an orbit, of any chain, written as an atlas of one family
         if (options.isSet("impacts")) return ended(io, impactsFamilyWithFiles(options, io, stop, error, true).code, error);
         // (the note's chain, however written, is the note's family: its engine, its files)
         return ended(io, runFamily(options, io, stop, error), error);
       },
       {}},
      {"orbit", kChain + kMassChain + QStringList{"precision", "onepp", "format", "period", "impacts", "energy", "guess"}, false,
       [](const OptionValues& options, const QStringList&, const Io& io, std::stop_token stop) {
         QString error;
         const int code = runOrbit(options, io, stop, error);
         return code == kExitInvalidInput ? fail(io, error) : code;
       },
       {}},
      {"modes", kChain + kMassChain + QStringList{"precision", "out", "max-impacts", "energy-range"}, false, writesFiles(runModes), {}},
      {"bar", QStringList{"bar", "speed", "masses-count", "stop-end", "each-impact"}, false,
       [](const OptionValues& options, const QStringList&, const Io& io, std::stop_token stop) {
         QString error;
         const int code = runBar(options, io, stop, error);
         return code == kExitInvalidInput ? fail(io, error) : code;
       },
       "a bar is its own chain: --bar E,rho,S,L lumped into --masses-count N masses"},
      {"glo-set", kChain + kMassChain + QStringList{"precision", "directions", "out"}, false,
       [](const OptionValues& options, const QStringList&, const Io& io, std::stop_token stop) {
         QString error;
         const int code = runGloSet(options, io, stop, error);
         if (code == kExitInterrupted) std::fprintf(io.messages, "grazelab-cli: interrupted: nothing written\n");
         return code == kExitInvalidInput ? fail(io, error) : code;
       },
       {}},
  };
  return table;
}

// The options given that `command` does not take, with the commands that do take them.
QString optionsRefused(const Command& command, const QStringList& given) {
  QStringList refused;
  QStringList owners;
  for (const QString& name : given) {
    if (name == "help" || name == "version" || command.options.contains(name) || refused.contains("--" + name)) continue;
    refused << "--" + name;
    for (const Command& other : commands()) {
      if (other.options.contains(name) && !owners.contains("'" + other.name + "'")) owners << "'" + other.name + "'";
    }
  }
  if (refused.isEmpty()) return {};
  QString message = QStringLiteral("%1 %2 not apply to '%3' (only to %4)")
                        .arg(refused.join(", "), refused.size() == 1 ? "does" : "do", command.name, owners.join(", "));
  if (!command.whyNot.isEmpty()) message += ": " + command.whyNot;
  return message;
}

const QString kCommandNames = "info, simulate, report, stability, map, merge, family, orbit, modes, glo-set or bar";

// Runs the command `name` with the parsed command line's `options`, `given` the names of the
// options given (any the command does not take is refused) and `operands` merge's parts.
int runCommand(const QString& name, const OptionValues& options, const QStringList& given, const QStringList& operands,
               const Io& io, std::stop_token stop) {
  const auto command = std::find_if(commands().begin(), commands().end(), [&](const Command& c) { return c.name == name; });
  if (command == commands().end()) {
    return fail(io, QStringLiteral("unknown command '%1': use %2").arg(name, kCommandNames));
  }
  if (!operands.isEmpty() && !command->takesOperands) {
    return fail(io, "expected one command: " + kCommandNames + " (see --help)");
  }
  const QString refused = optionsRefused(*command, given);
  if (!refused.isEmpty()) return fail(io, refused);
  return command->run(options, operands, io, stop);
}

}  // namespace

int runCommandLine(const QStringList& commandLine, const Io& io, std::stop_token stop) {
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Exact event-driven simulation of a chain of masses and springs against a rigid stop: the "
      "note's two masses in 1:2 internal resonance (--m1 --m2 --k1 --k2 --branch --gap), or N "
      "masses in any resonance (--masses, --springs or --frequencies).\nCommands: info (the model "
      "and its derived quantities), simulate (a run), "
      "report (every method against the exact solver: error against run time, --out DIR), "
      "stability (every method on stiff and extreme cases, --out DIR), map (a 2-D grid of runs "
      "reduced to summaries: --x, --y, --out PREFIX), merge (join a map's stripes: --out PREFIX "
      "PART1 ... PARTN), family --onepp (the 1IPP family: --out PREFIX), orbit (one periodic impacting orbit with its "
      "exact multipliers: --onepp --period T, or --impacts K --energy E --guess U1,V1), modes (the "
      "atlas of the chain's periodic impacting families up to --max-impacts K: --out PREFIX), glo-set "
      "(which combinations of a resonant chain's GLOMs graze: an interval for two modes, a region for three), bar (an "
      "elastic bar thrown at a wall, lumped into N masses for each --masses-count, computed exactly, against the "
      "continuum's 2L/c and E S v0 / c).\n"
      "A command refuses the options it does not take.");
  parser.addPositionalArgument("command", "info | simulate | report | stability | map | merge | family | orbit | modes | glo-set | bar");
  const QCommandLineOption help = parser.addHelpOption();
  const QCommandLineOption version = parser.addVersionOption();
  addOptions(parser);
  addReportOptions(parser);
  addMapOptions(parser);
  addOrbitOptions(parser);
  addModesOptions(parser);
  addBarOptions(parser);

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
  if (positional.isEmpty()) return fail(io, "expected one command: " + kCommandNames + " (see --help)");
  return runCommand(positional.first(), parser, parser.optionNames(), positional.mid(1), io, stop);
}

}  // namespace grazelab::cli
