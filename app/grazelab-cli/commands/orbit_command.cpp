// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli orbit`: one periodic impacting orbit, its multipliers, stability and checks.
#include "commands/orbit_command.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>
#include <string>

#include "io/cli_input.h"
#include "io/cli_output.h"
#include "core/orbits/onepp_family_points.h"
#include "core/orbits/periodic_orbit.h"
#include "exit_codes.h"
#include "io/json_value.h"

namespace grazelab::cli {
namespace {

template <typename S>
JsonValue stateValue(const core::BasicState<S>& x) {
  return JsonValue::object({{"u1", JsonValue::number(x.u1)},
                            {"u2", JsonValue::number(x.u2)},
                            {"v1", JsonValue::number(x.v1)},
                            {"v2", JsonValue::number(x.v2)}});
}

// The orbit's document: written with a field per line, or handed to Python as values.
template <typename S>
JsonValue orbitValue(const core::PeriodicOrbit<S>& orbit, const core::TwoMassForm<S>& chain,
                     const std::string& precision) {
  using V = JsonValue;
  const S T2 = core::twoPi<S>() / chain.omegaSlow;
  std::vector<V> events;
  for (const core::BasicEvent<S>& e : orbit.events) {
    events.push_back(V::object({{"t", V::number(e.t)},
                                {"type", V::of(std::string(core::toString(e.type)))},
                                {"before", stateValue(e.before)},
                                {"after", stateValue(e.after)}}));
  }
  const auto& mu = orbit.multipliers;
  const std::string symmetry = core::orbitSymmetry(orbit, core::symmetryTolerance<S>());
  const core::BasicModel<S>& m = chain.model;
  return V::object(
      {{"format", V::of("grazelab-orbit")},
       {"precision", V::of(precision)},
       {"model", V::object({{"m1", V::number(m.m1)},
                            {"m2", V::number(m.m2)},
                            {"k1", V::number(m.k1)},
                            {"k2", V::number(S(chain.kappa * m.k1))},
                            {"gap", V::number(m.gap)},
                            {"T2", V::number(T2)}})},
       {"period", V::number(orbit.period)},
       {"T_over_T2", V::number(S(orbit.period / T2))},
       {"energy", V::number(orbit.energy)},
       {"impacts", V::of(std::int64_t(orbit.impacts))},
       {"state", stateValue(orbit.state)},
       {"events", V::array(std::move(events))},
       {"trace", V::number(orbit.trace)},
       {"trace_error", V::number(orbit.traceError)},
       {"multipliers", V::array({V::array({V::number(mu[0][0]), V::number(mu[0][1])}),
                                 V::array({V::number(mu[1][0]), V::number(mu[1][1])})})},
       {"stability", V::of(std::string(core::toString(orbit.stability)))},
       {"symmetry", symmetry.empty() ? V::null() : V::of(symmetry)},
       {"checks", V::object({{"det_minus_1", V::number(orbit.checks.detMinus1)},
                             {"trivial_pair", V::number(orbit.checks.trivialPair)},
                             {"periodicity_residual", V::number(orbit.checks.periodicityResidual)}})},
       {"min_impact_speed", V::number(orbit.minImpactSpeed)},
       {"min_clearance", V::number(orbit.minClearance)},
       {"admissible", V::of(true)},
       {"reason", V::null()},
       {"generator", V::of("grazelab-cli " + QCoreApplication::applicationVersion().toStdString())}});
}

// Reads --NAME as a number of S, or says why not.
template <typename S>
std::optional<S> scalarOption(const OptionValues& options, const char* name, QString& error) {
  const core::ParsedScalar<S> parsed = core::parseScalar<S>(options.value(name).toStdString());
  if (!parsed.value) {
    error = QStringLiteral("--%1: '%2' %3").arg(name, options.value(name), QString::fromStdString(parsed.error));
  }
  return parsed.value;
}

enum class Outcome { Found, Undecided, Refused };

// The orbit in precision S: written to io.out when found; `error` says why not.
template <typename S>
Outcome orbitIn(const OptionValues& options, const std::string& precision, const Io& io, std::stop_token stop,
                QString& error) {
  const Parsed<ModelInput<S>> model = parseModel<S>(options);
  if (!model.value) {
    error = model.error;
    return Outcome::Refused;
  }
  const core::TwoMassForm<S>& chain = model.value->chain;
  core::OrbitSearch<S> search;
  if (options.isSet("onepp")) {
    const std::optional<S> T = scalarOption<S>(options, "period", error);
    if (!T) return Outcome::Refused;
    search = core::onePeriodicOrbitStability(chain, *T);
    if (!search.orbit && search.refusal != core::OrbitRefusal::Undecided) {
      // say where the family is, to the resolution of a scan of 400 periods
      const S T2 = core::twoPi<S>() / chain.omegaSlow;
      std::string parts;
      for (const auto& part : core::onePeriodicParts(chain, 400)) {
        char text[64];
        std::snprintf(text, sizeof text, "%s[%.4f, %.4f]", parts.empty() ? "" : " and ",
                      core::toDouble(S(part[0] / T2)), core::toDouble(S(part[1] / T2)));
        parts += text;
      }
      if (!parts.empty()) search.problem += "; this chain's 1IPP orbits have T/T2 in about " + parts;
    }
  } else {
    bool ok = false;
    const int impacts = options.value("impacts").toInt(&ok);
    if (!ok || impacts < 1 || impacts > 64) {
      error = QStringLiteral("--impacts: '%1' is not a number of impacts from 1 to 64").arg(options.value("impacts"));
      return Outcome::Refused;
    }
    const std::optional<S> energy = scalarOption<S>(options, "energy", error);
    if (!energy) return Outcome::Refused;
    if (!(*energy > 0)) {
      error = QStringLiteral("--energy: '%1' is not a positive energy").arg(options.value("energy"));
      return Outcome::Refused;
    }
    const QStringList guess = options.value("guess").split(',');
    if (guess.size() != 2) {
      error = QStringLiteral("--guess: '%1' is not two numbers u1,v1").arg(options.value("guess"));
      return Outcome::Refused;
    }
    const core::ParsedScalar<S> u1 = core::parseScalar<S>(guess[0].trimmed().toStdString());
    const core::ParsedScalar<S> v1 = core::parseScalar<S>(guess[1].trimmed().toStdString());
    if (!u1.value || !v1.value) {
      error = QStringLiteral("--guess: '%1' is not two numbers u1,v1").arg(options.value("guess"));
      return Outcome::Refused;
    }
    search = core::findOrbit(chain, *energy, *u1.value, *v1.value, impacts, stop);
  }
  if (!search.orbit) {
    error = QString::fromStdString("orbit: " + search.problem);
    return search.refusal == core::OrbitRefusal::Undecided ? Outcome::Undecided : Outcome::Refused;
  }
  // the closed form's data must be right to 1e-9, or a higher precision is needed
  constexpr double kDataAccuracy = 1e-9;
  if (core::toDouble(search.dataError) > kDataAccuracy) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "orbit --onepp: this near a multiple of T1 or T2 the closed form's data are right only to "
                  "about %.1g (relative) in %s: use --precision quad (or auto)",
                  core::toDouble(search.dataError), precision.c_str());
    error = text;
    return Outcome::Undecided;
  }
  emitDocument(io, orbitValue(*search.orbit, chain, precision));
  return Outcome::Found;
}

}  // namespace

