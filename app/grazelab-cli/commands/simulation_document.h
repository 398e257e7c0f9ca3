// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

// The document of `simulate` (its head, before the events, and its end), written once for any
// value type V (io/document_values.h): JsonValue, which the command line streams as text, or the
// Python module's objects (PyValue, python/value_to_python.h).

#include <cmath>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "commands/simulation.h"
#include "io/document_values.h"
#include "io/json_value.h"

namespace grazelab::cli {

// The names of a chain's columns, made once per document (an owned name is an allocation)
struct ColumnNames {
  std::vector<JsonKey> u, v, vPre;  ///< u1..uN, v1..vN, v1_pre..vN_pre
  JsonKey vPost;  ///< v<s>_post

  // (names appended, not "literal" + string: GCC 12 warns falsely on that at -O2)
  static std::string name(char letter, Eigen::Index i, const char* suffix = "") {
    return std::string(1, letter).append(std::to_string(i)).append(suffix);
  }
  ColumnNames(Eigen::Index n, int stopped) : vPost(JsonKey::owned(name('v', stopped, "_post"))) {
    for (Eigen::Index i = 1; i <= n; ++i) {
      u.push_back(JsonKey::owned(name('u', i)));
      v.push_back(JsonKey::owned(name('v', i)));
      vPre.push_back(JsonKey::owned(name('v', i, "_pre")));
    }
  }
  /// The names of a chain of n masses stopped on mass `stopped`, made once per process (a short
  /// run's document would spend more on them than on its run)
  static const ColumnNames& of(Eigen::Index n, int stopped) {
    static std::mutex mutex;
    static std::map<std::pair<Eigen::Index, int>, ColumnNames> made;
    const std::lock_guard lock(mutex);
    return made.try_emplace({n, stopped}, n, stopped).first->second;
  }
};

// The names of a run's chain's columns
template <typename S>
const ColumnNames& namesOf(const RunIn<S>& run) {
  return ColumnNames::of(run.ready->numbers.size(), run.ready->numbers.stopped());
}

// a state at time t as the two-mass documents write it: {t, u1..uN, v1..vN}
template <typename V, typename S>
V stateValue(const ColumnNames& names, const S& t, const core::BasicChainState<S>& state) {
  std::vector<typename V::Field> fields;
  fields.reserve(2 * names.u.size() + 1);
  fields.emplace_back("t", V::number(t));
  for (std::size_t i = 0; i < names.u.size(); ++i) fields.emplace_back(names.u[i], V::number(state.u[Eigen::Index(i)]));
  for (std::size_t i = 0; i < names.v.size(); ++i) fields.emplace_back(names.v[i], V::number(state.v[Eigen::Index(i)]));
  return V::object(std::move(fields));
}

// the samples as columns t, u1..uN, v1..vN, in double
template <typename V>
V samplesValue(const ColumnNames& names, const std::vector<std::pair<double, core::ChainState>>& samples) {
  const std::size_t n = names.u.size();
  std::vector<std::vector<V>> columns(2 * n + 1);
  for (std::vector<V>& column : columns) column.reserve(samples.size());
  for (const auto& [t, state] : samples) {
    columns[0].push_back(V::number(t));
    for (std::size_t i = 0; i < n; ++i) {
      columns[1 + i].push_back(V::number(state.u[Eigen::Index(i)]));
      columns[1 + n + i].push_back(V::number(state.v[Eigen::Index(i)]));
    }
  }
  std::vector<typename V::Field> fields;
  fields.emplace_back("t", V::array(std::move(columns[0])));
  for (std::size_t i = 0; i < n; ++i) fields.emplace_back(names.u[i], V::array(std::move(columns[1 + i])));
  for (std::size_t i = 0; i < n; ++i) fields.emplace_back(names.v[i], V::array(std::move(columns[1 + n + i])));
  return V::object(std::move(fields));
}

// The fields before the events: the chain, the note's model of it when the note's kernel runs it
// (two masses stopped on the second, no wall, a 1:2 design or not commensurate: its frequencies,
// periods, mode shapes, lambda*), and the start
template <typename V>
std::vector<typename V::Field> headFields(const AnyRun& any, PrecisionChoice precision) {
  return std::visit(
      [&]<typename S>(const RunIn<S>& run) {
        const core::BasicReadyChain<S>& ready = *run.ready;
        std::vector<typename V::Field> head;
        const std::string precisionName(toString(precision));
        head.emplace_back("chain", values::chainSection<V>("chain", &ready, std::string(), [&] {
                            return values::massChain<V>(ready.numbers, ready.dynamics.period);
                          }));
        if (ready.notesModel) {
          head.emplace_back("model", values::chainSection<V>("model", &ready, precisionName, [&] {
                              return values::model<V>(ModelInput<S>{*ready.notesModel, *ready.notes}, precisionName);
                            }));
        }
        head.emplace_back("initial", V::object({{"description", V::of(run.description)},
                                                {"state", stateValue<V>(namesOf(run), S(0), run.start.state)}}));
        return head;
      },
      any);
}

// The fields after the events of a run that ended: its final state, why it stopped, its totals,
// accuracy, error estimate, precision, time and samples
template <typename V>
std::vector<typename V::Field> endFields(const SimulateOutcome& outcome, const core::Trust& trust,
                                         PrecisionChoice precision, bool sampled) {
  return std::visit(
      [&]<typename S>(const RunIn<S>& ran) {
        const ColumnNames& names = namesOf(ran);
        const core::BasicChainRun<S>& run = ran.run;
        using std::abs;
        std::vector<V> raised;
        for (const std::string& line : outcome.escalations) raised.push_back(V::of(line));
        const std::string message = stopMessage(run.stop, std::is_same_v<S, core::Quad>);
        // (fields added one by one: a braced list of pairs would copy every value)
        std::vector<typename V::Field> end;
        end.reserve(12);
        end.emplace_back("final", stateValue<V>(names, run.tFinal, run.final));
        end.emplace_back("stop_reason", V::of(std::string(core::toString(run.stop))));
        end.emplace_back("message", message.empty() ? V::null() : V::of(message));
        end.emplace_back("contacts", V::object({{"total", V::of(std::int64_t(run.contacts))},
                                                {"impacts", V::of(std::int64_t(run.impacts))},
                                                {"grazings", V::of(std::int64_t(run.grazings))},
                                                {"sticks", V::of(std::int64_t(run.sticks))},
                                                {"releases", V::of(std::int64_t(run.releases))}}));
        end.emplace_back("energy",
                         V::object({{"initial", V::number(run.energyInitial)},
                                    {"final", V::number(run.energyFinal)},
                                    {"relative_drift", V::number(S(abs(run.energyFinal / run.energyInitial - 1)))},
                                    {"max_rel_drift", V::number(run.maxEnergyDrift)}}));
        end.emplace_back("accuracy", V::object({{"max_contact_residual", V::number(run.maxContactResidual)}}));
        end.emplace_back("trust", values::trust<V>(trust));
        end.emplace_back("precision", V::object({{"requested", V::of(std::string(toString(precision)))},
                                                 {"used", V::of(std::string(core::toString(outcome.precision)))},
                                                 {"escalations", V::array(std::move(raised))}}));
        if (!outcome.escalations.empty()) {
          // the start the raised run used, in its digits (the head holds the one read first)
          end.back().second.set("initial_state_used", stateValue<V>(names, S(0), ran.start.state));
        }
        // the run's own time, its shadow apart
        end.emplace_back("timing",
                         V::object({{"seconds", V::number(ran.seconds)},
                                    {"contacts_per_second",
                                     V::number(ran.seconds > 0 ? double(run.contacts) / ran.seconds : 0.0)}}));
        if (sampled) {
          end.emplace_back("samples", samplesValue<V>(names, outcome.samples));
          end.emplace_back("samples_truncated", V::of(outcome.samplesTruncated));
        }
        return end;
      },
      *outcome.last);
}

// The estimate says when it does not count the start's rounding
inline void withWidenedStart(const SimulateOutcome& outcome, core::Trust& trust) {
  if (!outcome.widenedStart.empty() && trust.verdict != core::Verdict::Unchecked) {
    trust.reason += "; " + outcome.widenedStart;
  }
}

/// The json document of a run that ended (SimulateStatus::Ran) as values of type V, its `events`
/// null: JsonValue for the command line's tests and benchmark, the Python module's objects for
/// its result (made as the document is built: no second pass).
template <typename V>
V simulationDocument(const SimulateOutcome& outcome, const SimulateRequest& request) {
  std::vector<typename V::Field> fields = headFields<V>(outcome.head(), request.precision);
  fields.emplace_back("events", V::null());
  core::Trust trust = outcome.trust;
  withWidenedStart(outcome, trust);
  for (typename V::Field& field : endFields<V>(outcome, trust, request.precision, request.sampled)) {
    fields.push_back(std::move(field));
  }
  return V::object(std::move(fields));
}

}  // namespace grazelab::cli
