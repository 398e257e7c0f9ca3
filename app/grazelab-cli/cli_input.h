// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <optional>

#include "core/model.h"
#include "core/resonance.h"
#include "core/simulate.h"

class QCommandLineParser;

namespace grazelab::cli {

/// Registers every option of `info` and `simulate` (DESIGN.md, "Command line").
void addOptions(QCommandLineParser& parser);

/// The model as the command line describes it.
struct ModelInput {
  core::Model model;
  std::optional<core::Branch> branch;  ///< set when k2 came from the 1:2 design
};

/// What `simulate` runs, with the words that describe its start.
struct RunInput {
  ModelInput model;
  core::Request request;
  QString initialDescription;  ///< e.g. "GLO_lambda, lambda = 0.5: grazing linear orbit ..."
  QString format;              ///< json | csv | summary
};

/// Either a value or the one line that says what is wrong.
template <typename T>
struct Parsed {
  std::optional<T> value;
  QString error;
};

Parsed<ModelInput> parseModel(const QCommandLineParser& parser);
Parsed<RunInput> parseRun(const QCommandLineParser& parser);

/// The options that only `simulate` takes and that are set; for rejecting them on `info`.
QStringList simulateOnlyOptionsSet(const QCommandLineParser& parser);

}  // namespace grazelab::cli
