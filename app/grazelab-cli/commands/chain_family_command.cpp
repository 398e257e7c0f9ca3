// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/chain_family_command.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QPainter>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/orbits/chain_glo.h"
#include "core/orbits/chain_onepp.h"
#include "core/orbits/onepp_family.h"
#include "core/solver/chain_run.h"
#include "exit_codes.h"
#include "io/cli_input.h"
#include "io/cli_output.h"
#include "io/json_value.h"
#include "io/npy.h"
#include "io/output_files.h"
#include "ui/pictures/family_picture.h"

namespace grazelab::cli {
namespace {

using V = JsonValue;

QByteArray number(double value) { return QByteArray::number(value, 'g', 17); }

V numbers(const Eigen::VectorXd& values) {
  std::vector<V> items;
  for (Eigen::Index i = 0; i < values.size(); ++i) items.push_back(V::number(values[i]));
  return V::array(std::move(items));
}

}  // namespace

int runChainFamily(const OptionValues& options, const Io& io, std::stop_token stop, QString& error) {
  if (options.isSet("precision") && options.value("precision") != "double" && options.value("precision") != "auto") {
    error = "--precision: the family of a chain of N masses is computed in double for now (give double or auto)";
    return kExitInvalidInput;
  }
  std::int64_t count = 2000;
  if (options.isSet("count")) {
    bool ok = false;
    count = options.value("count").toLongLong(&ok);
    if (!ok || count < 1 || count > 1'000'000) {
      error = QStringLiteral("--count: '%1' is not a count from 1 to 1000000").arg(options.value("count"));
      return kExitInvalidInput;
    }
  }
  const auto chainInput = parseMassChain(options, stop);
  if (!chainInput.value && chainInput.error.isEmpty()) return kExitInterrupted;
  if (!chainInput.value) {
    error = chainInput.error;
    return kExitInvalidInput;
  }
  const core::MassChain& chain = chainInput.value->chain;
  const auto output = openFileOutput(options, io, "PREFIX.csv, PREFIX.npy, PREFIX.json, ...", "family", error);
  if (!output) return kExitInvalidInput;
  const QString& prefix = output->prefix;

  const std::vector<core::ChainFamilyRow> rows = core::chainOnePeriodicFamily(chain, count, stop);
  if (stop.stop_requested()) return kExitInterrupted;
  const core::ChainDynamics dynamics = core::chainDynamics(chain);
  const bool commensurate = dynamics.period > 0;
  const double end = core::chainOnePeriodicEnd(chain);
  // the grazing limit of Theorem 2.1: the GLO the data tend to as T -> T_max
  const std::vector<double> weights = core::onePeriodicGrazingWeights(chain, end);
  const core::ChainGloStart glo = core::chainGloStart(chain, weights);

  const Eigen::Index n = chain.size();
  QByteArray csv = "T,omega,V,energy,admissible";
  for (Eigen::Index i = 0; i < n; ++i) csv += ",u" + QByteArray::number(i + 1);
  csv += "\n";
  NpyArray array;
  array.rows = std::int64_t(rows.size());
  array.columns = 5 + n;
  std::vector<pictures::FrequencyEnergyPoint> points;  // for the picture
  std::int64_t admissible = 0;
  for (const core::ChainFamilyRow& row : rows) {
    const core::ChainOnePeriodicOrbit& orbit = row.orbit;
    const bool hasData = orbit.refusal != core::OnePeriodicRefusal::MultipleOfPeriod &&
                         orbit.refusal != core::OnePeriodicRefusal::BadPeriod;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double omega = 2 * std::numbers::pi / row.T;
    csv += number(row.T) + "," + number(omega) + "," + (hasData ? number(orbit.V) : QByteArray()) + "," +
           (hasData ? number(orbit.energy) : QByteArray()) + "," + (orbit.admissible() ? "1" : "0");
    for (double value : {row.T, omega, hasData ? orbit.V : nan, hasData ? orbit.energy : nan,
                         orbit.admissible() ? 1.0 : 0.0}) {
      array.reals.push_back(value);
    }
    for (Eigen::Index i = 0; i < n; ++i) {
      csv += "," + (hasData ? number(orbit.postImpact.u[i]) : QByteArray());
      array.reals.push_back(hasData ? orbit.postImpact.u[i] : nan);
    }
    csv += "\n";
    admissible += orbit.admissible() ? 1 : 0;
    if (hasData) {
      points.push_back({orbit.energy, omega, orbit.admissible()});
    }
  }
  std::vector<V> weightValues;
  for (double weight : weights) weightValues.push_back(V::number(weight));
  const double gloEnergy = glo.problem == core::GloStartProblem::None ? core::chainEnergy(chain, glo.state) : 0;
  std::vector<V> columns{V::of("T"), V::of("omega"), V::of("V"), V::of("energy"), V::of("admissible")};
  for (Eigen::Index i = 0; i < n; ++i) columns.push_back(V::of(std::string("u").append(std::to_string(i + 1))));
  const std::string name = QFileInfo(prefix).fileName().toStdString();
  const V document = V::object(
      {{"format", V::of("grazelab-family")},
       {"family", V::of("onepp")},
       {"chain", massChainValue(chain, dynamics.period)},
       {"T_max", V::number(end)},
       {"T_max_is", V::of(commensurate ? "the common period of the commensurate chain"
                                       : "the slowest mode's period (the frequencies are not commensurate)")},
       {"grazing_limit",
        V::object({{"weights", V::array(std::move(weightValues))},
                   {"u", glo.problem == core::GloStartProblem::None ? numbers(glo.state.u) : V::null()},
                   {"energy", V::number(gloEnergy)},
                   {"meaning", V::of("as T -> T_max the post-impact data tend to GLO_lambda with these weights "
                                     "(fastest mode first; Theorem 2.1 for any N: lambda_j = a_sj w_j^-2 / sum "
                                     "a_si w_i^-2 over the modes whose period divides T_max), V -> 0")}})},
       {"columns", V::array(std::move(columns))},
       {"rows", V::of(std::int64_t(rows.size()))},
       {"admissible_rows", V::of(admissible)},
       {"periods", V::of(std::string("T_max k / (count + 1) for k = 1 ... ").append(std::to_string(count)) +
                         ", and T_max (1 - 2^-k) for k = 8 ... 30, sorted")},
       {"post_impact_state", V::of("u = V g(T) (u_s = gap), v = V e_s")},
       {"admissible", V::of("1 when V < 0 and the free flight from the data first returns to the stop at T "
                            "(certified contact search), else 0; V, energy and u empty (NaN in the .npy) at a "
                            "multiple of a mode's period")},
       {"files", V::object({{"csv", V::of(name + ".csv")},
                            {"npy", V::of(name + ".npy (float64, rows x " + std::to_string(5 + n) +
                                          " columns in the CSV's order)")}})},
       {"generator", V::of("grazelab-cli " + QCoreApplication::applicationVersion().toStdString())}});
  const QByteArray json = QByteArray::fromStdString(fieldPerLine(document, "  ", "") + "\n");
  if (!output->save(prefix + ".csv", csv, error) || !output->save(prefix + ".npy", encodeNpy(array), error) ||
      !output->save(prefix + ".json", json, error)) {
    return 1;
  }
  if (picturesAvailable() && !output->inMemory() && admissible > 0) {
    const pictures::FrequencyEnergyPoint endPoint{gloEnergy, 2 * std::numbers::pi / end, true};
    const QString title = QStringLiteral("1IPP family of %1 masses: frequency against energy").arg(n);
    const QSize size(1100, 760);
    const bool drawn = savePngAndSvg(
        prefix, size, title, "GrazeLabFamily", json,
        [&](QPainter& painter) {
          pictures::paintFrequencyEnergy(painter, QRectF(QPointF(0, 0), size), points, endPoint, title,
                                         QStringLiteral("grazing end: T → T_max, V → 0"));
        },
        error);
    if (!drawn) return 1;
  }
  std::fprintf(io.messages, "grazelab-cli: family: %lld orbits (%lld admissible): %s.csv\n", (long long)rows.size(),
               (long long)admissible, qPrintable(prefix));
  return kExitOk;
}

}  // namespace grazelab::cli
