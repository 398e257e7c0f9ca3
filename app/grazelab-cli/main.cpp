// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// grazelab-cli: `info` and `simulate` (DESIGN.md "Command line"). Exit 0 on success, 2 on
// invalid input with one line on stderr and nothing on stdout.
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>

#include "cli_input.h"
#include "cli_output.h"
#include "core/modes.h"
#include "core/simulate.h"

namespace {

constexpr int kInvalidInput = 2;

int fail(const QString& message) {
  std::fprintf(stderr, "grazelab-cli: %s\n", qPrintable(message.simplified()));
  return kInvalidInput;
}

void write(const QByteArray& bytes) { std::fwrite(bytes.constData(), 1, bytes.size(), stdout); }

}  // namespace

int main(int argc, char* argv[]) {
  QCoreApplication app(argc, argv);
  QCoreApplication::setApplicationName("grazelab-cli");
  QCoreApplication::setApplicationVersion("0.1.0");

  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Exact event-driven simulation of a 2-dof chain against a rigid stop in 1:2 internal "
      "resonance.\nCommands: info (the model and its derived quantities), simulate (a run).");
  parser.addPositionalArgument("command", "info | simulate");
  const QCommandLineOption help = parser.addHelpOption();
  const QCommandLineOption version = parser.addVersionOption();
  grazelab::cli::addOptions(parser);

  if (!parser.parse(QCoreApplication::arguments())) return fail(parser.errorText());
  if (parser.isSet(help)) {
    write(parser.helpText().toUtf8());
    return 0;
  }
  if (parser.isSet(version)) {
    write("grazelab-cli 0.1.0\n");
    return 0;
  }
  const QStringList positional = parser.positionalArguments();
  if (positional.size() != 1) return fail("expected one command, info or simulate (see --help)");
  const QString command = positional.first();

  if (command == "info") {
    const QStringList extra = grazelab::cli::simulateOnlyOptionsSet(parser);
    if (!extra.isEmpty()) return fail(extra.join(", ") + " only apply to 'simulate'");
    const auto model = grazelab::cli::parseModel(parser);
    if (!model.value) return fail(model.error);
    const auto modes = grazelab::core::computeModes(model.value->model);
    const QJsonObject json{{"model", grazelab::cli::modelJson(*model.value, modes)}};
    write(QJsonDocument(json).toJson(QJsonDocument::Indented));
    return 0;
  }
  if (command == "simulate") {
    const auto run = grazelab::cli::parseRun(parser);
    if (!run.value) return fail(run.error);
    const grazelab::core::Result result =
        grazelab::core::simulate(run.value->model.model, run.value->request);
    if (result.stop == grazelab::core::StopReason::InvalidInput) {
      return fail(QString::fromStdString(result.message));
    }
    if (run.value->format == "csv") {
      write(grazelab::cli::simulationCsv(result));
    } else if (run.value->format == "summary") {
      write(grazelab::cli::simulationSummary(*run.value, result));
    } else {
      write(grazelab::cli::simulationJson(*run.value, result));
    }
    return 0;
  }
  return fail(QStringLiteral("unknown command '%1': use info or simulate").arg(command));
}
