// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/chain_map_input.h"

#include <QStringList>

#include <cmath>
#include <string>

#include "io/cli_input.h"

namespace grazelab::cli {

namespace {

// `count` finite numbers separated by commas (--NAME), or nothing with `error` set
std::optional<std::vector<double>> finiteNumbers(const OptionValues& options, const char* name, Eigen::Index count,
                                                 const char* layout, QString& error) {
  const QStringList parts = options.value(name).split(',');
  if (parts.size() != count) {
    error = QStringLiteral("--%1: %2 numbers where %3 are wanted (%4)").arg(name).arg(parts.size()).arg(count).arg(layout);
    return std::nullopt;
  }
  std::vector<double> values;
  for (const QString& part : parts) {
    bool ok = false;
    const double value = part.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(value)) {
      error = QStringLiteral("--%1: '%2' is not a finite number").arg(name, part);
      return std::nullopt;
    }
    values.push_back(value);
  }
  return values;
}

}  // namespace

// A map of a chain of N masses: --masses ... (as simulate); axes u<i> or v<i> set the start
// --state u1..uN,v1..vN (default: the grazing-start plane, the stopped mass at rest on the stop and
// every other coordinate 0, as the two-mass map's), or axes w<j> the GLO weights of a start on
// GLO_lambda (--glo-weights, default 0; the last weight no axis sets balances the others)
// pushed by --perturb
std::optional<core::ChainMapSpec> parseChainMapSpec(const OptionValues& options, std::stop_token stop,
                                                    QString& error, bool& stopped) {
  const QString trust = options.isSet("trust") ? options.value("trust") : QStringLiteral("off");
  if (trust != "off" && trust != "auto") {
    error = QStringLiteral("--trust: '%1' is not off or auto (a map estimates each point's horizon with auto)")
                .arg(trust);
    return std::nullopt;
  }
  for (const char* name : {"glo", "onepp"}) {
    if (options.isSet(name)) {
      error = QStringLiteral("--%1: a map of N masses starts from --state u1,...,uN,v1,...,vN (axes u<i>, v<i>) "
                             "or from GLO_lambda (axes w<j>, --glo-weights, --perturb)")
                  .arg(name);
      return std::nullopt;
    }
  }
  const auto chain = parseMassChain(options, stop);
  stopped = !chain.value && chain.error.isEmpty();
  if (!chain.value) {
    error = chain.error;
    return std::nullopt;
  }
  core::ChainMapSpec spec;
  spec.chain = chain.value->chain;
  spec.estimateHorizon = trust == "auto";
  const Eigen::Index n = spec.chain.size();
  spec.start = {Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
  spec.push = spec.start;
  spec.start.u[spec.chain.stopped() - 1] = spec.chain.gap;  // the grazing-start plane
  for (const char* name : {"x", "y"}) {
    if (!options.isSet(name)) {
      error = QStringLiteral("--%1 u<i>|v<i>|w<j>:from:to:count is required").arg(name);
      return std::nullopt;
    }
    const QStringList parts = options.value(name).split(':');
    const auto axis = parts.size() == 4 ? core::parseChainMapVariable(parts[0].toStdString(), n) : std::nullopt;
    if (!axis) {
      error = QStringLiteral("--%1: '%2' is not u<i>|v<i>|w<j>:from:to:count with i, j from 1 to %3")
                  .arg(name, options.value(name))
                  .arg(n);
      return std::nullopt;
    }
    bool okFrom = false, okTo = false, okCount = false;
    core::ChainMapAxis& target = std::string(name) == "x" ? spec.x : spec.y;
    target = *axis;
    target.range.from = parts[1].toDouble(&okFrom);
    target.range.to = parts[2].toDouble(&okTo);
    target.range.count = parts[3].toLongLong(&okCount);
    if (!okFrom || !okTo || !okCount || target.range.count < 1) {
      error = QStringLiteral("--%1: '%2' is not u<i>|v<i>|w<j>:from:to:count (numbers, a count >= 1)").arg(name, options.value(name));
      return std::nullopt;
    }
  }
  const bool overWeights = spec.x.weight() || spec.y.weight();
  const std::vector<const char*> notHere = overWeights ? std::vector<const char*>{"state"}
                                                        : std::vector<const char*>{"glo-weights", "perturb"};
  for (const char* name : notHere) {
    if (options.isSet(name)) {
      error = overWeights ? QStringLiteral("--state: a map over GLO weights starts on GLO_lambda (push it with --perturb)")
                          : QStringLiteral("--%1: belongs to a map over GLO weights (axes w<j>)").arg(name);
      return std::nullopt;
    }
  }
  if (options.isSet("state")) {
    const auto values = finiteNumbers(options, "state", 2 * n, "u1,...,uN,v1,...,vN", error);
    if (!values) return std::nullopt;
    for (Eigen::Index i = 0; i < 2 * n; ++i) (i < n ? spec.start.u[i] : spec.start.v[i - n]) = (*values)[std::size_t(i)];
  }
  if (options.isSet("glo-weights")) {
    const auto weights = finiteNumbers(options, "glo-weights", n, "l1,...,lN, fastest mode first", error);
    if (!weights) return std::nullopt;
    spec.weights = *weights;
  }
  if (options.isSet("perturb")) {
    const auto push = finiteNumbers(options, "perturb", 2 * n, "du1,...,duN,dv1,...,dvN", error);
    if (!push) return std::nullopt;
    for (Eigen::Index i = 0; i < 2 * n; ++i) (i < n ? spec.push.u[i] : spec.push.v[i - n]) = (*push)[std::size_t(i)];
  }
  if (options.isSet("contacts")) {
    bool ok = false;
    spec.contacts = options.value("contacts").toLongLong(&ok);
    if (!ok || spec.contacts < 1) {
      error = QStringLiteral("--contacts: '%1' is not a count >= 1").arg(options.value("contacts"));
      return std::nullopt;
    }
  }
  const std::string problem = core::checkChainMap(spec);
  if (!problem.empty()) {
    error = QString::fromStdString(problem);
    return std::nullopt;
  }
  return spec;
}

}  // namespace grazelab::cli
