// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>
#include <QStringList>

#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "core/model/two_mass_form.h"
#include "core/model/chain_design.h"
#include "core/model/mass_chain.h"
#include "core/model/model.h"
#include "core/model/resonance.h"
#include "core/orbits/starts.h"
#include "core/solver/simulate.h"
#include "core/solver/trust.h"

#include "io/option_values.h"

class QCommandLineParser;

namespace grazelab::cli {

/// Registers every option of `info` and `simulate` (docs/design.md, "Command line").
void addOptions(QCommandLineParser& parser);

/// Options given more than once (the last would silently win): refused with their names.
QStringList repeatedOptions(const QCommandLineParser& parser);


/// --precision, checked ("double" when absent).
/// --precision as given: one arithmetic, or auto (`fixed` empty: double, the run raised to a
/// higher precision where a contact needs it).
struct PrecisionOption {
  std::optional<core::Precision> fixed;
};
std::optional<PrecisionOption> parsePrecisionOption(const OptionValues& options,
                                                    QString& error);

/// --trust, checked ("auto" when absent).
std::optional<core::TrustMode> parseTrustOption(const OptionValues& options, QString& error);

/// Which of the note's chain's numbers the command line gives exactly in precision S (its
/// decimal text is a number of S; parameters not given are exact defaults); its start counts as
/// rounded.
template <typename S>
core::ExactParameters exactParameters(const OptionValues& options);
/// The same for a chain of N masses (--masses, --springs, --right-spring, --gap); a designed
/// chain's masses and springs count as exact (its design is for them as they stand).
template <typename S>
core::ExactParameters chainExactParameters(const OptionValues& options);

/// The model as the command line describes it, in precision S, with its nondimensional chain.
template <typename S>
struct ModelInput {
  core::BasicModel<S> model;
  core::TwoMassForm<S> chain;
};

/// Output formats of `simulate`.
enum class Format { Json, JsonLines, Csv, Summary };

/// What `simulate` runs, with the words that describe its start.
template <typename S>
struct RunInput {
  ModelInput<S> model;
  core::BasicRequest<S> request;
  std::string initialDescription;  ///< e.g. "GLO_lambda data, lambda = 0.5 (as such: ...)"
  std::vector<std::string> notes;  ///< warnings for stderr (a perturbation lost in rounding)
  Format format = Format::Json;
};

/// Either a value or the one line that says what is wrong.
template <typename T>
struct Parsed {
  std::optional<T> value;
  QString error;
  /// the refusal is the precision's (a range, a rounding, an undecided return): a higher
  /// precision may answer, and --precision auto tries it
  bool precisionBound = false;
};

/// --NAME as a whole number >= least (given as a number: read as such), or nothing with the
/// reason in `error`.
std::optional<std::int64_t> countOption(const OptionValues& options, const char* name, std::int64_t least,
                                        QString& error);

template <typename S>
Parsed<ModelInput<S>> parseModel(const OptionValues& options);
/// The start options (--glo, --onepp, --state, --perturb) as a spec: GLO_0.5 when none is given.
template <typename S>
Parsed<core::StartSpec<S>> parseStartSpec(const OptionValues& options,
                                          const core::BasicModel<S>& model);
template <typename S>
Parsed<RunInput<S>> parseRun(const OptionValues& options);

/// A chain of N masses, and how its springs came when designed (--frequencies, --design-branch).
struct MassChainInput {
  core::MassChain chain;
  std::optional<core::DesignChoice> design;
};

/// A chain of N masses (--masses, --springs, --right-spring, --stop-mass, --gap), checked; or,
/// with --frequencies P:Q:..., its springs designed for those ratios (--springs then gives k1
/// alone, the scale, default 1; --design-branch I picks the I-th design, default 1). The
/// two-mass options beside --masses are refused; a request no chain meets is refused with the
/// reason. An interrupted design returns no chain and an empty error (`stop` was requested).
Parsed<MassChainInput> parseMassChain(const OptionValues& options, std::stop_token stop = {});

/// Whether --masses writes a chain of the note's shape: two masses stopped on mass 2, no right
/// wall (any springs): the two-mass engine's chain.
bool hasTheNotesShape(const OptionValues& options);

/// Whether --masses writes the note's chain: two masses stopped on mass 2, no right wall, the
/// springs designed for the ratios 2:1 (--frequencies 2:1). Its runs are the note's engine's (the
/// two-mass solver with the design's exact 1:2 resonance and its quartic contact search), so
/// that it gives the two-mass options' bits however it is written.
bool writesTheNotesChain(const OptionValues& options);

/// The options of a run of the note's chain given by --masses, as the two-mass commands read
/// them (`options` kept by reference): --glo-weights l1,l2, summing to 1, become --glo l2
/// (GLO_lambda = (1 - lambda) GLOM_1 + lambda GLOM_2); every other option is read as given.
/// Nothing, with `error`, for weights that are not two finite numbers summing to 1.
std::optional<OptionValues> notesRunOptions(const OptionValues& options, QString& error);

/// The chain of `input` (parseMassChain's) with its numbers in the run's precision S: read again
/// from their decimal text in S (0.7 in binary128 is not double's 0.7), designed springs refined
/// for those numbers in binary128 (core::refinedSprings); in double, input.chain itself.
template <typename S>
Parsed<core::BasicMassChain<S>> massChainIn(const OptionValues& options, const MassChainInput& input);

}  // namespace grazelab::cli
