// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// `grazelab-cli family --onepp`: the one-impact-per-period family of the chain (issue 10).
#include "commands/family_command.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

#include <cmath>
#include <optional>
#include <type_traits>

#include "commands/orbit_json.h"
#include "io/cli_input.h"
#include "core/orbits/onepp_family.h"
#include "core/orbits/special_orbits.h"
#include "core/orbits/onepp_family_points.h"
#include "io/npy.h"
#include "io/output_files.h"
#include "exit_codes.h"

#include <QPainter>

#include "ui/pictures/family_picture.h"

namespace grazelab::cli {
namespace {

QByteArray number(double value) { return QByteArray::number(value, 'g', 17); }

using V = JsonValue;

V pointValue(const core::OnePeriodicOrbit<double>& p) {
  return V::object({{"T", V::number(p.T)},
                    {"omega", V::number(core::twoPi<double>() / p.T)},
                    {"V", V::number(p.V)},
                    {"u1", V::number(p.postImpact.u1)},
                    {"energy", V::number(p.energy)}});
}

// the family as the frequency-energy picture draws it
std::vector<pictures::FrequencyEnergyPoint> frequencyEnergy(const std::vector<core::OnePeriodicOrbit<double>>& family) {
  std::vector<pictures::FrequencyEnergyPoint> points;
  points.reserve(family.size());
  for (const auto& p : family) points.push_back({p.energy, core::twoPi<double>() / p.T, p.admissible});
  return points;
}


// A stability class as a number for the .npy file (NaN where there is no admissible orbit).
double stabilityCode(core::Stability stability) {
  return double(int(stability));
}

// The stability along the family in precision S: the trace of each admissible row, and the
// bifurcations over (0, T2) with the 2-impact orbit born at each flip.
template <typename S>
struct FamilyStability {
  std::vector<double> traces;
  std::vector<double> codes;
  std::vector<JsonValue> bifurcations;
};

template <typename S>
std::optional<FamilyStability<S>> familyStability(const OptionValues& options,
                                                  const std::vector<core::OnePeriodicOrbit<double>>& family,
                                                  const Io& io, std::stop_token stop, QString& error) {
  const Parsed<ModelInput<S>> model = parseModel<S>(options);
  if (!model.value) {
    error = model.error;
    return std::nullopt;
  }
  const core::TwoMassForm<S>& chain = model.value->chain;
  FamilyStability<S> result;
  for (const core::OnePeriodicOrbit<double>& p : family) {
    if (stop.stop_requested()) return std::nullopt;
    const std::size_t index = result.traces.size();
    if (index % 64 == 0) {
      io.reportProgress(0.9 * double(index) / double(family.size()),
                        "stability of orbit " + std::to_string(index + 1) + " of " +
                            std::to_string(family.size()));
    }
    const core::OrbitSearch<S> found = p.admissible ? core::onePeriodicOrbitStability(chain, S(p.T))
                                                    : core::OrbitSearch<S>{};
    result.traces.push_back(found.orbit ? double(found.orbit->trace) : std::nan(""));
    result.codes.push_back(found.orbit ? stabilityCode(found.orbit->stability) : std::nan(""));
  }
  const S T2 = core::twoPi<S>() / chain.omegaSlow;
  io.reportProgress(0.9, "bifurcations of the family");
  const std::vector<core::FamilyBifurcation<S>> points = core::onePeriodicBifurcations(chain, 2000, stop);
  std::vector<S> energies;
  for (const core::FamilyBifurcation<S>& b : points) energies.push_back(b.energy);
  for (const core::FamilyBifurcation<S>& b : points) {
    if (stop.stop_requested()) return std::nullopt;
    // this command writes "checked" only when false
    std::vector<JsonValue::Field> point = bifurcationFields(b, T2, false);
    if (b.kind == core::PointKind::Undecided && b.checked) {
      point.emplace_back("note", V::of("not a bifurcation: beyond this period the orbit's data lose their digits "
                                       "(near a multiple of T1) or a contact cannot be decided in this precision; "
                                       "a higher --precision moves the point"));
    }
    if (b.kind == core::PointKind::PeriodDoubling) {
      const core::FlipSwitch<S> born = core::switchAtFlip(chain, b, 1, core::birthOffsetBound(b, energies), stop);
      if (born.search.orbit) {
        const core::PeriodicOrbit<S>& o = *born.search.orbit;
        const std::string symmetry = core::orbitSymmetry(o, core::symmetryTolerance<S>());
        point.emplace_back("born", V::object({{"impacts", V::of(std::int64_t(o.impacts))},
                                              {"side", V::of(std::string(core::toString(born.side)))},
                                              {"energy", V::number(o.energy)},
                                              {"period", V::number(o.period)},
                                              {"trace", V::number(o.trace)},
                                              {"stability", V::of(std::string(core::toString(o.stability)))},
                                              {"symmetry", symmetry.empty() ? V::null() : V::of(symmetry)},
                                              {"state", orbitStateValue(o.state)}}));
      } else {
        point.emplace_back("born", V::object({{"impacts", V::of(std::int64_t(2))}, {"problem", V::of(born.search.problem)}}));
      }
    }
    result.bifurcations.push_back(V::object(std::move(point)));
  }
  if (stop.stop_requested()) return std::nullopt;
  return result;
}

}  // namespace

int runFamily(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  if (!options.isSet("onepp")) {
    error = "family: name the family: --onepp (one impact per period)";
    return kExitInvalidInput;
  }
  const QString precision = options.value("precision");
  if (!QStringList{"auto", "double", "long", "quad"}.contains(precision)) {
    error = QStringLiteral("--precision: '%1' is not auto, double, long or quad").arg(precision);
    return kExitInvalidInput;
  }
  std::int64_t count = 2000;
  if (options.isSet("count")) {
    bool ok = false;
    count = options.value("count").toLongLong(&ok);
    if (!ok || count < 1 || count > 10'000'000) {
      error = QStringLiteral("--count: '%1' is not a count from 1 to 10000000").arg(options.value("count"));
      return kExitInvalidInput;
    }
  }
  const Parsed<ModelInput<double>> model = parseModel<double>(options);
  if (!model.value) {
    error = model.error;
    return kExitInvalidInput;
  }
  if (!model.value->chain.resonant) {
    error = "family: the 1IPP family of Theorem 2.1 needs the 1:2 resonant chain (give no --k2)";
    return kExitInvalidInput;
  }
  const auto output = openFileOutput(options, io, "PREFIX.csv, PREFIX.npy, PREFIX.json, ...", "family", error);
  if (!output) return kExitInvalidInput;
  const QString& prefix = output->prefix;

  const core::TwoMassForm<double>& chain = model.value->chain;
  const std::vector<core::OnePeriodicOrbit<double>> family = core::onePeriodicFamily(chain, count, stop);
  if (stop.stop_requested()) return kExitInterrupted;
  const core::OnePeriodicOrbit<double> end = core::grazingEnd(chain);
  // the stability of every admissible orbit and the family's bifurcations, in the precision asked
  std::vector<double> traces;
  std::vector<double> codes;
  std::vector<JsonValue> bifurcations;
  const auto take = [&](auto stability) {
    if (!stability) return false;
    traces = std::move(stability->traces);
    codes = std::move(stability->codes);
    bifurcations = std::move(stability->bifurcations);
    return true;
  };
  const bool computed = precision == "long"   ? take(familyStability<long double>(options, family, io, stop, error))
                        : precision == "quad" ? take(familyStability<core::Quad>(options, family, io, stop, error))
                                              : take(familyStability<double>(options, family, io, stop, error));
  if (stop.stop_requested()) return kExitInterrupted;
  if (!computed) return kExitInvalidInput;

  QByteArray csv = "T,omega,V,u1,energy,admissible,trace,stability\n";
  NpyArray array;
  array.rows = std::int64_t(family.size());
  array.columns = 8;
  for (std::size_t i = 0; i < family.size(); ++i) {
    const core::OnePeriodicOrbit<double>& p = family[i];
    const double omega = core::twoPi<double>() / p.T;
    const QByteArray stability = std::isnan(codes[i]) ? QByteArray()
                                 : QByteArray(core::toString(core::Stability(int(codes[i]))).data());
    csv += number(p.T) + "," + number(omega) + "," + number(p.V) + "," + number(p.postImpact.u1) + "," +
           number(p.energy) + "," + (p.admissible ? "1" : "0") + "," +
           (std::isnan(traces[i]) ? QByteArray() : number(traces[i])) + "," + stability + "\n";
    for (double v : {p.T, omega, p.V, p.postImpact.u1, p.energy, p.admissible ? 1.0 : 0.0, traces[i], codes[i]}) {
      array.reals.push_back(v);
    }
  }
  const core::Model& m = chain.model;
  const std::string name = QFileInfo(prefix).fileName().toStdString();
  const V json = V::object(
      {{"format", V::of("grazelab-family")},
       {"family", V::of("onepp")},
       {"model", V::object({{"m1", V::number(m.m1)}, {"m2", V::number(m.m2)}, {"k1", V::number(m.k1)},
                            {"k2", V::number(m.k2)}, {"gap", V::number(m.gap)},
                            {"T2", V::number(core::twoPi<double>() / chain.omegaSlow)}})},
       {"lambda_star", V::number(core::lambdaStar(chain))},
       {"grazing_end", pointValue(end)},
       {"columns", V::array({V::of("T"), V::of("omega"), V::of("V"), V::of("u1"), V::of("energy"), V::of("admissible"),
                             V::of("trace"), V::of("stability")})},
       {"stability_precision", V::of(precision == "auto" ? std::string("double") : precision.toStdString())},
       {"trace", V::of("tr DP of the return map at fixed energy (exact: flow and saltation matrices), in "
                       "the stability precision; empty (NaN in the .npy) where the orbit is not admissible")},
       {"stability", V::of("elliptic (|tr| < 2), hyperbolic (tr > 2), flip-hyperbolic (tr < -2), parabolic "
                           "(|tr| = 2 within rounding); in the .npy 0, 1, 2, 3 (NaN: not admissible)")},
       {"bifurcations", V::array(std::move(bifurcations))},
       {"rows", V::of(std::int64_t(family.size()))},
       {"periods", V::of(std::string("T2 k / (count + 1) for k = 1 ... ").append(std::to_string(count)) +
                         ", and T2 (1 - 2^-k) for k = 8 ... 40, sorted; multiples of T1 left out")},
       {"energy", V::of("E = 1/2 v^T M v + 1/2 u^T K u of the post-impact state (constant on the orbit)")},
       {"post_impact_state", V::of("u1 = u1, u2 = gap, v1 = 0, v2 = V")},
       {"conditioning", V::of("each row is computed in binary128 from its double period and rounded "
                              "once; near T2, V is conditioned like T2 / (T2 - T) in T and in the "
                              "masses: a mass that is not a binary number (m2 = 0.3) read exactly moves "
                              "V there by up to that factor times 1e-17")},
       {"files", V::object({{"csv", V::of(name + ".csv")},
                            {"npy", V::of(name + ".npy (float64, rows x 8 columns in the CSV's order, admissible "
                                                 "as 1.0 / 0.0, stability as 0..3)")}})},
       {"admissible", V::of("1 when V < 0 and the free flight from the data first returns to the stop "
                            "at T (exact contact search), else 0")},
       {"generator", V::of(std::string("grazelab-cli ").append(QCoreApplication::applicationVersion().toStdString()))}});
  const QByteArray jsonBytes = QByteArray::fromStdString(fieldPerLine(json, "  ", "") + "\n");
  if (!output->save(prefix + ".csv", csv, error) ||
      !output->save(prefix + ".npy", encodeNpy(array), error) ||
      !output->save(prefix + ".json", jsonBytes, error)) {
    return 1;
  }
  if (picturesAvailable() && !output->inMemory()) {
    const QString title = QStringLiteral("1IPP family: frequency against energy (m2/m1 = %1, λ* = %2)")
                              .arg(m.m2 / m.m1, 0, 'g', 4)
                              .arg(core::lambdaStar(chain), 0, 'g', 4);
    const QSize size(1100, 760);
    const bool drawn = savePngAndSvg(
        prefix, size, title, "GrazeLabFamily", QByteArray::fromStdString(oneLine(json)),
        [&](QPainter& painter) {
          pictures::paintFrequencyEnergy(painter, QRectF(QPointF(0, 0), size), frequencyEnergy(family),
                                         {end.energy, core::twoPi<double>() / end.T, true}, title);
        },
        error);
    if (!drawn) return 1;
  }
  std::int64_t admissible = 0;
  for (const auto& p : family) admissible += p.admissible ? 1 : 0;
  std::fprintf(io.messages, "grazelab-cli: family: %lld orbits (%lld admissible): %s.csv\n",
               (long long)family.size(), (long long)admissible, qPrintable(prefix));
  return kExitOk;
}

}  // namespace grazelab::cli