void addOrbitOptions(QCommandLineParser& parser) {
  parser.addOptions({
      {"period", "orbit --onepp: the period T of the 1IPP orbit.", "T"},
      {"impacts", "orbit: impacts per period K of the orbit sought.", "K"},
      {"energy", "orbit: the energy E of the orbit sought.", "E"},
      {"guess", "orbit: a guess of the orbit's point just after an impact on H.", "u1,v1"},
  });
}

int runOrbit(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  if (options.isSet("format") && options.value("format") != "json") {
    error = "orbit: --format json is the only format";
    return kExitInvalidInput;
  }
  const bool onePeriodic = options.isSet("onepp");
  if (onePeriodic == options.isSet("impacts")) {
    error = "orbit: give --onepp --period T, or --impacts K --energy E --guess U1,V1";
    return kExitInvalidInput;
  }
  if (onePeriodic && (!options.isSet("period") || options.isSet("energy") || options.isSet("guess"))) {
    error = "orbit --onepp: give --period T (and no --energy or --guess)";
    return kExitInvalidInput;
  }
  if (!onePeriodic && (!options.isSet("energy") || !options.isSet("guess") || options.isSet("period"))) {
    error = "orbit --impacts K: give --energy E and --guess U1,V1 (and no --period)";
    return kExitInvalidInput;
  }
  const QString precision = options.value("precision");
  Outcome outcome = Outcome::Refused;
  if (precision == "double") outcome = orbitIn<double>(options, "double", io, stop, error);
  else if (precision == "long") outcome = orbitIn<long double>(options, "long", io, stop, error);
  else if (precision == "quad") outcome = orbitIn<core::Quad>(options, "quad", io, stop, error);
  else if (precision == "auto") {
    // double, and again in long double then binary128 when a contact is too near tangent
    outcome = orbitIn<double>(options, "double", io, stop, error);
    if (outcome == Outcome::Undecided) outcome = orbitIn<long double>(options, "long", io, stop, error);
    if (outcome == Outcome::Undecided) outcome = orbitIn<core::Quad>(options, "quad", io, stop, error);
  } else {
    error = QStringLiteral("--precision: '%1' is not auto, double, long or quad").arg(precision);
    return kExitInvalidInput;
  }
  if (stop.stop_requested()) return kExitInterrupted;
  return outcome == Outcome::Found ? kExitOk : kExitInvalidInput;
}

}  // namespace grazelab::cli
