// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/chain_start.h"

#include <algorithm>

#include <QStringList>

#include <cmath>
#include <type_traits>
#include <vector>

#include "core/orbits/chain_glo.h"
#include "core/orbits/chain_onepp.h"

namespace grazelab::cli {
namespace {

// `count` finite numbers from a comma-separated list, read in precision S, or nothing with
// `error` set
template <typename S>
std::optional<std::vector<S>> numberList(const OptionValues& options, const char* name, Eigen::Index count,
                                         const QString& layout, QString& error) {
  std::vector<S> values;
  // numbers handed over as numbers (the Python module): in double the very numbers their
  // shortest text would give, read without the text
  const auto given = std::is_same_v<S, double> ? options.numbers(name) : std::nullopt;
  if (given) {
    for (const double value : *given) {
      if (!std::isfinite(value)) {
        error = QStringLiteral("--%1: '%2' is not a finite number").arg(name).arg(value);
        return std::nullopt;
      }
      values.push_back(value == 0 ? S(0) : S(value));  // (-0 reads as 0 from its text "0")
    }
  }
  for (const QString& part : given ? QStringList() : options.value(name).split(',')) {
    const core::ParsedScalar<S> value = core::parseScalar<S>(part.trimmed().toStdString());
    if (!value.value || !core::isFinite(*value.value)) {
      error = QStringLiteral("--%1: '%2' is not a finite number").arg(name, part);
      return std::nullopt;
    }
    values.push_back(*value.value);
  }
  if (Eigen::Index(values.size()) != count) {
    error = QStringLiteral("--%1: %2 numbers for %3 masses (%4: %5)")
                .arg(name)
                .arg(values.size())
                .arg(count / (layout.contains("v1") ? 2 : 1))
                .arg(layout)
                .arg(count);
    return std::nullopt;
  }
  return values;
}

}  // namespace

const char* onePeriodicRefusalWords(core::OnePeriodicRefusal refusal) {
  switch (refusal) {
    case core::OnePeriodicRefusal::None: return "admissible";
    case core::OnePeriodicRefusal::BadPeriod: return "the period is not positive and finite";
    case core::OnePeriodicRefusal::MultipleOfPeriod: return "the period is a multiple of a mode's period: no data";
    case core::OnePeriodicRefusal::LeavesIntoStop: return "its data leave into the stop (V >= 0)";
    case core::OnePeriodicRefusal::NotDecided: return "its return at T cannot be decided in this precision (V too small)";
    case core::OnePeriodicRefusal::NeverReturns: return "the flight from its data never returns to the stop";
    case core::OnePeriodicRefusal::ReturnsEarly: return "the flight from its data meets the stop before T";
    case core::OnePeriodicRefusal::SearchBudget:
      return "the search for its flight's return ran out of its windows before T (a stiff chain's fast modes)";
  }
  return "unknown";
}

bool oneStartOf(const OptionValues& options, Eigen::Index n, QString& error) {
  if (int(options.isSet("state")) + int(options.isSet("glo-weights")) + int(options.isSet("onepp")) == 1) return true;
  error = QStringLiteral("a chain of N masses starts from --state u1,...,uN,v1,...,vN (%1 numbers), "
                         "--glo-weights l1,...,lN (%2) or --onepp T: one of them")
              .arg(2 * n)
              .arg(n);
  return false;
}

bool noTwoMassStart(const OptionValues& options, QString& error) {
  if (!options.isSet("glo")) return true;
  error = "--glo is not available for a chain of N masses: start it with --state u1,...,uN,v1,...,vN, "
          "--glo-weights l1,...,lN or --onepp T";
  return false;
}

template <typename S>
std::optional<core::BasicChainStart<S>> chainStart(const OptionValues& options, const core::BasicMassChain<S>& chain,
                                                   QString& error, std::string* description,
                                                   const core::BasicChainDynamics<S>* ready) {
  const Eigen::Index n = chain.size();
  const int s = chain.stopped() - 1;
  if (!oneStartOf(options, n, error)) return std::nullopt;
  core::BasicChainStart<S> start;
  if (options.isSet("onepp")) {
    const core::ParsedScalar<S> T = core::parseScalar<S>(options.value("onepp").trimmed().toStdString());
    const core::BasicChainOnePeriodicOrbit<S> orbit = core::chainOnePeriodicOrbitIn<S>(chain, T.value.value_or(S(-1)));
    if (!orbit.admissible()) {
      error = QStringLiteral("--onepp %1: no admissible 1IPP orbit of that period: %2")
                  .arg(options.value("onepp"), onePeriodicRefusalWords(orbit.refusal));
      return std::nullopt;
    }
    start.state = orbit.postImpact;
  } else if (options.isSet("state")) {
    const auto values = numberList<S>(options, "state", 2 * n, "u1,...,uN,v1,...,vN", error);
    if (!values) return std::nullopt;
    using Vector = core::ChainVector<S>;
    start.state = {Eigen::Map<const Vector>(values->data(), n), Eigen::Map<const Vector>(values->data() + n, n)};
  } else {
    const auto weights = numberList<S>(options, "glo-weights", n, "l1,...,lN", error);
    if (!weights) return std::nullopt;
    const core::BasicChainGloStart<S> glo =
        ready ? core::chainGloStartIn<S>(*ready, *weights) : core::chainGloStartIn<S>(chain, *weights);
    switch (glo.problem) {
      case core::GloStartProblem::None: break;
      case core::GloStartProblem::WrongCount:
      case core::GloStartProblem::NotFinite:
        error = "--glo-weights: one finite weight per mode";
        return std::nullopt;
      case core::GloStartProblem::NotAffine:
        error = "--glo-weights: the weights must sum to 1 (an affine combination of the GLOMs keeps the "
                "stopped mass on the stop)";
        return std::nullopt;
      case core::GloStartProblem::WeightOnNode:
        error = "--glo-weights: a weight on a mode with a node at the stopped mass, which has no GLOM (see "
                "info's node_at_stop)";
        return std::nullopt;
    }
    start = glo.start();
  }
  if (options.isSet("perturb")) {
    const auto delta = numberList<S>(options, "perturb", 2 * n, "du1,...,duN,dv1,...,dvN", error);
    if (!delta) return std::nullopt;
    using Vector = core::ChainVector<S>;
    start.state.u += Eigen::Map<const Vector>(delta->data(), n);
    start.state.v += Eigen::Map<const Vector>(delta->data() + n, n);
    // pushed: every mode may move now
    if (std::any_of(delta->begin(), delta->end(), [](const S& x) { return x != 0; })) start.stillModes.clear();
  }
  if (description) {
    *description = options.isSet("onepp")
                       ? "1IPP orbit of period T = " + options.value("onepp").trimmed().toStdString() +
                             ", right after its impact"
                   : options.isSet("state") ? std::string("the state given")
                                            : "GLO_lambda at its touch, weights " +
                                                  options.text("glo-weights");
    if (options.isSet("perturb")) *description += ", pushed by " + options.text("perturb");
  }
  if (start.state.u[s] > chain.gap) {
    error = QStringLiteral("the start has u%1 = %2 past the stop (gap %3)")
                .arg(s + 1)
                .arg(core::toDouble(start.state.u[s]))
                .arg(core::toDouble(chain.gap));
    return std::nullopt;
  }
  return start;
}

#define GRAZELAB_INSTANTIATE(S)                                                                                  \
  template std::optional<core::BasicChainStart<S>> chainStart(const OptionValues&, const core::BasicMassChain<S>&, \
                                                              QString&, std::string*,                             \
                                                              const core::BasicChainDynamics<S>*);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(core::Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::cli
