// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/cli_input.h"

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <type_traits>

#include <QCommandLineOption>
#include <QCommandLineParser>

#include "core/orbits/starts.h"

namespace grazelab::cli {
namespace {


QString fromStd(const std::string& text) { return QString::fromStdString(text); }


// a number in precision S, or the reason it is not one ("is out of range ...")
template <typename S>
std::optional<S> toNumber(const QString& option, const QString& text, QString& error) {
  const core::ParsedScalar<S> parsed = core::parseScalar<S>(text.toStdString());
  if (!parsed.value) {
    error = QStringLiteral("--%1: '%2' %3").arg(option, text, fromStd(parsed.error));
  }
  return parsed.value;
}

// "a,b,c,d" into a state
template <typename S>
std::optional<core::BasicState<S>> toState(const QString& option, const QString& text,
                                           QString& error) {
  const QStringList parts = text.split(',');
  if (parts.size() != 4) {
    error = QStringLiteral("--%1: '%2' is not four numbers separated by commas").arg(option, text);
    return std::nullopt;
  }
  S values[4];
  for (int i = 0; i < 4; ++i) {
    const auto value = toNumber<S>(option, parts[i], error);
    if (!value) return std::nullopt;
    values[i] = *value;
  }
  return core::BasicState<S>{values[0], values[1], values[2], values[3]};
}

// `count` numbers given as numbers, read in double: the doubles themselves, as their texts would
// read (-0 as 0: the Python module writes a whole number as an integer). Nothing for any other
// precision, count or a number not finite: then the text is read.
template <typename S>
std::optional<std::array<double, 4>> givenDoubles(const OptionValues& options, const char* name, std::size_t count) {
  if constexpr (std::is_same_v<S, double>) {
    const auto numbers = options.numbers(name);
    if (!numbers || numbers->size() != count || count > 4) return std::nullopt;
    std::array<double, 4> values{};
    for (std::size_t i = 0; i < count; ++i) {
      if (!std::isfinite((*numbers)[i])) return std::nullopt;
      values[i] = (*numbers)[i] + 0.0;
    }
    return values;
  }
  return std::nullopt;
}

// --NAME as a number in precision S
template <typename S>
std::optional<S> numberOption(const OptionValues& options, const char* name, QString& error) {
  if (const auto given = givenDoubles<S>(options, name, 1)) return S((*given)[0]);
  return toNumber<S>(QString::fromUtf8(name), options.value(name), error);
}

// --NAME as a state in precision S
template <typename S>
std::optional<core::BasicState<S>> stateOption(const OptionValues& options, const char* name, QString& error) {
  if (const auto given = givenDoubles<S>(options, name, 4)) return core::BasicState<S>{S((*given)[0]), S((*given)[1]), S((*given)[2]), S((*given)[3])};
  return toState<S>(QString::fromUtf8(name), options.value(name), error);
}

// The options of `info` and `simulate`: name, description, value name, default.
struct OptionSpec {
  const char* name;
  const char* description;
  const char* valueName;
  const char* defaultValue;
};
const OptionSpec kOptions[] = {
    {"m1", "Mass 1 (default 1).", "value", "1"},
    {"m2", "Mass 2, the one that hits the stop (default 0.5).", "value", "0.5"},
    {"k1", "Stiffness wall-m1 (default 1).", "value", "1"},
    {"gap", "Gap d between mass 2 at rest and the stop (default 1).", "value", "1"},
    {"k2", "Stiffness m1-m2 as given: no resonance imposed (excludes --branch).", "value", nullptr},
    {"branch", "k2 from the 1:2 design: upper (default) or lower.", "upper|lower", nullptr},
    {"masses", "A chain of N masses m1,...,mN, for every command (--masses 1,0.5 --frequencies 2:1 "
               "is the note's chain): the whole chain, with --springs or --frequencies; excludes --m1 "
               "--m2 --k1 --k2 --branch.",
     "m1,...,mN", nullptr},
    {"springs", "The springs k1,...,kN of --masses: wall to m1 (0: no left wall, a free end), then between neighbours.",
     "k1,...,kN", nullptr},
    {"right-spring", "With --masses: a spring k(N+1) from the last mass to a right wall "
                     "(default none).", "K", nullptr},
    {"stop-mass", "With --masses: the mass the stop acts on, 1 to N (default the last).", "S", nullptr},
    {"frequencies", "With --masses: design the springs so that the frequencies are in the ratio "
                    "n1:n2:...:nN (fastest first), k1 from --springs (default 1) and a right wall's "
                    "--right-spring kept as given; every design is listed.", "n1:...:nN", nullptr},
    {"design-branch", "With --frequencies: the design to use, 1 to the number found (default 1; "
                      "designs are ordered by k2, largest first).", "I", nullptr},
    {"precision", "Arithmetic of the run: auto (default: double, and the whole run again in "
                    "long double, then binary128, from its input, when a contact touches the "
                    "stop within rounding), double, long or quad (binary128). Numbers are read "
                    "and written in it.", "auto|double|long|quad", "auto"},
    {"glo", "Start on GLO_lambda data, any real lambda (default 0.5).", "lambda", nullptr},
    {"onepp", "Start on the one-impact-per-period orbit of period T (T < T2 near T2). With "
                "'family', --onepp takes no value: it names the family.", "T", nullptr},
    {"state", "Start from the state u1,u2,v1,v2.", "u1,u2,v1,v2", nullptr},
    {"perturb", "Add du1,du2,dv1,dv2 to the initial state (N masses: du1,...,duN,dv1,...,dvN).",
     "du1,du2,dv1,dv2", nullptr},
    {"glo-weights", "With --masses: start on GLO_lambda = sum_j lambda_j GLOM_j at its touch "
                    "(weights fastest mode first, summing to 1; GLOM_j is mode j alone with its "
                    "top on the stop).", "l1,...,lN", nullptr},
    {"directions", "glo-set of three modes: the rays along which the region's boundary is found "
                   "(default 72).", "N", nullptr},
    {"contacts", "Stop after N contacts (default 100 when no --t-end).", "N", nullptr},
    {"t-end", "Stop at time T (it also bounds the contact search of a detuned chain).", "T", nullptr},
    {"search-steps", "Detuned chains: the most steps one flight's contact search may take "
                       "(default: about a second's worth, 10000000 in double, 3000000 in long, "
                       "300000 in quad); running out stops the run with stop_reason "
                       "search-budget, never 'no contact'.", "N", nullptr},
    {"sample-step", "Also report the state every DT time units from t = 0 to the run's end, "
                    "after the run (json and jsonl only; at most 4000000 samples, in double).",
     "DT", nullptr},
    {"sample-times", "Also report the state at these times, ascending (json and jsonl only).",
     "t1,t2,...", nullptr},
    {"format", "Output: json (default), jsonl (JSON Lines), csv or summary. json, jsonl and "
                 "csv stream: memory stays bounded and an interrupt leaves complete records.",
       "json|jsonl|csv|summary", "json"},
    {"trust", "Error estimate of the run: auto (default: a shadow run one precision up while "
                "it costs about the run itself, then extrapolation), full (the shadow to the "
                "end) or off. For 'map': off (default: horizon NaN) or auto (a shadow per "
                "point).", "off|auto|full", "auto"},
  };

}  // namespace

std::optional<std::int64_t> countOption(const OptionValues& options, const char* name,
                                        std::int64_t least, QString& error) {
  // a whole number given as a number (below 2^53: exact in double) is its count
  if (const auto numbers = options.numbers(name);
      numbers && numbers->size() == 1 && std::fabs(numbers->front()) < 0x1p53 &&
      numbers->front() == std::trunc(numbers->front()) && numbers->front() >= double(least)) {
    return static_cast<std::int64_t>(numbers->front());
  }
  bool ok = false;
  const qlonglong value = options.value(name).toLongLong(&ok);
  if (!ok || value < least) {
    error = QStringLiteral("--%1: '%2' is not a count (a whole number >= %3)")
                .arg(QString::fromUtf8(name), options.value(name))
                .arg(least);
    return std::nullopt;
  }
  return value;
}

QString defaultOptionValue(std::string_view name) {
  for (const OptionSpec& option : kOptions) {
    if (name == option.name) {
      return option.defaultValue ? QString::fromUtf8(option.defaultValue) : QString();
    }
  }
  return {};
}

void addOptions(QCommandLineParser& parser) {
  for (const OptionSpec& option : kOptions) {
    QCommandLineOption added(QString::fromUtf8(option.name), QString::fromUtf8(option.description),
                             QString::fromUtf8(option.valueName));
    if (option.defaultValue) added.setDefaultValue(QString::fromUtf8(option.defaultValue));
    parser.addOption(added);
  }
}

QStringList repeatedOptions(const QCommandLineParser& parser) {
  QStringList repeated;
  const QStringList names = parser.optionNames();
  for (const QString& name : names) {
    if (names.count(name) > 1 && !repeated.contains("--" + name)) repeated << "--" + name;
  }
  return repeated;
}

std::optional<core::TrustMode> parseTrustOption(const OptionValues& options,
                                                 QString& error) {
  const QString text = options.value("trust");
  const auto mode = core::parseTrustMode(text.toStdString());
  if (!mode) error = QStringLiteral("--trust: '%1' is not off, auto or full").arg(text);
  return mode;
}

std::optional<PrecisionOption> parsePrecisionOption(const OptionValues& options,
                                                    QString& error) {
  const QString text = options.value("precision");
  if (text == "auto") return PrecisionOption{};
  const auto precision = core::parsePrecision(text.toStdString());
  if (!precision) {
    error = QStringLiteral("--precision: '%1' is not auto, double, long or quad").arg(text);
    return std::nullopt;
  }
  return PrecisionOption{precision};
}

namespace {

// Whether a number's decimal text is a number of S (read with 400 bits, it equals its value read
// in S); an empty text is a default, exact
template <typename S>
bool exactIn(const char* name, const QString& text) {
  using Wide = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<400, boost::multiprecision::digit_base_2>>;
  if (text.isEmpty()) return true;
  QString error;
  const auto value = toNumber<S>(name, text, error);
  if (!value) return false;
  try {
    return Wide(text.toStdString()) == Wide(*value);
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

template <typename S>
core::ExactParameters exactParameters(const OptionValues& options) {
  // the text each number was written as: the two-mass options, or --masses m1,m2 and --springs
  // k1[,k2] for the same chain (k1 = 1 when not given, k2 designed when not given)
  const QStringList masses = options.value("masses").split(',');
  const QStringList springs = options.isSet("springs") ? options.value("springs").split(',') : QStringList();
  auto textOf = [&](const char* name) -> QString {
    if (!options.isSet("masses")) return options.value(name);
    const std::string_view field(name);
    if (field == "m1" || field == "m2") return masses.value(field == "m1" ? 0 : 1).trimmed();
    if (field == "k1") return springs.isEmpty() ? QStringLiteral("1") : springs.value(0).trimmed();
    if (field == "k2") return springs.value(1).trimmed();
    return options.value(name);
  };
  auto exact = [&](const char* name) { return exactIn<S>(name, textOf(name)); };
  core::ExactParameters read;
  read.masses = {exact("m1"), exact("m2")};
  read.springs = {exact("k1"), exact("k2")};
  read.gap = exact("gap");
  return read;
}

template <typename S>
core::ExactParameters chainExactParameters(const OptionValues& options) {
  core::ExactParameters read;
  read.gap = exactIn<S>("gap", options.value("gap"));
  // a design's springs are designed for the masses as they stand: nudging either would leave
  // the design (its grazing orbits would graze no more); the gap alone then
  if (options.isSet("frequencies")) return read;
  for (const QString& mass : options.value("masses").split(',')) read.masses.push_back(exactIn<S>("masses", mass.trimmed()));
  if (options.isSet("springs")) {
    for (const QString& spring : options.value("springs").split(',')) {
      read.springs.push_back(exactIn<S>("springs", spring.trimmed()));
    }
  }
  read.rightSpring = exactIn<S>("right-spring", options.value("right-spring"));
  return read;
}

template <typename S>
Parsed<ModelInput<S>> twoMassChain(const OptionValues& options);

// The model formed into its nondimensional chain, or why this precision cannot, with the flag
// that may help (a refusal the precision causes is marked: --precision auto goes higher)
template <typename S>
Parsed<ModelInput<S>> formedModel(const core::BasicModel<S>& model) {
  core::TwoMassFormOrProblem<S> formed = core::makeTwoMassForm(model);
  if (formed.chain) return {ModelInput<S>{model, *formed.chain}, {}};
  QString line = fromStd(formed.problem);
  switch (formed.kind) {
    case core::TwoMassFormProblem::BeyondRange: line += " (try --precision long or quad)"; break;
    case core::TwoMassFormProblem::PhaseRounding:
      if (!std::is_same_v<S, core::Quad>) line += ": --precision quad resolves more";
      break;
    case core::TwoMassFormProblem::None: break;
  }
  return {std::nullopt, line, formed.kind != core::TwoMassFormProblem::None};
}

template <typename S>
Parsed<ModelInput<S>> parseModel(const OptionValues& options) {
  if (options.isSet("masses")) return twoMassChain<S>(options);
  for (const char* chainOption : {"springs", "right-spring", "stop-mass", "frequencies", "design-branch"}) {
    if (options.isSet(chainOption)) {
      return {std::nullopt, QStringLiteral("--%1 describes a chain given by --masses").arg(chainOption)};
    }
  }
  QString error;
  S values[4];
  const char* names[] = {"m1", "m2", "k1", "gap"};
  for (int i = 0; i < 4; ++i) {
    const auto value = numberOption<S>(options, names[i], error);
    if (!value) return {std::nullopt, error};
    values[i] = *value;
  }
  if (options.isSet("k2") && options.isSet("branch")) {
    return {std::nullopt, "--k2 and --branch exclude each other: give k2, or let the 1:2 design "
                          "choose it"};
  }
  core::BasicModel<S> model{values[0], values[1], values[2], S(1), values[3], std::nullopt};
  if (options.isSet("k2")) {
    const auto k2 = numberOption<S>(options, "k2", error);
    if (!k2) return {std::nullopt, error};
    model.k2 = *k2;
  } else {
    const QString branchText = options.isSet("branch") ? options.value("branch") : "upper";
    const auto branch = core::parseBranch(branchText.toStdString());
    if (!branch) {
      return {std::nullopt,
              QStringLiteral("--branch: '%1' is neither 'upper' nor 'lower'").arg(branchText)};
    }
    model.design = branch;
  }
  const auto problems = core::validate(model);
  if (!problems.empty()) {
    QString line = fromStd(core::describe(problems));
    if (model.design) line += " (give --k2 for a detuned chain)";
    return {std::nullopt, line};
  }
  if (model.design) {
    model = *core::designedModel(model.m1, model.m2, model.k1, model.gap, *model.design);
  }
  return formedModel(model);
}

template <typename S>
Parsed<core::StartSpec<S>> parseStartSpec(const OptionValues& options,
                                          const core::BasicModel<S>& model) {
  QString error;
  const int starts = int(options.isSet("glo")) + int(options.isSet("onepp")) +
                     int(options.isSet("state"));
  if (starts > 1) return {std::nullopt, "give one of --glo, --onepp, --state, not several"};
  core::StartSpec<S> spec;
  if (options.isSet("onepp")) {
    const auto period = numberOption<S>(options, "onepp", error);
    if (!period) return {std::nullopt, error};
    spec.kind = core::StartSpec<S>::Kind::OnePeriodic;
    spec.period = *period;
  } else if (options.isSet("state")) {
    const auto state = stateOption<S>(options, "state", error);
    if (!state) return {std::nullopt, error};
    spec.kind = core::StartSpec<S>::Kind::Explicit;
    spec.state = *state;
  } else {
    const auto lambda = options.isSet("glo") ? numberOption<S>(options, "glo", error)
                                             : toNumber<S>("glo", "0.5", error);
    if (!lambda) return {std::nullopt, error};
    if (!core::isFinite(*lambda)) {
      return {std::nullopt, QStringLiteral("--glo must be a finite number (got %1)").arg(options.value("glo"))};
    }
    spec.lambda = *lambda;
  }
  if (options.isSet("perturb")) {
    const auto delta = stateOption<S>(options, "perturb", error);
    if (!delta) return {std::nullopt, error};
    const auto problems = core::validateState(model, *delta, "perturb");
    for (const auto& problem : problems) {
      if (problem.field != "perturb.u2") return {std::nullopt, fromStd(core::describe({problem}))};
    }
    spec.perturbation = *delta;
  }
  return {spec, {}};
}

namespace {

// "a,b,c" as numbers, or the reason it is not
template <typename S = double>
std::optional<std::vector<S>> toList(const QString& option, const QString& text, QString& error) {
  std::vector<S> values;
  for (const QString& part : text.split(',')) {
    const auto value = toNumber<S>(option, part, error);
    if (!value) return std::nullopt;
    values.push_back(*value);
  }
  return values;
}

// "3:2:1" as positive integers, fastest first (strictly decreasing), one per mass
std::optional<std::vector<int>> toRatios(const QString& text, std::size_t masses, QString& error) {
  std::vector<int> ratios;
  for (const QString& part : text.split(':')) {
    bool ok = false;
    const int value = part.trimmed().toInt(&ok);
    if (!ok || value < 1) {
      error = QStringLiteral("--frequencies: '%1' is not a positive whole number (give n1:n2:...:nN, fastest first)")
                  .arg(part);
      return std::nullopt;
    }
    ratios.push_back(value);
  }
  if (ratios.size() != masses) {
    error = QStringLiteral("--frequencies: %1 ratios for %2 masses (one per mass, fastest first)")
                .arg(ratios.size())
                .arg(masses);
    return std::nullopt;
  }
  for (std::size_t j = 1; j < ratios.size(); ++j) {
    if (ratios[j] >= ratios[j - 1]) {
      error = QStringLiteral("--frequencies: %1 must be strictly decreasing (fastest first; a chain's "
                             "frequencies are all different)")
                  .arg(text);
      return std::nullopt;
    }
  }
  if (ratios.size() > std::size_t(core::kMaxDesignMasses)) {
    error = QStringLiteral("--frequencies: designs %1 masses at most (the search follows N! solutions)")
                .arg(core::kMaxDesignMasses);
    return std::nullopt;
  }
  return ratios;
}

// the springs of `chain` designed for --frequencies: the chosen design, or why there is none
Parsed<MassChainInput> designedChain(const OptionValues& options, core::MassChain chain, std::stop_token stop) {
  QString error;
  const QString request = options.value("frequencies");
  const auto ratios = toRatios(request, chain.masses.size(), error);
  if (!ratios) return {std::nullopt, error};
  double k1 = 1;
  if (options.isSet("springs")) {
    const auto springs = toList("springs", options.value("springs"), error);
    if (!springs) return {std::nullopt, error};
    if (springs->size() != 1) {
      return {std::nullopt, "--frequencies designs k2,...,kN: give --springs k1 alone (the scale), or leave "
                            "it out (k1 = 1)"};
    }
    k1 = springs->front();
  }
  // k1 checked with the masses (the others stand in at 1 until designed)
  chain.springs.assign(chain.masses.size(), 1.0);
  chain.springs[0] = k1;
  if (const auto problems = core::validate(chain); !problems.empty()) return {std::nullopt, fromStd(core::describe(problems))};
  int branch = 1;
  if (options.isSet("design-branch")) {
    bool ok = false;
    branch = options.value("design-branch").toInt(&ok);
    if (!ok || branch < 1) {
      return {std::nullopt, QStringLiteral("--design-branch: '%1' is not a design number (1, 2, ...)")
                                .arg(options.value("design-branch"))};
    }
  }
  core::DesignChoice choice = core::chooseDesign(chain.masses, k1, chain.rightSpring, *ratios, branch, stop);
  const core::ChainDesigns& designs = choice.designs;
  switch (choice.problem) {
    case core::DesignChoiceProblem::Stopped: return {std::nullopt, {}};
    case core::DesignChoiceProblem::BadRequest: return {std::nullopt, "--frequencies: the request cannot be designed"};
    case core::DesignChoiceProblem::Incomplete:
      return {std::nullopt, QStringLiteral("--frequencies %1: the design search could not follow every one of its "
                                           "solutions, so no list of designs can be promised")
                                .arg(request)};
    case core::DesignChoiceProblem::NoPositiveDesign:
      return {std::nullopt, QStringLiteral("--frequencies %1: no chain with these masses has these ratios: each of "
                                           "the %2 solutions of the design equations is complex or has a spring <= 0")
                                .arg(request)
                                .arg(designs.paths)};
    case core::DesignChoiceProblem::NoSuchDesign:
      return {std::nullopt, QStringLiteral("--design-branch %1: the ratios %2 have %3 design%4 for these masses (1 to %3)")
                                .arg(branch)
                                .arg(request)
                                .arg(designs.designs.size())
                                .arg(designs.designs.size() == 1 ? "" : "s")};
    case core::DesignChoiceProblem::None: break;
  }
  chain.springs = choice.chosen().springs;
  return {MassChainInput{chain, std::move(choice)}, {}};
}

}  // namespace

Parsed<MassChainInput> parseMassChain(const OptionValues& options, std::stop_token stop) {
  for (const char* twoMass : {"m1", "m2", "k1", "k2", "branch"}) {
    if (options.isSet(twoMass)) {
      return {std::nullopt, QStringLiteral("--masses describes the whole chain: give it with --springs, "
                                           "or --%1 and the other two-mass options, not both").arg(twoMass)};
    }
  }
  const bool design = options.isSet("frequencies");
  if (!design && options.isSet("design-branch")) return {std::nullopt, "--design-branch picks a design of --frequencies"};
  if (!design && !options.isSet("springs")) {
    return {std::nullopt, "--masses needs --springs k1,...,kN (one per mass), or --frequencies n1:...:nN to design them"};
  }
  QString error;
  core::MassChain chain;
  const auto masses = toList("masses", options.value("masses"), error);
  if (!masses) return {std::nullopt, error};
  chain.masses = *masses;
  if (!design) {
    const auto springs = toList("springs", options.value("springs"), error);
    if (!springs) return {std::nullopt, error};
    chain.springs = *springs;
  }
  if (options.isSet("right-spring")) {
    const auto right = toNumber<double>("right-spring", options.value("right-spring"), error);
    if (!right) return {std::nullopt, error};
    chain.rightSpring = *right;
  }
  if (options.isSet("stop-mass")) {
    bool ok = false;
    chain.stopMass = options.value("stop-mass").toInt(&ok);
    if (!ok) return {std::nullopt, QStringLiteral("--stop-mass: '%1' is not a mass number").arg(options.value("stop-mass"))};
  }
  const auto gap = toNumber<double>("gap", options.value("gap"), error);
  if (!gap) return {std::nullopt, error};
  chain.gap = *gap;
  if (design) return designedChain(options, chain, stop);
  const auto problems = core::validate(chain);
  if (!problems.empty()) return {std::nullopt, fromStd(core::describe(problems))};
  return {MassChainInput{chain, std::nullopt}, {}};
}

// The chain of --masses for the commands that compute the note's chain (orbit, modes, report):
// two masses, the stop on mass 2, no right wall. It is the chain the two-mass options would give:
// --frequencies 2:1 is the 1:2 design of branch upper (--design-branch 1, the larger k2) or lower
// (2), with the design's exact resonance; springs given, or designed for another ratio, are k1
// and k2 as given. Every number is read from its text in S, as --m1 ... would be.
bool hasTheNotesShape(const OptionValues& options) {
  const qsizetype count = options.value("masses").split(',').size();
  const bool stopOnTwo = !options.isSet("stop-mass") || options.value("stop-mass").trimmed() == "2";
  const bool noWall = !options.isSet("right-spring") || core::parseScalar<double>(options.value("right-spring").toStdString()).value == 0.0;
  return count == 2 && stopOnTwo && noWall;
}

bool writesTheNotesChain(const OptionValues& options) {
  if (!options.isSet("masses") || !options.isSet("frequencies") || !hasTheNotesShape(options)) return false;
  QString error;
  const auto ratios = toRatios(options.value("frequencies"), 2, error);
  return ratios && *ratios == std::vector<int>{2, 1};
}

std::optional<OptionValues> notesRunOptions(const OptionValues& options, QString& error) {
  if (!options.isSet("glo-weights")) return OptionValues(options, {}, {});
  const QStringList parts = options.value("glo-weights").split(',');
  double sum = 0;
  for (const QString& part : parts) {
    const core::ParsedScalar<double> weight = core::parseScalar<double>(part.trimmed().toStdString());
    if (parts.size() != 2 || !weight.value || !std::isfinite(*weight.value)) {
      error = "--glo-weights: one finite weight per mode";
      return std::nullopt;
    }
    sum += *weight.value;
  }
  // (the tolerance of the chain's own GLO start, core/orbits/chain_glo.cpp)
  if (!(std::abs(sum - 1) <= 1e-12)) {
    error = "--glo-weights: the weights must sum to 1 (an affine combination of the GLOMs keeps the "
            "stopped mass on the stop)";
    return std::nullopt;
  }
  return OptionValues(options, {GivenOption{"glo", parts[1].trimmed(), {}, false}}, {"glo-weights"});
}

template <typename S>
Parsed<ModelInput<S>> twoMassChain(const OptionValues& options) {
  // the shape first: a chain of more masses is not designed only to be refused
  if (!hasTheNotesShape(options)) {
    return {std::nullopt, "this command computes the two-mass chain stopped on mass 2 (no right wall) for now: "
                          "give --masses m1,m2, or the two-mass options"};
  }
  Parsed<MassChainInput> input = parseMassChain(options);
  if (!input.value) return {std::nullopt, input.error};
  QString error;
  const std::vector<S> masses = *toList<S>("masses", options.value("masses"), error);
  const S gap = *toNumber<S>("gap", options.value("gap"), error);
  core::BasicModel<S> model{masses[0], masses[1], S(1), S(1), gap, std::nullopt};
  if (options.isSet("springs")) model.k1 = toList<S>("springs", options.value("springs"), error)->front();
  const std::optional<core::DesignChoice>& design = input.value->design;
  if (design && design->harmonics == std::vector<int>{2, 1}) {
    const core::Branch branch = design->number == 1 ? core::Branch::Upper : core::Branch::Lower;
    const auto designed = core::designedModel(model.m1, model.m2, model.k1, model.gap, branch);
    if (!designed) {
      return {std::nullopt, QStringLiteral("--frequencies 2:1: no 1:2 design for the masses read in this precision "
                                           "(m2/m1 > 9/16 there): give --precision double")};
    }
    model = *designed;
  } else {
    const Parsed<core::BasicMassChain<S>> inS = massChainIn<S>(options, *input.value);
    if (!inS.value) return {std::nullopt, inS.error};
    model.k2 = inS.value->springs[1];
  }
  if (const auto problems = core::validate(model); !problems.empty()) return {std::nullopt, fromStd(core::describe(problems))};
  return formedModel(model);
}

template <typename S>
Parsed<RunInput<S>> parseRun(const OptionValues& options) {
  Parsed<ModelInput<S>> model = parseModel<S>(options);
  if (!model.value) return {std::nullopt, model.error, model.precisionBound};
  RunInput<S> run{*model.value, {}, {}, {}, Format::Json};
  const core::TwoMassForm<S>& chain = run.model.chain;
  QString error;

  Parsed<core::StartSpec<S>> spec = parseStartSpec<S>(options, run.model.model);
  if (!spec.value) return {std::nullopt, spec.error};
  core::StartOrProblem<S> start = core::makeStart(chain, *spec.value);
  if (!start.start) {
    const QString option = spec.value->kind == core::StartSpec<S>::Kind::OnePeriodic ? "--onepp: " : "";
    return {std::nullopt, option + fromStd(start.problem) + (start.undecided ? " (--precision auto goes higher)" : ""),
            start.undecided};
  }
  const auto stateProblems = core::validateState(run.model.model, start.start->state, "initial");
  if (!stateProblems.empty()) return {std::nullopt, fromStd(core::describe(stateProblems))};
  run.request.initial = start.start->state;
  run.initialDescription = std::move(start.start->description);
  // core's notes on the start are about rounding: the command line can raise the precision
  for (const std::string& note : start.start->notes) run.notes.push_back(note + " (try --precision quad)");

  if (options.isSet("contacts")) {
    const auto contacts = countOption(options, "contacts", 0, error);
    if (!contacts) return {std::nullopt, error};
    run.request.maxContacts = *contacts;
  } else {
    run.request.maxContacts = options.isSet("t-end") ? std::numeric_limits<std::int64_t>::max() : 100;
  }
  if (options.isSet("t-end")) {
    const auto tEnd = numberOption<S>(options, "t-end", error);
    if (!tEnd) return {std::nullopt, error};
    if (!(*tEnd >= 0)) {
      return {std::nullopt,
              QStringLiteral("--t-end: '%1' is not a time >= 0").arg(options.value("t-end"))};
    }
    run.request.tEnd = *tEnd;
  }
  if (options.isSet("search-steps")) {
    const auto steps = countOption(options, "search-steps", 1, error);
    if (!steps) return {std::nullopt, error};
    run.request.flightSearchSteps = *steps;
  }
  // a request whose length is astronomical is said to be so up front (it still runs, and an
  // interrupt ends it with complete records)
  const S slowPeriod = core::twoPi<S>() / run.model.chain.omegaSlow;
  const double periods = core::toDouble(S(run.request.tEnd / slowPeriod));
  if (!options.isSet("contacts") && std::isfinite(periods) && periods > 1e12) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "--t-end spans %.2g slow periods (T2 = %.3g) and no --contacts bounds the run: "
                  "at ~1e7 contacts a second that could take %.2g years",
                  periods, core::toDouble(slowPeriod), periods / 1e7 / 3.15e7);
    run.notes.push_back(line);
  }
  if (options.isSet("sample-step") && options.isSet("sample-times")) {
    return {std::nullopt, "--sample-step and --sample-times exclude each other"};
  }
  core::SampleSpec& samples = run.request.needs.samples;
  if (options.isSet("sample-step")) {
    const auto step = toNumber<double>("sample-step", options.value("sample-step"), error);
    if (!step) return {std::nullopt, error};
    if (!(*step > 0) || !std::isfinite(*step)) {
      return {std::nullopt, QStringLiteral("--sample-step: '%1' is not a time > 0").arg(options.value("sample-step"))};
    }
    samples.spacing = *step;
  }
  if (options.isSet("sample-times")) {
    for (const QString& part : options.value("sample-times").split(',')) {
      const auto t = toNumber<double>("sample-times", part, error);
      if (!t) return {std::nullopt, error};
      if (!(*t >= 0) || !std::isfinite(*t) || (!samples.times.empty() && *t < samples.times.back())) {
        return {std::nullopt, QStringLiteral("--sample-times: '%1' is not a list of times >= 0, "
                                             "ascending").arg(options.value("sample-times"))};
      }
      samples.times.push_back(*t);
    }
  }
  // the user's times only: no extra states at the contacts
  samples.includeContacts = false;
  const QString format = options.value("format");
  if (format == "json") {
    run.format = Format::Json;
  } else if (format == "jsonl") {
    run.format = Format::JsonLines;
  } else if (format == "csv") {
    run.format = Format::Csv;
  } else if (format == "summary") {
    run.format = Format::Summary;
  } else {
    return {std::nullopt,
            QStringLiteral("--format: '%1' is not json, jsonl, csv or summary").arg(format)};
  }
  if (samples.wanted() && run.format != Format::Json && run.format != Format::JsonLines) {
    return {std::nullopt, "--sample-step and --sample-times are written in --format json and jsonl only"};
  }
  // outputs stream every event through the request's callback; nothing is kept in memory but
  // the samples asked for
  run.request.needs.events = false;
  return {std::move(run), {}};
}

template <typename S>
Parsed<core::BasicMassChain<S>> massChainIn(const OptionValues& options, const MassChainInput& input) {
  if constexpr (std::is_same_v<S, double>) {
    return {input.chain, {}};
  } else {
    // every number was read and checked in double already: read again, each parses in S too
    QString error;
    core::BasicMassChain<S> chain = core::chainCast<S>(input.chain);
    chain.masses = *toList<S>("masses", options.value("masses"), error);
    if (options.isSet("right-spring")) chain.rightSpring = *toNumber<S>("right-spring", options.value("right-spring"), error);
    chain.gap = *toNumber<S>("gap", options.value("gap"), error);
    if (!input.design) {
      chain.springs = *toList<S>("springs", options.value("springs"), error);
      return {std::move(chain), {}};
    }
    // designed: the double design's root polished with the chain's own numbers in binary128
    const core::DesignChoice& choice = *input.design;
    // --springs gives k1 alone here (checked)
    if (options.isSet("springs")) chain.springs.front() = *toNumber<S>("springs", options.value("springs"), error);
    const auto springs = core::designedSpringsIn<S>(chain.masses, chain.springs.front(), chain.rightSpring, choice);
    if (!springs) {
      return {std::nullopt, QStringLiteral("--frequencies %1: design %2 cannot be refined for the masses read in %3: "
                                           "give --precision double")
                                .arg(options.value("frequencies"))
                                .arg(choice.number)
                                .arg(std::is_same_v<S, core::Quad> ? "binary128" : "long double")};
    }
    chain.springs = *springs;
    return {std::move(chain), {}};
  }
}

#define GRAZELAB_INSTANTIATE(S)                                                     \
  template Parsed<core::BasicMassChain<S>> massChainIn<S>(const OptionValues&, const MassChainInput&); \
  template core::ExactParameters exactParameters<S>(const OptionValues&);     \
  template core::ExactParameters chainExactParameters<S>(const OptionValues&); \
  template Parsed<ModelInput<S>> parseModel<S>(const OptionValues&);          \
  template Parsed<core::StartSpec<S>> parseStartSpec<S>(const OptionValues&,  \
                                                        const core::BasicModel<S>&); \
  template Parsed<RunInput<S>> parseRun<S>(const OptionValues&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(core::Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::cli
